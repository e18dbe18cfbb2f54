"""Threshold conditions: the parameter value at which a force (or another measured quantity) reaches
zero, solved by the methods and checked by simulation: runs just below and just above the derived
value must see the quantity change sign, and where it crosses zero is compared with the derivation."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__
NAMES = ("m", "R", "g", "h", "theta_c")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, R, g, h, theta_c = (SYMBOLS[n] for n in NAMES)

LOOP = """
# a block slides without friction round a vertical loop of radius R (theta from the bottom), entering
# it with the speed a drop from height h gives
coordinates: [theta]
bodies:
  block: {mass: m, position: {x: "R*sin(theta)", y: "-R*cos(theta)"}}
gravity: g
constraints:
  track: {kind: surface, gap: "R - sqrt(x_block^2 + y_block^2)"}
state: {theta: 0, theta_dot: "sqrt(2*g*h)/R"}
domain:
  positive: ["h - 2*R"]
quantities:
  h_min: {solve: h, zero: {force: track, at: {theta: pi}}}
"""
DOME = """
# a block released at rest on top of a smooth hemisphere of radius R, with a vanishing push
coordinates: [theta]
bodies:
  block: {mass: m, position: {x: "R*sin(theta)", y: "R*cos(theta)"}}
gravity: g
constraints:
  dome: {kind: surface, gap: "sqrt(x_block^2 + y_block^2) - R"}
state: {theta: 0}
domain:
  ranges: {theta_c: ["0", "pi/2"]}
quantities:
  leaves: {solve: theta_c, zero: {force: dome, at: {theta: theta_c}}}
"""


def test_the_least_height_for_a_loop_the_loop_is_solved_and_simulated() -> None:
    result = uncached(load_model(yaml.safe_load(LOOP), SYMBOLS))
    assert sympy.simplify(result.quantities["h_min"] - 5 * R / 2) == 0
    check = result.simulation["h_min"]
    assert "changes sign" in check.compared and check.max_relative_error < 1e-3


def test_the_angle_where_a_block_leaves_a_dome_keeps_the_root_in_its_range() -> None:
    result = uncached(load_model(yaml.safe_load(DOME), SYMBOLS))
    assert result.quantities["leaves"] == sympy.acos(sympy.Rational(2, 3))
    assert "changes sign" in result.simulation["leaves"].compared


def test_a_wrong_threshold_is_caught_by_the_runs_either_side(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(derivation, "_simplest", lambda forms: 2 * R)  # where the block only just arrives
    with pytest.raises(derivation.DerivationError, match="runs either side of h"):
        uncached(load_model(yaml.safe_load(LOOP), SYMBOLS))


def test_the_escape_speed_is_where_the_mechanical_energy_vanishes() -> None:
    text = """
coordinates: [r, theta]
bodies:
  probe: {mass: m, position: {x: "r*cos(theta)", y: "r*sin(theta)"}}
potentials:
  - {bodies: [probe], anchor: {x: 0, y: 0}, distance: d, energy: "-G*M*m/d"}
state: {r: R, theta: 0, r_dot: v0}
domain:
  ranges: {r: ["0", "oo"]}
quantities:
  escape: {solve: v0, zero: {mechanical_energy: state}}
"""
    symbols = {n: sympy.Symbol(n, positive=True) for n in ("G", "M", "m", "R", "v0")}
    result = uncached(load_model(yaml.safe_load(text), symbols))
    G, M, radius = symbols["G"], symbols["M"], symbols["R"]
    assert sympy.simplify(result.quantities["escape"] - sympy.sqrt(2 * G * M / radius)) == 0
    assert "changes sign" in result.simulation["escape"].compared


OVER_THE_TOP = """
# a ball on a light rigid rod of length R, pivoted at its other end, launched at v0 from the bottom
coordinates: [theta]
bodies:
  ball: {mass: m, position: {x: "R*sin(theta)", y: "-R*cos(theta)"}}
gravity: g
constraints:
  rod: {kind: other, gap: "R - sqrt(x_ball^2 + y_ball^2)"}
state: {theta: 0, theta_dot: v0/R}
domain:
  positive: ["v0^2 - 4*g*R"]
quantities:
  least: {solve: v0, zero: {velocity: theta, at: {theta: pi}}}
"""
V0 = sympy.Symbol("v0", positive=True)


# (the value the derivation is forced to give, what the simulation must then say)
LEAST_LAUNCHES = [
    pytest.param(None, None, id="right"),
    pytest.param(2.1 * sympy.sqrt(g * R), "gets to theta = pi on both sides", id="too-fast"),
    pytest.param(1.9 * sympy.sqrt(g * R), "does not get to theta = pi on both sides", id="too-slow"),
]


@pytest.mark.parametrize(("forced", "refusal"), LEAST_LAUNCHES)
@pytest.mark.sample(2)
def test_the_least_launch_to_get_somewhere_is_bracketed_by_runs_that_turn_back_and_arrive(
    monkeypatch: pytest.MonkeyPatch, forced: sympy.Expr | None, refusal: str | None
) -> None:
    """A speed vanishing at `at` has no speed to measure below the threshold: the run just below must
    turn back, the run just above get there."""
    model = load_model(yaml.safe_load(OVER_THE_TOP), {**SYMBOLS, "v0": V0})
    if forced is None:
        result = uncached(model)
        assert sympy.simplify(result.quantities["least"] - 2 * sympy.sqrt(g * R)) == 0
        assert "turns back" in result.simulation["least"].compared
        return
    monkeypatch.setattr(derivation, "_simplest", lambda forms: forced)
    with pytest.raises(derivation.DerivationError, match=refusal):
        uncached(model)


LADDER_LEAVES = """
# a rod slides down a smooth wall on a smooth floor from rest at theta0 from the vertical; it leaves the
# wall where the wall's push vanishes
coordinates: [theta]
bodies:
  rod: {mass: m, inertia: "m*R^2/12", position: {x: "R*sin(theta)/2", y: "R*cos(theta)/2"}, angle: theta}
gravity: g
constraints:
  wall: {kind: surface, gap: "x_rod - R*sin(phi_rod)/2"}
  floor: {kind: surface, gap: "y_rod - R*cos(phi_rod)/2"}
state: {theta: theta0}
domain:
  ranges: {theta0: ["0", "pi/2"], theta_c: ["0", "pi/2"], theta: ["0", "pi/2"]}
  positive: [WHICH_WAY]
quantities:
  leaves: {solve: theta_c, zero: {force: wall, at: {theta: theta_c}}}
"""


def test_a_threshold_reached_from_a_symbolic_start_asks_which_way_the_coordinate_goes() -> None:
    """From rest at theta0, where theta_c lies against theta0 is the author's to declare: asked, the
    refusal says how; declared, the root is the textbook's."""
    symbols = {**SYMBOLS, "theta0": sympy.Symbol("theta0", positive=True)}
    undeclared = load_model(yaml.safe_load(LADDER_LEAVES.replace("WHICH_WAY", '"R"')), symbols)
    with pytest.raises(
        DerivationError, match=r"declare which way it goes \(domain.positive: \['-theta0 \+ theta_c'\]"
    ):
        uncached(undeclared)
    declared = load_model(yaml.safe_load(LADDER_LEAVES.replace("WHICH_WAY", '"theta_c - theta0"')), symbols)
    leaves = uncached(declared).quantities["leaves"]
    assert sympy.simplify(leaves - sympy.acos(2 * sympy.cos(symbols["theta0"]) / 3)) == 0
