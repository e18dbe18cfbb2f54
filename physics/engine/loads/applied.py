"""A force on a body's centre: given components (constant, or in the coordinates, velocities and time),
linear drag -b v, or quadratic drag -c |v| v."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from enum import StrEnum
from typing import TYPE_CHECKING

import sympy

from physics.dimensions import Dimension
from physics.engine.loads import FORCE, LENGTH, MASS, TIME, Entry, Traits, View, nothing, on_body
from physics.engine.text import Path

if TYPE_CHECKING:
    from physics.engine.mechanics import Mechanics
    from physics.engine.model import Model

ZERO = sympy.Integer(0)
DEPTH = "z"  # as depth.py names it (depth.py imports the model, which imports this module)


class ForceKind(StrEnum):
    APPLIED = "force"  # given components, constant or in the coordinates and their velocities
    LINEAR_DRAG = "drag"  # -b v (viscous damping)
    QUADRATIC_DRAG = "quadratic_drag"  # -c |v| v (air drag)


@dataclass(frozen=True)
class AppliedForce:
    """A force on a body (at its centre): given components, or drag opposing its velocity."""

    body: str
    kind: ForceKind
    components: tuple[tuple[str, sympy.Expr], ...] = ()  # for APPLIED: (axis, expression)
    coefficient: sympy.Expr = ZERO  # for drag

    def constant(self, moving: set[sympy.Symbol]) -> bool:
        """A given force that depends on no coordinate or velocity: it has a potential, -F . r."""
        return self.kind is ForceKind.APPLIED and not any(e.free_symbols & moving for _, e in self.components)

    def traits(self, model: Model) -> Traits:
        return Traits(
            conservative=self.constant(model.moving_symbols),
            bodies=(self.body,),
            dissipates=self.kind is not ForceKind.APPLIED,
            viscous=self.kind is ForceKind.LINEAR_DRAG,
        )

    def potential(self, mech: Mechanics, place: Mapping[str, sympy.Expr]) -> sympy.Expr:
        if not self.constant(mech.model.moving_symbols):
            return ZERO
        return -sympy.Add(
            *(
                c * place[f"{axis}_{self.body}"]
                for axis, c in self.components
                if f"{axis}_{self.body}" in place
            )
        )

    def force(self, mech: Mechanics, view: View) -> list[sympy.Expr]:
        if self.constant(mech.model.moving_symbols):
            return nothing(mech)
        if self.kind is ForceKind.APPLIED:
            return on_body(mech, self.body, dict(self.components))
        own = [d for d in mech.dofs if d.body == self.body and not d.name.startswith("phi_")]
        velocity = {
            d.name.split("_", 1)[0]: d.velocity if view.cartesian else mech.velocity_of(d) for d in own
        }
        factor = self.coefficient
        if self.kind is ForceKind.QUADRATIC_DRAG:
            factor = factor * sympy.sqrt(sympy.Add(*(v**2 for v in velocity.values())))
        return on_body(mech, self.body, {axis: -factor * v for axis, v in velocity.items()})

    def expressions(self) -> tuple[sympy.Expr, ...]:
        return (*(c for _, c in self.components), self.coefficient)

    def dimensions(self, path: Path) -> list[tuple[Path, sympy.Expr, Dimension]]:
        if self.kind is ForceKind.APPLIED:
            return [((*path, self.kind.value, axis), c, FORCE) for axis, c in self.components]
        per = TIME if self.kind is ForceKind.LINEAR_DRAG else LENGTH
        return [((*path, self.kind.value), self.coefficient, MASS / per)]


def read(key: str, entry: Entry) -> AppliedForce | None:
    """`{body: b, force: {x: ..., y: ...}}`, `{body: b, drag: b}` or `{body: b, quadratic_drag: c}`."""
    kind = ForceKind(key)
    if kind is ForceKind.APPLIED:
        components = entry.axes(entry.value, entry.path)
        placed = {axis for axis, _ in entry.body.position}
        for axis, _ in components:
            if axis == DEPTH and axis not in placed:  # it would push along an axis the body cannot move on
                entry.error(
                    f"{entry.body.name} has no z in its position, so a force along z would do nothing: "
                    "give the body's z, or leave the component out",
                    (*entry.path, axis),
                )
        return AppliedForce(entry.body.name, kind, components=components) if components else None
    coefficient = entry.parameter(entry.value, entry.path)
    return AppliedForce(entry.body.name, kind, coefficient=coefficient) if coefficient is not None else None
