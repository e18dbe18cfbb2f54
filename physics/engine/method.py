"""What every derivation method provides, and the quantities built on top of those basics."""

from __future__ import annotations

import dataclasses
from abc import ABC, abstractmethod
from collections.abc import Iterable, Sequence
from functools import cached_property, lru_cache

import sympy

from physics import typeset
from physics.answer_text import typed_text
from physics.engine import bounces, evaluated_at, impact, modes, quantity_table, tidy, work_energy
from physics.engine.mechanics import Mechanics
from physics.engine.model import Model, Quantity
from physics.engine.proof import domain_points
from physics.engine.results import MethodReport, Step, StepKind
from physics.engine.roots import CHOOSE, admissible, declared_range
from physics.engine.settle import plain_angle, settle
from physics.engine.signs import Sign, sign_on_domain
from physics.engine.supports import driven
from physics.errors import DerivationError


@lru_cache(maxsize=32)
def stable_equilibrium(model: Model, translation: bool = False) -> dict[sympy.Symbol, sympy.Expr]:
    """The stable equilibrium of all the coordinates (shared by the methods: it is where they linearize);
    with `translation`, for normal modes, a point of a continuum of rests that is a free translation."""
    if driven(model):  # grad V = 0 is no rest relative to a moving support
        raise NotApplicable(
            "normal modes and damped oscillations are worked about a fixed support only (this one moves as "
            "prescribed): ask for angular_frequency of one coordinate"
        )
    return modes.equilibrium_point(model, Mechanics(model), translation)


class NotApplicable(Exception):
    """This method cannot give this quantity (recorded as a note, not a failure)."""


