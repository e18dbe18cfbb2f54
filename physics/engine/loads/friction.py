"""Kinetic friction at a contact: on a particle, on a rigid body (with its torque), between two moving
bodies (with its reaction).

A friction of magnitude F = mu N (N the constraint's force) acts on `body` against its slip direction
(the direction its centre moves as the `sliding` coordinate grows; for a body on a surface, the
surface's tangent). At a rigid body's `contact` point r (relative to the centre) it also turns the body
with the torque r x F; `against` names the moving body underneath, which feels -F.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import sympy

from physics.engine import tidy
from physics.engine.loads import Traits, View
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.mechanics import Mechanics
    from physics.engine.model import Model


@dataclass(frozen=True)
class Friction:
    """Kinetic friction mu*lambda at a constraint, opposing the slip, which is towards increasing
    `sliding` coordinate. On a rigid body it acts at the `contact` point (relative to the body's centre)
    and so has a torque; with `against`, the surface is that moving body, which feels the reaction."""

    constraint: str
    body: str
    coefficient: sympy.Expr
    sliding: str
    contact: tuple[tuple[str, sympy.Expr], ...] = ()  # (axis, offset from the centre); () at the centre
    against: str | None = None

    def traits(self, model: Model) -> Traits:
        bodies = (self.body,) if self.against is None else (self.body, self.against)
        return Traits(conservative=False, bodies=bodies, dissipates=True, constraints=(self.constraint,))

    def potential(self, mech: Mechanics, place: Mapping[str, sympy.Expr]) -> sympy.Expr:
        return sympy.Integer(0)

    def force(self, mech: Mechanics, view: View) -> list[sympy.Expr]:
        names = [c.name for c in mech.model.constraints]
        normal = view.multipliers[names.index(self.constraint)]
        return self.of_magnitude(mech, self.coefficient * normal)

    def expressions(self) -> tuple[sympy.Expr, ...]:
        return (self.coefficient, *(e for _, e in self.contact))

    def of_magnitude(self, mech: Mechanics, magnitude: sympy.Expr) -> list[sympy.Expr]:
        """The friction of this magnitude on every Cartesian dof (forces on x, y; its torque on phi)."""
        direction = _sliding_direction(mech, self.body, self.sliding)
        loads = [-magnitude * u for u in direction]
        index = {d.name: i for i, d in enumerate(mech.dofs)}
        force = {
            axis: loads[index[f"{axis}_{self.body}"]] for axis in ("x", "y") if f"{axis}_{self.body}" in index
        }
        if self.contact:
            arm = dict(self.contact)
            zero = sympy.Integer(0)
            torque = arm.get("x", zero) * force.get("y", zero) - arm.get("y", zero) * force.get("x", zero)
            loads[index[f"phi_{self.body}"]] += torque
        if self.against is not None:
            for axis, component in force.items():
                name = f"{axis}_{self.against}"
                if name in index:
                    loads[index[name]] -= component
        return loads


def _sliding_direction(mech: Mechanics, body: str, coordinate: str) -> list[sympy.Expr]:
    """Unit vector (over the Cartesian dofs) along which `body` slides as `coordinate` increases."""
    q = mech.model.coordinate(coordinate).symbol
    tangent = [
        sympy.diff(d.mapping, q) if d.body == body and not d.name.startswith("phi_") else sympy.Integer(0)
        for d in mech.dofs
    ]
    norm = tidy.simplify(sympy.sqrt(sympy.Add(*(t**2 for t in tangent))))
    if norm == 0:
        raise DerivationError(f"body {body!r} does not move with coordinate {coordinate!r}")
    return [tidy.simplify(t / norm) for t in tangent]
