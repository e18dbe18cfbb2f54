"""Shared building blocks of the methods: Cartesian degrees of freedom, energies, forces, time derivatives.

Coordinates are plain symbols with separate velocity and acceleration symbols; d/dt is the chain rule
over them (`time_derivative`), which keeps every expression free of sympy's Function(t) machinery.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property

import sympy
from sympy.polys.constructor import construct_domain
from sympy.polys.matrices import DomainMatrix
from sympy.polys.matrices.exceptions import DMNonInvertibleMatrixError

from physics import typeset
from physics.engine import tidy as tidy_up
from physics.engine.loads import Traits, View
from physics.engine.model import Model, PairPotential
from physics.engine.notation import Notation, notation_of
from physics.errors import DerivationError


@dataclass(frozen=True)
class CartesianDof:
    """One Cartesian degree of freedom of a body: x, y or the angle phi."""

    body: str
    name: str  # e.g. "x_block"
    symbol: sympy.Symbol
    velocity: sympy.Symbol
    acceleration: sympy.Symbol
    inertia: sympy.Expr  # mass for x and y, moment of inertia for phi
    mapping: sympy.Expr  # the same coordinate in terms of the generalized coordinates


def time_derivative(expr: sympy.Expr, model: Model) -> sympy.Expr:
    """d/dt of an expression in the coordinates, their velocities and the time (a support moving as
    prescribed puts the time in the positions: supports.py)."""
    result = sympy.diff(expr, model.time) if model.time is not None else sympy.Integer(0)
    for c in model.coordinates:
        result += sympy.diff(expr, c.symbol) * c.velocity + sympy.diff(expr, c.velocity) * c.acceleration
    return result


class Mechanics:
    """The model's energies and forces in both descriptions (generalized and Cartesian)."""

    def __init__(self, model: Model) -> None:
        self.model = model

    @cached_property
    def dofs(self) -> tuple[CartesianDof, ...]:
        result: list[CartesianDof] = []
        for body in self.model.bodies:
            entries: list[tuple[str, sympy.Expr, sympy.Expr]] = [
                (f"{axis}_{body.name}", body.mass, expr) for axis, expr in body.position
            ]
            if body.angle is not None:
                entries.append((f"phi_{body.name}", body.inertia, body.angle))
            for name, inertia, mapping in entries:
                result.append(
                    CartesianDof(
                        body.name,
                        name,
                        self.model.cartesian_symbol(name),
                        sympy.Symbol(f"v_{name}", real=True),
                        sympy.Symbol(f"a_{name}", real=True),
                        inertia,
                        mapping,
                    )
                )
        return tuple(result)

    @cached_property
    def q(self) -> tuple[sympy.Symbol, ...]:
        return tuple(c.symbol for c in self.model.coordinates)

    @cached_property
    def qd(self) -> tuple[sympy.Symbol, ...]:
        return tuple(c.velocity for c in self.model.coordinates)

    @cached_property
    def qdd(self) -> tuple[sympy.Symbol, ...]:
        return tuple(c.acceleration for c in self.model.coordinates)

    @cached_property
    def multipliers(self) -> tuple[sympy.Symbol, ...]:
        return tuple(sympy.Symbol(f"lambda_{c.name}", real=True) for c in self.model.constraints)

    @cached_property
    def notation(self) -> Notation:
        return notation_of(self.model)

    @cached_property
    def latex_names(self) -> dict[sympy.Symbol, str]:
        """How the engine's own symbols are written in worked solutions: the coordinates, each body's
        x, y and angle, and the constraint forces by their physical names (notation.py)."""
        return self.notation.tex_names(self.model)

    # --- generalized description -------------------------------------------------------------

    @cached_property
    def kinetic(self) -> sympy.Expr:
        """T = sum of 1/2 m v^2 and 1/2 I omega^2, velocities from the positions in the coordinates."""
        terms: dict[tuple[str, bool], sympy.Expr] = {}
        for d in self.dofs:
            key = (d.body, d.name.startswith("phi_"))
            term = sympy.Rational(1, 2) * d.inertia * time_derivative(d.mapping, self.model) ** 2
            terms[key] = terms.get(key, sympy.Integer(0)) + term
        # a body's v^2 in polar-like positions is (r' cos - r theta' sin)^2 + (r' sin + r theta' cos)^2:
        # simplified per body here, before every method expands it
        return sympy.Add(
            *(sympy.trigsimp(sympy.expand(t)) if t.has(sympy.sin, sympy.cos) else t for t in terms.values())
        )

    @cached_property
    def potential(self) -> sympy.Expr:
        """V in the generalized coordinates: the loads' potential energies at the mapped positions."""
        by_name = {d.name: d.mapping for d in self.dofs}
        return self._potential(by_name)

    @cached_property
    def mass_matrix(self) -> sympy.Matrix:
        return sympy.Matrix(
            [[sympy.expand(sympy.diff(self.kinetic, a, b)) for b in self.qd] for a in self.qd]
        )

    # --- Cartesian description ---------------------------------------------------------------

    @cached_property
    def cartesian_potential(self) -> sympy.Expr:
        return self._potential({d.name: d.symbol for d in self.dofs})

    def cartesian_state(self) -> dict[sympy.Symbol, sympy.Expr]:
        """Cartesian positions and velocities of the current configuration, from the mapping."""
        result: dict[sympy.Symbol, sympy.Expr] = {}
        for d in self.dofs:
            result[d.symbol] = d.mapping
            result[d.velocity] = time_derivative(d.mapping, self.model)
        return result

    def gap_gradient(self, index: int) -> list[sympy.Expr]:
        gap = self.model.constraints[index].gap
        return [sympy.diff(gap, d.symbol) for d in self.dofs]

    def load_forces(
        self,
        cartesian: bool,
        multipliers: Sequence[sympy.Expr],
        which: Callable[[Traits], bool] = lambda traits: True,
    ) -> list[sympy.Expr]:
        """The loads' forces on each Cartesian dof beyond their potentials (kinetic friction at the given
        constraint forces, drag, forces in the coordinates, velocities or time), of the loads `which`
        selects by their traits. Velocities are the Cartesian velocity symbols (`cartesian`, Newton's
        view) or the time derivatives of the positions in the coordinates (Lagrange's)."""
        view = View(cartesian, multipliers)
        total = [sympy.Integer(0) for _ in self.dofs]
        for load in self.model.loads:
            if which(load.traits(self.model)):
                total = [t + f for t, f in zip(total, load.force(self, view), strict=True)]
        return total

    def given_at_rest(self) -> list[sympy.Expr]:
        """The generalized forces, with every velocity zero, of the given forces that have no potential
        (a force or torque written in the coordinates: a spring on a string's free end as a torque k R s):
        a rest is where they balance the potential's force too. Drag vanishes at rest; kinetic friction is
        not taken there."""
        forces = self.load_forces(
            False,
            [sympy.Integer(0)] * len(self.model.constraints),
            lambda traits: not (traits.conservative or traits.dissipates or traits.constraints),
        )
        rest = dict.fromkeys(self.qd, sympy.Integer(0))
        return [f.subs(rest) for f in self.generalized(forces)]

    def velocity_of(self, dof: CartesianDof) -> sympy.Expr:
        """A Cartesian dof's velocity in the coordinates and their velocities."""
        return time_derivative(dof.mapping, self.model)

    def generalized(self, forces: Sequence[sympy.Expr]) -> list[sympy.Expr]:
        """Generalized forces Q_j = sum_i F_i dx_i/dq_j of forces on the Cartesian dofs."""
        return [
            sympy.Add(*(f * sympy.diff(d.mapping, q) for f, d in zip(forces, self.dofs, strict=True)))
            for q in self.q
        ]

    # --- shared ------------------------------------------------------------------------------

    def _potential(self, place: Mapping[str, sympy.Expr]) -> sympy.Expr:
        return sympy.Add(*(load.potential(self, place) for load in self.model.loads))

    def distance(self, pair: PairPotential, place: Mapping[str, sympy.Expr]) -> sympy.Expr:
        """The length between a pair potential's bodies (or body and anchor) at `place`."""
        return pair.length(self.model, place)


