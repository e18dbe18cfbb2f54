"""A projectile that sticks in a rigid body away from its centre of mass (a bullet in a hanging rod's
end): every method counts the embedded mass where it is, the simulation couples the bullet at that
point, and a point that is not fixed on the body, or is away from a particle, is refused."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.errors import SpecErrors

uncached = derivation._derive.__wrapped__
m, M, L, g, theta = (sympy.Symbol(n, positive=True) for n in ("m", "M", "L", "g", "theta"))
TABLE = {str(s): s for s in (m, M, L, g, theta)}

ROD = """
elements:
  axle: {kind: pendulum, body: rod, mass: M, inertia: "M*L^2/12", distance: L/2, coordinate: phi}
gravity: g
collision:
  projectile: bullet
  mass: m
  direction: {x: 1}
  target: rod
  POINT
  at: {phi: 0}
  reaches: {phi: theta}
domain:
  ranges: {theta: ["0", "pi/2"]}
quantities:
  speed: {projectile_speed: bullet}
  lost: {energy_fraction_lost: bullet}
"""


def rod(point: str) -> dict[str, object]:
    data: dict[str, object] = yaml.safe_load(ROD.replace("POINT", point))
    return data


def struck_at(s: sympy.Expr) -> tuple[sympy.Expr, sympy.Expr]:
    """The textbook answer for a bullet sticking at distance s below the pivot: angular momentum about
    the pivot across the blow, then energy up to the turning point."""
    inertia = M * L**2 / 3 + m * s**2
    speed = sympy.sqrt(2 * inertia * g * (1 - sympy.cos(theta)) * (M * L / 2 + m * s)) / (m * s)
    return speed, 1 - m * s**2 / inertia


@pytest.mark.parametrize(
    ("s", "point"),
    [
        pytest.param(L, '{x: "L*sin(phi)", y: "-L*cos(phi)"}', id="lower-end"),
        pytest.param(2 * L / 3, '{x: "2*L*sin(phi)/3", y: "-2*L*cos(phi)/3"}', id="two-thirds-down"),
        pytest.param(L / 2, '{x: "L*sin(phi)/2", y: "-L*cos(phi)/2"}', id="centre"),
    ],
)
def test_a_bullet_in_a_rod_counts_its_moment_about_the_pivot_where_it_sticks(
    s: sympy.Expr, point: str
) -> None:
    result = uncached(load_model(rod(f"point: {point}"), TABLE))
    speed, lost = struck_at(s)
    assert sympy.simplify(result.quantities["speed"] - speed) == 0
    assert sympy.simplify(result.quantities["lost"] - lost) == 0
    assert set(result.agreement["speed"]) >= {"newton", "conservation"}
    assert result.simulation["speed"].max_relative_error < 1e-3
    assert result.simulation["lost"].max_relative_error < 1e-3


def test_without_a_point_the_bullet_sticks_at_the_centre_of_mass() -> None:
    result = uncached(load_model(rod(""), TABLE))
    assert sympy.simplify(result.quantities["speed"] - struck_at(L / 2)[0]) == 0


def test_newtons_method_balances_the_impulses_on_the_rod_and_on_the_bullet_in_it() -> None:
    result = uncached(load_model(rod('point: {x: "L*sin(phi)", y: "-L*cos(phi)"}'), TABLE))
    newton = next(report for report in result.methods if report.name == "newton")
    titles = [step.title for step in newton.steps]
    assert "Impulse balance on «rod», constraint impulses unknown" in titles
    assert "Impulse balance on the bullet, constraint impulses unknown" in titles
    assert "Velocities just after, as the constraints allow" in titles


@pytest.mark.parametrize(
    ("point", "message"),
    [
        pytest.param('{x: "L*sin(phi)", y: "-L"}', "the point moves on rod", id="in-the-rooms-axes"),
        pytest.param('{x: "L*sin(phi)"}', "give the point's x and y", id="one-axis"),
    ],
)
def test_a_point_not_fixed_on_the_rod_is_refused(point: str, message: str) -> None:
    with pytest.raises(SpecErrors, match=message) as refused:
        load_model(rod(f"point: {point}"), TABLE)
    assert [error.path for error in refused.value.errors] == [("collision", "point")]


BLOCK = """
elements:
  string: {kind: pendulum, body: block, mass: M, length: L, coordinate: phi}
gravity: g
collision:
  projectile: PROJECTILE
  mass: m
  direction: {x: 1}
  target: block
  point: POINT
  at: {phi: 0}
  reaches: {phi: theta}
quantities:
  speed: {projectile_speed: PROJECTILE}
"""


def test_a_particle_is_struck_where_it_is() -> None:
    where = BLOCK.replace("PROJECTILE", "bullet")
    same = uncached(
        load_model(yaml.safe_load(where.replace("POINT", '{x: "L*sin(phi)", y: "-L*cos(phi)"}')), TABLE)
    )
    plain = uncached(load_model(yaml.safe_load(where.replace("  point: POINT\n", "")), TABLE))
    assert sympy.simplify(same.quantities["speed"] - plain.quantities["speed"]) == 0
    with pytest.raises(SpecErrors, match="block is a particle: a projectile sticks where it is"):
        load_model(yaml.safe_load(where.replace("POINT", '{x: "L*sin(phi)/2", y: "-L*cos(phi)/2"}')), TABLE)


def test_a_projectile_named_as_a_body_is_refused() -> None:
    text = BLOCK.replace("PROJECTILE", "block").replace("  point: POINT\n", "")
    with pytest.raises(SpecErrors, match="'block' names a body already"):
        load_model(yaml.safe_load(text), TABLE)
