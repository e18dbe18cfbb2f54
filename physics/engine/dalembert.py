"""d'Alembert's principle: the virtual work of the applied and inertial forces vanishes.

delta W = sum_i (F_i - m_i a_i) . delta r_i = 0 for every virtual displacement the constraints allow.
Those displacements are delta r_i = sum_j dr_i/dq_j delta q_j (the positions written in the coordinates
satisfy every constraint), and the delta q_j are independent, so each coordinate gives one equation.
The constraint forces do no virtual work and never appear: the method needs workless constraints
(not kinetic friction, whose force is mu times a normal force), and gives no constraint force.
The accelerations a_i are the second time derivatives of the positions: vectors, not energies.
"""

from __future__ import annotations

from functools import cached_property

import sympy

from physics.engine import tidy
from physics.engine.mechanics import solve_linear, time_derivative
from physics.engine.method import Method, NotApplicable
from physics.engine.oscillation import frequency_from_accelerations
from physics.engine.results import StepKind
from physics.engine.supports import NOT_STEADY
from physics.wording import the_counted


class DAlembertMethod(Method):
    name = "dalembert"
    title = "d'Alembert's principle (virtual work of the applied and inertial forces)"

    def derive(self) -> None:
        if self.model.contact_loads:
            return
        self.step(
            "Virtual displacements the constraints allow",
            r"\delta\mathbf{r}_i = \sum_j \frac{\partial \mathbf{r}_i}{\partial q_j}\,\delta q_j,\quad "
            r"\delta W = \sum_i (\mathbf{F}_i - m_i\mathbf{a}_i)\cdot\delta\mathbf{r}_i = 0",
        )

    @cached_property
    def equations(self) -> list[sympy.Expr]:
        """One equation per coordinate: the coefficient of its delta q in the virtual work."""
        mech, model = self.mech, self.model
        if model.contact_loads:
            raise NotApplicable(
                "kinetic friction does work through a normal force, a constraint force that d'Alembert's "
                "principle leaves out"
            )
        place = mech.cartesian_state()
        applied = mech.load_forces(False, mech.multipliers)
        effective = []
        for d, given in zip(mech.dofs, applied, strict=True):
            force = (-sympy.diff(mech.cartesian_potential, d.symbol)).subs(place) + given
            inertial = -d.inertia * time_derivative(time_derivative(d.mapping, model), model)
            effective.append(force + inertial)
        result = []
        for c in model.coordinates:
            work = sympy.Add(
                *(e * sympy.diff(d.mapping, c.symbol) for e, d in zip(effective, mech.dofs, strict=True))
            )
            equation = sympy.collect(sympy.trigsimp(sympy.expand(work)), list(mech.qdd))
            self.step(
                f"Virtual work for a virtual displacement $\\delta {self.tex(c.symbol)}$ alone",
                rf"\sum_i (\mathbf{{F}}_i - m_i\mathbf{{a}}_i)\cdot\frac{{\partial \mathbf{{r}}_i}}"
                rf"{{\partial {self.tex(c.symbol)}}} = " + self.tex(equation) + " = 0",
                StepKind.EQUATION,
            )
            result.append(equation)
        return result

    def _solve(self, values: dict[sympy.Symbol, sympy.Expr]) -> dict[sympy.Symbol, sympy.Expr]:
        return solve_linear(
            [e.subs(values) for e in self.equations], list(self.mech.qdd), self.title, tidy=sympy.cancel
        )

    @cached_property
    def solution(self) -> dict[sympy.Symbol, sympy.Expr]:
        solution = self._solve(dict(self.model.state))
        self.step(
            f"Solve {the_counted(len(self.equations), 'equation')} for {the_counted(len(self.mech.qdd), 'acceleration')}",
            r"\text{each coordinate's acceleration follows}",
            StepKind.SOLVE,
            list(self.mech.qdd),
        )
        return solution

    def acceleration(self, coordinate: str) -> sympy.Expr:
        symbol = self.model.coordinate(coordinate).acceleration
        value = self.at_state(self.solution[symbol])
        self.step(f"The acceleration of {self.named(coordinate)}", self.tex(sympy.Eq(symbol, value)))
        return value

    def force(self, constraint: str) -> sympy.Expr:
        raise NotApplicable("constraint forces do no virtual work and drop out of d'Alembert's principle")

    def potential_force(self, coordinate: str) -> sympy.Expr:
        """At rest the inertial forces vanish, but for a support's prescribed acceleration: the virtual work
        of the applied forces along the coordinate, and of -m times that acceleration."""
        mech, model = self.mech, self.model
        q = model.coordinate(coordinate).symbol
        place = mech.cartesian_state()
        rest = {**dict.fromkeys(mech.qd, 0), **dict.fromkeys(mech.qdd, 0)}
        force = tidy.simplify(
            sympy.Add(
                *(
                    (
                        (-sympy.diff(mech.cartesian_potential, d.symbol)).subs(place)
                        - d.inertia * time_derivative(time_derivative(d.mapping, model), model).subs(rest)
                    )
                    * sympy.diff(d.mapping, q)
                    for d in mech.dofs
                )
            )
            + mech.given_at_rest()[list(mech.q).index(q)]
        )
        if model.time is not None and model.time in force.free_symbols:
            raise NotApplicable(NOT_STEADY)
        self.step(
            f"Virtual work at rest along {self.named(coordinate)}",
            rf"{self.mech.notation.letters.generalized}_{{{self.tex(q)}}} = \sum_i \mathbf{{F}}_i\cdot\frac{{\partial \mathbf{{r}}_i}}{{\partial "
            rf"{self.tex(q)}}} = " + self.tex(force),
        )
        return force

    def frequency(self, coordinate: str, equilibrium: sympy.Expr) -> sympy.Expr:
        rest = dict.fromkeys(self.mech.qd, sympy.Integer(0))
        accelerations = self._solve(rest)
        if self.model.time is not None and any(
            self.model.time in a.free_symbols for a in accelerations.values()
        ):
            raise NotApplicable(NOT_STEADY)
        return frequency_from_accelerations(self, coordinate, equilibrium, accelerations)
