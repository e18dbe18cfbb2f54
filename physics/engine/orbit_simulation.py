"""Orbits measured on the integrated equations of motion, never on the derived formulas.

- steady motion: the simulation finds the rate itself (the root of the other coordinates' numerical
  accelerations, by secant in the squared rate), integrates one revolution with RK4, checks that the
  other coordinates stayed put, and measures the time of one turn, the distance travelled over it
  divided by that time, and T + V;
- the effective potential: the momenta of the cyclic coordinates are taken from the state; the radial
  acceleration with them held is scanned for the root where it turns from outward to inward (the
  circular orbit), and an orbit launched just beside it is integrated: the centre of its radial
  oscillation is the radius, 2 pi over its period the epicyclic frequency;
- `mechanical_energy`: T + V of the state from the compiled mass matrix and potential.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import cached_property

import sympy

from physics.engine.conservation import cyclic_indices
from physics.engine.model import Quantity, QuantityKind
from physics.engine.orbits import FRAME, elsewhere
from physics.engine.simulation import Dynamics, Measured, Point, Vector, rk4, solve_numeric
from physics.errors import DerivationError

PER_TURN = 1000  # RK4 steps per revolution: the chord sum then misses 2e-6 of the circumference
PER_OSCILLATION = 400
STAYS_PUT = 1e-6  # largest relative drift of the held coordinates over one integrated revolution
SCAN = [10 ** (k / 20) for k in range(-120, 121)]  # radii from 1e-6 to 1e6 times the state's scale

Start = Callable[[Point], tuple[Vector, Vector]]


class OrbitMeasure:
    """Measures the orbit quantities of one model at parameter points."""

    def __init__(self, dynamics: Dynamics, start: Start) -> None:
        self.dyn = dynamics
        self.model = dynamics.model
        self.start = start
        self._turns: dict[tuple[str, tuple[float, ...]], tuple[float, float, float]] = {}

    def __call__(self, quantity: Quantity, point: Point, expected: float) -> Measured:
        kind = quantity.kind
        if kind is QuantityKind.MECHANICAL_ENERGY:
            q, qd = self.start(point)
            energy = self.dyn.energy(q, qd, self.dyn.values(point))
            return "T + V of the state from the compiled mass matrix and potential", energy, None
        if kind in (QuantityKind.CIRCULAR_RADIUS, QuantityKind.EPICYCLIC_FREQUENCY):
            centre, period = self._radial_oscillation(quantity.target, point)
            if kind is QuantityKind.CIRCULAR_RADIUS:
                return "centre of the radial oscillation of an orbit launched beside the circle", centre, None
            return (
                "2 pi / period of the radial oscillation of the integrated orbit",
                2 * math.pi / period,
                None,
            )
        if quantity.target == FRAME:
            return (
                "2 pi over the frame's rate at which the simulated bodies rest at the state",
                self._frame(point),
                None,
            )
        key = (quantity.target, tuple(point[s] for s in sorted(point, key=str)))
        if key not in self._turns:
            self._turns[key] = self._revolution(quantity.target, point)
        period, speed, energy = self._turns[key]
        if kind is QuantityKind.REVOLUTION_PERIOD:
            return "time of one revolution of the integrated steady motion", period, None
        if kind is QuantityKind.CIRCULAR_SPEED:
            return "distance travelled in one integrated revolution over its time", speed, None
        return "T + V of the steady motion found by the simulation", energy, None

    # --- steady motion -------------------------------------------------------------------------

    def _revolution(self, target: str, point: Point) -> tuple[float, float, float]:
        """(period, speed, energy) of the steady motion, found and integrated numerically."""
        dyn, names = self.dyn, [c.name for c in self.model.coordinates]
        params = dyn.values(point)
        i = names.index(target)
        q, qd = self.start(point)
        qd = [0.0] * dyn.n

        def others(rate: float) -> Vector:
            qd[i] = rate
            accelerations = dyn.unknowns(q, qd, params)[: dyn.n]
            return [a for k, a in enumerate(accelerations) if k != i]

        at_rest = others(0.0)
        j = max(range(len(at_rest)), key=lambda k: abs(at_rest[k]))
        if at_rest[j] == 0:
            raise DerivationError(f"in the simulation nothing pulls the other coordinates as {target} turns")
        squared = self._secant(lambda s: others(math.sqrt(max(s, 0.0)))[j], at_rest[j], q, j, i)
        rate = math.sqrt(squared)
        left = others(rate)
        if max(abs(a) for a in left) > 1e-9 * abs(at_rest[j]):
            raise DerivationError(
                f"the simulation finds no rate of {target} that holds every other coordinate"
            )
        turning = self._turning_dofs(target)
        states = rk4(
            dyn.derivative(params), dyn.initial(q, qd, params), 2 * math.pi / rate / PER_TURN, PER_TURN + 20
        )
        held = [k for k in range(dyn.n) if k != i]
        drift = max(abs(y[k] - q[k]) / max(abs(q[k]), 1.0) for y in states for k in held)
        if drift > STAYS_PUT:
            raise DerivationError(
                f"the integrated steady motion of {target} does not stay circular (drift {drift:.2g})"
            )
        travelled, period = 0.0, None
        before = [dyn.positions(states[0][: dyn.n], params)[d] for d in turning]
        for step in range(1, len(states)):
            after = [dyn.positions(states[step][: dyn.n], params)[d] for d in turning]
            chord = math.dist(before, after)
            turned = states[step][i] - q[i] - 2 * math.pi
            if turned >= 0:
                fraction = 1 - turned / (states[step][i] - states[step - 1][i])
                travelled += fraction * chord
                period = (step - 1 + fraction) * 2 * math.pi / rate / PER_TURN
                break
            travelled += chord
            before = after
        if period is None:
            raise DerivationError(f"the integrated motion of {target} did not complete a revolution")
        return period, travelled / period, dyn.energy(q, qd, params)

    @staticmethod
    def _secant(g: Callable[[float], float], g0: float, q: Vector, j: int, i: int) -> float:
        """The squared rate s > 0 where g(s) = 0; g is close to linear in s (centripetal r w^2)."""
        scale = max(abs(q[k]) for k in range(len(q)) if k != i) or 1.0
        a, ga = 0.0, g0
        b = abs(g0) / scale
        gb = g(b)
        for _ in range(60):
            if gb == ga:
                break
            a, ga, b = b, gb, b - gb * (b - a) / (gb - ga)
            gb = g(b)
            if abs(gb) <= 1e-14 * abs(g0):
                break
        if not b > 0 or abs(gb) > 1e-9 * abs(g0):
            raise DerivationError("the simulation finds no steady rotation (no positive squared rate)")
        return b

    def _turning_dofs(self, target: str) -> list[int]:
        """Positions (indices into the compiled positions) of the bodies that move with `target`."""
        q = self.model.coordinate(target).symbol
        return [
            k for k, d in enumerate(self.dyn.mech.dofs) if not d.name.startswith("phi_") and d.mapping.has(q)
        ]

    # --- a rotating frame ---------------------------------------------------------------------

    def _frame(self, point: Point) -> float:
        """2 pi / rate, the rate's own symbol (if the state is not at rest for every rate) found by
        scanning the numerical accelerations at the state for the value that makes them vanish."""
        frame = self.model.frame
        assert frame is not None and frame.rate is not None
        dyn = self.dyn
        q, _ = self.start(point)
        rest = [0.0] * dyn.n

        def accelerations(at: Point) -> Vector:
            return dyn.unknowns(q, rest, dyn.values(at))[: dyn.n]

        now = accelerations(point)
        scale = max(abs(a) for a in now)
        own = [s for s in frame.rate.free_symbols if s in point and not elsewhere(self.model, s)]
        if scale > 0 and len(own) == 1:
            symbol = own[0]
            j = max(range(dyn.n), key=lambda k: abs(now[k]))

            def pull(value: float) -> float:
                return accelerations({**point, symbol: value})[j]

            grid = [point[symbol] * f for f in SCAN]
            values = [pull(v) for v in grid]
            roots = [
                (grid[k], grid[k + 1]) for k in range(len(grid) - 1) if (values[k] > 0) != (values[k + 1] > 0)
            ]
            if len(roots) != 1:
                raise DerivationError(f"the simulation finds {len(roots)} rates that hold the bodies at rest")
            low, high = roots[0]
            sign_low = pull(low) > 0
            for _ in range(80):
                middle = (low + high) / 2
                low, high = (middle, high) if (pull(middle) > 0) == sign_low else (low, middle)
            point = {**point, symbol: (low + high) / 2}
            if max(abs(a) for a in accelerations(point)) > 1e-9 * scale:
                raise DerivationError(
                    "the simulated bodies do not rest in the frame at the state at any rate"
                )
        elif scale > 0:
            raise DerivationError("the simulated bodies do not rest in the frame at the state")
        rate = float(sympy.N(frame.rate.subs(point), 20))
        return 2 * math.pi / rate

    # --- the effective potential ---------------------------------------------------------------

    @cached_property
    def _cyclic(self) -> list[int]:
        return cyclic_indices(self.dyn.mech)

    def _held(self, q: Vector, params: Vector, momenta: Vector) -> Vector:
        """Velocities with the cyclic momenta held and every other coordinate at rest."""
        mass = self.dyn.mass(q, params)
        cyclic = self._cyclic
        block = [[mass[a][b] for b in cyclic] for a in cyclic]
        rates = solve_numeric(block, list(momenta))
        qd = [0.0] * self.dyn.n
        for k, rate in zip(cyclic, rates, strict=True):
            qd[k] = rate
        return qd

    def _radial_oscillation(self, target: str, point: Point) -> tuple[float, float]:
        """(centre, period) of the radial oscillation of an orbit launched just beside the circular one."""
        dyn = self.dyn
        params = dyn.values(point)
        i = [c.name for c in self.model.coordinates].index(target)
        q, qd = self.start(point)
        mass = dyn.mass(q, params)
        momenta = [sum(mass[c][k] * qd[k] for k in range(dyn.n)) for c in self._cyclic]

        def radial(x: float) -> float:
            at = [x if k == i else v for k, v in enumerate(q)]
            return dyn.unknowns(at, self._held(at, params, momenta), params)[i]

        scale = abs(q[i]) or 1.0
        grid = [scale * f for f in SCAN]
        values = [radial(x) for x in grid]
        brackets = [(grid[k], grid[k + 1]) for k in range(len(grid) - 1) if values[k] > 0 >= values[k + 1]]
        if len(brackets) != 1:
            raise DerivationError(
                f"the simulation finds {len(brackets)} circular orbits (roots of {target}'' where it turns "
                "inward) with the state's momenta"
            )
        low, high = brackets[0]
        for _ in range(80):
            middle = (low + high) / 2
            low, high = (middle, high) if radial(middle) > 0 else (low, middle)
        radius = (low + high) / 2
        delta = 1e-5 * radius
        stiffness = -(radial(radius + delta) - radial(radius - delta)) / (2 * delta)
        if not stiffness > 0:
            raise DerivationError(f"{target}: the simulated circular orbit is not stable")
        estimate = 2 * math.pi / math.sqrt(stiffness)
        launch = [radius * (1 + 1e-4) if k == i else v for k, v in enumerate(q)]
        qd0 = self._held(launch, params, momenta)
        states = rk4(
            dyn.derivative(params), [*launch, *qd0], estimate / PER_OSCILLATION, int(3.3 * PER_OSCILLATION)
        )
        radii = [y[i] for y in states]
        centre = (max(radii) + min(radii)) / 2
        offsets = [x - centre for x in radii]
        crossings = [
            k + offsets[k] / (offsets[k] - offsets[k + 1])
            for k in range(len(offsets) - 1)
            if offsets[k] < 0 <= offsets[k + 1]
        ]
        if len(crossings) < 2:
            raise DerivationError(f"{target}: no radial oscillation seen in the simulation")
        period = (crossings[-1] - crossings[0]) / (len(crossings) - 1) * estimate / PER_OSCILLATION
        return centre, period
