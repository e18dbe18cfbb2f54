"""Conservation laws: momentum of each cyclic coordinate, then energy d/dt(T + V) = 0 per degree of freedom.

Applies to conservative systems (no friction) that, once the conserved momenta are used to remove the
cyclic coordinates, fall apart into independent one-degree-of-freedom parts.
"""

from __future__ import annotations

from functools import cached_property

import sympy

from physics.engine import collision, tidy
from physics.engine.mechanics import Mechanics, solve_linear, time_derivative
from physics.engine.method import Method, NotApplicable
from physics.engine.model import Quantity
from physics.engine.results import StepKind
from physics.engine.supports import NOT_CONSERVED, driven


class ConservationMethod(Method):
    name = "conservation"
    title = "Conservation of momentum and energy"

    def answer(self, quantity: Quantity) -> sympy.Expr:
        if driven(self.model):  # the ground's frame: the moving support's work is no potential
            raise NotApplicable(NOT_CONSERVED)
        return super().answer(quantity)

    def derive(self) -> None:
        if driven(self.model):
            energy = self.mech.notation.letters.energy
            self.step(
                "Not conservative in the ground's frame: the support moving as prescribed does work",
                rf"\frac{{\mathrm{{d}}{energy}}}{{\mathrm{{d}}t}} \neq 0",
            )
        if self.model.contact_loads:
            energy = self.mech.notation.letters.energy
            self.step(
                "Not conservative: kinetic friction turns mechanical energy into heat",
                rf"\Delta {energy} < 0",
            )

    @cached_property
    def reduced(self) -> tuple[dict[sympy.Symbol, sympy.Expr], sympy.Expr, list[sympy.Symbol]]:
        """(cyclic velocities in terms of the others, reduced kinetic energy, remaining coordinates)."""
        if self.model.contact_loads:
            raise NotApplicable("energy is not conserved with kinetic friction")
        if self.model.nonconservative_loads:
            raise NotApplicable(
                "energy is not conserved with drag or forces that depend on the motion or the time"
            )
        mech = self.mech
        mass = mech.mass_matrix
        cyclic = cyclic_indices(mech)
        state = dict(self.model.state)
        velocities: dict[sympy.Symbol, sympy.Expr] = {}
        if cyclic:
            momenta = [sympy.Add(*(mass[i, j] * mech.qd[j] for j in range(len(mech.q)))) for i in cyclic]
            initial = [p.subs(state) for p in momenta]
            for i, p, p0 in zip(cyclic, momenta, initial, strict=True):
                self.step(
                    f"The momentum conjugate to {self.named(self.model.coordinates[i].name)} is conserved "
                    "(no force acts along it)",
                    self.tex(sympy.Eq(p, p0)),
                    StepKind.EQUATION,
                )
            velocities = solve_linear(
                [p - p0 for p, p0 in zip(momenta, initial, strict=True)],
                [mech.qd[i] for i in cyclic],
                self.title,
            )
        kinetic = tidy.simplify(mech.kinetic.subs(velocities))
        remaining = [q for i, q in enumerate(mech.q) if i not in cyclic]
        return velocities, kinetic, remaining

    @cached_property
    def accelerations(self) -> dict[sympy.Symbol, sympy.Expr]:
        mech, model = self.mech, self.model
        velocities, kinetic, remaining = self.reduced
        potential = mech.potential
        result: dict[sympy.Symbol, sympy.Expr] = {}
        for q in remaining:
            c = next(c for c in model.coordinates if c.symbol == q)
            others = [o for o in remaining if o != q]
            others_dot = [next(x.velocity for x in model.coordinates if x.symbol == o) for o in others]
            part_t = sympy.expand(kinetic).coeff(c.velocity, 2) * c.velocity**2
            # the cyclic velocities held by their momenta leave terms in q alone (p^2 / 2 m r^2 of an
            # orbit): the centrifugal part of the effective potential
            part_t += sympy.Add(
                *(t for t in sympy.Add.make_args(sympy.expand(kinetic)) if t.has(q) and not t.has(*mech.qd))
            )
            part_v = sympy.Add(*(t for t in sympy.Add.make_args(sympy.expand(potential)) if t.has(q)))
            if (
                part_t.has(*others, *others_dot)
                or part_v.has(*others)
                or sympy.expand(kinetic - part_t).has(c.velocity)
            ):
                raise NotApplicable(
                    f"{c.name} is coupled to other coordinates: more than one degree of freedom"
                )
            energy = part_t + part_v
            rate = sympy.expand(time_derivative(energy, model) / c.velocity)
            e = mech.notation.letters.energy
            self.step(
                f"The energy is conserved; its rate of change gives the acceleration of {self.named(c.name)}",
                rf"{e} = {self.tex(energy)},\ \frac{{\mathrm{{d}}{e}}}{{\mathrm{{d}}t}} = 0 \Rightarrow "
                + self.tex(sympy.Eq(tidy.simplify(rate), 0)),
                StepKind.EQUATION,
                [c.acceleration],
            )
            result[c.acceleration] = sympy.solve(rate, c.acceleration)[0]
        for velocity, expr in velocities.items():
            c = next(c for c in model.coordinates if c.velocity == velocity)
            result[c.acceleration] = tidy.simplify(time_derivative(expr, model).subs(result))
            self.step(
                f"The acceleration of {self.named(c.name)} from its conserved momentum",
                self.tex(sympy.Eq(c.acceleration, result[c.acceleration])),
                StepKind.SOLVE,
                [c.acceleration],
            )
        return result

    def acceleration(self, coordinate: str) -> sympy.Expr:
        c = self.model.coordinate(coordinate)
        return self.at_state(self.accelerations[c.acceleration])

    def potential_force(self, coordinate: str) -> sympy.Expr:
        q = self.model.coordinate(coordinate).symbol
        if q not in self.reduced[2]:
            raise NotApplicable(f"{coordinate} is cyclic")
        return tidy.simplify(-sympy.diff(self.mech.potential, q))

    def frequency(self, coordinate: str, equilibrium: sympy.Expr) -> sympy.Expr:
        """E = 1/2 M q'^2 + V(q) near the minimum: omega^2 = V''(q0)/M(q0)."""
        c = self.model.coordinate(coordinate)
        _, kinetic, remaining = self.reduced
        if c.symbol not in remaining:
            raise NotApplicable(f"{coordinate} is cyclic")
        inertia = sympy.expand(kinetic).coeff(c.velocity, 2) * 2
        others = [o for o in remaining if o != c.symbol]
        if inertia.has(*others):
            raise NotApplicable(f"{coordinate} is coupled to other coordinates")
        curvature = sympy.diff(self.mech.potential, c.symbol, 2).subs(c.symbol, equilibrium)
        omega2 = tidy.simplify(curvature / inertia.subs(c.symbol, equilibrium))
        letters, q = self.mech.notation.letters, self.tex(c.symbol)
        inertia_there = self._factor(sympy.factor(inertia.subs(c.symbol, equilibrium)))
        curvature_there = self._factor(sympy.factor(curvature))
        self.step(
            "Small oscillations from the energy: its inertia and the curvature of "
            f"${letters.potential}$ at the equilibrium",
            rf"{letters.energy} \approx \tfrac12\, {inertia_there}\, "
            rf"{self.tex(c.velocity)}^2 + \tfrac12\, {curvature_there}\,({q} - {q}_{{\mathrm{{eq}}}})^2,"
            r"\ \omega^2 = " + self.tex(sympy.factor(omega2)),
        )
        return tidy.simplify(sympy.sqrt(omega2))

    def _factor(self, expr: sympy.Expr) -> str:
        """A factor of a product, written: a sum in brackets (½ (a + b) θ̇², not ½ a + b θ̇²)."""
        written = self.tex(expr)
        return rf"\left({written}\right)" if expr.is_Add else written

    def mode_matrices(self, point: dict[sympy.Symbol, sympy.Expr]) -> tuple[sympy.Matrix, sympy.Matrix]:
        """The energy expanded to second order about the equilibrium: T = q'^T M q'/2, V = q^T K q/2."""
        mech = self.mech
        mass = sympy.hessian(mech.kinetic, list(mech.qd)).subs(point).applyfunc(tidy.simplify)
        stiffness = sympy.hessian(mech.potential, list(mech.q)).subs(point).applyfunc(tidy.simplify)
        return mass, stiffness

    def collision(self, item: Quantity) -> sympy.Expr:
        if self.model.collision is None:
            raise NotApplicable("no collision in the model")
        steps: list[tuple[str, str]] = []
        result = collision.by_conservation(self.model, item, steps)
        for title, latex in steps:
            self.step(title, latex)
        return result


def cyclic_indices(mech: Mechanics) -> list[int]:
    """The coordinates neither the potential nor the mass matrix depends on (polar positions leave
    cos^2 + sin^2 in the mass matrix: simplified before it counts as a dependence)."""
    mass, potential = mech.mass_matrix, mech.potential
    return [
        i
        for i, q in enumerate(mech.q)
        if not potential.has(q) and not any(e.has(q) and tidy.simplify(sympy.diff(e, q)) != 0 for e in mass)
    ]
