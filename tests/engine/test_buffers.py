"""A spring that only pushes (`attached: false`): a block sent along a floor onto a buffer's free end, or
launched by one. Its energy k (d - L0)^2/2 would pull as well, so a state before the block meets it, an
energy that pulls when squeezed, or a motion that leaves it at some of the domain's points and turns back
on it at others, is refused where written; the greatest compression from the contact derives as for any
spring, and a motion past where the body leaves it derives in two stages (leaving.py)."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import Model, derivation, load_model
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__

BUFFER = """
coordinates: [x]
bodies:
  block: {mass: m, position: {x: x}}
elements:
  buffer: {kind: spring, between: [{x: 0}, block], stiffness: k, length: L0, attached: false}
domain:
  ranges: {x: ["0", "oo"]}
  positive: ["D - L0", "L0^2*k - m*v^2"]
state: STATE
quantities:
  nearest: {turning_point: x}
"""
_SYMBOLS = {
    n: sympy.Symbol(n, positive=True) for n in ["m", "k", "L0", "v", "D", "c", "d", "g", "theta", "mu"]
}

# the buffer written low-level, with its energy's sign flipped: squeezed, it would pull
_PULLING = BUFFER.replace(
    "elements:\n  buffer: {kind: spring, between: [{x: 0}, block], stiffness: k, length: L0, attached: false}",
    'potentials:\n  - {bodies: [block], anchor: {x: 0}, distance: D0, energy: "-k*(D0 - L0)^2/2", reach: L0}',
)

REFUSED = [
    # (model, where the refusal is placed, what it says)
    (BUFFER.replace("STATE", "{x: D, x_dot: -v}"), ("elements", "buffer"), "the body is not touching it"),
    (_PULLING.replace("STATE", "{x: L0/2, x_dot: -v}"), ("potentials", 0), "check its sign"),
]


@pytest.mark.parametrize(("text", "path", "said"), REFUSED)
def test_a_spring_that_would_pull_is_refused_where_written(
    text: str, path: tuple[str | int, ...], said: str
) -> None:
    with pytest.raises(DerivationError) as refused:
        uncached(_model(text))
    assert refused.value.path == path
    assert said in refused.value.message and "only pushes" in refused.value.message


def test_a_block_leaving_a_buffer_on_a_smooth_floor_never_turns() -> None:
    with pytest.raises(DerivationError) as refused:
        uncached(_model(BUFFER.replace("STATE", "{x: L0, x_dot: v}")))
    assert refused.value.path == ("quantities", "nearest")
    assert "it does not turn" in refused.value.message


def test_the_greatest_compression_from_the_contact_derives() -> None:
    found = uncached(_model(BUFFER.replace("STATE", "{x: L0, x_dot: -v}"))).quantities["nearest"]
    m, k, length, v = (_SYMBOLS[n] for n in ["m", "k", "L0", "v"])
    assert sympy.simplify(found - (length - v * sympy.sqrt(m / k))) == 0


def test_an_attached_spring_still_pulls_a_block_released_beyond_its_length() -> None:
    attached = BUFFER.replace(", attached: false", "").replace("STATE", "{x: D}")
    found = uncached(_model(attached)).quantities["nearest"]
    assert sympy.simplify(found - (2 * _SYMBOLS["L0"] - _SYMBOLS["D"])) == 0


def test_a_spring_that_only_pushes_needs_its_natural_length() -> None:
    with pytest.raises(SpecErrors) as refused:
        _model(BUFFER.replace(" length: L0,", "").replace("STATE", "{x: 0, x_dot: -v}"))
    assert [e.path for e in refused.value.errors] == [("elements", "buffer", "attached")]


LAUNCHER = """
coordinates: [x]
bodies:
  block: {mass: m, position: {x: x}}
elements:
  launcher: {kind: spring, between: [{x: 0}, block], stiffness: k, length: L0, attached: false}
domain:
  ranges: {x: ["0", "oo"]}
  positive: ["L0 - c"]
state: {x: L0 - c}
quantities:
  launch: {speed: block, at: {x: AT}}
"""


def test_the_launch_speed_where_the_body_leaves_the_spring_derives() -> None:
    found = uncached(_model(LAUNCHER.replace("AT", "L0"))).quantities["launch"]
    assert sympy.simplify(found - _SYMBOLS["c"] * sympy.sqrt(_SYMBOLS["k"] / _SYMBOLS["m"])) == 0


# a block held against a spring compressed by d, then released: at the foot of a smooth incline (s up
# the slope from the spring's fixed end), or on a rough floor
UP_THE_SLOPE = """
elements:
  ramp: {kind: incline, body: block, mass: m, angle: theta, coordinate: s, direction: up}
  launcher: {kind: spring, between: [{x: 0, y: 0}, block], stiffness: k, length: L0, attached: false}
gravity: g
state: {s: L0 - d}
domain:
  ranges: {theta: ["0", "pi/2"], s: ["0", "oo"]}
  positive: ["L0 - d", LEAVES]
quantities:
  highest: {turning_point: s}
  distance: {expression: "highest - (L0 - d)"}
  later: {speed: block, at: {s: L0 + d}}
unused: [highest]
"""
ACROSS_THE_FLOOR = """
elements:
  floor: {kind: surface, body: block, mass: m, coordinate: x, friction: mu}
  launcher: {kind: spring, between: [{x: 0, y: 0}, block], stiffness: k, length: L0, attached: false}
gravity: g
state: {x: L0 - d}
domain:
  ranges: {x: ["0", "oo"]}
  positive: ["L0 - d", "k*d - 2*mu*m*g"]
quantities:
  stop: {turning_point: x}
  distance: {expression: "stop - (L0 - d)"}
unused: [stop]
"""
_LEAVES = '"k*d - 4*m*g*sin(theta)"'  # it leaves the spring, and gets a further d up the slope
LAUNCHED = [
    # (model, quantity, what it derives: past where the block leaves the spring)
    (UP_THE_SLOPE.replace("LEAVES", _LEAVES), "distance", "k*d^2/(2*m*g*sin(theta))"),
    (UP_THE_SLOPE.replace("LEAVES", _LEAVES), "later", "sqrt(d*(k*d - 4*m*g*sin(theta))/m)"),
    (ACROSS_THE_FLOOR, "distance", "k*d^2/(2*mu*m*g)"),
    (LAUNCHER.replace("AT", "2*L0"), "launch", "c*sqrt(k/m)"),  # the speed is kept past the spring
]


@pytest.mark.parametrize(("text", "name", "expected"), LAUNCHED)
@pytest.mark.sample(2)
def test_a_motion_past_where_the_body_leaves_the_spring_derives(text: str, name: str, expected: str) -> None:
    found = uncached(_model(text)).quantities[name]
    assert sympy.simplify(found - sympy.sympify(expected, locals=_SYMBOLS)) == 0


def test_a_launch_that_leaves_the_spring_only_on_part_of_the_domain_is_refused_at_the_quantity() -> None:
    """With k d > m g sin(theta) alone (it starts up the slope), not k d > 2 m g sin(theta), the block may
    stop on the spring: two motions, two answers."""
    text = UP_THE_SLOPE.replace("LEAVES", '"k*d - m*g*sin(theta)"').replace(
        "  later: {speed: block, at: {s: L0 + d}}\n", ""
    )
    with pytest.raises(DerivationError) as refused:
        uncached(_model(text))
    assert refused.value.path == ("quantities", "highest")
    assert "turns back on it at others" in refused.value.message


def _model(text: str) -> Model:
    return load_model(yaml.safe_load(text), _SYMBOLS)
