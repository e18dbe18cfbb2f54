"""Loads: everything that pushes on the bodies besides the constraints, as one list the methods consume.

As in `sympy.physics.mechanics`, where KanesMethod and LagrangesMethod take a list of (point or frame,
force or torque) loads, every method here (Newton with constraint forces, Lagrange, work and energy,
d'Alembert, the simulation) reads `Model.loads` through this protocol and never asks which section of
the model a load came from. A load gives

- its potential energy, if it has one (`potential`): gravity, a pair potential, a constant force;
- its force on each Cartesian degree of freedom otherwise (`force`): forces on x and y, torques on the
  angle; Lagrange turns them into generalized forces (F . dr/dq), Newton uses them as they are;
- its `traits`: whether it keeps the mechanical energy, dissipates it, needs a constraint's force
  (kinetic friction is mu N), is viscous drag (-b v), and which bodies it acts on.

A new kind of load is one module: a class with these methods and, for an entry of the model's `forces:`
section (`{body: wheel, torque: tau}`), a `read` function registered under its key in
`physics.engine.loads.entries` (`torque.py` is the example).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol

import sympy

from physics.dimensions import Dimension
from physics.engine.text import Path

if TYPE_CHECKING:
    from physics.engine.mechanics import Mechanics
    from physics.engine.model import Body, Model


@dataclass(frozen=True)
class Traits:
    """What the methods need to know of a load beyond its forces and energy."""

    conservative: bool  # its whole effect is its potential energy: it keeps T + V
    bodies: tuple[str, ...]  # the bodies it acts on
    dissipates: bool = False  # its power is never positive (drag, kinetic friction)
    viscous: bool = False  # linear drag -b v: oscillations under it decay exponentially
    constraints: tuple[str, ...] = ()  # constraints whose force sets its size (kinetic friction: mu N)


@dataclass(frozen=True)
class View:
    """How a method reads what a load's force depends on: the bodies' velocities as the Cartesian
    velocity symbols (`cartesian`, Newton's view) or as the time derivatives of the positions in the
    coordinates (Lagrange's), and the constraint forces (`multipliers`, in the model's constraint order)."""

    cartesian: bool
    multipliers: Sequence[sympy.Expr]


class Load(Protocol):
    def traits(self, model: Model) -> Traits:
        """Its traits in this model (a given force is conservative when it is constant)."""
        ...

    def potential(self, mech: Mechanics, place: Mapping[str, sympy.Expr]) -> sympy.Expr:
        """Its potential energy with the bodies' Cartesian coordinates (`x_<body>`, ...) at `place`;
        0 for a load without one."""
        ...

    def force(self, mech: Mechanics, view: View) -> list[sympy.Expr]:
        """Its force on each of `mech.dofs` that its potential does not already give (x, y; a torque on
        an angle)."""
        ...

    def expressions(self) -> tuple[sympy.Expr, ...]:
        """Every expression it holds: which parameters (and the time) it depends on."""
        ...


class ForceEntryLoad(Load, Protocol):
    """A load given as an entry of the `forces:` section: it also says what dimension each of its
    expressions has (checked when the problem declares its symbols' dimensions)."""

    def dimensions(self, path: Path) -> list[tuple[Path, sympy.Expr, Dimension]]:
        """(path of the expression inside the model section, expression, expected dimension)."""
        ...


@dataclass(frozen=True)
class Entry:
    """What the reader of a `forces:` entry kind is handed: the entry's body, the value under its kind's
    key and that value's path, and the loader's ways to read expressions and report faults."""

    body: Body
    value: Any
    path: Path
    expression: Callable[[Any, Path], sympy.Expr | None]  # in the parameters, coordinates, q_dot and t
    parameter: Callable[[Any, Path], sympy.Expr | None]  # in the parameters alone (a coefficient)
    axes: Callable[[Any, Path], tuple[tuple[str, sympy.Expr], ...]]  # {x: ..., y: ...} as `expression`
    error: Callable[[str, Path], None]


MASS = Dimension({"mass": 1})
LENGTH = Dimension({"length": 1})
TIME = Dimension({"time": 1})
FORCE = MASS * LENGTH / TIME**2


def nothing(mech: Mechanics) -> list[sympy.Expr]:
    """No force on any dof: what a load whose effect is its potential returns from `force`."""
    return [sympy.Integer(0) for _ in mech.dofs]


def on_body(mech: Mechanics, body: str, components: Mapping[str, sympy.Expr]) -> list[sympy.Expr]:
    """A force on a body's centre, by axis ("x", "y", and "phi" for a torque), spread over the dofs."""
    return [
        components.get(d.name.split("_", 1)[0], sympy.Integer(0)) if d.body == body else sympy.Integer(0)
        for d in mech.dofs
    ]
