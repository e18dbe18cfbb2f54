"""Sizes typed with a sign (a mass, a moment of inertia, a friction or drag coefficient, a spring's
stiffness) are refused where they were written, saying what they are; every method would read the same
wrong number and agree (a cylinder "rolling" down at 2 g sin(theta) with a negative inertia); a massless
body has no equation of motion of its own, and is refused there too. Kinetic
friction at a contact with another moving body must name it (`against`): it feels the reaction."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import Model, derivation, load_model
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__

ROLLING = """
elements:
  cylinder: {kind: rolling, mass: m, radius: R, inertia: INERTIA, angle: theta, coordinate: s}
gravity: g
domain:
  ranges: {theta: ["0", "pi/2"]}
quantities:
  a: {acceleration: s}
"""
ROUGH_SLOPE = """
elements:
  ramp: {kind: incline, body: block, mass: MASS, angle: theta, coordinate: s, friction: MU}
gravity: g
domain:
  ranges: {theta: ["0", "pi/2"]}
  positive: ["tan(theta) - mu"]
quantities:
  a: {acceleration: s}
"""
DRAGGED = """
coordinates: [x]
bodies:
  ball: {mass: m, position: {x: x}}
forces:
  - {body: ball, drag: DRAG}
state: {x_dot: v}
quantities:
  a: {acceleration: x}
"""
SPRUNG = """
coordinates: [y]
bodies:
  block: {mass: m, position: {y: y}}
elements:
  spring: {kind: spring, between: [block, {y: 0}], stiffness: STIFFNESS}
gravity: g
state: {y: 0}
quantities:
  a: {acceleration: y}
"""
STANDING_SPRING = """
coordinates: [y]
bodies:
  block: {mass: m, position: {y: y}}
elements:
  spring: {kind: spring, between: [block, {y: 0}], stiffness: k, length: LENGTH}
gravity: g
domain:
  ranges: {y: ["0", "oo"]}
  positive: ["k*L0 - m*g"]
quantities:
  rest: {equilibrium: y}
"""
SWING = """
elements:
  string: {kind: pendulum, body: bob, mass: m, length: LENGTH, coordinate: phi}
gravity: g
quantities:
  omega: {angular_frequency: phi}
"""
# springs in series, their junction a body of its own: massless, it had failed in the simulation
# ("ZeroDivisionError: matrix is numerically singular"); with a mass it is a two-body chain
IN_SERIES = """
coordinates: [x, j]
bodies:
  block: {mass: m, position: {x: x}}
  junction: {mass: MASS, position: {x: j}}
elements:
  inner: {kind: spring, between: [{x: 0}, junction], stiffness: k}
  outer: {kind: spring, between: [junction, block], stiffness: k}
quantities:
  slow: {normal_frequency: 1}
