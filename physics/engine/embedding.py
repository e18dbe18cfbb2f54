"""Where a projectile sticks: the point of the target it strikes, and the rigid body it joins.

A particle target takes the projectile where it is: the merged body is the particle with the two
masses. A rigid target (a body with an angle) may be struck away from its centre of mass, at a
`point` fixed on it (a rod's lower end); the projectile then stays a particle of its own, welded
to the body there by two bilateral constraints, so that every method sees the embedded mass where
it is: its moment about the pivot, its weight's lever, and the impulses that hold it. An impact's
`points` (a ball bouncing off a rod's end) are checked here the same way (`point_fault`).

A rigid target that turns must say where it is struck (`unplaced_fault`): struck at its end or at its
centre, a hanging rod swings off at rates 3 m u/((M + 3 m) L) and 6 m u/((4 M + 3 m) L), and a model
that left the point out had been struck at its centre without a word.
"""

from __future__ import annotations

import dataclasses

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.model import AXES, Body, Constraint, ConstraintKind, Model

ZERO = sympy.Integer(0)


def struck(model: Model) -> dict[str, sympy.Expr]:
    """The struck point's position on each axis, in the coordinates."""
    hit = model.collision
    assert hit is not None
    return dict(hit.point or model.body(hit.target).position)


def body_offset(target: Body, point: dict[str, sympy.Expr]) -> tuple[sympy.Expr, sympy.Expr]:
    """The point in the target's own frame: its offset from the centre of mass, turned back by the
    body's angle. Constant exactly when the point is fixed on the body."""
    assert target.angle is not None
    position = dict(target.position)
    dx = point.get("x", ZERO) - position.get("x", ZERO)
    dy = point.get("y", ZERO) - position.get("y", ZERO)
    cos, sin = sympy.cos(target.angle), sympy.sin(target.angle)
    return tidy.simplify(cos * dx + sin * dy), tidy.simplify(-sin * dx + cos * dy)


def joined(model: Model) -> Model:
    """The model after a projectile has stuck in a rigid target at `point`: the projectile a particle
    of the model, held at the point by `<projectile>X` and `<projectile>Y`."""
    hit = model.collision
    assert hit is not None and hit.point
    target = model.body(hit.target)
    point = dict(hit.point)
    particle = Body(hit.projectile, hit.projectile_mass, ZERO, tuple((a, point.get(a, ZERO)) for a in AXES))
    symbols = {name: sympy.Symbol(name, real=True) for name in particle.cartesian_names()}
    cartesian = dict(model.cartesian)

    def of_target(axis: str) -> sympy.Expr:
        name = f"{axis}_{target.name}"
        return cartesian.get(name, dict(target.position).get(axis, ZERO))

    ox, oy = body_offset(target, point)
    angle = cartesian[f"phi_{target.name}"]
    held = (
        of_target("x") + ox * sympy.cos(angle) - oy * sympy.sin(angle),
        of_target("y") + ox * sympy.sin(angle) + oy * sympy.cos(angle),
    )
    welds = tuple(
        Constraint(
            f"{hit.projectile}{axis.upper()}", symbols[f"{axis}_{hit.projectile}"] - at, ConstraintKind.OTHER
        )
        for axis, at in zip(AXES, held, strict=True)
    )
    return dataclasses.replace(
        model,
        bodies=(*model.bodies, particle),
        constraints=(*model.constraints, *welds),
        cartesian=(*model.cartesian, *symbols.items()),
    )


def unplaced_fault(target: Body, coordinates: set[sympy.Symbol], field: str) -> str | None:
    """Why a rigid target that the coordinates turn needs its struck point written (`field`), or None."""
    if target.angle is None or not target.angle.free_symbols & coordinates:
        return None
    centre = ", ".join(f"{axis}: {typed_text(at)}" for axis, at in target.position)
    return (
        f"{target.name} turns (its angle is {typed_text(target.angle)}): where it is struck decides how it "
        f"turns, so give {field}, fixed on it as its position is written (at its centre: {{{centre}}})"
    )


def point_fault(
    point: dict[str, sympy.Expr],
    target: Body,
    coordinates: set[sympy.Symbol],
    what: str = "a projectile sticks",
) -> str | None:
    """Why `point` cannot be where `target` is struck, or None."""
    if target.angle is None:
        position = dict(target.position)
        if any(tidy.simplify(point.get(a, ZERO) - position.get(a, ZERO)) != 0 for a in AXES):
            return (
                f"{target.name} is a particle: {what} where it is; a point away from it "
                "needs a rigid body (one with an inertia and an angle)"
            )
        return None
    if set(point) != set(AXES):
        return "give the point's x and y"
    offset = body_offset(target, point)
    if any(f.free_symbols & coordinates for f in offset):
        return (
            f"the point moves on {target.name}: in its own frame it is at "
            f"({', '.join(typed_text(f) for f in offset)}), which changes with the coordinates; "
            "write it as the body's position is written, fixed on the body"
        )
    return None
