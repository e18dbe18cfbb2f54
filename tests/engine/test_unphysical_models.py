"""Models every method derives consistently, and the simulation agrees with, that are still wrong
physics: a string that would push, a surface that would pull, gravity pointing up, a length that comes
out negative. Each is refused at the model's path with the reason; the same model made right derives."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.dimensions import Dimension
from physics.engine import derivation, load_model
from physics.errors import DerivationError
from physics.units import unit_dimension

uncached = derivation._derive.__wrapped__

ATWOOD_THRUST = """
# m1 and m2 over a light pulley; a rocket pushes m2 up with F
coordinates: [s]
bodies:
  m1: {mass: m1, position: {y: s}}
  m2: {mass: m2, position: {y: "-s"}}
gravity: g
forces:
  - {body: m2, force: {y: F}}
elements:
  string: {kind: pulley, ends: [{body: m1, pulls: up}, {body: m2, pulls: up}]}
domain:
  positive: [DOMAIN]
quantities:
  acceleration: {acceleration: s}
"""
LIFTED_CRATE = """
coordinates: [x]
bodies:
  crate: {mass: m, position: {x: x, y: 0}}
gravity: g
constraints:
  floor: {kind: surface, gap: y_crate}
forces:
  - {body: crate, force: {x: "F*cos(alpha)", y: "F*sin(alpha)"}}
domain:
  ranges: {alpha: ["0", "pi/2"]}
quantities:
  acceleration: {acceleration: x}
"""
HANGING_SPRING = """
# a block hanging from a spring whose top is the origin; y is up
coordinates: [y]
bodies:
  block: {mass: m, position: {y: y}}
elements:
  spring: {kind: spring, between: [block, {y: 0}], stiffness: k}
gravity: g
quantities:
  rest: {equilibrium: y}
  stretch: {expression: STRETCH}
"""
DIMENSIONS = {
    "R": "m",
    "h": "m",
    "m": "kg",
    "m1": "kg",
    "m2": "kg",
    "g": "m/s^2",
    "F": "N",
    "k": "N/m",
    "L0": "m",
    "alpha": "1",
    "v": "m/s",
    "A": "m/s^2",
}


def _derive(text: str, names: str) -> dict[str, sympy.Expr]:
    symbols = {name: sympy.Symbol(name, positive=True) for name in names.split()}
    dimensions: dict[str, Dimension] = {n: unit_dimension(DIMENSIONS[n], ()) for n in symbols}
    return dict(uncached(load_model(yaml.safe_load(text), symbols, dimensions)).quantities)


def _refusal(text: str, names: str) -> DerivationError:
    with pytest.raises(DerivationError) as caught:
        _derive(text, names)
    return caught.value


@pytest.mark.parametrize(
    ("domain", "where"),
    [
        ('"F - 2*m2*g"', "wherever F > 2*g*m2, which is the whole domain"),
        ('"F"', "where F > 2*g*m2"),
    ],
)
def test_a_string_that_would_push_is_refused_where_it_goes_slack(domain: str, where: str) -> None:
    error = _refusal(ATWOOD_THRUST.replace("DOMAIN", domain), "m1 m2 g F")
    assert error.path == ("constraints", "string")
    assert f"the string would push {where}: it goes slack" in error.message
    assert "m1*(-F + 2*g*m2)/(m1 + m2)" in error.message  # the tension, as derived


def test_a_thrust_that_keeps_the_string_taut_derives() -> None:
    found = _derive(ATWOOD_THRUST.replace("DOMAIN", '"2*m2*g - F"'), "m1 m2 g F")
    m1, m2, g, f = sympy.symbols("m1 m2 g F", positive=True)
    assert sympy.simplify(found["acceleration"] - (m2 * g - m1 * g - f) / (m1 + m2)) == 0


def test_a_surface_that_would_pull_is_refused_where_the_body_lifts_off() -> None:
    error = _refusal(LIFTED_CRATE, "m g F alpha")
    assert error.path == ("constraints", "floor")
    assert "the surface would pull where" in error.message and "the body leaves it" in error.message


def test_gravity_against_the_models_down_is_refused() -> None:
    error = _refusal(ATWOOD_THRUST.replace("gravity: g", "gravity: -g").replace("DOMAIN", '"F"'), "m1 m2 g F")
    assert error.path == ("gravity",)
    assert "gravity -g is negative on the whole domain: the weight would point up" in error.message


def test_a_length_negative_on_the_whole_domain_is_refused() -> None:
    error = _refusal(HANGING_SPRING.replace("STRETCH", "rest"), "m k g")
    assert error.path == ("quantities", "stretch")
    assert "stretch = -g*m/k is a length, yet negative on the whole domain" in error.message
    m, k, g = sympy.symbols("m k g", positive=True)
    assert _derive(HANGING_SPRING.replace("STRETCH", "-rest"), "m k g")["stretch"] == m * g / k


def test_a_quantity_nowhere_real_is_refused() -> None:
    error = _refusal(HANGING_SPRING.replace("STRETCH", "sqrt(rest*k/(m*g))"), "m k g")
    assert error.path == ("quantities", "stretch") and "not real anywhere" in error.message


LOOP_TOP = """
coordinates: [theta]
bodies:
  block: {mass: m, position: {x: "R*sin(theta)", y: "-R*cos(theta)"}}