class Method(ABC):
    name: str
    title: str

    def __init__(self, model: Model, mechanics: Mechanics) -> None:
        self.model = model
        self.mech = mechanics
        self.steps: list[Step] = []
        self._logged: set[str] = set()
        self._impact: impact.Worked | None = None  # the impact worked once, for all its quantities
        # v^2 where the motion arrives (work_energy), turning points (turning): found once per method
        self.arrivals: dict[tuple[object, ...], sympy.Expr] = {}
        # each coordinate's equilibrium, found once: frequencies, expressions and the simulation ask again
        self._equilibria: dict[str, sympy.Expr] = {}
        # where a coordinate's force depends on others: all the coordinates at their joint equilibrium
        self._joint: dict[str, dict[sympy.Symbol, sympy.Expr]] = {}
        self._printed: set[sympy.Basic] = set()  # symbols printed since the last step (Step.symbols)

    @cached_property
    def free(self) -> Method:
        """This method on the model with its state left free: accelerations as functions of q and q'."""
        model = dataclasses.replace(self.model, state=())
        return type(self)(model, Mechanics(model))

    def tex(self, expr: sympy.Basic) -> str:
        self._printed |= expr.free_symbols
        return str(typeset.latex(tidy.single_angles(expr), symbol_names=self.mech.latex_names))

    def step(
        self,
        title: str,
        latex: str,
        kind: StepKind = StepKind.WORK,
        unknowns: Sequence[sympy.Basic | str] = (),
    ) -> None:
        """Log a line of the worked solution (once per title), with the symbols its formulas printed; an
        unknown given as TeX (`\\omega^{2}`) is no symbol of the model's."""
        if title not in self._logged:
            self._logged.add(title)
            written = tuple(u if isinstance(u, str) else self.tex(u) for u in unknowns)
            symbols = tuple(sorted(str(s) for s in self._printed))
            self.steps.append(Step(title, latex, kind, written, symbols))
        self._printed = set()

    def adopt(self, steps: Iterable[Step]) -> None:
        """Log the steps of this method worked at another state as they were (once per title): its
        equations stay numbered and its solve keeps its unknowns, so the page counts them."""
        for step in steps:
            if step.title not in self._logged:
                self._logged.add(step.title)
                self.steps.append(step)

    def adopt_after(self, steps: Iterable[Step], said: str) -> None:
        """Log the steps of another solve (the same system at another state, or changed) with `said` added
        to each title, every other field as it was: its equations stay numbered, its solve keeps its
        unknowns, and its symbols take those printed for `said`."""
        printed, self._printed = {str(s) for s in self._printed}, set()
        self.adopt(
            dataclasses.replace(
                step, title=f"{step.title} {said}", symbols=tuple(sorted({*step.symbols, *printed}))
            )
            for step in steps
        )

    def named(self, coordinate: str) -> str:
        """A coordinate as the solution writes it, in a title: `$s$`."""
        return f"${self.mech.notation.coordinates[coordinate].tex}$"

    def force_named(self, constraint: str) -> str:
        """A constraint's force as the solution writes it, in a title: `$N_{1}$`."""
        return f"${self.mech.notation.forces[constraint].tex}$"

    # --- basics each method may provide --------------------------------------------------------

    def acceleration(self, coordinate: str) -> sympy.Expr:
        raise NotApplicable(f"{self.title} does not give accelerations here")

    def force(self, constraint: str) -> sympy.Expr:
        raise NotApplicable(f"{self.title} does not give constraint forces")

    def potential_force(self, coordinate: str) -> sympy.Expr:
        raise NotApplicable(f"{self.title} does not give generalized forces")

    def frequency(self, coordinate: str, equilibrium: sympy.Expr) -> sympy.Expr:
        raise NotApplicable(f"{self.title} does not give oscillation frequencies")

    def collision(self, item: Quantity) -> sympy.Expr:
        raise NotApplicable(f"{self.title} does not treat collisions")

    def impact(self, quantity: Quantity) -> sympy.Expr:
        work = impact.METHODS.get(self.name)
        if work is None or self.model.impact is None:
            raise NotApplicable(f"{self.title} does not treat impacts")
        if self._impact is None:
            self._impact = work(self.model)
        if quantity.bounces is not None:  # just after the n-th bounce off the fixed partner
            return bounces.final(self, quantity, self._impact)
        return impact.answer(self._impact, self.model, quantity, self.step)

    def after_impact(self, quantity: Quantity) -> sympy.Expr:
        """The quantity in the motion that starts with this method's own velocities after the impact."""
        work = impact.METHODS.get(self.name)
        if work is None or self.model.impact is None:
            raise NotApplicable(f"{self.title} does not treat impacts")
        if self._impact is None:
            self._impact = work(self.model)
        steps, _, after = self._impact
        for title, latex in steps:
            self.step(title, latex)
        rates = impact.coordinate_rates(self.model, after)
        if quantity.bounces is not None:  # bounced again and again off the fixed partner
            rates = bounces.velocities_after(self, quantity, rates)
        self.step(
            "The motion after the impact starts with these velocities",
            r",\ ".join(
                self.tex(sympy.Eq(c.velocity, r)) for c, r in zip(self.model.coordinates, rates, strict=True)
            ),
        )
        state = {
            **dict(self.model.state),
            **{c.velocity: r for c, r in zip(self.model.coordinates, rates, strict=True)},
        }
        bounced = dataclasses.replace(self.model, state=tuple(state.items()), impact=None)
        solver = type(self)(bounced, Mechanics(bounced))
        result = solver.answer(dataclasses.replace(quantity, after="", bounces=None))
        self.adopt_after(solver.steps, "(after the impact)")
        return result

    def mode_matrices(self, point: dict[sympy.Symbol, sympy.Expr]) -> tuple[sympy.Matrix, sympy.Matrix]:
        """(M, K) of the small oscillations about the equilibrium `point`, as this method sees them."""
        raise NotApplicable(f"{self.title} does not give normal modes")

    def mode_unknowns(self) -> list[sympy.Basic]:
        """The unknowns of the equations `mode_matrices` linearized, where the method wrote them as
        equations of its own (Lagrange's): no solve lists them, as the modes need no solve."""
        return []

    @cached_property
    def mode_frequencies(self) -> list[sympy.Expr]:
        """Squared normal-mode frequencies, lowest first."""
        if self.model.nonconservative_loads:
            raise NotApplicable("normal modes are for undamped systems")
        point = stable_equilibrium(self.model, True)
        mass, stiffness = self.mode_matrices(point)
        squares = modes.squared_frequencies(self.model, mass, stiffness)
        drift = len(squares) < mass.shape[0]  # a coordinate V leaves free, or the bodies moving together
        # the frequency equation is an equation of the method's, with omega^2 its unknown: the page counts it
        self.step(
            "Normal modes: the mass matrix $\\mathbf{M}$ and stiffness matrix $\\mathbf{K}$ at the equilibrium"
            + (" (the root $\\omega = 0$, a free drift with no restoring force, left out)" if drift else ""),
            r"\det(\mathbf{K} - \omega^2 \mathbf{M}) = 0,\ \mathbf{M} = "
            + self.tex(mass)
            + r",\ \mathbf{K} = "
            + self.tex(stiffness)
            + r"\Rightarrow \omega^2 \in \{"
            + ", ".join(self.tex(v) for v in squares)
            + r"\}",
            StepKind.EQUATION,
            [*self.mode_unknowns(), r"\omega^{2}"],
        )
        return squares

    # --- quantities -------------------------------------------------------------------------------

    def answer(self, quantity: Quantity) -> sympy.Expr:
        """The quantity by this method: its kind's handler in the quantity table (quantity_table.py)."""
        if evaluated_at.applies(quantity):  # a modifier: with a symbol at another quantity's value
            return evaluated_at.answer(self, quantity)
        if quantity.after:  # a modifier: in the motion that starts just after the impact
            return self.after_impact(quantity)
        if quantity.at:  # a modifier: where the motion from the state arrives (speed, force, ...)
            return work_energy.answer(self, quantity)
        return quantity_table.handler(quantity)(self, quantity)

    def equilibrium(self, coordinate: str) -> sympy.Expr:
        """The stable root of the generalized force Q(q) = 0: Q'(q0) < 0 on the whole domain."""
        if coordinate not in self._equilibria:
            self._equilibria[coordinate] = self._equilibrium(coordinate)
        return self._equilibria[coordinate]

    def _equilibrium(self, coordinate: str) -> sympy.Expr:
        q = self.model.coordinate(coordinate).symbol
        force = self.potential_force(coordinate)
        others = (force.free_symbols & set(self.mech.q)) - {q}
        if others:
            return self._joint_equilibrium(coordinate, sorted(map(str, others)))
        if tidy.simplify(force) == 0:
            raise DerivationError(
                f"{self.title}: " + modes.continuum([coordinate], f"at every {coordinate} (Q = 0 there)"),
                quantity=coordinate,
            )
        roots = _real_roots(force, q)
        slope = sympy.diff(force, q)
        stable = [
            root for root in roots if _negative_on_domain(tidy.simplify(slope.subs(q, root)), self.model)
        ]
        if len(stable) > 1:  # a symmetric pair, say: the coordinate's declared range chooses
            stable = [root for root in stable if _in_range(root, coordinate, self.model)]
        if len(stable) != 1:
            raise DerivationError(
                f"{self.title}: expected one stable equilibrium of {coordinate}, found {len(stable)} among "
                f"the roots {typed_text(roots)} of Q = {typed_text(force)}"
                + ("" if stable else _why_none_stable(force, q, roots, slope, self.model)),
                quantity=coordinate,
            )
        _check_in_range(stable[0], coordinate, self.model, self.title)
        stable[0] = plain_angle(tidy.simplify(stable[0]), self.model)  # not sympy's half-angle form
        generalized, at = self.mech.notation.letters.generalized, rf"{self.tex(q)}_{{\mathrm{{eq}}}}"
        self.step(
            f"Equilibrium of {self.named(coordinate)}: the generalized force vanishes, and pulls back",
            rf"{generalized}_{{{self.tex(q)}}} = {self.tex(force)} = 0 \Rightarrow {at} = "
            + self.tex(stable[0])
            + rf",\quad \frac{{\partial {generalized}_{{{self.tex(q)}}}}}{{\partial {self.tex(q)}}}"
            + rf"\Big|_{{{at}}} < 0",
            StepKind.SOLVE,
            [q],
        )
        return tidy.simplify(stable[0])

    def _joint_equilibrium(self, coordinate: str, others: list[str]) -> sympy.Expr:
        """The coordinate's value at the stable equilibrium of all the coordinates together (a bob on a
        spring free in x, y and z rests below the anchor), where this method's own force on it vanishes."""
        try:
            point = stable_equilibrium(self.model)
        except (DerivationError, NotApplicable) as error:
            why = error.message if isinstance(error, DerivationError) else str(error)
            raise NotApplicable(
                f"the force on {coordinate} depends on other coordinates {others}, and the coordinates have no "
                f"one stable equilibrium together ({why}): ask for its acceleration or potential_force at "
                "the state, or hold the others with constraints"
            ) from None
        q = self.model.coordinate(coordinate).symbol
        force = self.potential_force(coordinate)
        if tidy.simplify(force.subs(point)) != 0:
            raise DerivationError(
                f"{self.title}: the force on {coordinate}, {typed_text(force)}, does not vanish at the "
                f"equilibrium of all the coordinates {typed_text(point)}",
                quantity=coordinate,
            )
        self._joint[coordinate] = point
        generalized = self.mech.notation.letters.generalized
        self.step(
            f"Equilibrium of {self.named(coordinate)}: its force depends on the other coordinates, so all "
            "the generalized forces vanish together",
            rf"{generalized}_{{{self.tex(q)}}} = {self.tex(force)} = 0 \Rightarrow "
            + r",\ ".join(self.tex(sympy.Eq(c, v)) for c, v in point.items()),
            StepKind.SOLVE,
            [q],
        )
        return tidy.simplify(point[q])

    def rest(self, coordinate: str) -> dict[sympy.Symbol, sympy.Expr]:
        """Every coordinate where `coordinate` rests at its equilibrium, the point its small oscillations
        are linearized about: the others at 0, or at the equilibrium of all the coordinates together where
        its force depends on them."""
        q0 = self.equilibrium(coordinate)
        zero = dict.fromkeys(self.mech.q, sympy.Integer(0))
        return {**zero, **self._joint.get(coordinate, {}), self.model.coordinate(coordinate).symbol: q0}

    def terminal_velocity(self, coordinate: str) -> sympy.Expr:
        """The velocity at which the coordinate stops accelerating: this method's own acceleration with the
        velocity left free, set to zero; the stable root (the acceleration falls as the velocity grows)."""
        c = self.model.coordinate(coordinate)
        free = dataclasses.replace(
            self.model, state=tuple((s, v) for s, v in self.model.state if s != c.velocity)
        )
        acceleration = type(self)(free, Mechanics(free)).acceleration(coordinate)
        if not acceleration.has(c.velocity):
            raise NotApplicable(f"the acceleration of {coordinate} does not depend on its velocity")
        roots = [r for r in tidy.solve(acceleration, c.velocity) if r.is_real is not False and r != 0]
        slope = sympy.diff(acceleration, c.velocity)
        stable = [
            r for r in roots if _negative_on_domain(tidy.simplify(slope.subs(c.velocity, r)), self.model)
        ]
        if len(stable) != 1:
            raise DerivationError(
                f"{self.title}: expected one terminal velocity of {coordinate}, found {typed_text(stable)} among {typed_text(roots)}",
                quantity=coordinate,
            )
        self.step(
            f"Terminal velocity of {self.named(coordinate)}: the acceleration vanishes",
            self.tex(sympy.Eq(acceleration, 0)) + r"\Rightarrow " + self.tex(sympy.Eq(c.velocity, stable[0])),
        )
        return tidy.simplify(stable[0])

    def solve_for(self, parameter: sympy.Symbol, expr: sympy.Expr, name: str, what: str = "it") -> sympy.Expr:
        """The one root of expr = 0 in `parameter` that its declared sign and range allow; `what` says what
        expr is (the acceleration of r), for the refusal when there is none."""
        found = tidy.solve(expr, parameter)
        roots = admissible(found, parameter, self.model)
        if not roots:
            raise DerivationError(
                f"{self.title}: {name}: {_no_root(parameter, expr, found, what, self.model)}", quantity=name
            )
        if len(roots) != 1:
            raise DerivationError(
                f"{self.title}: {name}: expected one value of {parameter} {_declared(parameter, self.model)}, "
                f"found {typed_text(roots)} among the roots {typed_text(found)}" + CHOOSE.format(parameter),
                quantity=name,
            )
        self.step(
            f"Solve for ${typeset.latex(parameter)}$",
            self.tex(sympy.Eq(expr, 0)) + r"\Rightarrow " + self.tex(sympy.Eq(parameter, roots[0])),
        )
        return tidy.simplify(roots[0])

    @abstractmethod
    def derive(self) -> None:
        """Write the method's general steps (the equations of motion) before quantities are asked."""

    def report(self, results: dict[str, sympy.Expr], notes: list[str]) -> MethodReport:
        printed = {name for step in self.steps for name in step.symbols}
        forces = tuple(
            c.name
            for c, force in zip(self.model.constraints, self.mech.multipliers, strict=True)
            if str(force) in printed
        )
        return MethodReport(self.name, self.title, tuple(self.steps), dict(results), tuple(notes), forces)

    def along(self, dof: str) -> str:
        """A Cartesian degree of freedom in a title: "along $x$", or "turning ($\\varphi$)"."""
        axis = dof.split("_", 1)[0]
        if axis == "phi":
            return f"for its turning about its centre (${self.mech.notation.cartesian[dof].tex}$)"
        return f"along ${axis}$"

    def at_state(self, expr: sympy.Expr) -> sympy.Expr:
        value = tidy.simplify(expr.subs(dict(self.model.state)))
        settled = settle(value, self.model)  # |R - r| where R > r is declared
        return value if settled == value else tidy.simplify(settled)


