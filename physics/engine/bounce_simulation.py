"""A body bounced n times off its fixed partner, measured: the contact integrated through its
spring-dashpot (impact_simulation.py), the flight back integrated until the normal separation closes
again, n times. Nothing here reads the derived velocities: each bounce starts with those the integrated
flight arrived with."""

from __future__ import annotations

import dataclasses
import math

import sympy

from physics.engine.impact import contact
from physics.engine.impact_simulation import ImpactMeasure
from physics.engine.model import Quantity, QuantityKind
from physics.engine.simulation import Measured, Point, Simulator, Vector, _evaluate
from physics.errors import DerivationError


def velocities_after(simulator: Simulator, name: str, count: int, point: Point) -> Vector:
    """The coordinates' velocities just after bounce number `count` (1: the model's own impact)."""
    return bounced(simulator, name, count, point)[1]


def bounced(simulator: Simulator, name: str, count: int, point: Point) -> tuple[Vector, Vector]:
    """The coordinates' velocities just before and just after bounce number `count` (1: the model's own
    impact, from the state's velocities)."""
    from physics.engine.reach_simulation import ReachMeasure  # it builds on simulation, as this does

    model = simulator.model
    if count < 1:
        raise DerivationError(f"{name}: the number of bounces is {count} at a sampled point: 1 or more")
    row = [_evaluate(a, point) for a in contact(model).generalized]
    dyn = simulator.dynamics
    params = dyn.values(point)
    start, arriving = simulator._start(point)
    rates = simulator._impact.rates(point)
    reach = ReachMeasure(simulator)
    for _ in range(count - 1):
        parting = sum(a * v for a, v in zip(row, rates, strict=True))
        pull = sum(a * v for a, v in zip(row, dyn.unknowns(start, rates, params)[: dyn.n], strict=True))
        if not (parting > 0 and pull < 0):
            raise DerivationError(
                f"{name}: the integrated body does not fly back to the contact after a bounce"
            )

        def closed(y: Vector) -> float:  # >= 0 once the separation is back to zero
            return -sum(a * (q - q0) for a, q, q0 in zip(row, y[: dyn.n], start, strict=True))

        _, arrival = reach._integrate([*start, *rates], 2 * parting / -pull, point, closed, name)
        arriving = list(arrival[dyn.n : 2 * dyn.n])
        state = {
            **dict(model.state),
            **{c.velocity: sympy.Float(v, 17) for c, v in zip(model.coordinates, arriving, strict=True)},
        }
        again = ImpactMeasure(dataclasses.replace(model, state=tuple(state.items())))
        rates = again.rates(point)
        if not all(math.isfinite(v) for v in rates):
            raise DerivationError(f"{name}: the integrated bounce failed")
    return arriving, rates


def measure_final(simulator: Simulator, quantity: Quantity, point: Point, expected: float) -> Measured:
    """A body's velocity or speed just after the n-th integrated bounce, or the kinetic energy that bounce
    took (the velocities the integrated flight arrived with against those it left with)."""
    model = simulator.model
    count = round(_evaluate(quantity.bounces, point)) if quantity.bounces is not None else 1
    arriving, rates = bounced(simulator, quantity.name, count, point)
    what = f"after {count} integrated bounces"
    if quantity.kind is QuantityKind.KINETIC_ENERGY_LOST:
        dyn = simulator.dynamics
        start, launched = simulator._start(point)
        if quantity.total:  # into the first bounce with the state's velocities
            arriving = launched
        before, after = (dyn.energy(start, v, dyn.values(point)) for v in (arriving, rates))
        which = f"the first {count} bounces" if quantity.total else f"bounce {count}"
        return (
            f"kinetic energy lost in {which} of the integrated motion",
            before - after,
            abs(before - after - expected) / max(abs(before), 1e-12),
        )
    found = contact(model)
    velocity = [
        sum(_evaluate(found.jacobian[i, j], point) * r for j, r in enumerate(rates))
        for i, d in enumerate(found.mech.dofs)
        if d.body == quantity.target and not d.name.startswith("phi_")
    ]
    if quantity.kind is QuantityKind.FINAL_SPEED:
        return f"speed {what}", math.hypot(*velocity), None
    (component,) = velocity
    return f"velocity {what}", component, None
