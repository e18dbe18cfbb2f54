"""Newton's second law for every body and axis in Cartesian coordinates, constraint forces unknown.

Each constraint gap g(x) = 0 acts on the bodies with the force lambda * grad g (the multiplier is the
force's magnitude when the gap is written as a clearance); its second time derivative vanishing
closes the system. Nothing here uses the Lagrangian: the generalized coordinates only say where the
bodies are now, and turn Cartesian accelerations back into coordinate accelerations.
"""

from __future__ import annotations

from functools import cached_property

import sympy

from physics.engine import collision, modes, tidy
from physics.engine.frames import centripetal_accelerations
from physics.engine.mechanics import solve_linear, time_derivative
from physics.engine.method import Method, NotApplicable
from physics.engine.model import Quantity
from physics.engine.results import StepKind
from physics.engine.supports import driven
from physics.wording import the_counted


class NewtonMethod(Method):
    name = "newton"
    title = "Newton's laws with the constraint forces as unknowns"

    def derive(self) -> None:
        mech = self.mech
        applied = self.applied_forces
        frame = self.model.frame
        if frame is not None and frame.rate is not None and any(c != 0 for c in self.centripetal):
            self.step(
                "In the ground's frame the turning bodies accelerate towards the axis",
                r"a_x = \ddot{x} - \left("
                + self.tex(frame.rate)
                + r"\right)^2 (x - "
                + self.tex(frame.axis)
                + ")",
            )
        for d, force, centripetal in zip(mech.dofs, applied, self.centripetal, strict=True):
            constraint_terms = sympy.Add(
                *(
                    lam * g
                    for lam, g in zip(
                        mech.multipliers,
                        (sympy.diff(c.gap, d.symbol) for c in self.model.constraints),
                        strict=True,
                    )
                )
            )
            self.step(
                f"Newton's second law for «{d.body}», {self.along(d.name)}",
                self.tex(sympy.Eq(d.inertia * (d.acceleration + centripetal), force + constraint_terms)),
                StepKind.EQUATION,
            )
        for constraint in self.model.constraints:
            self.step(
                f"Constraint: {self.mech.notation.conditions[constraint.name]}",
                self.tex(sympy.Eq(constraint.gap, 0)),
            )

    @cached_property
    def centripetal(self) -> list[sympy.Expr]:
        return centripetal_accelerations(self.model, self.mech)

    @cached_property
    def applied_forces(self) -> list[sympy.Expr]:
        """The loads: -grad V in Cartesian coordinates plus the forces without a potential; a turning
        frame's centrifugal potential stands for the centripetal acceleration (moved to the left side)."""
        mech = self.mech
        loads = mech.load_forces(True, mech.multipliers)
        return [
            -sympy.diff(mech.cartesian_potential, d.symbol) + f + d.inertia * c
            for d, f, c in zip(mech.dofs, loads, self.centripetal, strict=True)
        ]

    @cached_property
    def solution(self) -> dict[sympy.Symbol, sympy.Expr]:
        """Cartesian accelerations and multipliers at the model's state."""
        mech, model = self.mech, self.model
        equations: list[sympy.Expr] = []
        for d, force, centripetal in zip(mech.dofs, self.applied_forces, self.centripetal, strict=True):
            constraint_terms = sympy.Add(
                *(
                    lam * sympy.diff(c.gap, d.symbol)
                    for lam, c in zip(mech.multipliers, model.constraints, strict=True)
                )
            )
            equations.append(d.inertia * (d.acceleration + centripetal) - force - constraint_terms)
        for c in model.constraints:
            gradient = [sympy.diff(c.gap, d.symbol) for d in mech.dofs]
            second = sympy.Add(*(g * d.acceleration for g, d in zip(gradient, mech.dofs, strict=True)))
            second += sympy.Add(
                *(
                    sympy.diff(c.gap, a.symbol, b.symbol) * a.velocity * b.velocity
                    for a in mech.dofs
                    for b in mech.dofs
                )
            )
            if model.time is not None and model.time in c.gap.free_symbols:  # a support moving as prescribed
                t = model.time
                second += 2 * sympy.Add(*(sympy.diff(c.gap, a.symbol, t) * a.velocity for a in mech.dofs))
                second += sympy.diff(c.gap, t, 2)
            self.step(
                f"Constraint ({self.mech.notation.conditions[c.name]}) differentiated twice in time, "
                "for the accelerations",
                self.tex(sympy.Eq(second, 0)),
                StepKind.EQUATION,
            )
            equations.append(second)
        place = mech.cartesian_state()
        state = dict(model.state)
        equations = [e.subs(place).subs(state) for e in equations]
        unknowns = [d.acceleration for d in mech.dofs] + list(mech.multipliers)
        solution = solve_linear(equations, unknowns, self.title)
        self.step(
            f"Solved: {the_counted(len(equations), 'equation')} for {the_counted(len(unknowns), 'unknown')}, the accelerations and the "
            "constraint forces",
            r",\quad ".join(self.tex(sympy.Eq(k, v)) for k, v in solution.items()),
            StepKind.SOLVE,
            unknowns,
        )
        return solution

    @cached_property
    def coordinate_accelerations(self) -> dict[sympy.Symbol, sympy.Expr]:
        """q'' from the Cartesian accelerations: a = d2x/dt2 (q), solved in the least-squares sense."""
        mech, model = self.mech, self.model
        state = dict(model.state)
        jac = sympy.Matrix([[sympy.diff(d.mapping, q) for q in mech.q] for d in mech.dofs]).subs(state)
        rest = sympy.Matrix(
            [
                (
                    time_derivative(time_derivative(d.mapping, model), model).subs(dict.fromkeys(mech.qdd, 0))
                ).subs(state)
                for d in mech.dofs
            ]
        )
        measured = sympy.Matrix([self.solution[d.acceleration] for d in mech.dofs])
        normal = jac.T * jac
        if normal.det() == 0:
            raise NotApplicable("the coordinates are not determined by the Cartesian positions")
        qdd = normal.inv() * jac.T * (measured - rest)
        return dict(zip(mech.qdd, qdd, strict=True))

    def acceleration(self, coordinate: str) -> sympy.Expr:
        return self.at_state(self.coordinate_accelerations[self.model.coordinate(coordinate).acceleration])

    def force(self, constraint: str) -> sympy.Expr:
        index = [c.name for c in self.model.constraints].index(constraint)
        return self.at_state(self.solution[self.mech.multipliers[index]])

    def potential_force(self, coordinate: str) -> sympy.Expr:
        """Virtual work of the Cartesian forces of the potentials: Q = sum F_i dx_i/dq."""
        if driven(self.model):
            raise NotApplicable(
                "at rest relative to a moving support the bodies still accelerate with it: the forces "
                "alone do not balance (d'Alembert's inertial forces do)"
            )
        mech = self.mech
        q = self.model.coordinate(coordinate).symbol
        place = mech.cartesian_state()
        force = sympy.Add(
            *(
                (-sympy.diff(mech.cartesian_potential, d.symbol)).subs(place) * sympy.diff(d.mapping, q)
                for d in mech.dofs
            )
        )
        force = tidy.simplify(force + mech.given_at_rest()[list(mech.q).index(q)])
        self.step(
            f"Virtual work of the forces along {self.named(coordinate)}",
            rf"{self.mech.notation.letters.generalized}_{{{self.tex(q)}}} = \sum_i F_i "
            rf"\frac{{\partial x_i}}{{\partial {self.tex(q)}}} = " + self.tex(force),
        )
        return force

    def frequency(self, coordinate: str, equilibrium: sympy.Expr) -> sympy.Expr:
        """Linearized Cartesian equations m x'' = -K x (no constraints): omega^2 from eig(M^-1 K)."""
        mech = self.mech
        if self.model.constraints:
            raise NotApplicable("Cartesian small oscillations are done here only without constraints")
        if any(g != 0 for g in mech.given_at_rest()):
            raise NotApplicable("a given force in the coordinates has no Cartesian stiffness matrix here")
        q = self.model.coordinate(coordinate).symbol
        at = {**self.rest(coordinate), q: equilibrium}
        point = {d.symbol: d.mapping.subs(at) for d in mech.dofs}
        symbols = [d.symbol for d in mech.dofs]
        stiffness = sympy.hessian(mech.cartesian_potential, symbols).subs(point)
        mass = sympy.diag(*[d.inertia for d in mech.dofs])
        moved = [i for i, d in enumerate(mech.dofs) if sympy.diff(d.mapping, q) != 0]
        block = sorted({j for i in moved for j in modes.coupled([stiffness], i)})  # other systems apart
        values = [tidy.simplify(v) for v in (mass.inv() * stiffness).extract(block, block).eigenvals()]
        nonzero = [v for v in values if v != 0]
        if len(nonzero) != 1:
            partners = [d.name for j, d in enumerate(mech.dofs) if j in block and j not in moved]
            raise NotApplicable(modes.no_single_mode(values, coordinate, partners))
        self.step(
            "Small oscillations of the Cartesian equations ($\\mathbf{K}$: the stiffness matrix)",
            r"\mathbf{M}\ddot{\mathbf{x}} = -\mathbf{K}\mathbf{x},\ \mathbf{K} = "
            + self.tex(tidy.simplify(stiffness))
            + r",\ \omega^2 = "
            + self.tex(nonzero[0]),
        )
        return tidy.simplify(sympy.sqrt(nonzero[0]))

    def mode_matrices(self, point: dict[sympy.Symbol, sympy.Expr]) -> tuple[sympy.Matrix, sympy.Matrix]:
        """m x'' = -K x on the Cartesian axes (no constraints), K the Hessian of V at the equilibrium."""
        mech = self.mech
        if self.model.constraints:
            raise NotApplicable("Cartesian normal modes are done here only without constraints")
        place = {d.symbol: d.mapping.subs(point) for d in mech.dofs}
        stiffness = sympy.hessian(mech.cartesian_potential, [d.symbol for d in mech.dofs]).subs(place)
        return sympy.diag(*[d.inertia for d in mech.dofs]), stiffness.applyfunc(tidy.simplify)

    def collision(self, item: Quantity) -> sympy.Expr:
        if self.model.collision is None:
            raise NotApplicable("no collision in the model")
        steps: list[tuple[str, str]] = []
        result = collision.by_newton(self.model, item, steps)
        for title, latex in steps:
            self.step(title, latex)
        return result
