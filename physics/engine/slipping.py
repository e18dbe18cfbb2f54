"""Friction quantities: the sliding phase of a kinetic contact, and a holding contact at its limit.

Sliding phase (`slip_time`, `slip_distance`, `slip_end_velocity`): a body launched so that its contact
slips (a ball thrown along a floor without spin) moves under constant kinetic friction until the slip
velocity u of the contact point reaches zero; from then on it rolls. Each method gives the
accelerations with the state's positions and velocities left free; they must be constant (otherwise
the quantity is not applicable), so t = -u0 / u', and a coordinate moves by q0' t + q'' t^2 / 2 and
ends with q0' + q'' t.

Limit of static friction (`slipping`): a contact that holds (a fixed foot, a rolling constraint) needs
the friction force f, one constraint force, and the normal force N, another; the method's own
constraint forces give both, and |f| = mu_s N (f = mu_s N or f = -mu_s N) is solved for the parameter,
the root chosen by the parameter's declared range and sign.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from typing import TYPE_CHECKING

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.contact_friction import only_friction, slip_velocity
from physics.engine.mechanics import Mechanics, time_derivative
from physics.engine.model import SLIP_KINDS, Model, Quantity, QuantityKind
from physics.engine.proof import domain_points
from physics.engine.quantity_table import derives
from physics.engine.roots import CHOOSE, chosen_by_positives
from physics.engine.settle import plain_angle
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.method import Method
    from physics.engine.simulation import Measured, Point, Simulator

SLIP_STEPS = 2000  # RK4 steps over the expected sliding time
NO_TORQUE = (
    "The friction at the contact also turns the body (its torque about the centre): the slipping stops "
    "when the contact point's velocity $v - R\\omega$ vanishes, not when the body stops."
)


def sliding_phase(method: Method, quantity: Quantity) -> sympy.Expr:
    """slip_time, slip_distance or slip_end_velocity by this method's accelerations."""
    from physics.engine.method import NotApplicable

    model = method.model
    try:
        friction = only_friction(model, quantity.target if quantity.kind is QuantityKind.SLIP_TIME else "")
    except ValueError as why:  # the frictionless variant of the model, say
        raise NotApplicable(str(why)) from None
    free = dataclasses.replace(model, state=())
    free_method = type(method)(free, Mechanics(free))
    moving = model.moving_symbols
    accelerations = {
        c.acceleration: tidy.simplify(free_method.acceleration(c.name)) for c in model.coordinates
    }
    if any(a.free_symbols & moving for a in accelerations.values()):
        raise NotApplicable("the accelerations change during the sliding (not constant): no closed form")
    slip = slip_velocity(method.mech, friction)
    rate = tidy.simplify(time_derivative(slip, model).subs(accelerations))
    start = dict(model.state)
    u0 = tidy.simplify(slip.subs(start).subs(dict.fromkeys(moving, 0)))
    if rate.free_symbols & moving or rate == 0:
        raise NotApplicable("the slip velocity does not change at a constant rate")
    time = tidy.simplify(-u0 / rate)
    method.step(
        "The slipping at the contact stops: its slip velocity $u$ reaches zero",
        rf"u = {method.tex(slip)},\ \dot u = {method.tex(rate)}\Rightarrow t = -u_0/\dot u = {method.tex(time)}",
    )
    if quantity.kind is QuantityKind.SLIP_TIME:
        return time
    c = model.coordinate(quantity.target)
    v0 = start.get(c.velocity, sympy.Integer(0))
    a = accelerations[c.acceleration]
    if quantity.kind is QuantityKind.SLIP_END_VELOCITY:
        value = tidy.simplify(v0 + a * time)
        method.step(
            f"The rate of {method.named(c.name)} when the slipping stops",
            method.tex(sympy.Eq(c.velocity, value)),
        )
        return value
    value = tidy.simplify(v0 * time + a * time**2 / 2)
    change = method.mech.notation.coordinates[c.name].tex
    method.step(
        f"How far {method.named(c.name)} moves while the contact slips",
        rf"\Delta {change} = " + method.tex(value),
    )
    return value


def without_torque(
    model: Model, quantity: Quantity, rederive: Callable[[Model, Quantity], sympy.Expr | None]
) -> sympy.Expr | None:
    """The answer with every friction acting at the body's centre (its torque forgotten)."""
    if not any(f.contact for f in model.frictions):
        return None
    central = tuple(dataclasses.replace(f, contact=()) for f in model.frictions)
    return rederive(dataclasses.replace(model, frictions=central), quantity)


