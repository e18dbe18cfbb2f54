"""A surface's or a string's gap is a clearance, whose multiplier is the normal force or the tension.
Written as a square or a multiple, the gap vanishes on the same surface: every method, the simulation
and the sign checks agree, and the force is the real one divided by how fast the gap grows (a car's
normal force over a hump verified as m (g R - v^2)/(2 R^2)). Refused at the constraint, saying the
rate; a string that a movable pulley's body takes up twice (two strands) derives."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__

HUMP = """
# a car over the top of a hump of radius R at speed v
coordinates: [theta]
bodies:
  car: {mass: m, position: {x: "R*sin(theta)", y: "R*cos(theta)"}}
gravity: g
constraints:
  road: {kind: surface, gap: GAP}
state: {theta: 0, theta_dot: v/R}
domain:
  positive: ["g*R - v^2"]
quantities:
  normal: {force: road}
"""
PENDULUM = """
coordinates: [phi]
bodies:
  bob: {mass: m, position: {x: "R*sin(phi)", y: "-R*cos(phi)"}}
gravity: g
constraints:
  string: {kind: string, gap: GAP}
state: {phi: 0, phi_dot: v/R}
quantities:
  tension: {force: string}
"""
m, R, g, v = sympy.symbols("m R g v", positive=True)

# (model, the gap as written, the force, or the rate the refusal names)
CLEARANCES = [
    pytest.param(HUMP, "sqrt(x_car^2 + y_car^2) - R", m * g - m * v**2 / R, None, id="hump"),
    pytest.param(HUMP, "x_car^2 + y_car^2 - R^2", None, "grows 2*R times", id="hump-squared"),
    pytest.param(HUMP, "2*(sqrt(x_car^2 + y_car^2) - R)", None, "grows 2 times", id="hump-doubled"),
    pytest.param(PENDULUM, "R - sqrt(x_bob^2 + y_bob^2)", m * g + m * v**2 / R, None, id="string"),
    pytest.param(PENDULUM, "R^2 - x_bob^2 - y_bob^2", None, "grows 2*R times", id="string-squared"),
]


@pytest.mark.parametrize(("text", "gap", "force", "refused"), CLEARANCES)
def test_a_gap_that_is_no_clearance_is_refused_at_its_constraint(
    text: str, gap: str, force: sympy.Expr | None, refused: str | None
) -> None:
    model = load_model(yaml.safe_load(text.replace("GAP", f'"{gap}"')), {"m": m, "R": R, "g": g, "v": v})
    if refused is None:
        found = uncached(model).quantities
        assert sympy.simplify(next(iter(found.values())) - force) == 0
        return
    with pytest.raises(DerivationError) as caught:
        uncached(model)
    assert caught.value.path[0] == "constraints"
    assert refused in caught.value.message and "Write the distance itself" in caught.value.message


def test_a_string_twice_round_a_movable_pulleys_body_derives() -> None:
    """The string under a movable pulley takes up twice the pulley's drop: a rate of 2 is two strands."""
    text = """
coordinates: [s]
bodies:
  m1: {mass: m1, position: {x: s}}
  m2: {mass: m2, position: {y: "-s/2"}}
gravity: g
constraints:
  string: {kind: string, gap: "x_m1 + 2*y_m2"}
quantities:
  tension: {force: string}
"""
    m1, m2 = sympy.symbols("m1 m2", positive=True)
    found = uncached(load_model(yaml.safe_load(text), {"m1": m1, "m2": m2, "g": g})).quantities["tension"]
    assert sympy.simplify(found - 2 * m1 * m2 * g / (4 * m1 + m2)) == 0
