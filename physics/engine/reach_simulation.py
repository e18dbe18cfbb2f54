"""Measuring where the motion gets to: integrate the equations of motion from the model's state until an
event (the coordinate reaches `at`, the body lands or passes its apex), locate the event within the step
by bisection, and read the quantity off the integrated state. The closed form is never used to steer
the integration, only to be compared with what was measured.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

from physics.engine.mechanics import time_derivative
from physics.engine.model import TRAJECTORY_KINDS, Quantity, QuantityKind
from physics.engine.simulation import Measured, Point, Simulator, Vector, _compile, _evaluate, rk4
from physics.errors import DerivationError

STEPS_PER_SCALE = 400  # RK4 steps per time scale of the motion: errors far below the 1e-3 tolerance
MAX_SCALES = 200
BISECTIONS = 60
PUSH = 1e-4  # a vanishing push off an unstable equilibrium, as a share of the motion's speed
EQUILIBRIUM_ROUNDING = 1e-9  # an acceleration this small against its growth over the distance is none
TANGENCY = 1e-6  # of the distance: a turn this close to the target is the target reached at zero rate
SEPARATION_ROUNDING = 1e-7  # of the coordinates' size: bodies left just touching (e = 0) are not closing


@dataclass
class ReachMeasure:
    """Integrates once per (parameter point, event) and measures every quantity taken there."""

    simulator: Simulator
    _events: dict[tuple[object, ...], tuple[float, Vector]] = field(default_factory=dict)
    _velocities: dict[str, Callable[..., list[float]]] = field(default_factory=dict)

    def __call__(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        if quantity.kind in TRAJECTORY_KINDS:
            return self._flight(quantity, point)
        return self._arrival(quantity, point, expected)

    # --- a coordinate reaching a value -----------------------------------------------------------

    def _arrival(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        ((name, value),) = quantity.at
        target = _evaluate(value, point)
        key = (name, target, *sorted((str(s), v) for s, v in point.items()))
        if key not in self._events:
            self._events[key] = self._arrive(quantity, point, [target])[0]
        compared, measured, error = self._read(quantity, self._events[key][1], point)
        if quantity.kind is QuantityKind.VELOCITY and expected == 0:
            # a rate that vanishes where it arrives (the top of a throw) is measured against its start
            j = [c.name for c in self.simulator.model.coordinates].index(quantity.target)
            start = abs(self.simulator._start(point)[1][j])
            error = abs(measured) / start if start else None
        return compared, measured, error

    def crossings(self, quantity: Quantity, point: Point, targets: list[float]) -> list[float]:
        """The quantity where one integrated motion reaches each of `targets` in turn (the same motion:
        the targets are not in its equations), read at each."""
        return [self._read(quantity, y, point)[1] for _, y in self._arrive(quantity, point, targets)]

    def _arrive(self, quantity: Quantity, point: Point, targets: list[float]) -> list[tuple[float, Vector]]:
        sim = self.simulator
        dyn = sim.dynamics
        ((name, _),) = quantity.at
        i = [c.name for c in sim.model.coordinates].index(name)
        q, qd = sim._start(point)
        sign = math.copysign(1.0, targets[-1] - q[i])
        params = dyn.values(point)
        acceleration = dyn.unknowns(q, qd, params)[i]
        distance = abs(targets[-1] - q[i])
        scales = [distance / abs(qd[i])] if qd[i] else []
        if not scales and self._balanced(q, qd, i, sign, distance, params, acceleration):
            # at rest where nothing pulls (sin(pi) leaves rounding): from the top with a vanishing push
            scales = [self._push(q, qd, i, sign, distance, params, quantity.name)]
        scales += [math.sqrt(2 * distance / abs(acceleration))] if acceleration else []

        def heading(y: Vector) -> float:
            """The rate towards the targets, once the coordinate has left its start (rounding at rest)."""
            return y[dyn.n + i] * sign if abs(y[i] - q[i]) > 1e-9 * max(distance, 1.0) else 1.0

        events: list[tuple[float, Vector]] = []
        y, elapsed = dyn.initial(q, qd, params), 0.0  # with a clock when a support moves as prescribed
        for target in targets:

            def passed(state: Vector, at: float = target) -> float:
                return sign * (state[i] - at)

            def touches(state: Vector, at: float = target) -> bool:
                # a turning point on the target (a projectile's top) is reached there, at zero rate
                return abs(state[i] - at) <= TANGENCY * max(distance, 1e-12)

            time, y = self._integrate(y, min(scales), point, passed, quantity.name, heading, touches)
            elapsed += time
            events.append((elapsed, y))
        return events

    def _read(self, quantity: Quantity, y: Vector, point: Point) -> Measured:
        sim = self.simulator
        dyn = sim.dynamics
        ((name, _),) = quantity.at
        n = dyn.n
        now = dyn.at(dyn.values(point), y, 2 * n)  # the parameters at the time the motion arrives
        y = y[: 2 * n]
        names = [c.name for c in sim.model.coordinates]
        if quantity.kind is QuantityKind.VELOCITY:
            j = names.index(quantity.target)
            return f"velocity of {quantity.target} when the integrated motion reaches {name}", y[n + j], None
        if quantity.kind is QuantityKind.SPEED:
            velocity = self._velocity(quantity.target)(*y, *now)
            return (
                f"speed of {quantity.target} when the integrated motion reaches {name}",
                math.hypot(*velocity),
                None,
            )
        unknowns = dyn.unknowns(y[:n], y[n:], now)
        if quantity.kind is QuantityKind.ACCELERATION:
            return (
                f"acceleration of {quantity.target} from the equations of motion where the integration arrives "
                f"({name})",
                unknowns[names.index(quantity.target)],
                None,
            )
        index = [c.name for c in sim.model.constraints].index(quantity.target)
        return (
            f"constraint force from the equations of motion at the state the integration reached ({name})",
            unknowns[n + index],
            None,
        )

    def _balanced(
        self, q: Vector, qd: Vector, i: int, sign: float, distance: float, params: Vector, acceleration: float
    ) -> bool:
        """At rest on an equilibrium: the acceleration there is rounding next to how it grows away from it
        (a rod balanced upright at phi = pi, where sin(pi) is 1.2e-16, not 0)."""
        if not acceleration:
            return True
        h = 1e-6 * max(distance, 1e-12)
        moved = list(q)
        moved[i] += sign * h
        growth = abs(self.simulator.dynamics.unknowns(moved, qd, params)[i] - acceleration) / h * distance
        return abs(acceleration) <= EQUILIBRIUM_ROUNDING * growth

    def _push(
        self, q: Vector, qd: Vector, i: int, sign: float, distance: float, params: Vector, name: str
    ) -> float:
        """A state at rest on an unstable equilibrium (a block on top of a dome): the motion the
        derivation describes starts with a vanishing push towards the target. Sets that push in qd (a
        velocity whose energy is PUSH^2 of the motion's) and returns the time scale of the runaway,
        1/sqrt(da/dq); refused if the equilibrium is stable that way (the coordinate would not move)."""
        dyn = self.simulator.dynamics
        h = 1e-6 * max(distance, 1e-12)
        moved = list(q)
        moved[i] += sign * h
        slope = (dyn.unknowns(moved, qd, params)[i] - dyn.unknowns(q, qd, params)[i]) * sign / h
        if not slope > 0:
            raise DerivationError(f"{name}: released at rest at the state, the coordinate does not move")
        scale = 1 / math.sqrt(slope)
        qd[i] = sign * PUSH * distance / scale
        return scale

    # --- where the coordinate turns ----------------------------------------------------------------

    def turning(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        """Integrate until the coordinate's rate changes sign; the derived value sets only the time scale."""
        sim = self.simulator
        dyn = sim.dynamics
        i = [c.name for c in sim.model.coordinates].index(quantity.target)
        q, qd = sim._start(point)
        params = dyn.values(point)
        acceleration = dyn.unknowns(q, qd, params)[i]
        heading = math.copysign(1.0, qd[i] if qd[i] else acceleration)
        distance = abs(expected - q[i]) or 1.0
        scales = [distance / abs(qd[i])] if qd[i] else []
        scales += [math.sqrt(2 * distance / abs(acceleration))] if acceleration else []
        if not scales:
            raise DerivationError(
                f"{quantity.name}: at rest where nothing pulls, the coordinate does not move"
            )

        def reversed_rate(y: Vector) -> float:
            return -heading * y[dyn.n + i]

        _, y = self._integrate(q + qd, min(scales), point, reversed_rate, quantity.name)
        return f"where the integrated motion of {quantity.target} stops and turns back", y[i], None

    # --- a body in flight --------------------------------------------------------------------------

    def _flight(self, quantity: Quantity, point: Point) -> Measured:
        sim = self.simulator
        dyn = sim.dynamics
        params = dyn.values(point)
        q, qd = sim._start(point)
        names = [d.name for d in dyn.mech.dofs]
        axes = [a for a, _ in sim.model.body(quantity.target).position]
        place = {a: names.index(f"{a}_{quantity.target}") for a in axes}
        start = dyn.positions(q, params)
        velocity = self._velocity(quantity.target)
        vy_index = axes.index("y")
        vx = velocity(*q, *qd, *params)
        # the vertical acceleration at launch, measured by a short integrated step: a time scale only
        h = 1e-6
        after = sim_rk4(dyn.derivative(params), q + qd, h)
        ay = (velocity(*after, *params)[vy_index] - vx[vy_index]) / h
        y0 = start[place["y"]]
        level = _evaluate(quantity.level, point) if quantity.level is not None else y0
        if ay >= 0:
            raise DerivationError(f"{quantity.name}: nothing pulls {quantity.target} down in the simulation")
        vy = vx[vy_index]
        scale = (abs(vy) + math.sqrt(vy**2 + 2 * abs(ay) * abs(y0 - level))) / abs(ay)
        x0 = start[place["x"]] if "x" in place else 0.0
        slope = _evaluate(quantity.slope, point) if quantity.slope is not None else None
        if slope is not None:  # the time to come back to the launch's line, falling as it does: a scale only
            horizontal = vx[axes.index("x")] if "x" in axes else 0.0
            scale = max(scale, 2 * abs(horizontal * math.tan(slope) - vy) / abs(ay))
        if quantity.kind is QuantityKind.MAX_HEIGHT:
            key: tuple[object, ...] = ("apex", *sorted((str(s), v) for s, v in point.items()))

            def event(y: Vector) -> float:
                return -velocity(*y, *params)[vy_index]

        elif slope is not None:
            key = ("slope", slope, *sorted((str(s), v) for s, v in point.items()))

            def event(y: Vector) -> float:
                now = dyn.positions(y[: dyn.n], params)
                across = now[place["x"]] - x0 if "x" in place else 0.0
                return y0 + across * math.tan(slope) - now[place["y"]]

        else:
            key = ("landing", level, *sorted((str(s), v) for s, v in point.items()))

            def event(y: Vector) -> float:
                return level - dyn.positions(y[: dyn.n], params)[place["y"]]

        if key not in self._events:
            self._events[key] = self._integrate(q + qd, scale, point, event, quantity.name)
        time, y = self._events[key]
        now = dyn.positions(y[: dyn.n], params)
        if quantity.kind is QuantityKind.TIME_OF_FLIGHT:
            landing = "lands on the slope" if slope is not None else "comes down to the landing level"
            return f"time until the integrated flight {landing}", time, None
        if quantity.kind is QuantityKind.RANGE and slope is not None:
            return (
                "distance along the slope of the integrated flight where it lands on it",
                (now[place["x"]] - x0) / math.cos(slope),
                None,
            )
        if quantity.kind is QuantityKind.RANGE:
            return (
                "horizontal distance of the integrated flight at the landing level",
                now[place["x"]] - start[place["x"]],
                None,
            )
        return "height of the integrated flight where it stops rising", now[place["y"]] - y0, None

    # --- shared ------------------------------------------------------------------------------------

    def _integrate(
        self,
        y: Vector,
        scale: float,
        point: Point,
        event: Callable[[Vector], float],
        name: str,
        heading: Callable[[Vector], float] | None = None,
        touches: Callable[[Vector], bool] = lambda y: False,
    ) -> tuple[float, Vector]:
        """(time, state) where `event` first goes from negative to zero or above, after the start; or,
        with `heading` (the rate towards the event), where that rate first vanishes if `touches` there."""
        dyn = self.simulator.dynamics
        f = dyn.derivative(dyn.values(point))
        dt = scale / STEPS_PER_SCALE
        before = event(y)
        for step in range(STEPS_PER_SCALE * MAX_SCALES):
            after_y = sim_rk4(f, y, dt)
            after = event(after_y)
            if before < 0 <= after:
                time = _bisect(f, y, dt, event)
                return step * dt + time, sim_rk4(f, y, time)
            if heading is not None and heading(after_y) < 0:
                time = _bisect(f, y, dt, lambda s: -heading(s))
                turn = sim_rk4(f, y, time)
                if touches(turn):
                    return step * dt + time, turn
                raise DerivationError(f"{name}: the integrated motion turns back before it gets there")
            self._keep_apart(after_y, name)
            y, before = after_y, after
        raise DerivationError(f"{name}: the integrated motion never gets there")

    def _keep_apart(self, y: Vector, name: str) -> None:
        """After an impact the bodies must not close on each other again before the motion gets where
        the quantity is taken: a cart that bounces weakly off one on a spring is caught up by it."""
        separation = self.simulator.separation
        if separation is None:
            return
        scale = max([abs(v) for v in y[: self.simulator.dynamics.n]] + [1.0])
        if separation(y) < -SEPARATION_ROUNDING * scale:
            raise DerivationError(
                f"{name}: after the impact the bodies meet again before the motion gets there (their "
                "separation along the impact's normal closes): a second impact, which the model does not "
                "follow. Ask about a motion that ends before they meet again, or model the second impact"
            )

    def _velocity(self, body: str) -> Callable[..., list[float]]:
        """The body's Cartesian velocity (its position's axes) as a compiled function of q, q', parameters."""
        if body not in self._velocities:
            sim = self.simulator
            dyn, model = sim.dynamics, sim.model
            exprs = [time_derivative(e, model) for _, e in model.body(body).position]
            self._velocities[body] = _compile([*dyn.mech.q, *dyn.mech.qd, *dyn.params], exprs)
        return self._velocities[body]


def _bisect(f: Callable[[Vector], Vector], y: Vector, dt: float, event: Callable[[Vector], float]) -> float:
    """The time within a step of length dt from y where `event` goes from negative to zero or above."""
    low, high = 0.0, dt
    for _ in range(BISECTIONS):
        middle = (low + high) / 2
        if event(sim_rk4(f, y, middle)) >= 0:
            high = middle
        else:
            low = middle
    return high


def sim_rk4(f: Callable[[Vector], Vector], y: Vector, dt: float) -> Vector:
    return rk4(f, y, dt, 1)[-1]
