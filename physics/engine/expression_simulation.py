"""An `expression` of other quantities, simulated: its formula evaluated on those quantities' measured
values (each measured as the simulation measures it on its own, at the same point), so that the work of
friction `-mu*m*g*distance` is checked through the integrated stopping distance, and a rebound height
`v1^2/(2*g)` through the integrated impact. An expression of a quantity the simulation cannot measure is
not simulated.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import sympy

from physics.answer_text import typed_text
from physics.engine import evaluated_at
from physics.engine.model import Quantity, QuantityKind

if TYPE_CHECKING:
    from physics.engine.simulation import Measure, Measured, Point, Simulator


def measure_of(simulator: Simulator, quantity: Quantity) -> Measure | None:
    """How the simulation measures a quantity an expression uses (None: it does not)."""
    if quantity.bounces is not None:
        return None
    if quantity.kind is QuantityKind.EXPRESSION:  # its inputs, measured (an extremum's `of:` has no name)
        if not all(measure_of(simulator, simulator.model.quantity(name)) for _, name in quantity.uses):
            return None
        return lambda q, point, expected: measure(simulator, q, point, expected)
    if quantity.name not in simulator.references:
        return None
    if quantity.after:
        return simulator.after_impact
    return simulator.measure_for(quantity)


def measure(simulator: Simulator, quantity: Quantity, point: Point, expected: float) -> Measured:
    """The formula on the measured values of the quantities it uses. An input whose measure checks it
    another way (a threshold: the inner quantity vanishing at the derived value) has no measured value:
    the formula takes its derived value there, and the expression's error is at least that input's."""
    assert quantity.expression is not None
    values: dict[object, float] = {}
    errors: list[float] = []
    for symbol, name in quantity.uses:
        used = simulator.model.quantity(name)
        measured, (at,) = evaluated_at.simulated(used, [point], simulator.references)
        how = measure_of(simulator, used)
        assert how is not None  # measure_for offers this measure only when every input has one
        reference = float(simulator.references[name].subs(at))
        _, value, own = how(measured, at, reference)
        values[symbol] = reference if own is not None else value
        errors += [own] if own is not None else []
    value = float(quantity.expression.subs(values).subs(point))
    errors.append(abs(value - expected) / max(abs(expected), 1e-12))
    names = ", ".join(name for _, name in quantity.uses)
    formula = quantity.expression.subs({symbol: sympy.Symbol(name) for symbol, name in quantity.uses})
    return f"{typed_text(formula)} of the measured {names}", value, max(errors)
