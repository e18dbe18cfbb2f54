"""A potential energy U(d) of the distance d between two bodies, or a body and a fixed anchor (a spring,
an interatomic potential, a central force)."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import sympy

from physics.engine.loads import Traits, View, nothing
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.mechanics import Mechanics
    from physics.engine.model import Model


@dataclass(frozen=True)
class PairPotential:
    name: str
    bodies: tuple[str, ...]
    anchor: tuple[tuple[str, sympy.Expr], ...]
    energy: sympy.Expr
    distance: sympy.Symbol
    # On one shared axis the length is |b - a|; +1/-1 says which sign b - a keeps on the model's domain,
    # 0 that the energy is even in the distance (the sign does not matter). Set by `load_model`.
    side: int = 1
    # the distance beyond which it lets go (an unattached spring's natural length: it only pushes);
    # None: it acts at every distance (buffers.py checks the motion stays within it)
    reach: sympy.Expr | None = None

    def traits(self, model: Model) -> Traits:
        return Traits(conservative=True, bodies=self.bodies)

    def potential(self, mech: Mechanics, place: Mapping[str, sympy.Expr]) -> sympy.Expr:
        return self.energy.subs(self.distance, self.length(mech.model, place))

    def force(self, mech: Mechanics, view: View) -> list[sympy.Expr]:
        return nothing(mech)

    def expressions(self) -> tuple[sympy.Expr, ...]:
        return (self.energy, *(e for _, e in self.anchor))

    def length(self, model: Model, place: Mapping[str, sympy.Expr]) -> sympy.Expr:
        """The length between the bodies (or body and anchor): Euclidean on several axes; on one axis
        |b - a| with its sign resolved when the model was loaded (`side`)."""
        first = model.body(self.bodies[0])
        if len(self.bodies) == 2:
            second = model.body(self.bodies[1])
            axes = [a for a, _ in first.position if any(b == a for b, _ in second.position)]
            ends = [(place[f"{a}_{first.name}"], place[f"{a}_{second.name}"]) for a in axes]
        else:
            anchor = dict(self.anchor)
            axes = [a for a, _ in first.position if a in anchor]
            ends = [(anchor[a], place[f"{a}_{first.name}"]) for a in axes]
        if not ends:
            raise DerivationError(f"the bodies of {self.bodies} share no axis")
        if len(ends) == 1:
            return (self.side or 1) * (ends[0][1] - ends[0][0])
        squared = sympy.Add(*((b - a) ** 2 for a, b in ends))
        if squared.has(sympy.sin, sympy.cos):  # polar positions: r^2 cos^2 + r^2 sin^2 is r^2
            squared = sympy.trigsimp(squared)
        from physics.engine.settle import settle  # here: settle builds on the model, which holds this

        # along a slope the length is |s - D|: the side the declared range gives, as on one axis
        return settle(sympy.sqrt(squared), model)
