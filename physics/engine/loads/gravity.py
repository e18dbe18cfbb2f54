"""Uniform gravity along -y: the potential m g y of every body with a y position."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import sympy

from physics.engine.loads import Traits, View, nothing

if TYPE_CHECKING:
    from physics.engine.mechanics import Mechanics
    from physics.engine.model import Model


@dataclass(frozen=True)
class Gravity:
    acceleration: sympy.Expr  # g, a magnitude

    def traits(self, model: Model) -> Traits:
        bodies = tuple(b.name for b in model.bodies if any(axis == "y" for axis, _ in b.position))
        return Traits(conservative=True, bodies=bodies)

    def potential(self, mech: Mechanics, place: Mapping[str, sympy.Expr]) -> sympy.Expr:
        return sympy.Add(
            *(
                body.mass * self.acceleration * place[f"y_{body.name}"]
                for body in mech.model.bodies
                if f"y_{body.name}" in place
            )
        )

    def force(self, mech: Mechanics, view: View) -> list[sympy.Expr]:
        return nothing(mech)

    def expressions(self) -> tuple[sympy.Expr, ...]:
        return (self.acceleration,)
