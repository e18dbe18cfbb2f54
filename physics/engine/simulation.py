"""Numerical checks: integrate the unsolved equations of motion with RK4 and measure each quantity.

The integrator only sees Lagrange's equations as a linear system A(q, q') [q'', lambda] = b(q, q'),
compiled with `lambdify(..., "math")` and solved numerically at every instant; it never sees the
closed-form answer, which is only evaluated at the end to be compared with what was measured.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property, partial
from typing import TYPE_CHECKING, Any

import mpmath
import sympy

from physics.answer_text import typed_text
from physics.engine import (
    embedding,
    expression_simulation,
    extremum,
    impact,
    impact_simulation,
    slipping,
    vanishing_frequency,
)
from physics.engine.collision import merged
from physics.engine.contact_friction import slip_velocity
from physics.engine.lagrange import LagrangeMethod
from physics.engine.leaving import switched_off
from physics.engine.mechanics import Mechanics
from physics.engine.method import stable_equilibrium
from physics.engine.model import (
    AXES,
    EXTREMUM_KINDS,
    IMPACT_KINDS,
    ORBIT_KINDS,
    SLIP_KINDS,
    TRAJECTORY_KINDS,
    Model,
    Quantity,
    QuantityKind,
)
from physics.engine.results import SimulationCheck
from physics.engine.sizes import friction_path
from physics.engine.supports import driven
from physics.errors import DerivationError

TOLERANCE = 1e-3
ENERGY_TOLERANCE = 1e-6  # RK4 keeps the books far better than this over a short motion
ROUNDING = 1e-6  # a force this small beside the largest constraint force is judged as zero, by its size
ENERGY_STEPS = 100
THRESHOLD_STEP = 1e-3  # runs at the derived threshold ± this fraction of it
SMALLEST_PIVOT = 1e-300  # a pivot this small: the equations of motion do not determine the accelerations
_SINGULAR = "the equations of motion are singular in the simulation"
if TYPE_CHECKING:
    from physics.engine.reach_simulation import ReachMeasure

Point = dict[sympy.Symbol, float]
Vector = list[float]
Measured = tuple[str, float, float | None]  # (what was compared, measured value, own error or None)


def _compile(args: Sequence[sympy.Symbol], exprs: Sequence[sympy.Expr]) -> Callable[..., list[float]]:
    function: Callable[..., Any] = sympy.lambdify(list(args), list(exprs), "math", dummify=True)
    return lambda *values: [float(v) for v in function(*values)]


def solve_numeric(matrix: list[list[float]], rhs: Vector) -> Vector:
    """Gaussian elimination with partial pivoting (the systems here are a handful of unknowns).

    It runs at every step of every integration, so one and two unknowns (most systems) are written out,
    doing the very operations of the general elimination in its order: the same floats to the last bit."""
    n = len(rhs)
    if n == 1:
        head = matrix[0][0]
        if abs(head) < SMALLEST_PIVOT:
            raise DerivationError(_SINGULAR)
        return [(rhs[0] - 0) / head]
    if n == 2:
        (a, b), (c, d) = matrix
        e, f = rhs
        if abs(c) > abs(a):  # the pivot: the first row of the largest size
            a, b, e, c, d, f = c, d, f, a, b, e
        if abs(a) < SMALLEST_PIVOT:
            raise DerivationError(_SINGULAR)
        factor = c / a
        d, f = d - factor * b, f - factor * e
        if abs(d) < SMALLEST_PIVOT:
            raise DerivationError(_SINGULAR)
        second = (f - 0) / d
        return [(e - (0 + b * second)) / a, second]  # 0 + ...: `sum` of one term, as below
    return eliminated(matrix, rhs)


def eliminated(matrix: list[list[float]], rhs: Vector) -> Vector:
    """`solve_numeric` for any number of unknowns."""
    n = len(rhs)
    rows = [[*row, rhs[i]] for i, row in enumerate(matrix)]
    for col in range(n):
        pivot, largest = col, abs(rows[col][col])
        for r in range(col + 1, n):
            size = abs(rows[r][col])
            if size > largest:
                pivot, largest = r, size
        if largest < SMALLEST_PIVOT:
            raise DerivationError(_SINGULAR)
        rows[col], rows[pivot] = rows[pivot], rows[col]
        top = rows[col]
        head = top[col]
        for row in rows[col + 1 :]:
            factor = row[col] / head
            row[col:] = [x - factor * y for x, y in zip(row[col:], top[col:], strict=True)]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        row = rows[r]
        x[r] = (row[n] - sum(row[c] * x[c] for c in range(r + 1, n))) / row[r]
    return x


class Dynamics:
    """The model's equations of motion, compiled for numerical integration."""

    def __init__(self, model: Model, lagrange: LagrangeMethod | None = None) -> None:
        """`lagrange`: the model's own method whose equations the derivation has already formed, if any."""
        self.model = model
        lagrange = lagrange or LagrangeMethod(model, Mechanics(model))
        self.mech = lagrange.mech
        equations, unknowns = lagrange.system
        matrix, rhs = sympy.linear_eq_to_matrix(equations, unknowns)
        self.n = len(self.mech.q)
        self.size = len(unknowns)
        self.params = [p for p in model.parameters if p not in self.mech.q]
        # a force in the time: the time is one more argument, advanced by a clock during integration
        self.clock: int | None = None
        if model.time is not None:
            if model.time not in self.params:
                self.params.append(model.time)
            self.clock = self.params.index(model.time)
        args = [*self.mech.q, *self.mech.qd, *self.params]
        self._matrix = _compile(args, list(matrix))
        self._rhs = _compile(args, list(rhs))
        position = [*self.mech.q, *self.params]
        self._potential = _compile(position, [self.mech.potential])
        self._mapping = _compile(position, [d.mapping for d in self.mech.dofs])
        self._mass = _compile(position, list(self.mech.mass_matrix))
        # generalized non-conservative forces (kinetic friction), given the multipliers: their power
        # is what the mechanical energy may change by
        lam = list(self.mech.multipliers)
        forces = self.mech.load_forces(False, lam)
        self._nonconservative = _compile([*args, *lam], self.mech.generalized(forces))
        dissipative = self.mech.load_forces(False, lam, lambda traits: traits.dissipates)
        self._dissipative = _compile([*args, *lam], self.mech.generalized(dissipative))
        # a support moving as prescribed: its constraints do work, lambda grad(g) . v = -lambda dg/dt,
        # and the kinetic energy has terms in the support's velocity beside q' M q' / 2
        self.driven = driven(model)
        if self.driven:
            assert model.time is not None
            place = {d.symbol: d.mapping for d in self.mech.dofs}
            work = -sympy.Add(
                *(
                    m * sympy.diff(c.gap, model.time).subs(place)
                    for m, c in zip(lam, model.constraints, strict=True)
                )
            )
            self._support_power = _compile([*args, *lam], [work])
            self._kinetic = _compile(args, [self.mech.kinetic])

    def uses(self, symbol: sympy.Symbol) -> bool:
        """Whether the equations of motion or the start depend on the symbol."""
        state = [v for _, v in self.model.state]
        return any(symbol in e.free_symbols for e in [self.mech.kinetic, self.mech.potential, *state]) or any(
            symbol in g.free_symbols for g in self._gaps
        )

    @cached_property
    def _gaps(self) -> list[sympy.Expr]:
        return [c.gap for c in self.model.constraints] + [
            e for load in self.model.loads for e in load.expressions()
        ]

    def values(self, point: Point) -> Vector:
        """The parameters' values at the point, the time from the state where it gives one (the
        derivation's answers are taken there, even when the time is also a symbol of the table)."""
        time = self.model.time
        start = dict(self.model.state).get(time) if time is not None else None
        if start is None and time is not None and time not in point:
            start = sympy.Integer(0)  # a support moving as prescribed, from t = 0 unless the state says
        return [_evaluate(start, point) if p == time and start is not None else point[p] for p in self.params]

    def initial(self, q: Vector, qd: Vector, params: Vector) -> Vector:
        """The integrated state: positions, velocities and, with a force in the time, the time."""
        return [*q, *qd, *([params[self.clock]] if self.clock is not None else [])]

    def later(self, params: Vector, dt: float) -> Vector:
        """The parameters dt later (the clock moved on, when there is one)."""
        if self.clock is None:
            return params
        now = list(params)
        now[self.clock] += dt
        return now

    def at(self, params: Vector, y: Vector, index: int) -> Vector:
        """The parameters at the integrated state y, whose time (if any) is at y[index]."""
        if self.clock is None:
            return params
        now = list(params)
        now[self.clock] = y[index]
        return now

    def unknowns(self, q: Vector, qd: Vector, params: Vector, extra: Vector | None = None) -> Vector:
        flat = self._matrix(*q, *qd, *params)
        matrix = [flat[i * self.size : (i + 1) * self.size] for i in range(self.size)]
        rhs = self._rhs(*q, *qd, *params)
        if extra is not None:
            rhs = [r + (extra[i] if i < self.n else 0.0) for i, r in enumerate(rhs)]
        return solve_numeric(matrix, rhs)

    def derivative(self, params: Vector) -> Callable[[Vector], Vector]:
        n = self.n
        if self.clock is not None:  # y = q, q', t: the time advances with the motion
            return lambda y: [
                *y[n : 2 * n],
                *self.unknowns(y[:n], y[n : 2 * n], self.at(params, y, 2 * n))[:n],
                1.0,
            ]
        return lambda y: y[n:] + self.unknowns(y[:n], y[n:], params)[:n]

    def power(self, q: Vector, qd: Vector, params: Vector, multipliers: Vector) -> float:
        """Power of the non-conservative forces: Q_nc . q'."""
        forces = self._nonconservative(*q, *qd, *params, *multipliers)
        support = self._support_power(*q, *qd, *params, *multipliers)[0] if self.driven else 0.0
        return support + sum(f * v for f, v in zip(forces, qd, strict=True))

    def dissipation(self, q: Vector, qd: Vector, params: Vector, multipliers: Vector) -> float:
        """Power of kinetic friction and drag alone (never positive in a consistent model)."""
        forces = self._dissipative(*q, *qd, *params, *multipliers)
        return sum(f * v for f, v in zip(forces, qd, strict=True))

    def energy(self, q: Vector, qd: Vector, params: Vector) -> float:
        if self.driven:
            return self._kinetic(*q, *qd, *params)[0] + self.potential(q, params)
        matrix = self.mass(q, params)
        kinetic = 0.5 * sum(qd[i] * matrix[i][j] * qd[j] for i in range(self.n) for j in range(self.n))
        return kinetic + self.potential(q, params)

    def potential(self, q: Vector, params: Vector) -> float:
        return self._potential(*q, *params)[0]

    def positions(self, q: Vector, params: Vector) -> Vector:
        return self._mapping(*q, *params)

    def mass(self, q: Vector, params: Vector) -> list[list[float]]:
        flat = self._mass(*q, *params)
        return [flat[i * self.n : (i + 1) * self.n] for i in range(self.n)]


