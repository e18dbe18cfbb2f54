"""Lagrange's equations in the generalized coordinates, with friction as a generalized force.

Constraint forces do not appear in the reduced Lagrangian; they (and the normal force that friction
needs) come from Newton's second law projected on each constraint's normal, using the accelerations
that Lagrange's equations give.
"""

from __future__ import annotations

from functools import cached_property

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.mechanics import solve_linear, time_derivative
from physics.engine.method import Method, NotApplicable


class LagrangeMethod(Method):
    name = "lagrange"
    title = "Lagrange's equations"

    def derive(self) -> None:
        mech = self.mech
        self.step("Kinetic energy", "T = " + self.tex(tidy.simplify(mech.kinetic)))
        self.step("Potential energy", "V = " + self.tex(tidy.simplify(mech.potential)))

    @cached_property
    def system(self) -> tuple[list[sympy.Expr], list[sympy.Symbol]]:
        """Lagrange's equations (and the constraint-force equations), unsolved: (equations = 0, unknowns)."""
        mech, model = self.mech, self.model
        lagrangian = mech.kinetic - mech.potential
        self.step("Lagrangian", "L = T - V")
        lam = mech.multipliers
        friction = [f + a for f, a in zip(mech.friction_forces(lam), mech.applied_forces(False), strict=True)]
        equations = []
        for c in model.coordinates:
            generalized = sympy.Add(
                *(f * sympy.diff(d.mapping, c.symbol) for f, d in zip(friction, mech.dofs, strict=True))
            )
            el = time_derivative(sympy.diff(lagrangian, c.velocity), model) - sympy.diff(lagrangian, c.symbol)
            equation = sympy.collect(sympy.trigsimp(sympy.expand(el - generalized)), list(mech.qdd))
            self.step(
                f"Lagrange's equation for {c.name}",
                rf"\frac{{d}}{{dt}}\frac{{\partial L}}{{\partial \dot{{{self.tex(c.symbol)}}}}} - "
                rf"\frac{{\partial L}}{{\partial {self.tex(c.symbol)}}} = Q_{{{self.tex(c.symbol)}}}"
                r":\quad " + self.tex(sympy.Eq(equation, 0)),
            )
            equations.append(equation)
        if lam:
            place = mech.cartesian_state()
            applied = [
                -sympy.diff(mech.cartesian_potential, d.symbol) + f
                for d, f in zip(mech.dofs, friction, strict=True)
            ]
            gradients = [[g.subs(place) for g in mech.gap_gradient(k)] for k in range(len(lam))]
            residual = [
                d.inertia * time_derivative(time_derivative(d.mapping, model), model) - a.subs(place)
                for d, a in zip(mech.dofs, applied, strict=True)
            ]
            for grad in gradients:
                lhs = sympy.Add(*(g * r for g, r in zip(grad, residual, strict=True)))
                rhs = sympy.Add(
                    *(
                        lam[j] * sympy.Add(*(a * b for a, b in zip(grad, other, strict=True)))
                        for j, other in enumerate(gradients)
                    )
                )
                equations.append(lhs - rhs)
            self.step(
                "Constraint forces from Newton's law along each constraint normal",
                r"\nabla g_k \cdot (M\ddot{\mathbf{x}} - \mathbf{F}) = \sum_l (\nabla g_k\cdot\nabla g_l)"
                r"\,\lambda_l",
            )
        return equations, [*mech.qdd, *lam]

    @cached_property
    def solution(self) -> dict[sympy.Symbol, sympy.Expr]:
        """Accelerations and constraint multipliers at the model's state."""
        equations, unknowns = self.system
        state = dict(self.model.state)
        solution = solve_linear([e.subs(state) for e in equations], unknowns, self.title)
        self.step("Solved", r",\quad ".join(self.tex(sympy.Eq(k, v)) for k, v in solution.items()))
        return solution

    def acceleration(self, coordinate: str) -> sympy.Expr:
        return self.at_state(self.solution[self.model.coordinate(coordinate).acceleration])

    def force(self, constraint: str) -> sympy.Expr:
        index = [c.name for c in self.model.constraints].index(constraint)
        return self.at_state(self.solution[self.mech.multipliers[index]])

    def potential_force(self, coordinate: str) -> sympy.Expr:
        q = self.model.coordinate(coordinate).symbol
        force = tidy.simplify(-sympy.diff(self.mech.potential, q))
        self.step(
            f"Generalized force on {coordinate}",
            rf"Q_{{{self.tex(q)}}} = -\frac{{\partial V}}{{\partial {self.tex(q)}}} = " + self.tex(force),
        )
        return force

    def mode_matrices(self, point: dict[sympy.Symbol, sympy.Expr]) -> tuple[sympy.Matrix, sympy.Matrix]:
        """Lagrange's equations linearized about the equilibrium: M = d(eq)/d(q''), K = d(eq)/dq at rest."""
        mech = self.mech
        equations = self.system[0][: len(mech.q)]
        rest = {**point, **dict.fromkeys(mech.qd, 0), **dict.fromkeys(mech.qdd, 0)}
        mass = sympy.Matrix(
            [[tidy.simplify(sympy.diff(e, a).subs(rest)) for a in mech.qdd] for e in equations]
        )
        stiffness = sympy.Matrix(
            [[tidy.simplify(sympy.diff(e, q).subs(rest)) for q in mech.q] for e in equations]
        )
        return mass, stiffness

    def frequency(self, coordinate: str, equilibrium: sympy.Expr) -> sympy.Expr:
        """Linearized Lagrange equations M q'' + K q = 0 about the equilibrium: omega^2 = eig(M^-1 K)."""
        mech = self.mech
        q = self.model.coordinate(coordinate).symbol
        at = {q: equilibrium, **{c: 0 for c in mech.q if c != q}}
        stiffness = sympy.hessian(mech.potential, mech.q).subs(at)
        mass = mech.mass_matrix.subs(at)
        omega2 = _single_nonzero_eigenvalue(mass.inv() * stiffness)
        self.step(
            "Small oscillations",
            r"M\ddot{q} + Kq = 0,\ M = "
            + self.tex(mass)
            + r",\ K = "
            + self.tex(tidy.simplify(stiffness))
            + r",\ \omega^2 = "
            + self.tex(omega2),
        )
        return tidy.simplify(sympy.sqrt(omega2))


def _single_nonzero_eigenvalue(matrix: sympy.Matrix) -> sympy.Expr:
    values = [tidy.simplify(v) for v in matrix.eigenvals()]
    nonzero = [v for v in values if v != 0]
    if len(nonzero) != 1:
        raise NotApplicable(f"expected one oscillating mode, found eigenvalues {typed_text(values)}")
    return nonzero[0]
