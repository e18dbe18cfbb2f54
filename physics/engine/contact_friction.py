"""The slip velocity kinetic friction opposes (the load itself: `loads/friction.py`).

The power of a friction of magnitude F is -F times the slip velocity of the contact point, which is how
`slip_velocity` is defined: the same expression the energy bookkeeping and the sliding-phase quantities
use.

At the state, a body already sliding must slide the way the friction's `sliding` says: kinetic friction
is written to oppose slip towards increasing `sliding`, so a block sent up a slope whose coordinate
grows down it would be pushed up by its friction. The methods would then find no place where it stops
("it does not turn"), or a speed it never has; refused at the friction instead, saying which way it
slides (`check_state_slips`).

A rigid body's `contact` is where it touches the surface, so it lies on the surface's side of its centre
(against the gap's gradient, which points away from the surface). Written on the far side (`{y: R}` for
a ball on a floor), the friction's torque spins the body the other way, and its skid ends with the
right time and speed but the spin of a ball rolling backwards, every method and the simulation
agreeing (`check_contact_sides`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.grips import state_points
from physics.engine.model import Friction, Model
from physics.engine.signs import Sign, sign_on_domain
from physics.engine.sizes import friction_path
from physics.errors import DerivationError

_POINTS = 8

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


def check_contact_sides(model: Model, mech: Mechanics) -> None:
    """DerivationError at the first friction whose contact point lies, at every sampled state, on the far
    side of its body's centre from the surface (along the gap's gradient)."""
    place = {d.symbol: d.mapping for d in mech.dofs}
    points = state_points(model, mech)[:_POINTS]
    constraints = {c.name: c for c in model.constraints}
    for index, friction in enumerate(model.frictions):
        constraint = constraints.get(friction.constraint)
        if not friction.contact or constraint is None:
            continue
        axes = {d.name: d.symbol for d in mech.dofs if d.body == friction.body}
        normal = {
            axis: sympy.diff(constraint.gap, axes[name]) if (name := f"{axis}_{friction.body}") in axes else 0
            for axis, _ in friction.contact
        }
        facing = sympy.Add(*(offset * normal[axis] for axis, offset in friction.contact))
        values = [complex(sympy.N(facing.subs(place).subs(point), 15)).real for point in points]
        if not values or not all(v > 0 for v in values):
            continue
        # mirrored across the surface's tangent: the point on the surface's side (unit normal: a clearance)
        mirrored = {a: tidy.simplify((o - 2 * facing * normal[a]).subs(place)) for a, o in friction.contact}
        written = friction_path(model, index)
        raise DerivationError(
            f"friction on {friction.body} at {friction.constraint!r}: its contact point {_point(dict(friction.contact))} "
            f"lies on the far side of {friction.body}'s centre from the surface (the gap "
            f"{typed_text(constraint.gap)} grows towards it), so the friction's torque would turn "
            f"{friction.body} the wrong way. The contact is where {friction.body} touches the surface, on its side "
            f"of the centre: {_point(mirrored)}",
            path=(*written, "contact") if written[0] == "friction" else written,
        )


def _point(offsets: dict[str, sympy.Expr]) -> str:
    return "{" + ", ".join(f"{axis}: {typed_text(offset)}" for axis, offset in offsets.items()) + "}"