def solve_linear(
    equations: Sequence[sympy.Expr],
    unknowns: Sequence[sympy.Symbol],
    what: str,
    tidy: Callable[[sympy.Expr], sympy.Expr] = tidy_up.simplify,
) -> dict[sympy.Symbol, sympy.Expr]:
    """The unique solution of linear equations (each `= 0`), each value put through `tidy`;
    DerivationError if there is none."""
    matrix, rhs = sympy.linear_eq_to_matrix(list(equations), list(unknowns))
    if matrix.shape[0] > matrix.shape[1]:
        rows = _independent_rows(matrix)
        matrix, rhs = matrix.extract(rows, list(range(matrix.shape[1]))), rhs.extract(rows, [0])
    if matrix.shape[0] != matrix.shape[1]:
        raise DerivationError(f"{what}: the equations do not determine {', '.join(map(str, unknowns))}")
    try:
        solution = solve_square(matrix, rhs)
    except (ValueError, ZeroDivisionError, DMNonInvertibleMatrixError) as error:
        raise DerivationError(
            f"{what}: the equations do not determine {', '.join(map(str, unknowns))} ({error})"
        ) from error
    result = {u: tidy(v) for u, v in zip(unknowns, solution, strict=True)}
    if any(v.has(sympy.zoo, sympy.nan, sympy.oo) for v in result.values()):
        raise DerivationError(f"{what}: the equations are singular for {', '.join(map(str, unknowns))}")
    return result