def slipping_limit(method: Method, quantity: Quantity) -> sympy.Expr:
    """The parameter value at which the holding contact's friction reaches mu_s times its normal force."""
    parameter, mu = quantity.parameter, quantity.coefficient
    assert parameter is not None and mu is not None
    friction_name, normal_name = quantity.contact
    friction, normal = method.force(friction_name), method.force(normal_name)
    roots: list[sympy.Expr] = []
    for sign in (1, -1):
        for root in tidy.solve(tidy.simplify(friction - sign * mu * normal), parameter):
            if root.is_real is not False and not (parameter.is_positive and root.is_positive is False):
                roots.append(tidy.simplify(root))
    roots = list(dict.fromkeys(roots))
    inside = [plain_angle(r, method.model) for r in roots if _in_parameter_range(r, parameter, method.model)]
    inside = chosen_by_positives(inside, parameter, method.model)
    if len(inside) != 1:
        raise DerivationError(
            f"{method.title}: {quantity.name}: expected one value of {parameter} in its declared range at "
            f"which |f| = {typed_text(mu)} N, found {typed_text(inside)} among {typed_text(roots)}"
            + (CHOOSE.format(parameter) if len(inside) > 1 else ""),
            quantity=quantity.name,
        )
    method.step(
        f"Limit of static friction {method.force_named(friction_name)}",
        rf"f = {method.tex(friction)},\ N = {method.tex(normal)},\ |f| = {method.tex(mu)} N"
        rf"\Rightarrow {method.tex(parameter)} = {method.tex(inside[0])}",
    )
    return inside[0]


def _in_parameter_range(value: sympy.Expr, parameter: sympy.Symbol, model: Model) -> bool:
    """value is positive where the parameter must be, and inside its declared range at domain points."""
    bounds = [(low, high) for symbol, low, high in model.ranges if symbol == parameter]
    try:
        for point in domain_points(model, 8, seed=11):
            number = complex(sympy.N(value.subs(point), 20))
            if abs(number.imag) > 1e-12 * max(1.0, abs(number.real)):
                return False
            if parameter.is_positive and number.real <= 0:
                return False
            for low, high in bounds:
                if not float(low.subs(point)) < number.real < float(high.subs(point)):
                    return False
    except (TypeError, ValueError):
        return False
    return True


# --- simulation ---------------------------------------------------------------------------------


def measure_sliding(simulator: Simulator, quantity: Quantity, point: Point, expected: float) -> Measured:
    """Integrate from the state until the contact's slip velocity crosses zero (linear interpolation
    between the two RK4 steps around it); the time, the coordinate's change or its velocity there."""
    from physics.engine.simulation import _compile, rk4

    model, dyn = simulator.model, simulator.dynamics
    friction = only_friction(model, quantity.target if quantity.kind is QuantityKind.SLIP_TIME else "")
    slip = _compile([*dyn.mech.q, *dyn.mech.qd, *dyn.params], [slip_velocity(dyn.mech, friction)])
    params = dyn.values(point)
    n = dyn.n
    q, qd = simulator._start(point)
    step = dyn.derivative(params)
    u0 = slip(*q, *qd, *params)[0]
    probe = 1e-6
    u1 = slip(*rk4(step, [*q, *qd], probe, 1)[-1], *params)[0]
    rate = (u1 - u0) / probe
    if u0 == 0 or rate * u0 >= 0:
        raise DerivationError(f"{quantity.name}: in the simulation the contact does not slow its slipping")
    h = abs(u0 / rate) / SLIP_STEPS
    y, t, u = [*q, *qd], 0.0, u0
    for _ in range(2 * SLIP_STEPS):
        after = rk4(step, y, h, 1)[-1]
        u_after = slip(*after, *params)[0]
        if math.copysign(1.0, u_after) != math.copysign(1.0, u0):
            share = u / (u - u_after)
            at = [a + share * (b - a) for a, b in zip(y, after, strict=True)]
            if quantity.kind is QuantityKind.SLIP_TIME:
                return "time at which the integrated slip velocity vanishes", t + share * h, None
            i = [c.name for c in model.coordinates].index(quantity.target)
            if quantity.kind is QuantityKind.SLIP_END_VELOCITY:
                return "velocity of the integrated motion when the slip velocity vanishes", at[n + i], None
            return (
                "displacement of the integrated motion until the slip velocity vanishes",
                at[i] - q[i],
                None,
            )
        y, t, u = after, t + h, u_after
    raise DerivationError(f"{quantity.name}: the simulated contact never stopped slipping")


def measure_slipping(simulator: Simulator, quantity: Quantity, point: Point, expected: float) -> Measured:
    """With the parameter at the derived value, the constraint forces measured on the integrated motion
    (Newton's law on its accelerations): |f| / N must be mu_s."""
    from physics.engine.simulation import _evaluate

    assert quantity.parameter is not None and quantity.coefficient is not None
    at = {**point, quantity.parameter: expected}
    friction_name, normal_name = quantity.contact
    probe = dataclasses.replace(quantity, kind=QuantityKind.FORCE)
    friction = simulator._force(dataclasses.replace(probe, target=friction_name), at, 0.0)[1]
    normal = simulator._force(dataclasses.replace(probe, target=normal_name), at, 0.0)[1]
    mu = _evaluate(quantity.coefficient, at)
    ratio = abs(friction) / max(abs(normal), 1e-300)
    return (
        "|f| / N from the forces measured on the integrated motion, against mu_s",
        ratio,
        abs(ratio - mu) / mu,
    )


derives(*SLIP_KINDS)(sliding_phase)
derives(QuantityKind.SLIPPING)(slipping_limit)
