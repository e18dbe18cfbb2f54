"""A string must stay taut and a surface keep pushing all along the motion to where a quantity is taken
(`at`, a turning point), not only at the state and at the end: a ball whirled too slowly to keep its
string taut over the top still has a speed there by energy, but never gets there on its circle. Each
wrong model is refused at the quantity naming the contact; the same motion kept in contact derives."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.errors import DerivationError
from physics.mathinput import parse_math

uncached = derivation._derive.__wrapped__

WHIRLED = """
elements:
  string: {kind: pendulum, body: ball, mass: m, length: L, coordinate: phi}
gravity: g
state: {phi: 0, phi_dot: v0/L}
domain:
  positive: [BLANK]
quantities:
  top: {speed: ball, at: {phi: pi}}
"""
LOOP = """
coordinates: [theta]
bodies:
  block: {mass: m, position: {x: "R*sin(theta)", y: "-R*cos(theta)"}}
gravity: g
constraints:
  track: {kind: surface, gap: "R - sqrt(x_block^2 + y_block^2)"}
state: {theta: 0, theta_dot: "sqrt(2*g*h)/R"}
domain:
  positive: [BLANK]
quantities:
  v: {speed: block, at: {theta: "3*pi/2"}}
"""
TRACK_TURN = """
coordinates: [theta]
bodies:
  block: {mass: m, position: {x: "R*sin(theta)", y: "-R*cos(theta)"}}
gravity: g
constraints:
  track: {kind: surface, gap: "R - sqrt(x_block^2 + y_block^2)"}
state: {theta: 0, theta_dot: "v0/R"}
domain:
  ranges: {theta: ["0", "pi"]}
  positive: [BLANK]
quantities:
  highest: {turning_point: theta}
"""
LADDER = """
coordinates: [theta]
bodies:
  rod: {mass: m, inertia: "m*L^2/12", position: {x: "L*sin(theta)/2", y: "L*cos(theta)/2"}, angle: theta}
gravity: g
constraints:
  wall: {kind: surface, gap: "x_rod - L*sin(phi_rod)/2"}
  floor: {kind: surface, gap: "y_rod - L*cos(phi_rod)/2"}
state: {theta: theta0}
domain:
  ranges: {theta0: ["0", "pi/3"], theta: ["0", "pi/2"]}
quantities:
  spin: {velocity: theta, at: {theta: BLANK}}
"""

# (model, its blank filled, symbols, refusal or None, the quantity and what it derives when right)
CASES = [
    # 4 g L < v0^2 < 5 g L: v^2 = v0^2 - 4 g L > 0 at the top by energy, the string slack before it
    (
        WHIRLED,
        '"v0^2 - 4*g*L", "5*g*L - v0^2"',
        "m L g v0",
        "constraint 'string': the string would push on the way",
        None,
    ),
    (WHIRLED, '"v0^2 - 5*g*L"', "m L g v0", None, ("top", "sqrt(v0^2 - 4*g*L)")),
    # dropped from h < 5 R / 2, asked three quarters round: it fell off the track at the top
    (
        LOOP,
        '"h - 2*R", "5*R - 2*h"',
        "m R g h",
        "constraint 'track': the surface would pull on the way",
        None,
    ),
    (LOOP, '"2*h - 5*R"', "m R g h", None, ("v", "sqrt(2*g*(h - R))")),
    # up the inside of a track past the quarter: where it would stop, it has already fallen off
    (
        TRACK_TURN,
        '"v0^2 - 2*g*R", "4*g*R - v0^2"',
        "m R g v0",
        "the body leaves it before the motion gets there",
        None,
    ),
    (TRACK_TURN, '"2*g*R - v0^2"', "m R g v0", None, ("highest", "acos(1 - v0^2/(2*g*R))")),
    # a rod sliding down a wall leaves it where cos(theta) = 2 cos(theta0)/3: asked beyond, the wall pulls
    (LADDER, '"acos(cos(theta0)/2)"', "m L g theta0", "constraint 'wall': the surface would pull", None),
    (LADDER, '"acos(5*cos(theta0)/6)"', "m L g theta0", None, ("spin", "sqrt(g*cos(theta0)/(2*L))")),
]


@pytest.mark.parametrize(("text", "blank", "names", "refused", "gives"), CASES)
@pytest.mark.sample(3)
def test_contacts_hold_along_the_way(
    text: str, blank: str, names: str, refused: str | None, gives: tuple[str, str] | None
) -> None:
    symbols = {n: sympy.Symbol(n, positive=True) for n in names.split()}
    model = load_model(yaml.safe_load(text.replace("BLANK", blank)), symbols)
    if refused is not None:
        with pytest.raises(DerivationError, match=refused.replace("(", r"\(").replace(")", r"\)")) as caught:
            uncached(model)
        assert caught.value.path[:1] == ("quantities",)
        return
    assert gives is not None
    name, expected = gives
    derived = uncached(model)
    reference = parse_math(expected, symbols).expr
    assert sympy.simplify(derived.quantities[name] - reference) == 0
    assert "contacts along the way" in derived.checks
