"""Kinetic friction as a force at a contact: on a particle, on a rigid body (with its torque), between
two moving bodies (with its reaction), and the slip velocity it opposes.

A friction of magnitude F acts on `body` against its slip direction (the direction its centre moves as
the `sliding` coordinate grows; for a body on a surface, the surface's tangent). At a rigid body's
`contact` point r (relative to the centre) it also turns the body with the torque r x F; `against`
names the moving body underneath, which feels -F. The power of these loads is -F times the slip
velocity of the contact point, which is how `slip_velocity` is defined: the same expression the
energy bookkeeping and the sliding-phase quantities use.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import sympy

from physics.engine import tidy
from physics.engine.model import Friction, Model

if TYPE_CHECKING:
    from physics.engine.mechanics import Mechanics


def friction_load(mech: Mechanics, friction: Friction, magnitude: sympy.Expr) -> list[sympy.Expr]:
    """The friction of this magnitude on every Cartesian dof (forces on x, y; its torque on phi)."""
    direction = mech.sliding_direction(friction.body, friction.sliding)
    loads = [-magnitude * u for u in direction]
    index = {d.name: i for i, d in enumerate(mech.dofs)}
    force = {
        axis: loads[index[f"{axis}_{friction.body}"]]
        for axis in ("x", "y")
        if f"{axis}_{friction.body}" in index
    }
    if friction.contact:
        arm = dict(friction.contact)
        zero = sympy.Integer(0)
        torque = arm.get("x", zero) * force.get("y", zero) - arm.get("y", zero) * force.get("x", zero)
        loads[index[f"phi_{friction.body}"]] += torque
    if friction.against is not None:
        for axis, component in force.items():
            name = f"{axis}_{friction.against}"
            if name in index:
                loads[index[name]] -= component
    return loads


def slip_velocity(mech: Mechanics, friction: Friction) -> sympy.Expr:
    """The contact point's velocity relative to the surface along the slip direction, in the coordinates
    and their velocities: minus the generalized friction per unit magnitude, dotted with q'."""
    generalized = mech.generalized(friction_load(mech, friction, sympy.Integer(1)))
    return tidy.simplify(-sympy.Add(*(g * v for g, v in zip(generalized, mech.qd, strict=True))))


def only_friction(model: Model, constraint: str = "") -> Friction:
    """The friction at `constraint` (or the model's one friction when no constraint is named)."""
    found = [f for f in model.frictions if not constraint or f.constraint == constraint]
    if len(found) != 1:
        raise ValueError(f"expected one kinetic friction{' at ' + constraint if constraint else ''}")
    return found[0]