def _no_root(
    parameter: sympy.Symbol, expr: sympy.Expr, found: list[sympy.Expr], what: str, model: Model
) -> str:
    """Why no value of the parameter makes expr vanish: the sign it keeps (a repulsion pushes the orbit
    outward at every speed), or the roots there are and what they are not."""
    said = f"no value of {parameter} {_declared(parameter, model)} makes {what} vanish: {what} is {typed_text(expr)}"
    if found:
        return f"{said}, whose roots {typed_text(found)} are not real, of {parameter}'s sign and in its range"
    sign = sign_on_domain(expr, model).sign
    if sign in (Sign.POSITIVE, Sign.NEGATIVE):
        return f"{said}, {sign.value} on the whole domain, whatever {parameter} is"
    return f"{said}, which is zero for no {parameter}"


def _declared(symbol: sympy.Symbol, model: Model) -> str:
    """What the model declares of the symbol, for a message: "(positive, in [0, pi/2])"."""
    said = ["positive"] if symbol.is_positive else ["negative"] if symbol.is_negative else ["real"]
    bounds = declared_range(symbol, model)
    if bounds is not None:
        said.append(f"in [{bounds[0]:.4g}, {bounds[1]:.4g}]")
    return f"({', '.join(said)})"


def _real_roots(expr: sympy.Expr, q: sympy.Symbol) -> list[sympy.Expr]:
    """Real roots of expr = 0 in q that respect q's sign. `solve` under q's assumptions can return
    fewer roots than exist, so an unrestricted real stand-in is tried when it finds none."""
    roots = tidy.solve(expr, q)
    if not roots:
        free = sympy.Dummy("q", real=True)
        roots = sympy.solve(expr.subs(q, free), free)
    return [
        r
        for r in roots
        if r.is_real is not False
        and not (q.is_positive and r.is_positive is False)
        and not (q.is_negative and r.is_negative is False)
    ]


