"""Where the motion from the state first stops: a coordinate's turning point (a spring's greatest
compression, how far up a slope a sliding block gets, how high a released bob swings).

Each method finds the square of the coordinate's rate along the way by its own route (work and energy,
or its equation of motion integrated: work_energy.py), as a function of where the motion has got to;
the turning point is the first place ahead, in the direction the coordinate starts moving, where that
square reaches zero. Other coordinates must be cyclic: their conserved momenta fix their velocities
(work_energy.held_velocities), as for a speed where the motion arrives. The simulation integrates the motion until the coordinate's rate changes sign.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy, work_energy
from physics.engine.leaving import staged
from physics.engine.model import Model, Quantity, QuantityKind
from physics.engine.proof import domain_points
from physics.engine.quantity_table import derives
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.method import Method

POINTS = 8


@derives(QuantityKind.TURNING_POINT)
def turning_point(method: Method, quantity: Quantity) -> sympy.Expr:
    # found once per method and coordinate: an `expression` of it (how far from the start) asks again
    key = ("turning point", quantity.target)
    if key not in method.arrivals:
        method.arrivals[key] = _turning_point(method, quantity)
    return method.arrivals[key]


def _turning_point(method: Method, quantity: Quantity) -> sympy.Expr:
    model = method.model
    c = model.coordinate(quantity.target)
    state = dict(model.state)
    start = state.get(c.symbol, c.symbol)
    velocity = state.get(c.velocity, sympy.Integer(0))
    # the other coordinates cyclic, their momenta keep the state's values (two carts meeting through a
    # spring bumper, a satellite's angle): their velocities follow c's, as for a speed `at` a place
    held = work_energy.held_velocities(method, c, quantity) if len(model.coordinates) > 1 else {}
    heading = _heading(method, quantity, velocity)
    end = c.symbol  # the rate's square where the coordinate has got to, as a function of it
    trip = work_energy.Journey(c, start, end, velocity, heading, held)
    # past where the body leaves a spring that only pushes, the motion without it (leaving.py)
    square, since, _ = staged(method, trip)
    roots = [tidy.simplify(r) for r in tidy.solve(square, end)]
    first = _first_ahead(model, roots, since, heading, quantity.name)
    method.step(
        f"{method.named(c.name)} turns where its rate vanishes, first along the way it moves",
        method.tex(sympy.Eq(tidy.simplify(square), 0)) + r"\Rightarrow " + method.tex(sympy.Eq(end, first)),
    )
    return first


def _heading(method: Method, quantity: Quantity, velocity: sympy.Expr) -> int:
    """+1 or -1: the way the coordinate starts moving (its velocity, or from rest its acceleration)."""
    model = method.model
    start = velocity if velocity != 0 else method.acceleration(quantity.target)
    what = "velocity" if velocity != 0 else "acceleration at rest"
    values = [float(sympy.N(start.subs(p))) for p in domain_points(model, POINTS, seed=23)]
    if all(v > 0 for v in values):
        return 1
    if all(v < 0 for v in values):
        return -1
    raise DerivationError(
        f"{quantity.name}: cannot tell which way {quantity.target} starts moving: its {what} "
        f"{typed_text(start)} is zero or changes sign on the domain",
        quantity=quantity.name,
    )


def _first_ahead(
    model: Model, roots: list[sympy.Expr], start: sympy.Expr, heading: int, name: str
) -> sympy.Expr:
    """The root nearest the start among those ahead of it, the same one at every sampled point."""
    chosen: set[int] = set()
    for point in domain_points(model, POINTS, seed=29):
        here = float(sympy.N(start.subs(point)))
        ahead: list[tuple[float, int]] = []
        for index, root in enumerate(roots):
            value = complex(sympy.N(root.subs(point)))
            if abs(value.imag) <= 1e-12 * max(1.0, abs(value.real)) and heading * (value.real - here) > 1e-12:
                ahead.append((heading * (value.real - here), index))
        if not ahead:
            raise DerivationError(
                f"{name}: the motion never stops ahead of its start (the rate's square vanishes only at "
                f"{typed_text(roots)}): it does not turn",
                quantity=name,
            )
        chosen.add(min(ahead)[1])
    if len(chosen) != 1:
        raise DerivationError(
            f"{name}: which of {typed_text(roots)} the motion reaches first changes over the domain",
            quantity=name,
        )
    return roots[chosen.pop()]
