"""The slip velocity kinetic friction opposes (the load itself: `loads/friction.py`).

The power of a friction of magnitude F is -F times the slip velocity of the contact point, which is how
`slip_velocity` is defined: the same expression the energy bookkeeping and the sliding-phase quantities
use.

At the state, a body already sliding must slide the way the friction's `sliding` says: kinetic friction
is written to oppose slip towards increasing `sliding`, so a block sent up a slope whose coordinate
grows down it would be pushed up by its friction. The methods would then find no place where it stops
("it does not turn"), or a speed it never has; refused at the friction instead, saying which way it
slides (`check_state_slips`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.model import Friction, Model
from physics.engine.signs import Sign, sign_on_domain
from physics.engine.sizes import friction_path
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.mechanics import Mechanics


def slip_velocity(mech: Mechanics, friction: Friction) -> sympy.Expr:
    """The contact point's velocity relative to the surface along the slip direction, in the coordinates
    and their velocities: minus the generalized friction per unit magnitude, dotted with q'."""
    generalized = mech.generalized(friction.of_magnitude(mech, sympy.Integer(1)))
    return tidy.simplify(-sympy.Add(*(g * v for g, v in zip(generalized, mech.qd, strict=True))))


def only_friction(model: Model, constraint: str = "") -> Friction:
    """The friction at `constraint` (or the model's one friction when no constraint is named)."""
    found = [f for f in model.frictions if not constraint or f.constraint == constraint]
    if len(found) != 1:
        raise ValueError(f"expected one kinetic friction{' at ' + constraint if constraint else ''}")
    return found[0]


def check_state_slips(model: Model, mech: Mechanics) -> None:
    """DerivationError at the first friction whose contact slips, at the state, against its `sliding`
    direction on the whole domain (a state from rest is left to the motion: it slides the way it is
    pulled, which the energy bookkeeping checks). The state before an impact or a collision is not the
    slide's."""
    if model.impact is not None or model.collision is not None:
        return
    state = dict(model.state)
    at_state = {c.symbol: state.get(c.symbol, c.symbol) for c in model.coordinates}
    at_state |= {c.velocity: state.get(c.velocity, sympy.Integer(0)) for c in model.coordinates}
    for index, friction in enumerate(model.frictions):
        slip = tidy.simplify(slip_velocity(mech, friction).subs(at_state))
        if slip == 0 or sign_on_domain(slip, model).sign is not Sign.NEGATIVE:
            continue
        raise DerivationError(
            f"at the state, {friction.body} slides towards decreasing {friction.sliding} (its contact slips at "
            f"{typed_text(slip)}), but kinetic friction is written to oppose sliding towards increasing "
            f"{friction.sliding} (`sliding: {friction.sliding}`), so it would push {friction.body} along. Write "
            f"the coordinate so that it grows the way {friction.body} slides (an incline's or surface's "
            f"`direction`), or the state's velocity that way",
            path=friction_path(model, index),
        )