def _why_none_stable(
    force: sympy.Expr, q: sympy.Symbol, roots: list[sympy.Expr], slope: sympy.Expr, model: Model
) -> str:
    """Why no root is a stable rest, for the refusal: the roots that push away, and those the
    coordinate's declared sign (its range starting at 0, open) left out."""
    why = []
    unstable = [
        r for r in roots if sign_on_domain(tidy.simplify(slope.subs(q, r)), model).sign is Sign.POSITIVE
    ]
    if unstable:
        why.append(
            f"at {typed_text(unstable[0]) if len(unstable) == 1 else typed_text(unstable)} the force pushes "
            f"{q} away (dQ/d{q} > 0): an unstable rest, so no small oscillation about it (check the sign "
            "of the potential or of the coordinate)"
        )
    free = sympy.Dummy(str(q), real=True)
    try:
        everything = [r.subs(free, q) for r in sympy.solve(force.subs(q, free), free)]
    except (NotImplementedError, TypeError, ValueError):
        everything = []
    dropped = [
        r for r in everything if r.is_real is not False and all(sympy.simplify(r - k) != 0 for k in roots)
    ]
    if dropped:
        why.append(
            f"{typed_text(dropped)} left out: {q}'s declared range excludes it (a range is open: a rest at "
            "its end is outside it; widen the range past the rest)"
        )
    return "; " + "; ".join(why) if why else ""


