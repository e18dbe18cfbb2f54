"""Newton's laws in the frame the model declares or implies, with the fictitious forces in it.

The seed document's second method. In a frame translating with a body (the wedge), every other body
feels the translational force -m A, A being the frame body's acceleration, and moves relative to it:
its positions are x' = x - x_frame, and each constraint is rewritten in them (the incline is fixed in
the wedge's frame). The frame body obeys Newton's law as seen from the ground (in its own frame it is at
rest: 0 = F - M A). In a frame turning uniformly at the rate w about the vertical line x = a, each body
turning with it feels the centrifugal force m w^2 (x - a) away from the axis and the Coriolis force
-2 m w x v', which is perpendicular to the plane of motion and balanced by whatever keeps the body in
that plane. The frame's centrifugal potential, which the model writes for the other methods, is left
out of the potential energy here and replaced by that force, computed from the frame's own rate.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import sympy

from physics import typeset
from physics.engine import tidy
from physics.engine.mechanics import CartesianDof, Mechanics, solve_linear, time_derivative
from physics.engine.method import Method, NotApplicable
from physics.engine.model import ZERO, Frame, Model, PairPotential
from physics.engine.notation import split_subscript
from physics.engine.oscillation import frequency_from_accelerations
from physics.engine.results import StepKind
from physics.engine.supports import NOT_STEADY, translation
from physics.wording import the_counted


@dataclass(frozen=True)
class FrameDof:
    """A Cartesian degree of freedom as seen in the frame: relative to the frame body, or its own."""

    dof: CartesianDof
    symbol: sympy.Symbol
    velocity: sympy.Symbol
    acceleration: sympy.Symbol
    mapping: sympy.Expr  # in the generalized coordinates
    carrier: CartesianDof | None  # the frame body's dof on the same axis, for a relative one
    shift: sympy.Expr = ZERO  # a prescribed support's displacement R(t) on that axis


class FramesMethod(Method):
    name = "frames"
    title = "Newton's laws in the moving frame, with fictitious forces"

    @cached_property
    def support(self) -> dict[str, sympy.Expr] | None:
        """A support moving as prescribed, without a frame of the model's own: its displacement R(t) per
        axis, the frame that moves with it (supports.py)."""
        return translation(self.model) if self.model.frame is None else None

    @cached_property
    def frame(self) -> Frame:
        frame = self.model.frame
        if frame is None and self.support:
            return Frame()  # translating with the support: each body feels -m R''(t)
        if frame is None:
            raise NotApplicable(
                "the model has no accelerating or rotating frame (a wedge, a rotating element, or `frame:`)"
            )
        return frame

    @cached_property
    def latex_names(self) -> dict[sympy.Symbol, str]:
        names = dict(self.mech.latex_names)
        for f in self.frame_dofs:
            if f.carrier is not None or f.shift != 0:  # x' of the block: its x relative to the frame
                base, sub = split_subscript(self.mech.notation.cartesian[f.dof.name].tex)
                primed = f"{base}'" + (f"_{{{sub}}}" if sub else "")
                names[f.symbol] = primed
                names[f.velocity] = rf"\dot{{{base}}}'" + (f"_{{{sub}}}" if sub else "")
                names[f.acceleration] = rf"\ddot{{{base}}}'" + (f"_{{{sub}}}" if sub else "")
        return names

    def tex(self, expr: sympy.Basic) -> str:
        names = self.latex_names if self.model.frame is not None or self.support else self.mech.latex_names
        self._printed |= expr.free_symbols
        return str(typeset.latex(tidy.single_angles(expr), symbol_names=names))

    @cached_property
    def frame_dofs(self) -> tuple[FrameDof, ...]:
        carriers = {}
        if self.frame.body is not None:
            carriers = {d.name.split("_", 1)[0]: d for d in self.mech.dofs if d.body == self.frame.body}
        result = []
        for d in self.mech.dofs:
            axis = d.name.split("_", 1)[0]
            carrier = carriers.get(axis) if d.body != self.frame.body and axis != "phi" else None
            shift = (self.support or {}).get(axis, sympy.Integer(0))
            if carrier is None and shift == 0:
                result.append(FrameDof(d, d.symbol, d.velocity, d.acceleration, d.mapping, None))
                continue
            relative = f"{d.name}_rel"
            result.append(
                FrameDof(
                    d,
                    sympy.Symbol(relative, real=True),
                    sympy.Symbol(f"v_{relative}", real=True),
                    sympy.Symbol(f"a_{relative}", real=True),
                    d.mapping - (carrier.mapping if carrier is not None else shift),
                    carrier,
                    shift,
                )
            )
        return tuple(result)

    @cached_property
    def centrifugal_potentials(self) -> tuple[PairPotential, ...]:
        return centrifugal_potentials(self.model)

    @cached_property
    def static_forces(self) -> list[sympy.Expr]:
        """Gravity, potentials (but the frame's centrifugal one) and the centrifugal force on each
        Cartesian dof, in the bodies' Cartesian symbols."""
        mech, frame = self.mech, self.frame
        cartesian = {d.name: d.symbol for d in mech.dofs}
        potential = mech.cartesian_potential - sympy.Add(
            *(p.potential(mech, cartesian) for p in self.centrifugal_potentials)
        )
        result = []
        for d in mech.dofs:
            force = -sympy.diff(potential, d.symbol)
            if frame.rate is not None and d.body in frame.bodies and d.name.startswith("x_"):
                force += d.inertia * frame.rate**2 * (d.symbol - frame.axis)
            result.append(force)
        return result

    @cached_property
    def forces(self) -> list[sympy.Expr]:
        """The static forces, friction and given forces, and the translational force -m A."""
        mech = self.mech
        loads = mech.load_forces(False, mech.multipliers)
        result = []
        for f, static, given in zip(self.frame_dofs, self.static_forces, loads, strict=True):
            force = static + given
            if f.carrier is not None:
                force -= f.dof.inertia * f.carrier.acceleration
            elif f.shift != 0:  # the support's prescribed acceleration
                assert self.model.time is not None
                force -= f.dof.inertia * sympy.diff(f.shift, self.model.time, 2)
            result.append(force)
        return result

    def derive(self) -> None:
        if self.model.frame is None and not self.support:
            return
        frame = self.frame
        if self.support:
            assert self.model.time is not None
            moved = {axis: sympy.diff(shift, self.model.time, 2) for axis, shift in self.support.items()}
            self.step(
                "The frame moving with the support: positions $\\mathbf{r}'$ relative to it; each body feels "
                "the translational fictitious force $-m\\mathbf{A}$, $\\mathbf{A}$ the support's acceleration",
                r"\mathbf{r}' = \mathbf{r} - \mathbf{R}(t),\quad \mathbf{F}_{\mathrm{trans}} = -m\,\mathbf{A},\ "
                + r",\ ".join(rf"A_{axis} = {self.tex(a)}" for axis, a in moved.items()),
            )
        elif frame.body is not None:
            self.step(
                f"The frame moving with «{frame.body}»: positions $\\mathbf{{r}}'$ relative to it; each other "
                "body feels the translational fictitious force $-m\\mathbf{A}$, $\\mathbf{A}$ the frame's "
                "acceleration",
                rf"\mathbf{{r}}' = \mathbf{{r}} - \mathbf{{r}}_{{\mathrm{{{frame.body}}}}},\quad"
                rf" \mathbf{{F}}_{{\mathrm{{trans}}}} = -m\,\mathbf{{A}},\ \mathbf{{A}} = "
                rf"\ddot{{\mathbf{{r}}}}_{{\mathrm{{{frame.body}}}}}",
            )
        else:
            assert frame.rate is not None
            rate = self.tex(frame.rate)
            self.step(
                "The frame turning about the vertical axis",
                rf"\omega = {rate},\quad \mathbf{{F}}_{{\mathrm{{cf}}}} = m\omega^2 (x - {self.tex(frame.axis)})"
                r"\,\hat{x},\quad \mathbf{F}_{\mathrm{Cor}} = -2m\,\boldsymbol{\omega}\times\mathbf{v}' = "
                r"2m\omega\dot{x}\,\hat{z}",
            )
            self.step(
                "Coriolis force",
                r"\perp \text{ the turning plane: balanced by the reaction that keeps the body in it, no "
                r"effect in the plane}",
            )
        for f, force in zip(self.frame_dofs, self.total_forces, strict=True):
            d = f.dof
            where = "(the frame's own body, seen from the ground)" if frame.body == d.body else "in the frame"
            self.step(
                f"Newton's second law for «{d.body}» {where}, {self.along(d.name)}",
                self.tex(sympy.Eq(d.inertia * f.acceleration, force)),
                StepKind.EQUATION,
            )

    @cached_property
    def total_forces(self) -> list[sympy.Expr]:
        """Each dof's forces with the constraint forces lambda * grad(gap), in the frame's symbols."""
        mech, model = self.mech, self.model
        result = []
        for f, force in zip(self.frame_dofs, self.forces, strict=True):
            constraint = sympy.Add(
                *(
                    lam * sympy.diff(c.gap, f.dof.symbol)
                    for lam, c in zip(mech.multipliers, model.constraints, strict=True)
                )
            )
            result.append(self._relative(force + constraint))
        return result

    def _relative(self, expr: sympy.Expr) -> sympy.Expr:
        """An expression in the bodies' Cartesian symbols rewritten in the frame's."""
        return expr.subs(
            {
                f.dof.symbol: f.symbol + (f.carrier.symbol if f.carrier is not None else f.shift)
                for f in self.frame_dofs
                if f.carrier is not None or f.shift != 0
            }
        )

    @cached_property
    def equations(self) -> tuple[list[sympy.Expr], list[sympy.Symbol]]:
        """Newton's law per dof in the frame and each constraint differentiated twice, unsolved."""
        mech, model = self.mech, self.model
        equations = [
            f.dof.inertia * f.acceleration - force
            for f, force in zip(self.frame_dofs, self.total_forces, strict=True)
        ]
        for c in model.constraints:
            gap = self._relative(c.gap)
            if model.time is not None and model.time in gap.free_symbols:
                gap = tidy.simplify(gap)
            if model.time is not None and model.time in gap.free_symbols:
                raise NotApplicable(f"the constraint {c.name!r} moves relative to the support's frame")
            second = sympy.Add(*(sympy.diff(gap, f.symbol) * f.acceleration for f in self.frame_dofs))
            second += sympy.Add(
                *(
                    sympy.diff(gap, a.symbol, b.symbol) * a.velocity * b.velocity
                    for a in self.frame_dofs
                    for b in self.frame_dofs
                )
            )
            self.step(
                f"Constraint in the frame ({self.mech.notation.conditions[c.name]}), differentiated twice",
                self.tex(sympy.Eq(second, 0)),
                StepKind.EQUATION,
            )
            equations.append(second)
        return equations, [f.acceleration for f in self.frame_dofs] + list(mech.multipliers)

    def _solve(self, values: dict[sympy.Symbol, sympy.Expr]) -> dict[sympy.Symbol, sympy.Expr]:
        """Accelerations in the frame and constraint forces where the coordinates and velocities are `values`."""
        equations, unknowns = self.equations
        place: dict[sympy.Symbol, sympy.Expr] = {}
        for f in self.frame_dofs:
            place[f.symbol] = f.mapping
            place[f.velocity] = time_derivative(f.mapping, self.model)
        # cancelled, not simplified: only the few values asked for are simplified, at the state
        return solve_linear(
            [e.subs(place).subs(values) for e in equations], unknowns, self.title, tidy=sympy.cancel
        )

    @cached_property
    def solution(self) -> dict[sympy.Symbol, sympy.Expr]:
        solution = self._solve(dict(self.model.state))
        equations, unknowns = self.equations
        self.step(
            f"Solve {the_counted(len(equations), 'equation')} for {the_counted(len(unknowns), 'unknown')}: the accelerations in the "
            "frame and the constraint forces",
            r"\text{then the coordinates' accelerations follow from those in the frame}",
            StepKind.SOLVE,
            unknowns,
        )
        return solution

    def _coordinate_accelerations(
        self, solution: dict[sympy.Symbol, sympy.Expr], values: dict[sympy.Symbol, sympy.Expr]
    ) -> dict[sympy.Symbol, sympy.Expr]:
        """q'' from the accelerations in the frame (the frame's positions are functions of q)."""
        mech = self.mech
        jac = sympy.Matrix([[sympy.diff(f.mapping, q) for q in mech.q] for f in self.frame_dofs]).subs(values)
        rest = sympy.Matrix(
            [
                time_derivative(time_derivative(f.mapping, self.model), self.model)
                .subs(dict.fromkeys(mech.qdd, 0))
                .subs(values)
                for f in self.frame_dofs
            ]
        )
        measured = sympy.Matrix([solution[f.acceleration] for f in self.frame_dofs])
        normal = jac.T * jac
        if normal.det() == 0:
            raise NotApplicable("the coordinates are not determined by the positions in the frame")
        return dict(zip(mech.qdd, normal.inv() * jac.T * (measured - rest), strict=True))

    def acceleration(self, coordinate: str) -> sympy.Expr:
        accelerations = self._coordinate_accelerations(self.solution, dict(self.model.state))
        symbol = self.model.coordinate(coordinate).acceleration
        value = self.at_state(accelerations[symbol])
        self.step(
            f"Solved for the acceleration of {self.named(coordinate)}", self.tex(sympy.Eq(symbol, value))
        )
        return value

    def force(self, constraint: str) -> sympy.Expr:
        index = [c.name for c in self.model.constraints].index(constraint)
        symbol = self.mech.multipliers[index]
        value = self.at_state(self.solution[symbol])
        self.step(
            f"Solved for {self.force_named(constraint)}, {self.mech.notation.forces[constraint].words}",
            self.tex(sympy.Eq(symbol, value)),
        )
        return value

    def potential_force(self, coordinate: str) -> sympy.Expr:
        """At rest in a turning frame: gravity, potentials and the centrifugal force along the coordinate;
        in a support's frame, gravity, potentials and -m A."""
        if self.frame.rate is None and not self.support:
            raise NotApplicable(
                "in a frame moving with a body the fictitious force -m A depends on the motion: no static force"
            )
        q = self.model.coordinate(coordinate).symbol
        place = {d.symbol: d.mapping for d in self.mech.dofs}
        time = self.model.time
        force = sympy.Add(
            *(
                (
                    static.subs(place)
                    - (f.dof.inertia * sympy.diff(f.shift, time, 2) if time is not None else 0)
                )
                * sympy.diff(f.mapping, q)
                for f, static in zip(self.frame_dofs, self.static_forces, strict=True)
            )
        )
        force = tidy.simplify(force)
        if time is not None and time in force.free_symbols:
            raise NotApplicable(NOT_STEADY)
        self.step(
            f"Forces along {self.named(coordinate)} at rest in the frame (gravity, centrifugal)",
            rf"{self.mech.notation.letters.generalized}_{{{self.tex(q)}}} = \sum_i \mathbf{{F}}_i\cdot\frac{{\partial \mathbf{{r}}'_i}}{{\partial "
            rf"{self.tex(q)}}} = " + self.tex(force),
        )
        return force

    def frequency(self, coordinate: str, equilibrium: sympy.Expr) -> sympy.Expr:
        """Newton's law in the frame at rest at q: q'' = f(q), linearized about the equilibrium."""
        if self.frame.rate is None and not self.support:
            raise NotApplicable("small oscillations are worked here in a turning frame only")
        rest = dict.fromkeys(self.mech.qd, sympy.Integer(0))
        accelerations = self._coordinate_accelerations(self._solve(rest), rest)
        time = self.model.time
        if time is not None and any(time in a.free_symbols for a in accelerations.values()):
            raise NotApplicable(NOT_STEADY)
        return frequency_from_accelerations(self, coordinate, equilibrium, accelerations)


def centrifugal_potentials(model: Model) -> tuple[PairPotential, ...]:
    """The model's potentials that are its turning frame's own centrifugal potential, -m w^2 d^2 / 2 of
    the distance d of a body turning with the frame from the frame's axis."""
    frame = model.frame
    if frame is None or frame.rate is None:
        return ()
    found = []
    for pair in model.potentials:
        anchor = dict(pair.anchor)
        if len(pair.bodies) != 1 or pair.bodies[0] not in frame.bodies or set(anchor) != {"x"}:
            continue
        own = -model.body(pair.bodies[0]).mass * frame.rate**2 * pair.distance**2 / 2
        if tidy.simplify(anchor["x"] - frame.axis) == 0 and tidy.simplify(pair.energy - own) == 0:
            found.append(pair)
    return tuple(found)


def centripetal_accelerations(model: Model, mech: Mechanics) -> list[sympy.Expr]:
    """For Newton's law in the ground's frame: the centripetal part -w^2 (x - a) of the acceleration of
    each dof of a body turning with the model's frame whose centrifugal potential the model writes
    (that potential then stands for this acceleration, not for a force); zero elsewhere."""
    frame = model.frame
    turning = {p.bodies[0] for p in centrifugal_potentials(model)}
    if frame is None or frame.rate is None or not turning:
        return [sympy.Integer(0) for _ in mech.dofs]
    return [
        -(frame.rate**2) * (d.symbol - frame.axis)
        if d.body in turning and d.name.startswith("x_")
        else sympy.Integer(0)
        for d in mech.dofs
    ]
