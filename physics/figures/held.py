"""The forces of a model's constraints of kind "other" on a body, for free-body diagrams. The engine
knows such a constraint only by its gap, so what its force is, is read from the gap's geometry:

- two that fix the body's x and its y, each linearly (a rigid pendulum's pivot, a pulley's axle), are
  one force from the axle (Fₐₓₗₑ) or pivot (Fₚᵢᵥₒₜ), drawn against the resultant of the directions of
  the body's other forces: exact where those are parallel (a pulley's weight and strings, a rod hanging
  at rest), and the support's pull elsewhere;
- one across the normal of a surface the body touches is that surface's grip, static friction f (the
  foot of a ladder that does not slip);
- any other holds the body along its gap's gradient, as a wire or a hoop holds a bead: N.
"""

from __future__ import annotations

import math

import sympy

from physics.engine.model import Constraint, ConstraintKind, Model
from physics.figures.figure import Values
from physics.figures.loads import applied_forces, potential_forces

Direction = tuple[float, float]
Source = tuple[str, str | int]  # as free_body.py names a contact: ("constraint", its name)
_ALIGNED = 1e-9


def held_forces(
    model: Model,
    body_name: str,
    values: Values,
    held: list[tuple[Constraint, Direction]],
    found: list[tuple[Source, str, Direction]],
) -> list[tuple[Source, str, Direction]]:
    """The body's forces from the "other" constraints in `held` (each with its gap's gradient there),
    given the contacts already `found` on it."""
    pin = _pin(model, body_name, held)
    forces: list[tuple[Source, str, Direction]] = []
    if pin is not None:
        across, up = pin
        others = [direction for _, _, direction in found]
        others += [direction for _, direction in potential_forces(model, body_name, values)]
        others += [direction for _, direction in applied_forces(model, body_name, values)]
        if model.gravity is not None:
            others.append((0.0, -1.0))
        sx, sy = sum(d[0] for d in others), sum(d[1] for d in others)
        norm = math.hypot(sx, sy)
        direction = (0.0 - sx / norm, 0.0 - sy / norm) if norm > 1e-9 else (0.0, 1.0)
        axle = "axle" in (across.name + up.name).lower()
        forces.append((("constraint", across.name), "Fₐₓₗₑ" if axle else "Fₚᵢᵥₒₜ", direction))
    normals = [
        direction
        for (kind, name), _, direction in found
        if kind == "constraint" and model.constraint(str(name)).kind is ConstraintKind.SURFACE
    ]
    for constraint, direction in held:
        if pin is not None and constraint in pin:
            continue
        grip = any(abs(direction[0] * n[0] + direction[1] * n[1]) < _ALIGNED for n in normals)
        forces.append((("constraint", constraint.name), "f" if grip else "N", direction))
    return forces


def _pin(
    model: Model, body_name: str, held: list[tuple[Constraint, Direction]]
) -> tuple[Constraint, Constraint] | None:
    """(the x constraint, the y constraint) if two of `held` fix the body's x and y, each linearly."""
    names = dict(model.cartesian)
    x, y = names.get(f"x_{body_name}"), names.get(f"y_{body_name}")
    if x is None or y is None:
        return None

    def linear(constraint: Constraint) -> bool:
        return all(sympy.diff(constraint.gap, a, b) == 0 for a in (x, y) for b in (x, y))

    across = [c for c, d in held if abs(d[1]) < _ALIGNED and linear(c)]
    up = [c for c, d in held if abs(d[0]) < _ALIGNED and linear(c)]
    return (across[0], up[0]) if len(across) == 1 and len(up) == 1 else None
