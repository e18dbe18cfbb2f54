"""A body leaving a spring that only pushes (`attached: false`): the motion in two stages.

A spring launcher pushes a block until the spring is back at its natural length; from there the block
moves on without it (up an incline, across a rough floor). The spring's energy k (d - L0)^2 / 2 would
pull it back past that point, so each method follows the motion as a textbook does: its own route (work
and energy, or its equation of motion integrated: work_energy.py) to where the body leaves the spring,
then the same route again from that leaving state, in the model without the spring. The methods agree
only if both stages do; the simulation integrates the whole motion with the spring's force switched off
past its natural length (`switched_off`), never reading the stages.
"""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING

import sympy

from physics.engine import tidy
from physics.engine.loads.pair import PairPotential
from physics.engine.mechanics import Mechanics
from physics.engine.proof import domain_points

if TYPE_CHECKING:
    from physics.engine.method import Method
    from physics.engine.model import Model
    from physics.engine.work_energy import Journey

POINTS = 8
SEED = 31  # the points buffers.py checks the motion at: the stages are decided where they are checked
_TOLERANCE = 1e-9  # of the coordinate's size: the state written where the body leaves the spring


@dataclasses.dataclass(frozen=True)
class Leaving:
    """The spring the body leaves and the coordinate's value where its length reaches its natural length."""

    potential: PairPotential
    place: sympy.Expr


def leaving(method: Method, trip: Journey) -> Leaving | None:
    """Where the motion leaves a spring that only pushes, ahead of its start (and before its end, when the
    end is a place), the same root at every sampled point; None when it leaves none on the way."""
    model, c = method.model, trip.coordinate
    state = {s: v for s, v in model.state if s != c.symbol}
    lengths = {d.name: d.mapping for d in method.mech.dofs}
    for potential in model.potentials:
        if potential.reach is None:
            continue
        length = potential.length(model, lengths).subs(state)
        # the length must follow the moving coordinate alone (not a bumper between two moving carts)
        if c.symbol not in length.free_symbols or length.free_symbols & (model.moving_symbols - {c.symbol}):
            continue
        growth = sympy.diff(length, c.symbol) * trip.sign
        roots = [r for r in tidy.solve(length - potential.reach, c.symbol) if _ahead(model, trip, r, growth)]
        if len(roots) == 1:
            return Leaving(potential, roots[0])
    return None


def _ahead(model: Model, trip: Journey, root: sympy.Expr, growth: sympy.Expr) -> bool:
    """At every sampled point: the root is real, not behind the start nor past a place asked about, and
    the spring lengthens there as the coordinate moves on (the body moves off it, not onto it)."""
    c = trip.coordinate
    for point in domain_points(model, POINTS, seed=SEED):
        value = complex(sympy.N(root.subs(point), 15))
        if abs(value.imag) > 1e-12 * max(1.0, abs(value.real)):
            return False
        start = float(sympy.N(trip.start.subs(point)))
        size = _TOLERANCE * max(1.0, abs(start))
        if trip.sign * (value.real - start) < -size:
            return False
        if trip.end != c.symbol and trip.sign * (float(sympy.N(trip.end.subs(point))) - value.real) <= size:
            return False
        if not float(sympy.N(growth.subs(point).subs(c.symbol, value.real))) > 0:
            return False
    return True


def staged(method: Method, trip: Journey) -> tuple[sympy.Expr, sympy.Expr, Method]:
    """q'^2 where the trip ends (a function of the coordinate for a free end) by this method's route, the
    place from which that expression holds, and the method of the model it holds in: the start and this
    method, or where the body leaves a spring that only pushes, reached with a speed, and the method
    without that spring (else it turns back on the spring: one stage, buffers.py checks it)."""
    from physics.engine.work_energy import ROUTES, by_integration

    route = ROUTES.get(method.name, by_integration)
    found = leaving(method, trip)
    if found is None:
        return route(method, trip), trip.start, method
    model, c = method.model, trip.coordinate
    at_start = tidy.simplify(found.place - trip.start) == 0
    first = trip.velocity**2 if at_start else route(method, dataclasses.replace(trip, end=found.place))
    if not _positive(model, first):
        return route(method, trip), trip.start, method
    velocity = tidy.simplify(trip.sign * sympy.sqrt(first))
    state = {**dict(model.state), c.symbol: found.place, c.velocity: velocity}
    state.update(
        {
            v: tidy.simplify(e.subs({c.symbol: found.place, c.velocity: velocity}))
            for v, e in trip.held.items()
        }
    )
    freed = dataclasses.replace(
        model,
        potentials=tuple(p for p in model.potentials if p is not found.potential),
        state=tuple(state.items()),
    )
    later = type(method)(freed, Mechanics(freed))
    square = route(later, dataclasses.replace(trip, start=found.place, velocity=velocity))
    method.step(
        f"The body leaves the spring where {method.named(c.name)} = ${method.tex(found.place)}$ (its natural "
        "length); from there it moves on without it",
        method.tex(sympy.Eq(c.velocity, velocity)),
    )
    method.adopt_after(later.steps, "(after leaving the spring)")
    return square, found.place, later


def _positive(model: Model, expr: sympy.Expr) -> bool:
    """expr > 0 at every sampled domain point: the body gets to where it leaves the spring, still moving."""
    for point in domain_points(model, POINTS, seed=SEED):
        value = complex(sympy.N(expr.subs(point), 15))
        if abs(value.imag) > 1e-9 * max(1.0, abs(value.real)) or not value.real > 0:
            return False
    return True


def switched_off(model: Model) -> Model:
    """The model with each spring that only pushes exerting no force past its natural length: the
    simulation's motion (the methods' stages are never read by it)."""
    if all(p.reach is None for p in model.potentials):
        return model
    return dataclasses.replace(
        model,
        potentials=tuple(
            p
            if p.reach is None
            else dataclasses.replace(
                p, energy=sympy.Piecewise((p.energy, p.distance < p.reach), (sympy.Integer(0), True))
            )
            for p in model.potentials
        ),
    )
