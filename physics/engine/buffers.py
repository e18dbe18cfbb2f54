"""A spring that only pushes: a body meets its free end (`attached: false`, a buffer or bumper).

The spring's potential k (d - L0)^2 / 2 pulls as well as pushes: a block sent along a floor onto a
spring's free end would be pulled towards it before they meet, and back after they part, so the
greatest compression would be derived for a motion that does not happen. As Modelica writes a contact
that can only push as a component with its own condition (ElastoGap: no force while the gap is open),
the spring carries its reach, its natural length, and the model must stay within it: at the state
(the body touching or squeezing it), and all along each motion a quantity is taken at the end of.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy

from physics.answer_text import typed_text
from physics.engine.along_the_way import POINTS, SEED, STEPS, trip
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
    """Before any method: each spring that only pushes is met at the state, and no quantity is taken
    `at` a place beyond its reach (where the body has left it); DerivationError where written."""
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
        for quantity in model.quantities:
            if not quantity.at or quantity.after:
                continue
            there = length.subs({model.coordinate(n).symbol: v for n, v in quantity.at}).subs(state)
            past = _past(model, [there], pair.reach)
            if past is not None:
                raise DerivationError(
                    f"{quantity.name}: the spring at {'.'.join(map(str, where))} only pushes (attached: "
                    f"false), and where the quantity is taken its length would be {typed_text(there)}, longer "
                    f"than its natural length {typed_text(pair.reach)} ({point_text(past)}): the body has left "
                    "the spring by then and moves on freely, which the model does not follow. Ask where the "
                    f"body leaves it (its length {typed_text(pair.reach)}): the speed is kept after that",
                    quantity=quantity.name,
                    path=("quantities", quantity.name),
                )


def check_buffers(model: Model, method: Method, quantities: Mapping[str, sympy.Expr]) -> dict[str, str]:
    """Each spring that only pushes is kept squeezed along each asked motion: a check's name -> what was
    shown; DerivationError at the quantity where it is not."""
    state = dict(model.state)
    shown = []
    for index, pair, length in _buffers(model, method.mech):
        assert pair.reach is not None
        where = _written(model, pair.name, index)
        for quantity in model.quantities:
            journey = trip(method, quantity, quantities)
            if journey is None:
                continue
            c = journey.coordinate
            along = length.subs({s: v for s, v in state.items() if s != c.symbol})
            places = [
                journey.start + (journey.end - journey.start) * sympy.Rational(k, STEPS)
                for k in range(STEPS + 1)
            ]
            past = _past(model, [along.subs(c.symbol, place) for place in places], pair.reach)
            if past is not None:
                raise DerivationError(
                    f"{quantity.name}: the spring at {'.'.join(map(str, where))} only pushes (attached: false), "
                    f"but on the way from {c.name} = {typed_text(journey.start)} to {c.name} = "
                    f"{typed_text(journey.end)} its length passes its natural length {typed_text(pair.reach)} "
                    f"({point_text(past)}): the body leaves the spring and moves on freely, which the model "
                    "does not follow. Ask about a motion that keeps it squeezed (the greatest compression, "
                    "from where the body meets it)",
                    quantity=quantity.name,
                    path=("quantities", quantity.name),
                )
            shown.append(f"{'.'.join(map(str, where))} ({quantity.name})")
    if not shown:
        return {}
    return {"springs that only push": f"{', '.join(shown)}: squeezed from the state to where each is taken"}


def _buffers(model: Model, mech: Mechanics) -> list[tuple[int, PairPotential, sympy.Expr]]:
    """Each spring that only pushes, with its index among the potentials and its length in the coordinates."""
    lengths = {d.name: d.mapping for d in mech.dofs}
    return [(i, p, p.length(model, lengths)) for i, p in enumerate(model.potentials) if p.reach is not None]


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