def solve_square(matrix: sympy.Matrix, rhs: sympy.Matrix) -> list[sympy.Expr]:
    """matrix * x = rhs, eliminated over the field of fractions in the entries' symbols and functions
    (sin(theta) and cos(theta) as independent generators), each step cancelled: one reduced fraction per
    unknown, which `tidy` simplifies in a fraction of the time it takes on LUsolve's nested quotients.
    The reduced fraction is the unique solution, so it is the same function as LUsolve's."""
    domain, elements = construct_domain([*matrix, *rhs], field=True, composite=True)
    if not domain.is_Exact:  # floats: cancelling over an approximate field can lose terms
        return list(matrix.LUsolve(rhs))
    rows, columns = matrix.shape
    left = DomainMatrix(
        [elements[r * columns : (r + 1) * columns] for r in range(rows)], (rows, columns), domain
    )
    right = DomainMatrix([[e] for e in elements[rows * columns :]], (rows, 1), domain)
    return list(left.lu_solve(right).to_Matrix())


def rates_giving(
    jacobian: sympy.Matrix,
    cartesian: Sequence[sympy.Expr],
    what: str,
    tidy: Callable[[sympy.Expr], sympy.Expr] = tidy_up.simplify,
) -> list[sympy.Expr]:
    """The coordinates' velocities that give these Cartesian velocities, `jacobian` being d(dof)/d(q)
    where they are taken (the constraints hold, so the Cartesian velocities determine them)."""
    rates = [sympy.Symbol(f"rate_{j}", real=True) for j in range(jacobian.shape[1])]
    equations = [
        sympy.Add(*(jacobian[i, j] * r for j, r in enumerate(rates))) - value
        for i, value in enumerate(cartesian)
    ]
    solved = solve_linear(equations, rates, what, tidy=tidy)
    return [solved[r] for r in rates]


def _independent_rows(matrix: sympy.Matrix) -> list[int]:
    chosen: list[int] = []
    for row in range(matrix.shape[0]):
        trial = [*chosen, row]
        if matrix.extract(trial, list(range(matrix.shape[1]))).rank(simplify=True) == len(trial):
            chosen.append(row)
    return chosen


def cartesian_subscript(dof: str) -> str:
    """A Cartesian degree of freedom's subscript in a worked solution: `x_block` is x,block; `phi_disk`
    is φ,disk."""
    axis, _, body = dof.partition("_")
    written = typeset.latex(sympy.Symbol(axis))
    return rf"{written},\mathrm{{{body}}}" if body else written
