"""A period asked of a motion the state swings wide is refused unless the quantity says `amplitude:
small`: every method and the simulation take small oscillations, so a pendulum released from the
horizontal had its period verified as 2 pi sqrt(L/g), 18 % short. A damped oscillation's frequencies
and decay time are held to the same. A linear oscillator (with a dashpot or without) keeps its period
at any amplitude and is derived as before."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import Model, derivation, load_model
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__

PENDULUM = """
elements:
  string: {kind: pendulum, body: bob, mass: m, length: L, coordinate: phi}
gravity: g
state: STATE
quantities:
  T: QUANTITY
"""
HUNG_SPRING = """
coordinates: [y]
bodies:
  block: {mass: m, position: {y: y}}
elements:
  spring: {kind: spring, between: [block, {y: 0}], stiffness: k, length: L}
gravity: g
domain:
  ranges: {y: ["-oo", "0"]}
state: STATE
quantities:
  T: QUANTITY
"""
DAMPED_PENDULUM = """
elements:
  string: {kind: pendulum, body: bob, mass: m, length: L, coordinate: phi}
forces:
  - {body: bob, drag: b}
gravity: g
domain:
  ranges: {phi: ["-pi/2", "pi/2"]}
  positive: ["4*g*m^2 - b^2*L"]
state: STATE
quantities:
  T: QUANTITY
"""
DAMPED_SPRING = """
coordinates: [x]
bodies:
  block: {mass: m, position: {x: x}}
elements:
  spring: {kind: spring, between: [{x: 0}, block], stiffness: k}
forces:
  - {body: block, drag: b}
domain:
  positive: ["4*k*m - b^2"]
state: STATE
quantities:
  T: QUANTITY
"""
PERIOD, SMALL = "{period: phi}", "{period: phi, amplitude: small}"

SWUNG_WIDE = [
    # (model, state, the quantity, what the refusal says)
    (PENDULUM, "{phi: pi/3}", PERIOD, "released at phi = pi/3"),
    (PENDULUM, "{phi: 0, phi_dot: v/L}", PERIOD, "moving at phi' = v/L"),
    (PENDULUM, "{phi: pi/2}", "{angular_frequency: phi}", "the angular frequency of phi"),
    (DAMPED_PENDULUM, "{phi: pi/3}", "{damped_frequency: phi}", "the damped frequency of phi"),
    (DAMPED_PENDULUM, "{phi: pi/3}", "{decay_time: phi}", "the decay time of phi"),
    (DAMPED_PENDULUM, "{phi: 0, phi_dot: v/L}", "{undamped_frequency: phi}", "moving at phi' = v/L"),
]


@pytest.mark.parametrize(("model", "state", "quantity", "said"), SWUNG_WIDE)
def test_a_period_of_a_wide_swing_is_refused_at_the_quantity(
    model: str, state: str, quantity: str, said: str
) -> None:
    with pytest.raises(DerivationError) as refused:
        uncached(_model(model, state, quantity))
    assert refused.value.path == ("quantities", "T")
    assert said in refused.value.message and "amplitude: small" in refused.value.message


DERIVED = [
    # (model, state, the quantity, the period)
    (PENDULUM, "{phi: pi/3}", SMALL, "2*pi*sqrt(L/g)"),  # the problem says the oscillations are small
    (PENDULUM, "{phi: 0}", PERIOD, "2*pi*sqrt(L/g)"),  # at rest at the equilibrium: no swing given
    (HUNG_SPRING, "{y: -L}", "{period: y}", "2*pi*sqrt(m/k)"),  # released off its equilibrium: linear
    (HUNG_SPRING, "{y: -L, y_dot: v}", "{period: y}", "2*pi*sqrt(m/k)"),
    (DAMPED_PENDULUM, "{phi: pi/3}", "{decay_time: phi, amplitude: small}", "2*m/b"),
    (DAMPED_SPRING, "{x: L}", "{decay_time: x}", "2*m/b"),  # released off its equilibrium: linear
    (DAMPED_SPRING, "{x: L, x_dot: v}", "{damped_frequency: x}", "sqrt(k/m - b^2/(4*m^2))"),
]


@pytest.mark.parametrize(("model", "state", "quantity", "period"), DERIVED)
def test_a_small_or_isochronous_oscillation_is_derived(
    model: str, state: str, quantity: str, period: str
) -> None:
    found = uncached(_model(model, state, quantity)).quantities["T"]
    assert sympy.simplify(found - sympy.sympify(period, locals=_SYMBOLS)) == 0


def test_an_amplitude_other_than_small_is_refused_where_written() -> None:
    with pytest.raises(SpecErrors) as refused:
        _model(PENDULUM, "{phi: pi/3}", "{period: phi, amplitude: large}")
    assert [e.path for e in refused.value.errors] == [("quantities", "T", "amplitude")]


_SYMBOLS = {n: sympy.Symbol(n, positive=True) for n in ["m", "L", "g", "k", "v", "b"]}


def _model(text: str, state: str, quantity: str) -> Model:
    data = yaml.safe_load(text.replace("STATE", state).replace("QUANTITY", quantity))
    return load_model(data, _SYMBOLS)
