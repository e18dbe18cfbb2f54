"""Measuring damped oscillations and mode shapes on integrated motions (see `simulation`).

A damped oscillation is released at rest a little off the equilibrium; its velocity then crosses zero
exactly every half damped period (the release is the first extremum), and the extrema's sizes fall by
exp(-t/tau): the period and the decay time are read from those zero crossings and that envelope. They
are located on the cubic Hermite interpolant of each RK4 step (values and slopes at both ends), far
finer than the step, and the velocity carries no rounding from the equilibrium's own size.
A mode shape
is measured by releasing the system along the mode found numerically (M and K from the compiled
energy) and fitting the ratio of the two coordinates' displacements over the motion, which must keep
its shape throughout.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import partial

from physics.engine.method import stable_equilibrium
from physics.engine.model import Quantity, QuantityKind
from physics.engine.simulation import Measured, Point, Simulator, Vector, _evaluate, rk4
from physics.errors import DerivationError

PER_PERIOD = 400
PERIODS = 2.6
AMPLITUDE = 1e-3  # of the coordinate's scale: small enough to stay linear, large against rounding
NOISE = 1e-9  # extrema smaller than this fraction of the release are left out
ROUNDING = 1e-13  # nor those this close to rounding of the coordinate's own size
MOST_STEPS = 8000
SHAPE_PERIODS = 3.3
SHAPE_HOLDS = 1e-4  # how far the motion may stray from the fitted shape, relative to its size


def measures(simulator: Simulator) -> dict[QuantityKind, Callable[[Quantity, Point, float], Measured]]:
    return {
        QuantityKind.DAMPED_FREQUENCY: partial(damped_frequency, simulator),
        QuantityKind.DECAY_TIME: partial(decay_time, simulator),
        QuantityKind.UNDAMPED_FREQUENCY: partial(undamped_frequency, simulator),
        QuantityKind.MODE_SHAPE: partial(mode_shape, simulator),
    }


def damped_frequency(simulator: Simulator, quantity: Quantity, point: Point, expected: float) -> Measured:
    period, _ = _damped_motion(simulator, quantity.target, point)
    return (
        "2 pi / period between the velocity's zero crossings (the extrema) of the integrated damped motion",
        2 * math.pi / period,
        None,
    )


def decay_time(simulator: Simulator, quantity: Quantity, point: Point, expected: float) -> Measured:
    _, rate = _damped_motion(simulator, quantity.target, point)
    return "e-folding time of the extrema of the integrated damped motion", 1 / rate, None


def undamped_frequency(simulator: Simulator, quantity: Quantity, point: Point, expected: float) -> Measured:
    """omega_0^2 = omega_d^2 + 1/tau^2 for linear damping: both read off the same integrated damped motion."""
    period, rate = _damped_motion(simulator, quantity.target, point)
    return (
        "sqrt((2 pi / period)^2 + (1 / decay time)^2) of the integrated damped motion",
        math.hypot(2 * math.pi / period, rate),
        None,
    )


def _damped_motion(simulator: Simulator, coordinate: str, point: Point) -> tuple[float, float]:
    """(damped period, amplitude decay rate) of the motion released at rest beside the equilibrium.

    Released at rest, the linear motion's velocity vanishes exactly every half damped period (the
    release is the first extremum), whatever the damping; the extrema's sizes fall by exp(-t/tau)."""
    dyn = simulator.dynamics
    params = dyn.values(point)
    n = dyn.n
    i = [c.name for c in simulator.model.coordinates].index(coordinate)
    q0 = [
        _evaluate(stable_equilibrium(simulator.model)[c.symbol], point) for c in simulator.model.coordinates
    ]
    scale = max(abs(q0[i]), 1.0)
    rest = [0.0] * n

    def nudged(vector: Vector, by: float) -> Vector:
        return [v + (by if k == i else 0.0) for k, v in enumerate(vector)]

    # local stiffness and damping per unit inertia, only to choose the time step and the duration
    h = 1e-6 * scale
    stiffness = dyn.unknowns(nudged(q0, -h), rest, params)[i] - dyn.unknowns(nudged(q0, h), rest, params)[i]
    damping = dyn.unknowns(q0, nudged(rest, -h), params)[i] - dyn.unknowns(q0, nudged(rest, h), params)[i]
    stiffness, damping = stiffness / (2 * h), damping / (2 * h)
    squared = stiffness - damping**2 / 4
    if not squared > 0:
        raise DerivationError(f"{coordinate}: the integrated motion does not oscillate (overdamped here)")
    period = 2 * math.pi / math.sqrt(squared)
    dt = min(period / PER_PERIOD, 1 / (40 * max(damping / 2, 1e-300)))
    derivative = dyn.derivative(params)
    amplitude = AMPLITUDE * scale
    floor = max(NOISE * amplitude, ROUNDING * scale)  # below it, the displacement is rounding
    y = nudged(q0, amplitude) + rest
    slope = derivative(y)[n + i]
    extrema: list[tuple[float, float]] = [(0.0, amplitude)]
    for step in range(min(int(PERIODS * period / dt), MOST_STEPS)):
        after = rk4(derivative, y, dt, 1)[-1]
        slope_after = derivative(after)[n + i]
        x0, v0, x1, v1 = y[i] - q0[i], y[n + i], after[i] - q0[i], after[n + i]
        turning = _root(partial(_hermite, v0, slope, v1, slope_after, dt), dt)
        if turning is not None:
            size = abs(_hermite(x0, v0, x1, v1, dt, turning))
            if size < floor:
                break
            extrema.append((step * dt + turning, size))
        y, slope = after, slope_after
    if len(extrema) < 2:
        raise DerivationError(
            f"{coordinate}: the integrated motion dies out before its first swing back (too close to "
            "critical damping to measure at this point: narrow domain.positive)"
        )
    (t0, a0), (t1, a1) = extrema[0], extrema[-1]
    return 2 * (t1 - t0) / (len(extrema) - 1), math.log(a0 / a1) / (t1 - t0)


