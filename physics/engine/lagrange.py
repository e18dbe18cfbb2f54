"""Lagrange's equations in the generalized coordinates, with friction as a generalized force.

Constraint forces do not appear in the reduced Lagrangian; they (and the normal force that friction
needs) come from Newton's second law projected on each constraint's normal, using the accelerations
that Lagrange's equations give.
"""

from __future__ import annotations

from functools import cached_property

import sympy

from physics.engine import modes, tidy
from physics.engine.mechanics import solve_linear, time_derivative
from physics.engine.method import Method, NotApplicable
from physics.engine.results import StepKind
from physics.engine.supports import NOT_STEADY, driven
from physics.wording import the_counted


class LagrangeMethod(Method):
    name = "lagrange"
    title = "Lagrange's equations"

    def derive(self) -> None:
        mech, letters = self.mech, self.mech.notation.letters
        self.step("Kinetic energy", f"{letters.kinetic} = " + self.tex(tidy.simplify(mech.kinetic)))
        self.step("Potential energy", f"{letters.potential} = " + self.tex(tidy.simplify(mech.potential)))

    @cached_property
    def system(self) -> tuple[list[sympy.Expr], list[sympy.Symbol]]:
        """Lagrange's equations (and the constraint-force equations), unsolved: (equations = 0, unknowns)."""
        mech, model = self.mech, self.model
        lagrangian = mech.kinetic - mech.potential
        letters = mech.notation.letters
        self.step("The Lagrangian", f"{letters.lagrangian} = {letters.kinetic} - {letters.potential}")
        lam = mech.multipliers
        friction = mech.load_forces(False, lam)
        equations = []
        for c in model.coordinates:
            generalized = sympy.Add(
                *(f * sympy.diff(d.mapping, c.symbol) for f, d in zip(friction, mech.dofs, strict=True))
            )
            el = time_derivative(sympy.diff(lagrangian, c.velocity), model) - sympy.diff(lagrangian, c.symbol)
            equation = sympy.collect(sympy.trigsimp(sympy.expand(el - generalized)), list(mech.qdd))
            q, lag = self.tex(c.symbol), letters.lagrangian
            source = rf"{letters.generalized}_{{{q}}}" if generalized != 0 else "0"
            self.step(
                f"Lagrange's equation for {self.named(c.name)}"
                + (" (the generalized force of friction or drag on the right)" if generalized != 0 else ""),
                rf"\frac{{\mathrm{{d}}}}{{\mathrm{{d}}t}}\frac{{\partial {lag}}}{{\partial {self.tex(c.velocity)}}} - "
                rf"\frac{{\partial {lag}}}{{\partial {q}}} = {source}"
                r":\quad " + self.tex(sympy.Eq(equation, 0)),
                StepKind.EQUATION,
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
            self._show_force_equations(applied, gradients, place)
        return equations, [*mech.qdd, *lam]

    def _show_force_equations(
        self,
        applied: list[sympy.Expr],
        gradients: list[list[sympy.Expr]],
        place: dict[sympy.Symbol, sympy.Expr],
    ) -> None:
        """Newton's second law for as many body axes as there are constraint forces, chosen so that they
        determine them, with the accelerations written in the coordinates: the textbook's way to the
        forces once Lagrange's equations give the motion (solved as their projections on the
        constraints' normals, which are the same equations combined)."""
        mech, model = self.mech, self.model
        chosen: list[int] = []
        for index in range(len(mech.dofs)):
            rows = [[gradients[k][i] for k in range(len(gradients))] for i in [*chosen, index]]
            if sympy.Matrix(rows).rank(simplify=True) == len(chosen) + 1:
                chosen.append(index)
            if len(chosen) == len(gradients):
                break
        for index in chosen:
            d = mech.dofs[index]
            pulls = sympy.Add(
                *(lam * grad[index] for lam, grad in zip(mech.multipliers, gradients, strict=True))
            )
            acceleration = tidy.simplify(time_derivative(time_derivative(d.mapping, model), model))
            named = [
                self.force_named(c.name)
                for c, grad in zip(model.constraints, gradients, strict=True)
                if grad[index] != 0
            ]
            self.step(
                f"Newton's second law for «{d.body}», {self.along(d.name)}, with "
                f"${self.tex(d.acceleration)} = {self.tex(acceleration)}$ from the coordinates: "
                f"it gives {' and '.join(named)}",
                self.tex(
                    sympy.Eq(d.inertia * acceleration, tidy.simplify(applied[index].subs(place)) + pulls)
                ),
                StepKind.EQUATION,
            )

    @cached_property
    def solution(self) -> dict[sympy.Symbol, sympy.Expr]:
        """Accelerations and constraint multipliers at the model's state."""
        equations, unknowns = self.system
        state = dict(self.model.state)
        solution = solve_linear([e.subs(state) for e in equations], unknowns, self.title)
        self.step(
            f"Solved: {the_counted(len(equations), 'equation')} for {the_counted(len(unknowns), 'unknown')}",
            r",\quad ".join(self.tex(sympy.Eq(k, v)) for k, v in solution.items()),
            StepKind.SOLVE,
            unknowns,
        )
        return solution

    def acceleration(self, coordinate: str) -> sympy.Expr:
        return self.at_state(self.solution[self.model.coordinate(coordinate).acceleration])

    def force(self, constraint: str) -> sympy.Expr:
        index = [c.name for c in self.model.constraints].index(constraint)
        return self.at_state(self.solution[self.mech.multipliers[index]])

    def _at_rest(self) -> list[sympy.Expr]:
        """Lagrange's equations at rest (q' = q'' = 0): with a support moving as prescribed they keep its
        acceleration, which must not depend on the time for the system to rest relative to it."""
        mech = self.mech
        rest = {**dict.fromkeys(mech.qd, 0), **dict.fromkeys(mech.qdd, 0)}
        if self.model.contact_loads:
            raise NotApplicable("kinetic friction on a moving support is not treated at rest")
        equations = [tidy.simplify(e.subs(rest)) for e in self.system[0][: len(mech.q)]]
        if any(self.model.time in e.free_symbols for e in equations):
            raise NotApplicable(NOT_STEADY)
        return equations

    def potential_force(self, coordinate: str) -> sympy.Expr:
        q = self.model.coordinate(coordinate).symbol
        letters = self.mech.notation.letters
        if driven(self.model):
            index = list(self.mech.q).index(q)
            force = tidy.simplify(-self._at_rest()[index])
            self.step(
                f"Generalized force on {self.named(coordinate)} at rest relative to the moving support "
                "(Lagrange's equation with the velocities and accelerations of the coordinates zero)",
                rf"{letters.generalized}_{{{self.tex(q)}}} = " + self.tex(force),
            )
            return force
        given = self.mech.given_at_rest()[list(self.mech.q).index(q)]
        force = tidy.simplify(-sympy.diff(self.mech.potential, q) + given)
        self.step(
            f"Generalized force on {self.named(coordinate)}"
            + (" (the potential's, and the given forces' at rest)" if given != 0 else ""),
            rf"{letters.generalized}_{{{self.tex(q)}}} = -\frac{{\partial {letters.potential}}}"
            rf"{{\partial {self.tex(q)}}}"
            + (" + " + self.tex(given) if given != 0 else "")
            + " = "
            + self.tex(force),
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

    def mode_unknowns(self) -> list[sympy.Basic]:
        return list(self.system[1])

    def frequency(self, coordinate: str, equilibrium: sympy.Expr) -> sympy.Expr:
        """Linearized Lagrange equations M q'' + K q = 0 about the equilibrium: omega^2 = eig(M^-1 K)."""
        mech = self.mech
        q = self.model.coordinate(coordinate).symbol
        at = {**self.rest(coordinate), q: equilibrium}
        if driven(self.model):  # Lagrange's equations linearized about the rest relative to the support
            self._at_rest()
            mass, stiffness = self.mode_matrices(at)
        else:  # the given forces without a potential stiffen it too: K = V'' - dQ/dq
            given = sympy.Matrix(mech.given_at_rest())
            stiffness = (sympy.hessian(mech.potential, mech.q) - given.jacobian(mech.q)).subs(at)
            mass = mech.mass_matrix.subs(at)
        block = modes.coupled([mass, stiffness], list(mech.q).index(q))  # other, uncoupled systems apart
        values = [
            tidy.simplify(v)
            for v in (mass.extract(block, block).inv() * stiffness.extract(block, block)).eigenvals()
        ]
        nonzero = [v for v in values if v != 0]
        if len(nonzero) != 1:
            partners = [str(mech.q[j]) for j in block if mech.q[j] != q]
            raise NotApplicable(modes.no_single_mode(values, coordinate, partners))
        omega2 = nonzero[0]
        self.step(
            "Small oscillations: the mass matrix $\\mathbf{M}$ and stiffness matrix $\\mathbf{K}$",
            r"\mathbf{M}\ddot{\mathbf{q}} + \mathbf{K}\mathbf{q} = 0,\ \mathbf{M} = "
            + self.tex(mass.applyfunc(sympy.factor))
            + r",\ \mathbf{K} = "
            + self.tex(tidy.simplify(stiffness).applyfunc(sympy.factor))
            + r",\ \omega^2 = "
            + self.tex(omega2),
        )
        return tidy.simplify(sympy.sqrt(omega2))
