"""An angle coordinate's value typed in degrees (a pendulum's `phi: 30`) is 30 radians, which every
method reads alike: refused where it was written, saying how 30° is written. Radians derive, and a
length a wheel rolls (its angle -x/R) is no angle."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import degrees, derivation, load_model
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__
NAMES = "m L g R theta"
m, L, g, R, theta = sympy.symbols(NAMES, positive=True)

CONE = """
elements:
  string: {kind: pendulum, body: bob, mass: m, length: L, coordinate: phi}
  frame: {kind: rotating, rate: Omega, bodies: [bob]}
gravity: g
state: {phi: ANGLE}
domain:
  ranges: {phi: ["0", "pi/2"]}
quantities:
  rate: {solve: Omega, zero: {acceleration: phi}}
"""
SWING = """
elements:
  string: {kind: pendulum, body: bob, mass: m, length: L, coordinate: phi}
gravity: g
state: {phi: 0, phi_dot: "2*sqrt(g/L)"}
quantities:
  v: {speed: bob, at: {phi: ANGLE}}
"""
ROLLED = """
elements:
  wheel: {kind: rolling, mass: m, radius: R, inertia: "m*R^2/2", angle: theta, coordinate: x}
gravity: g
state: {x: ANGLE}
domain:
  ranges: {theta: ["0", "pi/2"]}
quantities:
  a: {acceleration: x}
"""

# (model, the value typed, the refusal's path, or the quantity and its value: it derives)
CASES = [
    pytest.param(CONE, "30", ("state", "phi"), None, id="cone-in-degrees"),
    pytest.param(CONE, "pi/6", "rate", sympy.sqrt(2 * g / (sympy.sqrt(3) * L)), id="cone-in-radians"),
    pytest.param(SWING, "20", ("quantities", "v", "at", "phi"), None, id="swing-up-to-degrees"),
    pytest.param(SWING, "pi/3", "v", sympy.sqrt(3 * g * L), id="swing-up-to-radians"),
    pytest.param(ROLLED, "30", "a", 2 * g * sympy.sin(theta) / 3, id="a-length-rolled-is-no-angle"),
]


@pytest.mark.parametrize(("text", "angle", "where", "expected"), CASES)
def test_an_angle_coordinate_typed_in_degrees_is_refused_where_written(
    text: str, angle: str, where: tuple[str, ...] | str, expected: sympy.Expr | None
) -> None:
    symbols = {n: sympy.Symbol(n, positive=True) for n in [*NAMES.split(), "Omega"]}
    model = load_model(yaml.safe_load(text.replace("ANGLE", angle)), symbols)
    if expected is None:
        with pytest.raises(DerivationError) as caught:
            uncached(model)
        assert caught.value.path == where
        assert f"{angle}° is written {angle}*pi/180" in caught.value.message
        return
    assert isinstance(where, str)
    assert sympy.simplify(uncached(model).quantities[where] - expected) == 0


def test_an_angle_written_with_pi_past_a_full_turn_is_radians_already() -> None:
    # a bob that has gone round once and a half: 3*pi is no degrees slip
    symbols = {n: sympy.Symbol(n, positive=True) for n in NAMES.split()}
    text = SWING.replace('state: {phi: 0, phi_dot: "2*sqrt(g/L)"}', "state: {phi: 3*pi}").replace(
        "v: {speed: bob, at: {phi: ANGLE}}", "a: {acceleration: phi}"
    )
    degrees.check_angles_in_radians(load_model(yaml.safe_load(text), symbols))
