"""Supports that move as prescribed: positions and constraint gaps in the time `t`.

A pendulum hung in a truck whose position is `A*t^2/2` is written as the physics states it: the pivot's
position in the time (`pivot: {x: "A*t^2/2", y: 0}`, or the bob's position and the string's gap written
with it). The Lagrangian then depends on the time explicitly, and d/dt is the chain rule over the
coordinates plus the partial derivative in t (`mechanics.time_derivative`): Lagrange's equations carry
the support's acceleration, Newton's law differentiates each gap twice in time (with its partial
derivatives in t), d'Alembert's inertial forces are the second derivatives of the positions. Energy is
not conserved in the ground's frame (the moving support does work on the system), so the conservation
method does not apply; the simulation integrates with the clock and keeps the books with the moving
constraints' work, -lambda dg/dt. Relative to a support that accelerates uniformly the system has a
steady equilibrium: where the equations of motion at rest (q' = q'' = 0) balance, free of t.
"""

from __future__ import annotations

import sympy

from physics.engine.model import Model

NOT_CONSERVED = (
    "energy is not conserved in the ground's frame: the support moving as prescribed does work on the system"
)
NOT_STEADY = "the support's motion is not a uniform acceleration: there is no equilibrium relative to it"


def driven(model: Model) -> bool:
    """Whether a position, angle or constraint gap depends on the time (a support moving as prescribed)."""
    return model.time is not None and uses_time(model, model.time)


def uses_time(model: Model, time: sympy.Symbol) -> bool:
    """Whether the model's positions, angles or gaps use `time` (before the model's time is set)."""
    exprs = [e for body in model.bodies for _, e in body.position]
    exprs += [b.angle for b in model.bodies if b.angle is not None]
    exprs += [c.gap for c in model.constraints]
    return any(time in e.free_symbols for e in exprs)


def translation(model: Model) -> dict[str, sympy.Expr] | None:
    """The support's displacement since t = 0 on each axis, R(t), when every body's position is its own
    relative to the support plus R(t), the same for every body (a truck carrying a pendulum), and no angle
    moves with the time; None otherwise (or when nothing moves)."""
    time = model.time
    if time is None or not driven(model):
        return None
    if any(b.angle is not None and time in b.angle.free_symbols for b in model.bodies):
        return None
    coordinates = {c.symbol for c in model.coordinates}
    shifts: dict[str, sympy.Expr] = {}
    for body in model.bodies:
        for axis, expr in body.position:
            shift = sympy.expand(expr - expr.subs(time, 0))
            if (
                shift.free_symbols & coordinates
                or sympy.simplify(shifts.setdefault(axis, shift) - shift) != 0
            ):
                return None
    return {axis: shift for axis, shift in shifts.items() if shift.has(time)}
