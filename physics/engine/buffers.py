"""A spring that only pushes: a body meets its free end (`attached: false`, a buffer, a bumper, a launcher).

The spring's potential k (d - L0)^2 / 2 pulls as well as pushes: a block sent along a floor onto a
spring's free end would be pulled towards it before they meet, and back after they part. As Modelica
writes a contact that can only push as a component with its own condition (ElastoGap: no force while
the gap is open), the spring carries its reach, its natural length. The state must have the body
touching it; a motion may carry the body off it (the methods follow it in two stages: leaving.py), but
then for good, at every point of the domain alike: a body that meets the spring again on the way, or
leaves it at some of the domain's points and turns back on it at others, is refused at the quantity.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy

from physics.answer_text import typed_text
from physics.engine.along_the_way import STEPS, trip
from physics.engine.leaving import POINTS, SEED, leaving
from physics.engine.loads.pair import PairPotential
from physics.engine.mechanics import Mechanics
from physics.engine.method import Method
from physics.engine.model import Model
from physics.engine.proof import domain_points
from physics.engine.signs import point_text
from physics.engine.text import Path
from physics.errors import DerivationError

_TOLERANCE = 1e-9  # of the natural length: a state written at the contact itself


def check_buffers_placed(model: Model, mech: Mechanics) -> None:
    """Before any method: each spring that only pushes is met at the state; DerivationError where written."""
    state = dict(model.state)
    for index, pair, length in _buffers(model, mech):
        assert pair.reach is not None
        where = _written(model, pair.name, index)
        at_state = length.subs(state)
        past = _past(model, [at_state], pair.reach)
        if past is not None:
            raise DerivationError(
                f"the spring only pushes (attached: false), but at the state its length is "
                f"{typed_text(at_state)}, longer than its natural length {typed_text(pair.reach)} "
                f"({point_text(past)}): the body is not touching it, and the spring's energy would pull "
                "it in. Start the state where the body meets the spring (its length "
                f"{typed_text(pair.reach)}), with the velocity it arrives with",
                path=where,
            )
        pulls = _pulls_when_squeezed(model, pair, at_state)
        if pulls is not None:
            raise DerivationError(
                f"the spring only pushes (attached: false), but its energy {typed_text(pair.energy)} rises as "
                f"it lengthens towards its natural length {typed_text(pair.reach)} ({point_text(pulls)}): "
                "squeezed, it would pull the body in. A spring's energy is k (d - L0)^2/2, positive: check "
                "its sign",
                path=where,
            )


def _pulls_when_squeezed(
    model: Model, pair: PairPotential, at_state: sympy.Expr
) -> dict[sympy.Symbol, float] | None:
    """A sampled point where the energy grows with the length between the state's and the natural length
    (the force -dU/dd pulls the body in), or None."""
    if at_state.free_symbols - set(model.parameters):
        return None
    assert pair.reach is not None
    force = -sympy.diff(pair.energy, pair.distance)
    for point in domain_points(model, POINTS, seed=SEED):
        start, reach = (float(sympy.N(e.subs(point))) for e in (at_state, pair.reach))
        for share in (0.25, 0.5, 0.75):
            value = complex(
                sympy.N(force.subs(point).subs(pair.distance, start + (reach - start) * share), 15)
            )
            if abs(value.imag) <= 1e-9 * max(1.0, abs(value.real)) and value.real < 0:
                return point
    return None


def check_buffers(model: Model, method: Method, quantities: Mapping[str, sympy.Expr]) -> dict[str, str]:
    """Along each asked motion, each spring that only pushes stays squeezed, or the body leaves it for
    good, alike at every sampled point: a check's name -> what was shown; DerivationError at the quantity
    where it is not."""
    state = dict(model.state)
    shown = []
    for index, pair, length in _buffers(model, method.mech):
        assert pair.reach is not None
        where = ".".join(map(str, _written(model, pair.name, index)))
        for quantity in model.quantities:
            journey = trip(method, quantity, quantities)
            if journey is None:
                continue
            c = journey.coordinate
            along = length.subs({s: v for s, v in state.items() if s != c.symbol})
            if along.free_symbols - set(model.parameters) - {c.symbol}:
                continue  # a coordinate the state leaves free: nothing to tell here
            places = [
                journey.start + (journey.end - journey.start) * sympy.Rational(k, STEPS)
                for k in range(STEPS + 1)
            ]
            ways = _ways(model, [along.subs(c.symbol, place) for place in places], pair.reach)
            way = f"on the way from {c.name} = {typed_text(journey.start)} to {c.name} = {typed_text(journey.end)}"
            said = f"{quantity.name}: the spring at {where} only pushes (attached: false), "
            refusal = None
            if "again" in ways:
                refusal = (
                    f"{said}and {way} the body leaves it and meets it again ({point_text(ways['again'])}), "
                    "which the model does not follow. Ask about a motion that leaves it once, or stays on it"
                )
            elif "leaves" in ways and "stays" in ways:
                refusal = (
                    f"{said}and {way} the body leaves it at some of the domain's points "
                    f"({point_text(ways['leaves'])}) but turns back on it at others ({point_text(ways['stays'])}): "
                    "two motions, two answers. Keep the domain to one of them (domain.positive: the condition "
                    "that the body gets back to the spring's natural length still moving, such as "
                    "k*d - 2*m*g*sin(theta) for a launcher compressed by d up a slope)"
                )
            elif "leaves" in ways and leaving(method, journey) is None:
                refusal = (
                    f"{said}and {way} the body leaves it ({point_text(ways['leaves'])}), but where it does "
                    f"is not one place ahead of the start: {typed_text(along)} = {typed_text(pair.reach)} "
                    f"must have a single root for {c.name} on the way"
                )
            if refusal is not None:
                raise DerivationError(refusal, quantity=quantity.name, path=("quantities", quantity.name))
            if "leaves" in ways:
                shown.append(f"{where} ({quantity.name}: left once, at its natural length)")
            else:
                shown.append(f"{where} ({quantity.name}: squeezed all the way)")
    if not shown:
        return {}
    return {"springs that only push": f"{', '.join(shown)}: from the state to where each is taken"}


def _buffers(model: Model, mech: Mechanics) -> list[tuple[int, PairPotential, sympy.Expr]]:
    """Each spring that only pushes, with its index among the potentials and its length in the coordinates."""
    lengths = {d.name: d.mapping for d in mech.dofs}
    return [(i, p, p.length(model, lengths)) for i, p in enumerate(model.potentials) if p.reach is not None]


def _ways(model: Model, lengths: list[sympy.Expr], reach: sympy.Expr) -> dict[str, dict[sympy.Symbol, float]]:
    """How the body goes along the lengths in order, by sampled domain point: "stays" squeezed, "leaves"
    for good, or leaves and meets the spring "again"; the first point of each."""
    found: dict[str, dict[sympy.Symbol, float]] = {}
    for point in domain_points(model, POINTS, seed=SEED):
        limit = float(sympy.N(reach.subs(point)))
        past = [
            float(sympy.re(sympy.N(length.subs(point), 15))) > limit + _TOLERANCE * max(1.0, abs(limit))
            for length in lengths
        ]
        way = "stays" if not any(past) else "leaves" if all(past[past.index(True) :]) else "again"
        found.setdefault(way, point)
    return found


def _past(model: Model, lengths: list[sympy.Expr], reach: sympy.Expr) -> dict[sympy.Symbol, float] | None:
    """A sampled domain point where a length exceeds the reach, or None."""
    if any(length.free_symbols - set(model.parameters) for length in lengths):
        return None  # a coordinate the state leaves free: nothing to tell here
    for point in domain_points(model, POINTS, seed=SEED):
        limit = float(sympy.N(reach.subs(point)))
        for length in lengths:
            value = complex(sympy.N(length.subs(point), 15))
            if abs(value.imag) <= 1e-9 * max(1.0, abs(value.real)) and value.real > limit + _TOLERANCE * max(
                1.0, abs(limit)
            ):
                return point
    return None


def _written(model: Model, potential: str, index: int) -> Path:
    """Where the spring was written: its element, else its entry under `potentials:`."""
    element = next((e for e in model.elements if potential in e.potentials), None)
    return ("elements", element.name) if element is not None else ("potentials", index)