"""
NAMES = "m R theta g mu b v k L0"

# (model, its blanks filled, the refusal and its path, or None: the model derives)
CASES = [
    (
        ROLLING,
        {"INERTIA": '"-m*R^2/2"'},
        ("moment of inertia -R^2*m/2 is negative", ("elements", "cylinder", "inertia")),
    ),
    (ROLLING, {"INERTIA": '"m*R^2/2"'}, None),
    (
        ROUGH_SLOPE,
        {"MASS": "m", "MU": "-mu"},
        ("kinetic friction on block -mu is negative", ("elements", "ramp", "friction")),
    ),
    (ROUGH_SLOPE, {"MASS": "-m", "MU": "mu"}, ("block's mass -m is negative", ("elements", "ramp", "mass"))),
    (ROUGH_SLOPE, {"MASS": "m", "MU": "mu"}, None),
    (DRAGGED, {"DRAG": "-b"}, ("drag would push the body along its velocity", ("forces", 0))),
    (DRAGGED, {"DRAG": "b"}, None),
    (
        SPRUNG,
        {"STIFFNESS": "-k"},
        ("the stiffness of spring 'spring' -k is negative", ("elements", "spring", "stiffness")),
    ),
    (SPRUNG, {"STIFFNESS": "k"}, None),
    # lengths an element is built from: a spring of natural length -L0 had found no equilibrium ("found 0
    # among the roots []"), a pendulum of length -L0 had violated its own string
    (
        STANDING_SPRING,
        {"LENGTH": "-L0"},
        ("the natural length of spring 'spring' -L0 is negative", ("elements", "spring", "length")),
    ),
    (STANDING_SPRING, {"LENGTH": "L0"}, None),
    (
        SWING,
        {"LENGTH": "-L0"},
        ("the length of pendulum 'string' -L0 is negative", ("elements", "string", "length")),
    ),
    (SWING, {"LENGTH": "L0"}, None),
    (IN_SERIES, {"MASS": "0"}, ("junction's mass is 0", ("bodies", "junction", "mass"))),
    (IN_SERIES, {"MASS": "m"}, None),
]


def _model(text: str, blanks: dict[str, str]) -> Model:
    for blank, value in blanks.items():
        text = text.replace(blank, value)
    return load_model(yaml.safe_load(text), {n: sympy.Symbol(n, positive=True) for n in NAMES.split()})


@pytest.mark.parametrize(("text", "blanks", "refused"), CASES)
def test_a_size_typed_with_a_sign_is_refused_where_written(
    text: str, blanks: dict[str, str], refused: tuple[str, tuple[str | int, ...]] | None
) -> None:
    model = _model(text, blanks)
    if refused is None:
        uncached(model)
        return
    message, path = refused
    with pytest.raises(DerivationError) as caught:
        uncached(model)
    assert message in str(caught.value)
    assert caught.value.path == path


ROUGH_WEDGE = """
coordinates: [X, s]
bodies:
  wedge: {mass: M, position: {x: X, y: 0}}
  block: {mass: m, position: {x: "X + s*cos(theta)", y: "-s*sin(theta)"}}
gravity: g
constraints:
  floor: {kind: surface, gap: y_wedge}
  incline: {kind: surface, gap: "(x_block - x_wedge)*sin(theta) + (y_block - y_wedge)*cos(theta)"}
friction:
  - {constraint: incline, body: block, coefficient: mu, sliding: s}
domain:
  ranges: {theta: ["0", "pi/2"]}
  positive: ["tan(theta) - mu"]
quantities:
  slide: {acceleration: s}
"""


def test_friction_against_a_moving_body_must_name_it() -> None:
    """Without `against`, the wedge feels no friction: the pair's horizontal momentum would change with no
    horizontal force on it. Refused at the friction, naming the body to add."""
    symbols = {n: sympy.Symbol(n, positive=True) for n in ["m", "M", "g", "theta", "mu"]}
    with pytest.raises(DerivationError, match="Add `against: wedge` to the friction") as caught:
        uncached(load_model(yaml.safe_load(ROUGH_WEDGE), symbols))
    assert caught.value.path == ("friction", 0)


def test_an_inclines_angle_typed_in_degrees_is_refused_where_written() -> None:
    """`angle: 30` is 30 radians, an incline steeper than vertical that had verified a = g sin(30)."""
    with pytest.raises(SpecErrors) as caught:
        _model(
            "elements:\n  ramp: {kind: incline, body: block, mass: m, angle: 30, coordinate: s}\nquantities: {a: {acceleration: s}}\n",
            {},
        )
    [error] = caught.value.errors
    assert error.path == ("elements", "ramp", "angle")
    assert (
        error.message
        == "30 radians is 1719°, steeper than vertical: angles are in radians, so 30° is written 30*pi/180"
    )
    _model(
        "elements:\n  ramp: {kind: incline, body: block, mass: m, angle: 0.5, coordinate: s}\nquantities: {a: {acceleration: s}}\n",
        {},
    )