def _in_range(value: sympy.Expr, coordinate: str, model: Model) -> bool:
    """value lies inside the coordinate's declared range at sampled domain points (no range: inside)."""
    bounds = [(low, high) for name, low, high in model.coordinate_ranges if name == coordinate]
    if not bounds:
        return True
    low, high = bounds[0]
    try:
        return all(
            float(low.subs(point)) < float(value.subs(point)) < float(high.subs(point))
            for point in domain_points(model, 12, seed=5)
        )
    except (TypeError, ValueError):
        return False


def _check_in_range(value: sympy.Expr, coordinate: str, model: Model, title: str) -> None:
    """The one stable equilibrium must lie in the coordinate's declared range wherever the domain goes: a
    block hanging under a ceiling spring, its coordinate declared above it, would otherwise be derived as
    resting on a spring that stands on the floor, below the floor where m g > k L0."""
    bounds = [(low, high) for name, low, high in model.coordinate_ranges if name == coordinate]
    if not bounds or value.free_symbols - set(model.parameters):
        return
    low, high = bounds[0]
    for point in domain_points(model, 12, seed=5):
        try:
            at, lowest, highest = (float(e.subs(point)) for e in (value, low, high))
        except (TypeError, ValueError):
            return
        slack = 1e-9 * max(1.0, abs(at))
        if not lowest - slack <= at <= highest + slack:
            raise DerivationError(
                f"{title}: the stable equilibrium {coordinate} = {typed_text(value)} lies outside {coordinate}'s "
                f"declared range [{typed_text(low)}, {typed_text(high)}] at "
                + ", ".join(f"{s}={v:.4g}" for s, v in point.items())
                + f" ({coordinate} = {at:.4g}): the body rests on the other side there (a spring's or a "
                "surface's). Check the side the range declares, or keep the domain where it holds "
                "(domain.positive)",
                quantity=coordinate,
            )


def _negative_on_domain(expr: sympy.Expr, model: Model) -> bool:
    """expr < 0 under the symbols' assumptions, or else at every one of a set of domain points."""
    if expr.is_negative is not None:
        return bool(expr.is_negative)
    try:
        return all(float(expr.subs(point)) < 0 for point in domain_points(model, 12, seed=3))
    except (TypeError, ValueError):
        return False