def _hermite(x0: float, v0: float, x1: float, v1: float, dt: float, s: float) -> float:
    """The cubic through values x0, x1 with slopes v0, v1 at 0 and dt, at s."""
    u = s / dt
    return (
        (2 * u**3 - 3 * u**2 + 1) * x0
        + (u**3 - 2 * u**2 + u) * dt * v0
        + (-2 * u**3 + 3 * u**2) * x1
        + (u**3 - u**2) * dt * v1
    )


def _root(f: Callable[[float], float], dt: float) -> float | None:
    """The root of f in (0, dt] where it changes sign, by bisection."""
    low, high = 0.0, dt
    f_low, f_high = f(low), f(high)
    if f_low == 0 or (f_low > 0) == (f_high > 0):
        return None
    for _ in range(60):
        middle = (low + high) / 2
        f_middle = f(middle)
        if (f_middle > 0) == (f_low > 0):
            low, f_low = middle, f_middle
        else:
            high = middle
    return (low + high) / 2


def mode_shape(simulator: Simulator, quantity: Quantity, point: Point, expected: float) -> Measured:
    """Released along mode n, the displacements' ratio fitted over the integrated motion, which must keep
    that ratio throughout (a wrong shape would beat between the modes)."""
    dyn = simulator.dynamics
    params = dyn.values(point)
    n = dyn.n
    q0, modes = simulator.numeric_modes(point)
    omega2, shape = modes[int(quantity.target) - 1]
    names = [c.name for c in simulator.model.coordinates]
    top, bottom = (names.index(name) for name in quantity.ratio)
    size = 1e-4 / max(abs(x) for x in shape)
    start = [v + size * x for v, x in zip(q0, shape, strict=True)]
    period = 2 * math.pi / math.sqrt(omega2)
    states = rk4(
        dyn.derivative(params), start + [0.0] * n, period / PER_PERIOD, int(SHAPE_PERIODS * PER_PERIOD)
    )
    upper = [y[top] - q0[top] for y in states]
    lower = [y[bottom] - q0[bottom] for y in states]
    ratio = sum(a * b for a, b in zip(upper, lower, strict=True)) / sum(b * b for b in lower)
    stray = max(abs(a - ratio * b) for a, b in zip(upper, lower, strict=True))
    if stray > SHAPE_HOLDS * max(abs(a) + abs(ratio * b) for a, b in zip(upper, lower, strict=True)):
        raise DerivationError(
            f"{quantity.name}: released along mode {quantity.target} the motion does not keep its shape"
        )
    return (
        "ratio of the displacements along the integrated motion released along the mode",
        ratio,
        abs(ratio - expected) / max(abs(expected), 1e-6),
    )
