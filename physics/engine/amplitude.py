"""A period or angular frequency asked of a motion the state sets swinging wide.

`period` and `angular_frequency` are those of small oscillations about the stable equilibrium, and so
are a damped oscillation's `damped_frequency`, `decay_time` and `undamped_frequency`: every
method linearizes there, and the simulation releases the body 1e-4 beside it. A pendulum released from
60° swings with a longer period than 2 pi sqrt(L/g) (by 7 %; from the horizontal by 18 %), so a model
whose state puts the coordinate away from equilibrium, or moving through it, asks for a period the
engine does not derive, unless the motion is isochronous (a quadratic potential and a constant
inertia, with linear drag a constant coefficient of the rate: a mass on a spring keeps its period at any
amplitude, and with a dashpot its ringing frequency and decay time). Such a quantity is refused unless it
says `amplitude: small`, the problem's own words that the oscillations are small.
"""

from __future__ import annotations

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.lagrange import LagrangeMethod
from physics.engine.model import Quantity, QuantityKind
from physics.errors import DerivationError

KINDS = frozenset(
    {
        QuantityKind.PERIOD,
        QuantityKind.ANGULAR_FREQUENCY,
        QuantityKind.DAMPED_FREQUENCY,
        QuantityKind.DECAY_TIME,
        QuantityKind.UNDAMPED_FREQUENCY,
    }
)


def check_amplitudes(lagrange: LagrangeMethod) -> None:
    """DerivationError at the first small-oscillation quantity whose state swings the motion wide."""
    for outer in lagrange.model.quantities:
        for quantity in (outer, outer.inner):  # a period made least (`minimize: h, of: {period: phi}`)
            if quantity is not None and quantity.kind in KINDS and not quantity.small:
                _check(lagrange, quantity, outer.name)


def _check(lagrange: LagrangeMethod, quantity: Quantity, name: str) -> None:
    """Lagrange's equation for the coordinate, the others held where the state puts them: linear in it
    and its acceleration with constant coefficients and free of its velocity keeps its period at any
    amplitude; otherwise the state must hold it at rest where that equation leaves it (equilibrium)."""
    model = lagrange.model
    index = [c.name for c in model.coordinates].index(quantity.target)
    coordinate = model.coordinates[index]
    q, rate, acceleration = coordinate.symbol, coordinate.velocity, coordinate.acceleration
    state = dict(model.state)
    held = {s: v for s, v in state.items() if s not in (q, rate)}
    held |= {c.acceleration: 0 for c in model.coordinates if c is not coordinate}
    held |= {c.velocity: 0 for c in model.coordinates if c.velocity not in held}
    equation = sympy.expand(lagrange.system[0][index].subs(held))
    if _isochronous(equation, q, rate, acceleration):
        return
    moving = tidy.simplify(state.get(rate, sympy.Integer(0)))
    place = state.get(q)
    at_rest = equation.subs({rate: 0, acceleration: 0})
    pushed = sympy.Integer(0) if place is None else tidy.simplify(at_rest.subs(q, place))
    if moving == 0 and pushed == 0:
        return
    where = (
        f"moving at {coordinate.name}' = {typed_text(moving)}"
        if moving != 0
        else f"released at {coordinate.name} = {typed_text(place)}, away from its equilibrium"
    )
    raise DerivationError(
        f"the {quantity.kind.value.replace('_', ' ')} of {coordinate.name} is derived for small "
        f"oscillations, but the state has it {where}: its swing is not small, and at a large amplitude "
        "the period is longer (a pendulum released from the horizontal by 18 %). If the problem says the "
        f"oscillations are small, write `amplitude: small` beside `{quantity.kind.value}:`; the engine "
        "does not derive the period of a wide swing",
        path=("quantities", name),
    )


def _isochronous(
    equation: sympy.Expr, q: sympy.Symbol, rate: sympy.Symbol, acceleration: sympy.Symbol
) -> bool:
    """a q'' + b q' + k q + c = 0 with a, b and k constant: the period keeps at any amplitude (a mass on a
    spring, with a dashpot or without)."""
    return all(
        tidy.simplify(d) == 0
        for d in (
            sympy.diff(equation, q, 2),
            sympy.diff(equation, acceleration, q),
            sympy.diff(equation, acceleration, 2),
            sympy.diff(equation, rate, q),
            sympy.diff(equation, rate, acceleration),
            sympy.diff(equation, rate, 2),
        )
    )
