"""Sizes that physics makes positive, and friction's reaction: what the model's own parameters must say.

A mass, a moment of inertia, a friction or drag coefficient and a spring's stiffness are sizes. Typed
with a sign (`inertia: -m*R^2/2`, `friction: -mu`, `drag: -b`), every method reads the same wrong
number and agrees: a cylinder "rolls" down an incline at 2 g sin(theta), friction and drag push the
body along. The energy bookkeeping catches some of them later, but blames the direction of sliding; here
each is refused at what was typed, saying what it is.

Kinetic friction at a contact between two bodies that both move acts on both (Newton's third law):
without `against`, the surface's body feels nothing, and a block on a rough wedge free on a smooth floor
would leave the pair's horizontal momentum changing with no horizontal force on it.
"""

from __future__ import annotations

from collections.abc import Iterator

import sympy

from physics.answer_text import typed_text
from physics.engine.loads.applied import AppliedForce, ForceKind
from physics.engine.model import Model
from physics.engine.signs import Sign, point_text, sign_on_domain
from physics.engine.text import Path, read_expr
from physics.errors import DerivationError, SpecError


def check_sizes(model: Model) -> None:
    """Every mass, inertia, friction and drag coefficient and spring stiffness is not negative on the
    domain, and no body is massless; DerivationError at the first that is, where the author wrote it."""
    for body in model.bodies:
        if body.mass == 0:  # its equation of motion is a balance of forces: no acceleration of its own
            raise DerivationError(
                f"{body.name}'s mass is 0: every body moves by Newton's law, and a massless point has no "
                "acceleration of its own (the forces on it balance), so the equations of motion are singular. "
                "Give it a mass, or leave it out: springs in series are one spring of stiffness k1*k2/(k1 + k2), "
                "a light pulley under a body is the pulley element's `under`",
                path=body_path(model, body.name, "mass"),
            )
    for expr, what, meaning, path in _sizes(model):
        found = sign_on_domain(expr, model)
        if found.sign not in (Sign.NEGATIVE, Sign.MIXED):
            continue
        where = (
            "on the whole domain"
            if found.sign is Sign.NEGATIVE
            else f"at {point_text(found.negative_at or {})}"
        )
        raise DerivationError(
            f"{what} {typed_text(expr)} is negative {where}: {meaning}. Write it as its size", path=path
        )


def check_friction_reactions(model: Model) -> None:
    """Friction at a contact whose other side is a body that moves names it (`against`), which then feels
    the reaction; refused at the friction otherwise."""
    moving = {b.name for b in model.bodies if _moves(model, b.name)}
    written = {c.name: c for c in model.constraints}
    for index, friction in enumerate(model.frictions):
        constraint = written.get(friction.constraint)
        if friction.against is not None or constraint is None:
            continue
        symbols = {s.name for s in constraint.gap.free_symbols}
        others = sorted(
            b
            for b in moving
            if b != friction.body and any(f"{axis}_{b}" in symbols for axis in ("x", "y", "phi"))
        )
        if others:
            raise DerivationError(
                f"kinetic friction on {friction.body} at {friction.constraint!r}, a contact with {others[0]}, "
                f"which moves: {others[0]} feels the opposite friction (Newton's third law), which the model "
                f"leaves out. Add `against: {others[0]}` to the friction",
                path=friction_path(model, index),
            )


def _moves(model: Model, body: str) -> bool:
    """Whether a coordinate places the body (a support moving as prescribed feels no reaction that matters)."""
    coordinates = {c.symbol for c in model.coordinates}
    placed = model.body(body)
    exprs = [e for _, e in placed.position] + ([placed.angle] if placed.angle is not None else [])
    return any(e.free_symbols & coordinates for e in exprs)


def _sizes(model: Model) -> Iterator[tuple[sympy.Expr, str, str, Path]]:
    for body in model.bodies:
        yield body.mass, f"{body.name}'s mass", "a mass is a size", body_path(model, body.name, "mass")
        if body.angle is not None:
            yield (
                body.inertia,
                f"{body.name}'s moment of inertia",
                "a moment of inertia is a sum of m r^2, never negative",
                body_path(model, body.name, "inertia"),
            )
    for index, friction in enumerate(model.frictions):
        yield (
            friction.coefficient,
            f"the coefficient of kinetic friction on {friction.body}",
            "friction would push the body along its slip instead of opposing it",
            friction_path(model, index),
        )
    applied = [f for f in model.force_entries if isinstance(f, AppliedForce)]
    for force in applied:
        if force.kind in (ForceKind.LINEAR_DRAG, ForceKind.QUADRATIC_DRAG):
            yield (
                force.coefficient,
                f"the drag coefficient on {force.body}",
                "drag would push the body along its velocity instead of opposing it",
                ("forces", model.force_entries.index(force)),
            )
    for element in model.elements:
        if element.kind == "spring":
            for name in element.potentials:
                [potential] = [p for p in model.potentials if p.name == name]
                stiffness = sympy.diff(potential.energy, potential.distance, 2)
                yield (
                    stiffness,
                    f"the stiffness of spring {element.name!r}",
                    "the spring would push its ends apart when stretched",
                    ("elements", element.name, "stiffness"),
                )
        for field, what in _ELEMENT_LENGTHS.get(element.kind, ()):
            length = _field_expr(model, element.fields.get(field))
            if length is not None:
                yield (
                    length,
                    f"the {what} of {element.kind} {element.name!r}",
                    "a length is a size",
                    (
                        "elements",
                        element.name,
                        field,
                    ),
                )


# an element's lengths, which its expansion puts under a square root or beside a distance: a spring of
# natural length -L0 would be pulled towards its anchor, a pendulum's string of length -L violated
_ELEMENT_LENGTHS = {
    "spring": (("length", "natural length"),),
    "pendulum": (("length", "length"),),
    "rolling": (("radius", "radius"),),
}


def _field_expr(model: Model, raw: object) -> sympy.Expr | None:
    """An element's field as written (a number or text over the model's symbols); None if it is not one."""
    if raw is None or isinstance(raw, bool) or not isinstance(raw, str | int | float):
        return None
    try:
        return read_expr(raw, {str(s): s for s in model.parameters}, ())
    except SpecError:
        return None


def body_path(model: Model, body: str, field: str) -> Path:
    """Where the author wrote the body's `field`: the element that generated the body, or `bodies`."""
    for element in model.elements:
        if body in element.bodies and field in element.fields:
            return ("elements", element.name, field)
    return ("bodies", body, field)


def friction_path(model: Model, index: int) -> Path:
    """The element whose `friction` generated it, or its entry under `friction`."""
    friction = model.frictions[index]
    for element in model.elements:
        if friction.constraint in element.constraints and "friction" in element.fields:
            return ("elements", element.name, "friction")
    written = [i for i, f in enumerate(model.frictions) if not _from_element(model, f.constraint)]
    return ("friction", written.index(index)) if index in written else ("friction",)


def _from_element(model: Model, constraint: str) -> bool:
    return any(
        constraint in element.constraints and "friction" in element.fields for element in model.elements
    )
