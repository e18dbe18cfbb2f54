"""The slip velocity kinetic friction opposes (the load itself: `loads/friction.py`).

The power of a friction of magnitude F is -F times the slip velocity of the contact point, which is how
`slip_velocity` is defined: the same expression the energy bookkeeping and the sliding-phase quantities
use.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import sympy

from physics.engine import tidy
from physics.engine.model import Friction, Model

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
