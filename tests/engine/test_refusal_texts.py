"""A refused model's message quotes the engine's expressions as an instructor types them (`b^2`,
`k*(-L0 + springLength)^2/2`), never in sympy's own syntax (`b**2`)."""

from __future__ import annotations

from typing import Any

import pytest
import sympy
import yaml

from physics.engine import derive, load_model
from physics.errors import DerivationError, SpecError

HANGING_SPRING = """
coordinates: [y]
bodies:
  block: {mass: m, position: {y: y}}
elements:
  spring: {kind: spring, between: [block, {y: 0}], stiffness: k, length: L0}
gravity: g
quantities:
  height: {equilibrium: y}
"""
MAYBE_OVERDAMPED = """
coordinates: [x]
bodies:
  block: {mass: m, position: {x: x}}
elements:
  spring: {kind: spring, between: [{x: 0}, block], stiffness: k}
forces:
  - {body: block, drag: b}
quantities:
  omega_d: {damped_frequency: x}
"""
WRONG_FRAME_RATE = """
coordinates: [r]
bodies:
  bead: {mass: m, position: {x: r, y: 0}}
gravity: g
constraints:
  rod: {kind: surface, gap: y_bead}
potentials:
  - {bodies: [bead], anchor: {x: 0}, distance: d, energy: "k*(d - L0)^2/2"}
  - {bodies: [bead], anchor: {x: 0}, distance: e, energy: "-m*omega^2*e^2/2"}
frame: {rate: 2*omega, bodies: [bead]}
state: {r: L0}
domain:
  ranges: {r: ["0", "oo"]}
  positive: ["k - m*omega^2"]
quantities:
  rest: {equilibrium: r}
  start: {acceleration: r}
"""

# (symbols, model, what the message must quote)
REFUSALS = [
    pytest.param("m k L0 g", HANGING_SPRING, ["the energy k*(-L0 + springLength)^2/2"], id="spring-side"),
    pytest.param("m k b", MAYBE_OVERDAMPED, ["omega_d^2 = (-b^2/4 + k*m)/m^2"], id="overdamped"),
    pytest.param(
        "m k L0 omega g",
        WRONG_FRAME_RATE,
        ["frames gives 5*L0*omega^2", "lagrange gives L0*k/(k - m*omega^2)"],
        id="frame-rate",
    ),
]


def _refusal(symbols: str, model: str) -> str:
    names = {n: sympy.Symbol(n, positive=True) for n in symbols.split()}
    data: Any = yaml.safe_load(model)
    with pytest.raises((SpecError, DerivationError)) as caught:
        derive(load_model(data, names))
    error = caught.value
    if isinstance(error, DerivationError) and error.findings:
        return "\n".join(message for _, message in error.findings)
    return str(error)


@pytest.mark.parametrize(("symbols", "model", "quoted"), REFUSALS)
def test_refusal_quotes_expressions_as_an_instructor_types_them(
    symbols: str, model: str, quoted: list[str]
) -> None:
    message = _refusal(symbols, model)
    for text in quoted:
        assert text in message, message
    assert "**" not in message, message


UPSIDE_DOWN_SPRING = """
coordinates: [x]
bodies:
  block: {mass: m, position: {x: x}}
potentials:
  - {bodies: [block], anchor: {x: 0}, distance: d, energy: "-k*d^2/2"}
quantities:
  rest: {equilibrium: x}
"""


def test_a_cause_every_method_stops_for_is_said_once_naming_them_all() -> None:
    message = _refusal("m k", UPSIDE_DOWN_SPRING)
    assert (
        "lagrange, newton, conservation and dalembert stopped: expected one stable equilibrium of x"
        in message
    )
    assert message.count("expected one stable equilibrium") == 1, message
    assert "Lagrange's equations" not in message, message
    assert "frames does not apply" not in message, message  # no frame to try: beside a cause, noise