def rk4(f: Callable[[Vector], Vector], y: Vector, dt: float, steps: int) -> list[Vector]:
    """Classical fourth-order Runge-Kutta; returns every state including the first."""
    states = [y]
    for _ in range(steps):
        k1 = f(y)
        k2 = f([a + dt / 2 * b for a, b in zip(y, k1, strict=True)])
        k3 = f([a + dt / 2 * b for a, b in zip(y, k2, strict=True)])
        k4 = f([a + dt * b for a, b in zip(y, k3, strict=True)])
        y = [a + dt / 6 * (b + 2 * c + 2 * d + e) for a, b, c, d, e in zip(y, k1, k2, k3, k4, strict=True)]
        states.append(y)
    return states


Measure = Callable[[Quantity, Point, float], Measured]


@dataclass
class Simulator:
    """Measures the model's quantities numerically at given parameter points."""

    model: Model
    equilibrium_of: Callable[[str], sympy.Expr]
    # the derived value of each quantity (what an expression's inputs are measured near)
    references: Mapping[str, sympy.Expr] = dataclasses.field(default_factory=dict)
    # the derivation's Lagrange method of this same model: its equations and energies, formed once
    lagrange: LagrangeMethod | None = None
    # every coordinate where a coordinate rests at its equilibrium (Method.rest); the others at 0 without it
    rest_of: Callable[[str], Mapping[sympy.Symbol, sympy.Expr]] | None = None
    # after an impact: the bodies' separation along its normal at an integrated state (q, q'), which the
    # motion must keep from closing again (a second impact the model does not follow)
    separation: Callable[[Vector], float] | None = None

    @cached_property
    def dynamics(self) -> Dynamics:
        switched = switched_off(self.model)  # a spring that only pushes lets go past its natural length
        return Dynamics(self.model, self.lagrange) if switched is self.model else Dynamics(switched)

    def check(
        self, quantity: Quantity, reference: sympy.Expr, points: Sequence[Point]
    ) -> SimulationCheck | None:
        measure = self.measure_for(quantity)
        if quantity.after:
            measure = self.after_impact
        elif quantity.bounces is not None:  # just after the n-th bounce
            from physics.engine import bounce_simulation  # it builds on this module

            measure = partial(bounce_simulation.measure_final, self)
        if measure is None:
            return None
        worst = 0.0
        compared = ""
        for point in points:
            expected = _evaluate(reference, point)
            compared, measured, error = measure(quantity, point, expected)
            if error is None:
                error = abs(measured - expected) / max(abs(expected), 1e-12)
            worst = max(worst, error)
            if not error <= TOLERANCE:
                raise DerivationError(
                    f"{quantity.name}: the simulation disagrees with the derivation ({compared}): measured "
                    f"{measured:.8g}, derived {typed_text(reference)} = {expected:.8g} (relative error {error:.2g}) at "
                    + ", ".join(f"{s}={v:.4g}" for s, v in point.items()),
                    quantity=quantity.name,
                )
        return SimulationCheck(compared, worst, len(points))

    def measure_for(self, quantity: Quantity) -> Measure | None:
        """How the simulation measures this quantity (None: it does not)."""
        if quantity.kind is QuantityKind.EXPRESSION:
            return expression_simulation.measure_of(self, quantity)
        return self._reach if _reaches(quantity) else self._measures().get(quantity.kind)

    def _measures(self) -> dict[QuantityKind, Measure]:
        from physics.engine import oscillation_measures  # it integrates with this module's tools

        return {
            QuantityKind.ACCELERATION: self._acceleration,
            QuantityKind.FORCE: self._force,
            QuantityKind.EQUILIBRIUM: self._equilibrium,
            QuantityKind.ANGULAR_FREQUENCY: self._frequency,
            QuantityKind.PERIOD: self._period,
            QuantityKind.STIFFNESS: self._stiffness,
            QuantityKind.POTENTIAL_FORCE: self._potential_force,
            QuantityKind.SOLVE: self._solve,
            QuantityKind.TERMINAL_VELOCITY: self._terminal_velocity,
            QuantityKind.TURNING_POINT: self._reach.turning,
            QuantityKind.NORMAL_FREQUENCY: self._normal_frequency,
            **oscillation_measures.measures(self),
            QuantityKind.PROJECTILE_SPEED: self._collision,
            QuantityKind.ENERGY_FRACTION_LOST: self._collision,
            QuantityKind.VELOCITY_AFTER: self._velocity_after,
            **dict.fromkeys(IMPACT_KINDS, self._impact),
            **dict.fromkeys(ORBIT_KINDS, self._orbit),
            **dict.fromkeys(SLIP_KINDS, partial(slipping.measure_sliding, self)),
            QuantityKind.SLIPPING: partial(slipping.measure_slipping, self),
            **dict.fromkeys(EXTREMUM_KINDS, partial(extremum.measure, self)),
        }

    @cached_property
    def _orbit(self) -> Measure:
        from physics.engine.orbit_simulation import OrbitMeasure  # here: it builds on this module

        return OrbitMeasure(self.dynamics, self._start)

    @cached_property
    def _reach(self) -> ReachMeasure:
        from physics.engine.reach_simulation import ReachMeasure  # it builds on this module

        return ReachMeasure(self)

    @cached_property
    def _impact(self) -> impact_simulation.ImpactMeasure:
        return impact_simulation.ImpactMeasure(self.model)

    @cached_property
    def _bounced(self) -> dict[tuple[tuple[str, float], ...], Simulator]:
        return {}

    def _velocity_after(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        """Just after a collision (the projectile coupled) or an impact (the contact let go)."""
        if self.model.collision is not None:
            return self._collision(quantity, point, expected)
        index = [c.name for c in self.model.coordinates].index(quantity.target)
        return "velocity after an integrated spring-dashpot contact", self._impact.rates(point)[index], None

    def _separation(self, point: Point) -> Callable[[Vector], float]:
        """The impact's normal separation at an integrated state: its row of generalized directions
        times the coordinates' displacement from where the bodies met."""
        row = [_evaluate(a, point) for a in impact.contact(self.model).generalized]
        start, _ = self._start(point)
        return lambda y: sum(a * (q - q0) for a, q, q0 in zip(row, y, start, strict=False))

    def after_impact(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        """The motion after the impact, started with the velocities the integrated contact left (never
        the derived ones), measured as any motion from a state is."""
        count = 1 if quantity.bounces is None else round(_evaluate(quantity.bounces, point))
        key = (*sorted((s.name, v) for s, v in point.items()), ("bounces", count))
        if key not in self._bounced:
            rates = self._impact.rates(point)
            if count != 1:
                from physics.engine import bounce_simulation  # it builds on this module

                rates = bounce_simulation.velocities_after(self, quantity.name, count, point)
            state = {
                **dict(self.model.state),
                **{
                    c.velocity: sympy.Float(r, 17) for c, r in zip(self.model.coordinates, rates, strict=True)
                },
            }
            bounced = dataclasses.replace(self.model, state=tuple(state.items()), impact=None)
            self._bounced[key] = Simulator(
                bounced, self.equilibrium_of, rest_of=self.rest_of, separation=self._separation(point)
            )
        simulator = self._bounced[key]
        inner = dataclasses.replace(quantity, after="", bounces=None)
        measure = simulator._reach if _reaches(inner) else simulator._measures().get(inner.kind)
        if measure is None:
            raise DerivationError(f"{quantity.name}: no simulation of this quantity after an impact")
        what, measured, error = measure(inner, point, expected)
        contacts = "an integrated contact" if count == 1 else f"{count} integrated bounces"
        return f"{what}, after {contacts}", measured, error

    def energy_balance(self, points: Sequence[Point]) -> SimulationCheck | None:
        """Integrate the motion from the model's state and keep the books: the change of T + V must equal
        the work of the non-conservative forces, and friction may only take energy out."""
        worst, moved = 0.0, False
        for point in points:
            change, work, kinetic, dissipated = self._books(point)
            scale = max(kinetic, abs(change), abs(work), 1e-300)
            moved = moved or kinetic > 0
            error = abs(change - work) / scale
            at = ", ".join(f"{s}={v:.4g}" for s, v in point.items())
            if not error <= ENERGY_TOLERANCE:
                raise DerivationError(
                    f"energy bookkeeping fails: over an integrated motion T + V changes by {change:.8g} but the "
                    f"non-conservative forces do work {work:.8g} at {at}",
                    path=(),
                )
            if dissipated > ENERGY_TOLERANCE * scale:
                raise DerivationError(
                    f"kinetic friction or drag does positive work ({dissipated:.8g}) in the integrated motion: a body slides "
                    f"against the direction the model's friction assumes (`sliding`) at {at}",
                    path=("friction",),
                )
            worst = max(worst, error)
        if not moved:
            return None
        return SimulationCheck(
            "work of the non-conservative forces against the change of T + V along an integrated motion",
            worst,
            len(points),
        )

    def _books(self, point: Point) -> tuple[float, float, float, float]:
        """(change of T + V, work of the non-conservative forces, largest kinetic energy) along a short
        integrated motion from the model's state, stopped where a sliding body turns back."""
        dyn = self.dynamics
        params = dyn.values(point)
        q, qd = self._start(point)
        n = dyn.n
        h = self._step_for(point)

        def f(y: Vector) -> Vector:
            now = dyn.at(params, y, 2 * n + 2)  # a force in the time works at the time of the motion
            unknowns = dyn.unknowns(y[:n], y[n : 2 * n], now)
            return [
                *y[n : 2 * n],
                *unknowns[:n],
                dyn.power(y[:n], y[n : 2 * n], now, unknowns[n:]),
                dyn.dissipation(y[:n], y[n : 2 * n], now, unknowns[n:]),
                *([1.0] if dyn.clock is not None else []),
            ]

        slips = self._slip_velocities
        initial = slips(*q, *qd, *params)
        states = [[*q, *qd, 0.0, 0.0, *dyn.initial([], [], params)]]
        for _ in range(ENERGY_STEPS):
            after = rk4(f, states[-1], h, 1)[-1]
            backwards = [k for k, u in enumerate(slips(*after[: 2 * n], *params)) if u < 0]
            # (a collision's state is before the blow: the slide it starts goes the projectile's way)
            if backwards and all(initial[k] <= 0 for k in backwards) and self.model.collision is None:
                name = self.model.frictions[backwards[0]].sliding
                at = ", ".join(f"{s}={v:.4g}" for s, v in point.items())
                if self._pushed_forward(point, backwards[0]):
                    raise DerivationError(
                        f"released at rest from the model's state, the body is pushed towards increasing {name} "
                        "less hard than kinetic friction holds it back: it stays at rest, static friction holding "
                        "it (the model's kinetic friction would drive it backwards). Keep the domain where the "
                        f"push beats friction (domain.positive), or give the state a velocity ({name}_dot > 0) "
                        f"if it is already sliding, at {at}",
                        path=friction_path(self.model, backwards[0]),
                    )
                raise DerivationError(
                    f"released from the model's state, the body slides towards decreasing {name}, against the "
                    f"direction the model's kinetic friction assumes (`sliding: {name}`): give the state a "
                    f"velocity that way ({name}_dot > 0), or check the domain, at {at}",
                    path=friction_path(self.model, backwards[0]),
                )
            if backwards:
                break  # it stopped and turned back: kinetic friction as modelled ends there
            states.append(after)
        start, end = states[0], states[-1]
        # each state's energy at its own time (a support moving as prescribed)
        change = dyn.energy(end[:n], end[n : 2 * n], dyn.at(params, end, 2 * n + 2)) - dyn.energy(
            start[:n], start[n : 2 * n], params
        )
        kinetic = max(
            dyn.energy(y[:n], y[n : 2 * n], now) - dyn.potential(y[:n], now)
            for y in states
            for now in [dyn.at(params, y, 2 * n + 2)]
        )
        return change, end[2 * n], abs(kinetic), end[2 * n + 1]

    def _pushed_forward(self, point: Point, index: int) -> bool:
        """Whether, without its friction, the body at rest at the state would start sliding the way that
        friction assumes: a push that kinetic friction, written as always acting, overpowers."""
        frictionless = Dynamics(dataclasses.replace(self.model, frictions=()))
        params = frictionless.values(point)
        q, qd = self._start(point)
        step = self._step_for(point)
        after = rk4(frictionless.derivative(params), frictionless.initial(q, qd, params), step, 1)[-1]
        n = frictionless.n
        return self._slip_velocities(*after[: 2 * n], *self.dynamics.values(point))[index] > 0

    @cached_property
    def _slip_velocities(self) -> Callable[..., list[float]]:
        """Each kinetic friction's slip velocity (positive: slipping the way `sliding` says)."""
        mech = self.dynamics.mech
        exprs = [slip_velocity(mech, f) for f in self.model.frictions]
        return _compile([*mech.q, *mech.qd, *self.dynamics.params], exprs)

    # --- dynamics from the model's state -----------------------------------------------------

    def _start(self, point: Point) -> tuple[Vector, Vector]:
        state = dict(self.model.state)
        q = [
            _evaluate(state.get(c.symbol, c.symbol if c.symbol in point else sympy.Integer(0)), point)
            for c in self.model.coordinates
        ]
        qd = [_evaluate(state.get(c.velocity, sympy.Integer(0)), point) for c in self.model.coordinates]
        return q, qd

    def _step_for(self, point: Point, start: tuple[Vector, Vector] | None = None) -> float:
        """A finite-difference step short enough that the system moves little (1e-4 of its scale)."""
        dyn = self.dynamics
        q, qd = start if start is not None else self._start(point)
        qdd = dyn.unknowns(q, qd, dyn.values(point))[: dyn.n]
        scale = max([abs(v) for v in q] + [1.0])
        fastest = max([abs(v) for v in qdd] + [1e-300])
        speed = max([abs(v) for v in qd] + [1e-300])
        # how fast the acceleration changes with position (omega^2 of the local motion)
        rate = 1e-300
        for i in range(dyn.n):
            delta = 1e-6 * max(abs(q[i]), 1.0)
            moved = dyn.unknowns(
                [v + (delta if j == i else 0.0) for j, v in enumerate(q)], qd, dyn.values(point)
            )[: dyn.n]
            rate = max(rate, *(abs(a - b) / delta for a, b in zip(moved, qdd, strict=True)))
        step = min(1e-2, math.sqrt(1e-4 * scale / fastest), 1e-3 * scale / speed, 1e-2 / math.sqrt(rate))
        return self._resolve_time(q, qd, point, step)

    def _resolve_time(self, q: Vector, qd: Vector, point: Point, step: float) -> float:
        """With a force in the time, halve the step until the acceleration's own second difference in
        time (the system held still) is negligible: a fast driving force needs a short step."""
        dyn = self.dynamics
        if dyn.clock is None or dyn.n == 0:  # nothing moves but as prescribed: no step to resolve
            return step
        params = dyn.values(point)
        now = params[dyn.clock]
        for _ in range(40):
            before, at, after = (
                dyn.unknowns(q, qd, dyn.at(params, [now + d], 0))[: dyn.n] for d in (-step, 0.0, step)
            )
            size = max([abs(v) for v in (*before, *at, *after)] + [1e-300])
            if max(abs(a - 2 * b + c) for a, b, c in zip(before, at, after, strict=True)) <= 1e-6 * size:
                break
            step /= 2
        return step

    def _trajectory_around(
        self, point: Point, h: float, steps: int = 10, start: tuple[Vector, Vector] | None = None
    ) -> tuple[Vector, ...]:
        dyn = self.dynamics
        q, qd = start if start is not None else self._start(point)
        params = dyn.values(point)
        f = dyn.derivative(params)
        forward = rk4(f, dyn.initial(q, qd, params), h / steps, steps)[-1]
        backward = rk4(f, dyn.initial(q, qd, params), -h / steps, steps)[-1]
        return backward[: dyn.n], q, forward[: dyn.n]

    def _acceleration(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        h = self._step_for(point)
        before, now, after = self._trajectory_around(point, h)
        i = [c.name for c in self.model.coordinates].index(quantity.target)
        return (
            "second difference of the integrated trajectory",
            (after[i] - 2 * now[i] + before[i]) / h**2,
            None,
        )

    def _force(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        """Cartesian accelerations measured on the trajectory, then Newton's law along each normal.

        A second difference is off by h²/12 times the acceleration's own second derivative: beside a
        force of its own size that is noise, but a force that vanishes at the state while the others
        change fast (a pivot's horizontal push on a rod released from the horizontal) would be judged by
        it alone. Measured at h and h/2, the h² term is extrapolated away (Richardson); what is left is
        rounding, judged beside the largest constraint force."""
        h = self._step_for(point)
        index = [c.name for c in self.model.constraints].index(quantity.target)
        coarse, fine = (self._forces_measured(point, step) for step in (h, h / 2))
        forces = [(4 * f - c) / 3 for f, c in zip(fine, coarse, strict=True)]
        largest = max(abs(f) for f in forces)
        error = abs(forces[index] - expected) / max(abs(expected), ROUNDING * largest, 1e-300)
        return (
            "Newton's law applied to the accelerations measured on the integrated trajectory",
            forces[index],
            error,
        )

    def _forces_measured(self, point: Point, h: float) -> list[float]:
        """Every constraint's force, from the accelerations a second difference of step h measures."""
        dyn = self.dynamics
        params = dyn.values(point)
        trajectory = self._trajectory_around(point, h)
        # each position at its own time: a support moving as prescribed carries the bodies with it
        before, now, after = (
            dyn.positions(q, dyn.later(params, dt)) for q, dt in zip(trajectory, (-h, 0.0, h), strict=True)
        )
        accel = [(a - 2 * b + c) / h**2 for a, b, c in zip(before, now, after, strict=True)]
        grads, base, per_lambda, masses = self._force_parts(trajectory[1], point, self._start(point)[1])
        k = len(grads)
        matrix = [
            [
                sum(g * (x + y) for g, x, y in zip(grads[r], grads[c], per_lambda[c], strict=True))
                for c in range(k)
            ]
            for r in range(k)
        ]
        rhs = [
            sum(g * (m * a - f) for g, m, a, f in zip(grads[r], masses, accel, base, strict=True))
            for r in range(k)
        ]
        return solve_numeric(matrix, rhs)

    @cached_property
    def _force_functions(self) -> tuple[Callable[..., list[float]], ...]:
        dyn, mech = self.dynamics, self.dynamics.mech
        position = [*mech.q, *mech.qd, *dyn.params]
        place = {d.symbol: d.mapping for d in mech.dofs}
        grads = [g.subs(place) for k in range(len(self.model.constraints)) for g in mech.gap_gradient(k)]
        # the loads whose size is a constraint force (kinetic friction) are linear in it: per unit force
        free = [sympy.Integer(0) for _ in self.model.constraints]
        base = [
            (-sympy.diff(mech.cartesian_potential, d.symbol)).subs(place) + applied
            for d, applied in zip(mech.dofs, mech.load_forces(False, free), strict=True)
        ]
        units = []
        for k in range(len(self.model.constraints)):
            unit = [sympy.Integer(1 if j == k else 0) for j in range(len(self.model.constraints))]
            units += mech.load_forces(False, unit, lambda traits: bool(traits.constraints))
        masses = [d.inertia for d in mech.dofs]
        return tuple(_compile(position, exprs) for exprs in (grads, base, units, masses))

    def _force_parts(
        self, q: Vector, point: Point, qd: Vector | None = None
    ) -> tuple[list[Vector], Vector, list[Vector], Vector]:
        values = [*q, *(qd if qd is not None else [0.0] * len(q)), *self.dynamics.values(point)]
        grads_f, base_f, units_f, masses_f = self._force_functions
        n = len(self.dynamics.mech.dofs)
        flat_g, flat_u = grads_f(*values), units_f(*values)
        grads = [flat_g[i * n : (i + 1) * n] for i in range(len(flat_g) // n)]
        units = [flat_u[i * n : (i + 1) * n] for i in range(len(flat_u) // n)]
        return grads, base_f(*values), units, masses_f(*values)

    def numeric_modes(self, point: Point) -> tuple[Vector, list[tuple[float, Vector]]]:
        """(equilibrium, [(omega^2, shape)] lowest first): M and K measured numerically from the compiled
        energy at the stable equilibrium, never from the derived matrices."""
        dyn = self.dynamics
        params = dyn.values(point)
        n = dyn.n
        rest = stable_equilibrium(self.model, True)
        q0 = [_evaluate(rest[c.symbol], point) for c in self.model.coordinates]
        h = 1e-4
        stiffness = mpmath.matrix(n, n)
        for i in range(n):
            for j in range(n):

                def shifted(a: float, b: float, i: int = i, j: int = j) -> Vector:
                    return [v + (a if k == i else 0.0) + (b if k == j else 0.0) for k, v in enumerate(q0)]

                stiffness[i, j] = (
                    dyn.potential(shifted(h, h), params)
                    - dyn.potential(shifted(h, -h), params)
                    - dyn.potential(shifted(-h, h), params)
                    + dyn.potential(shifted(-h, -h), params)
                ) / (4 * h * h)
        mass = mpmath.matrix(dyn.mass(q0, params))
        found = mpmath.eig(mass**-1 * stiffness)
        values, vectors = found[0], found[-1]  # a 1 x 1 matrix gives (E, EL, ER) whatever is asked
        modes = sorted(
            (float(mpmath.re(v)), [float(mpmath.re(vectors[k, c])) for k in range(n)])
            for c, v in enumerate(values)
            if abs(v) > 1e-9 * max(abs(x) for x in values)
        )
        return q0, modes

    def _normal_frequency(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        """Released from the equilibrium displaced along the mode, the integrated motion's period."""
        dyn = self.dynamics
        params = dyn.values(point)
        n = dyn.n
        q0, modes = self.numeric_modes(point)
        omega2, shape = modes[int(quantity.target) - 1]
        largest = max(range(n), key=lambda k: abs(shape[k]))
        size = 1e-4 / abs(shape[largest])
        start = [v + size * x for v, x in zip(q0, shape, strict=True)]
        estimate = 2 * math.pi / math.sqrt(omega2)
        per_period = 400
        states = rk4(dyn.derivative(params), start + [0.0] * n, estimate / per_period, int(3.3 * per_period))
        values_i = [y[largest] - q0[largest] for y in states]
        crossings = [
            k + values_i[k] / (values_i[k] - values_i[k + 1])
            for k in range(len(values_i) - 1)
            if values_i[k] < 0 <= values_i[k + 1]
        ]
        if len(crossings) < 2:
            raise DerivationError(f"{quantity.name}: no oscillation seen in the simulation")
        period = (crossings[-1] - crossings[0]) / (len(crossings) - 1) * estimate / per_period
        return "2 pi / period of the integrated motion released along the mode", 2 * math.pi / period, None

    def _terminal_velocity(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        """Released with that velocity zero, the integrated motion settles to a constant velocity."""
        dyn = self.dynamics
        params = dyn.values(point)
        i = [c.name for c in self.model.coordinates].index(quantity.target)
        q, qd = self._start(point)
        qd[i] = 0.0
        initial = abs(dyn.unknowns(q, qd, params)[i]) or 1.0
        relax = abs(expected) / initial  # time to reach the derived speed at the initial acceleration
        y = rk4(dyn.derivative(params), [*q, *qd], relax / 100, 3000)[-1]
        return "velocity the integrated motion settles to, released from rest", y[dyn.n + i], None

    def _solve(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        """Integrate with the derived parameter value: the inner acceleration must vanish, measured against
        the acceleration with half that value. Any other inner quantity the simulation measures (a
        normal force where the motion gets to, a speed) is a threshold: measured on runs just below and
        just above the derived value, it must change sign, and where it crosses zero is compared."""
        inner, parameter = quantity.inner, quantity.parameter
        if inner is None or parameter is None:
            raise DerivationError(f"{quantity.name}: no simulation for this kind of condition")
        if inner.kind is not QuantityKind.ACCELERATION or inner.at:
            return self._threshold(quantity, inner, parameter, point, expected)
        at_value = self._acceleration(inner, {**point, parameter: expected}, 0.0)[1]
        at_half = self._acceleration(inner, {**point, parameter: expected / 2}, 0.0)[1]
        return (
            "acceleration of the integrated motion with the derived value (relative to half the value)",
            at_value,
            abs(at_value) / max(abs(at_half), 1e-300),
        )

    def _threshold(
        self, quantity: Quantity, inner: Quantity, parameter: sympy.Symbol, point: Point, expected: float
    ) -> Measured:
        measure = self._reach if _reaches(inner) else self._measures().get(inner.kind)
        if measure is None or inner.kind is QuantityKind.SOLVE:
            raise DerivationError(f"{quantity.name}: no simulation for this kind of condition")
        if inner.kind in vanishing_frequency.KINDS and not inner.at:
            crossing = vanishing_frequency.measured_zero(
                lambda value: measure(inner, {**point, parameter: value}, 0.0)[1], expected, quantity.name
            )
            return (
                f"where the integrated {inner.kind.value.replace('_', ' ')}, squared and measured on runs that "
                "swing, extrapolates to zero",
                crossing,
                None,
            )
        if inner.kind in (QuantityKind.SPEED, QuantityKind.VELOCITY) and inner.at:
            return self._least_to_reach(quantity, inner, parameter, point, expected, measure)
        step = THRESHOLD_STEP * max(abs(expected), 1e-12)
        below, above = expected - step, expected + step
        try:
            low, high = self._either_side(inner, parameter, point, expected, (below, above), measure)
        except DerivationError as error:
            raise DerivationError(
                f"{quantity.name}: the runs either side of {parameter} = {expected:.6g} fail: {error.message}",
                quantity=quantity.name,
            ) from None
        if low * high > 0 or low == high:
            raise DerivationError(
                f"{quantity.name}: the integrated {inner.kind.value.replace('_', ' ')} does not change sign across "
                f"{parameter} = {expected:.6g}: {low:.6g} at {below:.6g}, {high:.6g} at {above:.6g}",
                quantity=quantity.name,
            )
        crossing = below - low * (above - below) / (high - low)
        return (
            f"where the integrated {inner.kind.value.replace('_', ' ')} changes sign, between runs just below and "
            "just above",
            crossing,
            None,
        )

    def _least_to_reach(
        self,
        quantity: Quantity,
        inner: Quantity,
        parameter: sympy.Symbol,
        point: Point,
        expected: float,
        measure: Measure,
    ) -> Measured:
        """A speed vanishing where the motion gets to: the least launch that gets there. Below it the motion
        turns back first, so there is no speed to measure; the runs just either side of the derived value
        must be one that turns back and one that gets there, which brackets the threshold."""
        step = THRESHOLD_STEP / 4 * max(abs(expected), 1e-12)
        gets_there = []
        for value in (expected - step, expected + step):
            try:
                measure(inner, {**point, parameter: value}, 0.0)
                gets_there.append(True)
            except DerivationError:
                gets_there.append(False)
        if gets_there[0] == gets_there[1]:
            ((coordinate, end),) = inner.at
            raise DerivationError(
                f"{quantity.name}: the integrated motion {'gets' if gets_there[0] else 'does not get'} to "
                f"{coordinate} = {typed_text(end)} on both sides of {parameter} = {expected:.6g}",
                quantity=quantity.name,
            )
        return (
            "between runs just below and just above, of which one turns back before it gets there",
            expected,
            step / max(abs(expected), 1e-12),
        )

    def _either_side(
        self,
        inner: Quantity,
        parameter: sympy.Symbol,
        point: Point,
        expected: float,
        values: tuple[float, float],
        measure: Measure,
    ) -> tuple[float, float]:
        """The inner quantity measured with the parameter at each of `values`."""
        ends = [value for _, value in inner.at]
        if (
            inner.at
            and not self.dynamics.uses(parameter)
            and all(v.free_symbols <= {parameter} for v in ends)
        ):
            # the parameter only says where the motion is read: one run, read as it passes each value
            ((_, end),) = inner.at
            places = [_evaluate(end, {**point, parameter: v}) for v in values]
            low, high = self._reach.crossings(inner, {**point, parameter: expected}, places)
            return low, high
        low = measure(inner, {**point, parameter: values[0]}, 0.0)[1]
        high = measure(inner, {**point, parameter: values[1]}, 0.0)[1]
        return low, high

    # --- potentials and oscillations ---------------------------------------------------------

    def _oscillate(self, coordinate: str, point: Point) -> tuple[float, list[float], float]:
        """(equilibrium, turning-point values, measured period) of a small oscillation."""
        dyn = self.dynamics
        params = dyn.values(point)
        i = [c.name for c in self.model.coordinates].index(coordinate)
        base = self._rest(coordinate, point)
        q0 = base[i]
        scale = max(abs(q0), 1.0)
        h = 1e-3 * scale

        def shifted(delta: float) -> Vector:
            return [b + (delta if k == i else 0.0) for k, b in enumerate(base)]

        stiffness = (
            dyn.potential(shifted(h), params)
            - 2 * dyn.potential(base, params)
            + dyn.potential(shifted(-h), params)
        ) / h**2
        inertia = dyn.mass(base, params)[i][i]
        if self.model.loads_where(lambda t: not (t.conservative or t.dissipates or t.constraints)):
            # a force in the coordinates pulls back too (a torque k R s): its slope, from the accelerations
            pull = [dyn.unknowns(shifted(d), [0.0] * dyn.n, params)[i] for d in (h, -h)]
            stiffness = -inertia * (pull[0] - pull[1]) / (2 * h)
        if stiffness <= 0:
            raise DerivationError(
                f"{coordinate}: the potential is not a minimum at the equilibrium {typed_text(q0)}"
            )
        estimate = 2 * math.pi * math.sqrt(inertia / stiffness)
        per_period = 400
        start = shifted(1e-4 * (abs(q0) or 1.0))
        states = rk4(  # with a support moving as prescribed, its clock too
            dyn.derivative(params),
            dyn.initial(start, [0.0] * dyn.n, params),
            estimate / per_period,
            int(3.3 * per_period),
        )
        values = [s[i] - q0 for s in states]
        crossings = [
            k + values[k] / (values[k] - values[k + 1])
            for k in range(len(values) - 1)
            if values[k] < 0 <= values[k + 1]
        ]
        if len(crossings) < 2:
            raise DerivationError(f"{coordinate}: no oscillation seen in the simulation")
        period = (crossings[-1] - crossings[0]) / (len(crossings) - 1) * estimate / per_period
        return q0, [max(values) + q0, min(values) + q0], period

    def _rest(self, coordinate: str, point: Point) -> Vector:
        """The coordinates' values where `coordinate` rests at its equilibrium."""
        rest = self.rest_of(coordinate) if self.rest_of is not None else {}
        q0 = self.equilibrium_of(coordinate)
        return [
            _evaluate(q0, point)
            if c.name == coordinate
            else _evaluate(rest.get(c.symbol, sympy.Integer(0)), point)
            for c in self.model.coordinates
        ]

    def _equilibrium(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        q0, (high, low), _ = self._oscillate(quantity.target, point)
        centre = (high + low) / 2
        # an equilibrium at 0 has no scale of its own: measure against the unit the oscillation used
        return "centre of a small integrated oscillation", centre, abs(centre - q0) / max(abs(q0), 1.0)

    def _frequency(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        omega = 2 * math.pi / self._oscillate(quantity.target, point)[2]
        return "2 pi / period of the integrated motion", omega, None

    def _period(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        return "period of the integrated motion", self._oscillate(quantity.target, point)[2], None

    def _coordinate_point(self, coordinate: str, point: Point) -> tuple[int, Vector, Vector]:
        dyn = self.dynamics
        i = [c.name for c in self.model.coordinates].index(coordinate)
        q = [point.get(c.symbol, 0.0) for c in self.model.coordinates]
        return i, q, dyn.values(point)

    def _measured_generalized_force(self, i: int, q: Vector, point: Point) -> float:
        """Release the system at rest at q, measure the Cartesian accelerations on the integrated
        trajectory, and return their virtual work along coordinate i: sum m_k a_k dx_k/dq_i (the
        constraint forces do no virtual work, so this is the generalized force of the applied forces)."""
        dyn = self.dynamics
        params = dyn.values(point)
        start = (q, [0.0] * dyn.n)
        h = self._step_for(point, start)
        before, now, after = (
            dyn.positions(x, dyn.later(params, dt))
            for x, dt in zip(self._trajectory_around(point, h, start=start), (-h, 0.0, h), strict=True)
        )
        accel = [(a - 2 * b + c) / h**2 for a, b, c in zip(before, now, after, strict=True)]
        if dyn.driven:  # relative to the support: less the acceleration the bodies have held at q
            held = [dyn.positions(q, dyn.later(params, dt)) for dt in (-h, 0.0, h)]
            accel = [x - (a - 2 * b + c) / h**2 for x, a, b, c in zip(accel, *held, strict=True)]
        masses = self._force_parts(q, point)[3]
        step = 1e-6 * max(abs(q[i]), 1.0)
        up = dyn.positions([v + (step if j == i else 0.0) for j, v in enumerate(q)], params)
        down = dyn.positions([v - (step if j == i else 0.0) for j, v in enumerate(q)], params)
        return sum(m * a * (u - d) / (2 * step) for m, a, u, d in zip(masses, accel, up, down, strict=True))

    def _stiffness(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        i = [c.name for c in self.model.coordinates].index(quantity.target)
        base = self._rest(quantity.target, point)
        h = 1e-4 * (abs(base[i]) or 1.0)
        forces = [
            self._measured_generalized_force(i, [b + d if j == i else b for j, b in enumerate(base)], point)
            for d in (-h, h)
        ]
        return (
            "slope of the generalized force measured on trajectories released at rest beside the equilibrium",
            -(forces[1] - forces[0]) / (2 * h),
            None,
        )

    def _potential_force(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        i, q, _ = self._coordinate_point(quantity.target, point)
        return (
            "virtual work of the accelerations measured on a trajectory released at rest",
            self._measured_generalized_force(i, q, point),
            None,
        )

    @cached_property
    def _after(self) -> Dynamics:
        return Dynamics(merged(self.model))

    @cached_property
    def _target_motion(self) -> Callable[..., list[float]]:
        """d(struck point)/dq on each axis (x row, then y row), compiled: the velocity of the point the
        projectile strikes (the target's position, or a `point` of a rigid target) is this times q',
        however the constraints guide it (along an incline, round a pendulum's arc)."""
        hit = self.model.collision
        assert hit is not None
        mech = self.dynamics.mech
        position = embedding.struck(self.model)
        rows = [sympy.diff(position.get(axis, sympy.Integer(0)), q) for axis in AXES for q in mech.q]
        return _compile([*mech.q, *self.dynamics.params], rows)

    def _collision(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        """The projectile, a particle in the plane, couples to the target by a stiff drag on their relative
        velocity until they move together (a perfectly inelastic collision): the target's constraints
        take whatever part of the blow they resist. Then the merged body moves until it turns back."""
        hit = self.model.collision
        assert hit is not None
        before, after = self.dynamics, self._after
        params = before.values(point)
        n = before.n
        names = [c.name for c in self.model.coordinates]
        at = dict(hit.at)
        q0 = [_evaluate(at.get(name, sympy.Integer(0)), point) for name in names]
        mass = _evaluate(hit.projectile_mass, point)
        speed = (
            expected
            if quantity.kind is QuantityKind.PROJECTILE_SPEED
            else 1.0
            if hit.speed is None
            else _evaluate(hit.speed, point)
        )
        direction = [_evaluate(dict(hit.direction).get(axis, sympy.Integer(0)), point) for axis in AXES]
        norm = math.hypot(*direction)
        tau = 1e-6  # short beside every other time: friction or a spring acting meanwhile takes no part
        drag = mass / tau
        # the projectile's weight, while it is being stopped: the merged body carries it from then on
        weight = [0.0, -_evaluate(self.model.gravity, point) if self.model.gravity is not None else 0.0]

        def f(y: Vector) -> Vector:
            q, qd, u = y[:n], y[n : 2 * n], y[2 * n : 2 * n + len(AXES)]
            rows = self._target_motion(*q, *params)
            jacobian = [rows[k * n : (k + 1) * n] for k in range(len(AXES))]
            force = [
                drag * (u[k] - sum(a * b for a, b in zip(jacobian[k], qd, strict=True)))
                for k in range(len(AXES))
            ]
            generalized = [sum(force[k] * jacobian[k][j] for k in range(len(AXES))) for j in range(n)]
            qdd = before.unknowns(q, qd, params, extra=generalized)[:n]
            # last: the projectile's height, for the work of its weight
            return [*qd, *qdd, *(-p / mass + w for p, w in zip(force, weight, strict=True)), u[1]]

        start = [*q0, *[0.0] * n, *(speed * d / norm for d in direction), 0.0]
        end = rk4(f, start, tau / 10, 300)[-1]
        q1, qd1, u1, rise = end[:n], end[n : 2 * n], end[2 * n : 2 * n + len(AXES)], end[-1]
        matrix = before.mass(q1, params)
        kinetic = 0.5 * mass * sum(c * c for c in u1) + 0.5 * sum(
            qd1[i] * matrix[i][j] * qd1[j] for i in range(n) for j in range(n)
        )
        initial = 0.5 * mass * speed**2
        gained = before.potential(q1, params) - before.potential(q0, params) - mass * weight[1] * rise
        lost = (initial - kinetic - gained) / initial
        if quantity.kind is QuantityKind.ENERGY_FRACTION_LOST:
            return "kinetic energy lost in an integrated stiff inelastic coupling", lost, None
        if quantity.kind is QuantityKind.VELOCITY_AFTER:
            measured = qd1[names.index(quantity.target)]
            return "velocity at the end of an integrated stiff inelastic coupling", measured, None
        ((name, target_text),) = hit.reaches
        i = names.index(name)
        target = _evaluate(target_text, point)
        step = after.derivative(after.values(point))
        y, reached = [*q1, *qd1], q1[i]
        sign = math.copysign(1.0, qd1[i])
        for _ in range(200_000):
            y = rk4(step, y, 2e-3, 1)[-1]
            reached = max(reached * sign, y[i] * sign) * sign
            if y[n + i] * sign <= 0:
                break
        else:
            raise DerivationError(f"{quantity.name}: the simulated motion never turned back")
        return (
            "turning point reached after an integrated inelastic collision at the derived speed",
            reached,
            abs(reached - target) / max(abs(target), 1e-12),
        )


def _reaches(quantity: Quantity) -> bool:
    """Taken where the motion from the state gets to (`at`, a flight's end or apex): see reach_simulation."""
    return bool(quantity.at) or quantity.kind in TRAJECTORY_KINDS


def _evaluate(expr: sympy.Expr, point: Point) -> float:
    value = sympy.N(expr.subs(point), 20)
    if not value.is_real:
        raise DerivationError(f"{typed_text(expr)} is not real at {typed_text(point)}")
    return float(value)