gravity: g
constraints:
  track: {kind: surface, gap: "R - sqrt(x_block^2 + y_block^2)"}
state: {theta: 0, theta_dot: "sqrt(2*g*h)/R"}
domain:
  positive: [DOMAIN]
quantities:
  top: {force: track, at: {theta: pi}}
"""


def test_a_surface_force_asked_where_the_body_has_already_left_is_refused() -> None:
    error = _refusal(LOOP_TOP.replace("DOMAIN", '"h - 2*R"'), "m R g h")
    assert error.path == ("quantities", "top")
    assert (
        "the surface would pull at theta = pi where h < 5*R/2: the body leaves it before it gets there"
        in error.message
    )
    m, r, g, h = sympy.symbols("m R g h", positive=True)
    found = _derive(LOOP_TOP.replace("DOMAIN", '"2*h - 5*R"'), "m R g h")["top"]
    assert sympy.simplify(found - m * g * (2 * h / r - 5)) == 0


SPRING_SIDE = """
# a block on a spring whose foot is at y = 0; the range says which side of it the block is
coordinates: [y]
bodies:
  block: {mass: m, position: {y: y}}
elements:
  spring: {kind: spring, between: [block, {y: 0}], stiffness: k, length: L0}
gravity: g
domain:
  ranges: {y: RANGE}
  positive: [POSITIVE]
quantities:
  rest: {equilibrium: y}
"""


_m, _k, _L0, _g = (sympy.Symbol(n, positive=True) for n in ("m", "k", "L0", "g"))
# (the block's declared side, the domain's condition, the rest position or None where it is refused)
SPRING_SIDES = [
    pytest.param('["0", "oo"]', '"k*L0 - m*g"', _L0 - _g * _m / _k, id="standing-spring"),
    pytest.param('["-oo", "0"]', '"k"', -_L0 - _g * _m / _k, id="hanging-from-a-ceiling"),
    pytest.param('["0", "oo"]', '"k"', None, id="ceiling-spring-declared-above"),
]


@pytest.mark.parametrize(("side", "positive", "rest"), SPRING_SIDES)
def test_a_rest_position_outside_the_coordinates_declared_range_is_refused(
    side: str, positive: str, rest: sympy.Expr | None
) -> None:
    text = SPRING_SIDE.replace("RANGE", side).replace("POSITIVE", positive)
    if rest is not None:
        found = _derive(text, "m k L0 g")
        assert sympy.simplify(found["rest"] - rest) == 0
        return
    error = _refusal(text, "m k L0 g")
    assert "the stable equilibrium y = L0 - g*m/k lies outside y's declared range [0, oo]" in error.message
    assert "the body rests on the other side there" in error.message


BUMPER = """
# cart 2 ahead of cart 1 by d, a spring bumper of natural length L0 between them
coordinates: [x1, d]
bodies:
  cart1: {mass: m1, position: {x: x1}}
  cart2: {mass: m2, position: {x: "x1 + d"}}
elements:
  bumper: {kind: spring, between: [cart1, cart2], stiffness: k, length: L0}
state: {x1: 0, d: STATE}
domain:
  ranges: {d: RANGE}
quantities:
  closing: {acceleration: d}
"""
_m1, _m2 = (sympy.Symbol(n, positive=True) for n in ("m1", "m2"))
# (the state's separation, the declared side, the acceleration or None where it is refused)
BUMPER_STATES = [
    pytest.param("L0/2", '["0", "oo"]', _k * _L0 * (_m1 + _m2) / (2 * _m1 * _m2), id="squeezed"),
    pytest.param("0", '["0", "oo"]', _k * _L0 * (_m1 + _m2) / (_m1 * _m2), id="at-the-end-of-its-range"),
    # d declared negative, so the spring's length is -d: at d = L0/2 it would be squeezed by 3 L0/2
    pytest.param("L0/2", '["-oo", "0"]', None, id="state-on-the-side-the-range-excludes"),
]


@pytest.mark.parametrize(("state", "side", "acceleration"), BUMPER_STATES)
def test_a_state_outside_the_coordinates_declared_range_is_refused(
    state: str, side: str, acceleration: sympy.Expr | None
) -> None:
    text = BUMPER.replace("STATE", state).replace("RANGE", side)
    if acceleration is not None:
        assert sympy.simplify(_derive(text, "m1 m2 k L0")["closing"] - acceleration) == 0
        return
    error = _refusal(text, "m1 m2 k L0")
    assert "the state puts d at L0/2, outside its declared range [-oo, 0]" in error.message
    assert error.path == ("state", "d")


CREST = """
# a car cresting a circular hill of radius R at speed v, faster than the hill can hold it
coordinates: [theta]
bodies:
  car: {mass: m, position: {x: "R*sin(theta)", y: "R*cos(theta)"}}
