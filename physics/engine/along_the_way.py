"""Unilateral contacts along the way: a string must stay taut, a surface keep pushing, all the way from
the model's state to where a quantity is taken.

The state's check (contacts.py) and an asked force's check at its `at` look at two places. A speed at
the top of a vertical circle, or how far up a circular track a block gets, is taken at the end of a
motion whose contacts may have let go in between: a ball whirled on a string with 4 g L < v0^2 < 5 g L
still has v^2 = v0^2 - 4 g L > 0 at the top by energy, but its string went slack before it got there,
so the answer describes a motion that does not happen. Here each string's and surface's force is found
along the path, as a function of where the coordinate has got to (Lagrange's constraint force with the
state left free, at the velocity its own integrated equation of motion gives there), and sampled from
the start to the end at sampled domain points; a wrong sign anywhere refuses the quantity, saying where.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy, work_energy
from physics.engine.contacts import UNILATERAL
from physics.engine.leaving import leaving, staged
from physics.engine.method import Method, NotApplicable
from physics.engine.model import (
    REACH_KINDS,
    Action,
    Constraint,
    Model,
    Quantity,
    QuantityKind,
)
from physics.engine.proof import domain_points
from physics.engine.signs import point_text
from physics.errors import DerivationError, PhyscheckError

POINTS = 8
SEED = 31
STEPS = 24  # places along the way, the end included
# of the force's largest size along the way (at least 1, the sampled parameters' order: a force that is
# zero all along, a threshold's contact letting go at its end, may round to a tiny negative value)
_TOLERANCE = 1e-9

_AT_KINDS = REACH_KINDS | {QuantityKind.FORCE, QuantityKind.ACCELERATION}


def check_along_the_way(model: Model, method: Method, quantities: Mapping[str, sympy.Expr]) -> dict[str, str]:
    """Every string and surface holds all along each motion a quantity is taken at the end of (`at`, a
    turning point): a check's name -> what was shown; DerivationError at the quantity where it does not."""
    unilateral = [c for c in model.acting(Action.UNILATERAL) if isinstance(c, Constraint)]
    shown: list[str] = []
    for quantity in model.quantities:
        journey = trip(method, quantity, quantities)
        if journey is None or not unilateral:
            continue
        for constraint in unilateral:
            if _holds_along(model, method, quantity, journey, constraint):
                shown.append(f"{constraint.name} ({quantity.name})")
    if not shown:
        return {}
    return {"contacts along the way": f"{', '.join(shown)}: held from the state to where each is taken"}


def trip(
    method: Method, quantity: Quantity, quantities: Mapping[str, sympy.Expr]
) -> work_energy.Journey | None:
    """The motion from the state to where the quantity is taken, or None for a quantity taken elsewhere
    (after an impact its motion starts from other velocities; `with` puts a symbol at another's value)."""
    if quantity.after or quantity.uses:
        return None
    if quantity.kind in _AT_KINDS and quantity.at:
        reached = quantity
    elif quantity.kind is QuantityKind.TURNING_POINT:
        reached = dataclasses.replace(quantity, at=((quantity.target, quantities[quantity.name]),))
    else:
        return None
    try:
        return work_energy.journey(method, reached)
    except (NotApplicable, DerivationError):  # the quantity's own derivation said why already
        return None


def _holds_along(
    model: Model, method: Method, quantity: Quantity, trip: work_energy.Journey, constraint: Constraint
) -> bool:
    """True when the force keeps its sign along the way; False when it could not be found there."""
    c = trip.coordinate
    # the other coordinates stay where the state puts them (cyclic ones: nothing depends on them)
    state = {**{v: sympy.Integer(0) for v in method.mech.qd}, **dict(model.state)}

    def settled(force: sympy.Expr, square: sympy.Expr) -> sympy.Expr:
        velocity = trip.sign * sympy.sqrt(square)
        there = {c.velocity: velocity, **{v: e.subs(c.velocity, velocity) for v, e in trip.held.items()}}
        return force.subs(there).subs({s: v for s, v in state.items() if s != c.symbol and s not in there})

    try:
        along = dataclasses.replace(
            trip, end=c.symbol
        )  # the rate's square wherever the coordinate has got to
        square = work_energy.by_integration(method, along)
        force = settled(method.free.force(constraint.name), square)
        # past where the body leaves a spring that only pushes, the motion without it (leaving.py)
        later, since, freed = (
            staged(method, along) if leaving(method, along) else (square, trip.start, method)
        )
        if freed is not method:
            force = sympy.Piecewise(
                (force, trip.sign * (c.symbol - since) <= 0),
                (settled(freed.free.force(constraint.name), later), True),
            )
    except PhyscheckError:
        return False
    except Exception:  # sympy's failures on an uploaded model: the quantity itself was derived already
        return False
    worst: tuple[float, dict[sympy.Symbol, float], float] | None = None
    for sampled in domain_points(model, POINTS, seed=SEED):
        point = {s: v for s, v in sampled.items() if s != c.symbol}  # the coordinate runs along the way
        start, end = (float(sympy.N(e.subs(point))) for e in (trip.start, trip.end))
        values: list[tuple[float, float]] = []
        for step in range(1, STEPS + 1):
            place = start + (end - start) * step / STEPS
            value = complex(sympy.N(force.subs(point).subs(c.symbol, place), 15))
            if abs(value.imag) > 1e-9 * max(1.0, abs(value.real)):
                return False  # not real along the way: the turn-back the simulation finds, not this check's
            values.append((place, value.real))
        scale = max(abs(v) for _, v in values)
        first = next(((place, v) for place, v in values if v < -_TOLERANCE * max(scale, 1.0)), None)
        if first is not None and worst is None:
            worst = (first[0], point, first[1])
    if worst is None:
        return True
    place, point, _ = worst
    named, wrong, then = UNILATERAL[constraint.kind]
    target = typed_text(trip.end)
    raise DerivationError(
        f"{quantity.name}: constraint {constraint.name!r}: {wrong} on the way from {c.name} = "
        f"{typed_text(trip.start)} to {c.name} = {target} (at {c.name} = {place:.4g}, {point_text(point)}): "
        f"{then} before the motion gets there (its {named} along the way, "
        f"{typed_text(tidy.simplify(force))}, must not be negative). Keep the domain where it holds "
        f"(domain.positive), or ask about a motion that keeps the contact",
        quantity=quantity.name,
        path=("quantities", quantity.name),
    )
