"""A projectile that embeds in a block which then slides to rest against kinetic friction: the speed
before the blow is derived with the work of friction after it (both methods), and the simulation, whose
coupling is short beside friction's time, agrees; without the friction's work it would not."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model

uncached = derivation._derive.__wrapped__
m, M, mu, d, g, theta = (sympy.Symbol(n, positive=True) for n in ("m", "M", "mu", "d", "g", "theta"))
TABLE = {str(s): s for s in (m, M, mu, d, g, theta)}

SKID = """
elements:
  floor: {kind: incline, body: block, mass: M, angle: ANGLE, coordinate: x, direction: up, friction: mu}
gravity: g
collision: {projectile: bullet, mass: m, direction: {x: 1}, target: block, at: {x: 0}, reaches: {x: d}}
domain:
  ranges: {theta: ["0", "pi/2"]}
quantities:
  speed: {projectile_speed: bullet}
  lost: {energy_fraction_lost: bullet}
"""

# (the surface's angle, the bullet's speed, the fraction of the energy lost in the blow)
SKIDS = [
    pytest.param("0", (m + M) / m * sympy.sqrt(2 * mu * g * d), M / (m + M), id="level-floor"),
    pytest.param(
        "theta",
        (m + M) / (m * sympy.cos(theta)) * sympy.sqrt(2 * g * d * (sympy.sin(theta) + mu * sympy.cos(theta))),
        (M + m * sympy.sin(theta) ** 2) / (M + m),
        id="up-a-rough-incline",
    ),
]


@pytest.mark.parametrize(("angle", "speed", "lost"), SKIDS)
def test_the_bullets_speed_counts_the_work_of_friction_after_the_blow(
    angle: str, speed: sympy.Expr, lost: sympy.Expr
) -> None:
    result = uncached(load_model(yaml.safe_load(SKID.replace("ANGLE", angle)), TABLE))
    assert sympy.simplify(result.quantities["speed"] - speed) == 0
    assert sympy.simplify(result.quantities["lost"] - lost) == 0
    assert set(result.agreement["speed"]) >= {"newton", "conservation"}
    assert result.simulation["speed"].max_relative_error < 1e-3


# a stop behind the blow, or a bullet fired the other way: every method had taken the block to stop at
# `reaches` all the same (the speed squared), the first refused as a negative energy, the second only by
# a simulation that "never turned back"
BEHIND = [
    pytest.param(("reaches: {x: d}", "reaches: {x: -d}"), "towards increasing values", id="stop-behind"),
    pytest.param(("direction: {x: 1}", "direction: {x: -1}"), "towards decreasing values", id="fired-back"),
]


@pytest.mark.parametrize(("change", "heading"), BEHIND)
def test_a_stop_the_blow_does_not_drive_the_block_towards_is_refused_at_the_direction(
    change: tuple[str, str], heading: str
) -> None:
    text = SKID.replace("ANGLE", "0").replace(*change)
    with pytest.raises(derivation.DerivationError) as caught:
        uncached(load_model(yaml.safe_load(text), TABLE))
    assert caught.value.path == ("collision", "direction")
    assert f"the projectile drives x {heading}" in caught.value.message