gravity: g
constraints:
  hill: {kind: surface, gap: "sqrt(x_car^2 + y_car^2) - R"}
state: {theta: 0, theta_dot: v/R}
domain:
  positive: ["v^2 - g*R"]
quantities:
  normal: {force: hill}
"""


def test_a_surface_pulling_on_the_whole_domain_says_so_without_a_constant_for_a_condition() -> None:
    error = _refusal(CREST, "m g R v")
    assert "the surface would pull on the whole domain" in error.message
    assert "-1 < 0" not in error.message


HANGING_WEIGHT = """
# a block hanging from a spring whose top is the origin; y is up; its weight given as a force
coordinates: [y]
bodies:
  block: {mass: m, position: {y: y}}
elements:
  spring: {kind: spring, between: [block, {y: 0}], stiffness: k, length: L0}
forces:
  - {body: block, force: {y: WEIGHT}}
GRAVITY
domain:
  ranges: {y: ["-oo", "0"]}
  positive: ["k*L0 - m*g"]
quantities:
  rest: {equilibrium: y}
"""


_m, _k, _g, _L0 = sympy.symbols("m k g L0", positive=True)


@pytest.mark.parametrize(
    ("weight", "gravity", "rest"),
    [
        ('"m*g"', "", None),  # the weight typed up, no gravity: refused
        ('"-m*g"', "", -_L0 - _m * _g / _k),  # typed down: it is the weight
        ('"m*g"', "gravity: g", -_L0),  # up beside gravity: a lift that balances the weight, as given
    ],
)
def test_a_force_of_mass_times_g_pointing_up_without_gravity_is_refused_as_a_weight_typed_up(
    weight: str, gravity: str, rest: sympy.Expr | None
) -> None:
    text = HANGING_WEIGHT.replace("WEIGHT", weight).replace("GRAVITY", gravity)
    if rest is None:
        error = _refusal(text, "m k g L0")
        assert error.path == ("forces", 0)
        assert "the force g*m on block points up (+y) and the model has no gravity" in error.message
        assert "Write `gravity: g`" in error.message
        return
    assert sympy.simplify(_derive(text, "m k g L0")["rest"] - rest) == 0


def test_a_push_of_mass_times_another_acceleration_without_gravity_is_no_weight_typed_up() -> None:
    # a rocket's thrust m*A in space (no gravity) points up as written: it is no weight
    text = HANGING_WEIGHT.replace("WEIGHT", '"m*A"').replace("GRAVITY", "").replace("m*g", "m*A")
    _A = sympy.Symbol("A", positive=True)
    assert sympy.simplify(_derive(text, "m k A L0")["rest"] - (-_L0 + _m * _A / _k)) == 0


BEAD_ON_A_ROD = """
# a bead free on a horizontal rod: nothing pulls it anywhere along x
coordinates: [x]
bodies:
  bead: {mass: m, position: {x: x}}
gravity: g
quantities:
  QUANTITY
"""
TWO_BEADS_ON_A_SPRING = """
# two beads on a horizontal rod joined by a spring: at rest wherever it has its natural length
coordinates: [x1, x2]
bodies:
  a: {mass: m1, position: {x: x1}}
  b: {mass: m2, position: {x: x2}}
elements:
  spring: {kind: spring, between: [a, b], stiffness: k, length: L0}
domain:
  ranges: {x1: ["-oo", "0"], x2: ["0", "oo"]}
quantities:
  QUANTITY
"""


@pytest.mark.parametrize(
    ("model", "names", "quantity", "where"),
    [
        pytest.param(BEAD_ON_A_ROD, "m g", "rest: {equilibrium: x}", "at every x", id="bead-equilibrium"),
        pytest.param(BEAD_ON_A_ROD, "m g", "w: {angular_frequency: x}", "at every x", id="bead-frequency"),
        pytest.param(
            TWO_BEADS_ON_A_SPRING,
            "m1 m2 k L0",
            "rest: {equilibrium: x1}",
            "wherever x1 = -L0 + x2",
            id="beads",
        ),
    ],
)
def test_a_continuum_of_equilibria_is_refused_as_one(
    model: str, names: str, quantity: str, where: str
) -> None:
    """Every point of the coordinate is a rest: there is no one equilibrium to give or oscillate about,
    which the refusal says, not 'found 0'."""
    error = _refusal(model.replace("QUANTITY", quantity), names)
    assert f"the bodies rest {where}" in error.message
    assert "a continuum of equilibria, with no one point to oscillate about" in error.message
