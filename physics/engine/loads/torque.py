"""A torque on a rigid body's angle: `forces: [{body: wheel, torque: tau}]` (counter-clockwise positive).

The example of a load kind added as one module. A constant torque has the potential -tau phi; one given
in the coordinates, their velocities (`phi_dot`) or the time has none, and enters Lagrange's equations as
the generalized force tau d(phi)/dq and Newton's law on the body's angle as it is.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import sympy

from physics.dimensions import Dimension
from physics.engine.loads import FORCE, LENGTH, Entry, Traits, View, nothing, on_body
from physics.engine.text import Path

if TYPE_CHECKING:
    from physics.engine.mechanics import Mechanics
    from physics.engine.model import Model

KEY = "torque"


@dataclass(frozen=True)
class Torque:
    body: str
    torque: sympy.Expr

    def constant(self, model: Model) -> bool:
        return not self.torque.free_symbols & model.moving_symbols

    def traits(self, model: Model) -> Traits:
        return Traits(conservative=self.constant(model), bodies=(self.body,))

    def potential(self, mech: Mechanics, place: Mapping[str, sympy.Expr]) -> sympy.Expr:
        angle = place.get(f"phi_{self.body}")
        if angle is None or not self.constant(mech.model):
            return sympy.Integer(0)
        return -self.torque * angle

    def force(self, mech: Mechanics, view: View) -> list[sympy.Expr]:
        if self.constant(mech.model):
            return nothing(mech)
        return on_body(mech, self.body, {"phi": self.torque})

    def expressions(self) -> tuple[sympy.Expr, ...]:
        return (self.torque,)

    def dimensions(self, path: Path) -> list[tuple[Path, sympy.Expr, Dimension]]:
        return [((*path, KEY), self.torque, FORCE * LENGTH)]


def read(key: str, entry: Entry) -> Torque | None:
    if entry.body.angle is None:
        entry.error("a torque turns a rigid body: give the body an `angle` (and an `inertia`)", entry.path)
        return None
    torque = entry.expression(entry.value, entry.path)
    return Torque(entry.body.name, torque) if torque is not None else None
