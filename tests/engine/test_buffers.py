"""A spring that only pushes (`attached: false`): a block sent along a floor onto a buffer's free end.
Its energy k (d - L0)^2/2 would pull as well, so a state before the block meets it, or a motion that
carries the block off it again, is refused where written; the greatest compression from the contact
derives as for any spring."""

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
_SYMBOLS = {n: sympy.Symbol(n, positive=True) for n in ["m", "k", "L0", "v", "D", "c"]}

REFUSED = [
    # (state, where the refusal is placed, what it says)
    ("{x: D, x_dot: -v}", ("elements", "buffer"), "the body is not touching it"),  # not yet met
    ("{x: L0, x_dot: v}", ("quantities", "nearest"), "the body leaves the spring"),  # moving off it
]


@pytest.mark.parametrize(("state", "path", "said"), REFUSED)
def test_a_motion_the_spring_would_pull_is_refused_where_written(
    state: str, path: tuple[str, ...], said: str
) -> None:
    with pytest.raises(DerivationError) as refused:
        uncached(_model(BUFFER.replace("STATE", state)))
    assert refused.value.path == path
    assert said in refused.value.message and "only pushes" in refused.value.message


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


def test_a_speed_asked_beyond_where_the_body_leaves_the_spring_is_refused_at_the_quantity() -> None:
    with pytest.raises(DerivationError) as refused:
        uncached(_model(LAUNCHER.replace("AT", "2*L0")))
    assert refused.value.path == ("quantities", "launch")
    assert "has left the spring" in refused.value.message


def test_the_launch_speed_where_the_body_leaves_the_spring_derives() -> None:
    found = uncached(_model(LAUNCHER.replace("AT", "L0"))).quantities["launch"]
    assert sympy.simplify(found - _SYMBOLS["c"] * sympy.sqrt(_SYMBOLS["k"] / _SYMBOLS["m"])) == 0


def _model(text: str) -> Model:
    return load_model(yaml.safe_load(text), _SYMBOLS)
