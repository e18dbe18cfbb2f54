"""A body in free flight from the model's state: time of flight, range and maximum height, worked two ways.

Kinematics (Lagrange's, Newton's and d'Alembert's methods, each from its own equations of motion with
the state left free): the body's acceleration must be constant (gravity, constant forces; not drag); then
y(t) = y0 + vy0 t + ay t^2/2, the flight ends at the later root of y(t) = level, the apex is where
y'(t) = 0, and the range is x(T) - x0.

Energy and momentum (the conservation method): with no horizontal force the horizontal momentum keeps
vx; energy gives the height at which the vertical velocity vanishes and the vertical velocity on landing;
the vertical impulse Fy T = m (vy1 - vy0) gives the time, and the range is vx T.

A body may land instead on a slope through the launch point (`slope`: its angle above the horizontal,
an incline's surface), the range then taken along it. Kinematics: y(t) - y0 = (x(t) - x0) tan θ, the root
other than the launch. Energy and momentum: the drop to the landing is vx T tan θ, so energy and the
vertical impulse give vy1² - 2 vx tan θ vy1 = vy0² - 2 vx tan θ vy0, whose roots are the launch's vy0 and
(their sum) 2 vx tan θ - vy0; the range is vx T / cos θ.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from typing import TYPE_CHECKING

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.mechanics import time_derivative
from physics.engine.model import TRAJECTORY_KINDS, Model, Quantity, QuantityKind
from physics.engine.proof import domain_points
from physics.engine.quantity_table import derives
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.method import Method

POINTS = 8
Vector = dict[str, sympy.Expr]  # axis -> component


@dataclasses.dataclass(frozen=True)
class Launch:
    """Where and how fast the body starts (at the model's state), and the height it lands at."""

    position: Vector
    velocity: Vector
    level: sympy.Expr
    slope: sympy.Expr | None  # lands on the line through the launch point at this angle instead


def launch(model: Model, quantity: Quantity) -> Launch:
    state = dict(model.state)
    position = dict(model.body(quantity.target).position)
    start = {a: tidy.simplify(e.subs(state)) for a, e in position.items()}
    velocity = {a: tidy.simplify(time_derivative(e, model).subs(state)) for a, e in position.items()}
    moving = model.moving_symbols
    for axis, value in (*start.items(), *velocity.items()):
        if value.free_symbols & moving:
            raise DerivationError(
                f"{quantity.name}: the launch ({axis} = {typed_text(value)}) depends on coordinates the state does not give",
                path=("state",),
            )
    level = quantity.level if quantity.level is not None else start["y"]
    return Launch(
        {a: start.get(a, sympy.Integer(0)) for a in ("x", "y")},
        {a: velocity.get(a, sympy.Integer(0)) for a in ("x", "y")},
        level,
        quantity.slope,
    )


def check_slopes(model: Model) -> None:
    """A slope is a line's angle above the horizontal, within a right angle either way: 30 (30° meant)
    is 30 radians, a line falling at 81°, on which every method would land the body alike."""
    for quantity in model.quantities:
        if quantity.slope is not None:
            _check_slope(model, quantity.name, quantity.slope)


def _check_slope(model: Model, name: str, slope: sympy.Expr) -> None:
    for point in domain_points(model, POINTS, seed=29):
        value = float(sympy.N(slope.subs(point), 15))
        if abs(value) < math.pi / 2:
            continue
        at = (
            ""
            if isinstance(slope, sympy.Number)
            else " at " + ", ".join(f"{s}={v:.4g}" for s, v in point.items())
        )
        degrees = f": {slope}° is written {slope}*pi/180" if isinstance(slope, sympy.Number) else ""
        raise DerivationError(
            f"{name}: the slope {typed_text(slope)} is {math.degrees(value):.0f}°{at}; it is the angle in radians "
            f"of the line the body lands on, between -pi/2 and pi/2{degrees}",
            path=("quantities", name, "slope"),
        )


@derives(*TRAJECTORY_KINDS)
def answer(method: Method, quantity: Quantity) -> sympy.Expr:
    return ROUTES.get(method.name, by_kinematics)(method, quantity)


# --- kinematics ---------------------------------------------------------------------------------


def _coordinate_acceleration(method: Method, body: str) -> Vector:
    """d^2(position)/dt^2 with the coordinates' accelerations from the method's own equations of motion
    (Lagrange's, d'Alembert's principle, ...; state free)."""
    model = method.model
    solution = {c.acceleration: method.free.acceleration(c.name) for c in model.coordinates}
    return {
        axis: tidy.simplify(time_derivative(time_derivative(expr, model), model).subs(solution))
        for axis, expr in model.body(body).position
    }


def _newton_acceleration(method: Method, body: str) -> Vector:
    """The body's Cartesian accelerations from Newton's second law (state free)."""
    from physics.engine.newton import NewtonMethod

    newton = method.free
    assert isinstance(newton, NewtonMethod)
    return {
        d.name.split("_", 1)[0]: tidy.simplify(newton.solution[d.acceleration])
        for d in newton.mech.dofs
        if d.body == body and not d.name.startswith("phi_")
    }


ACCELERATIONS: dict[str, Callable[[Method, str], Vector]] = {"newton": _newton_acceleration}


def by_kinematics(method: Method, quantity: Quantity) -> sympy.Expr:
    from physics.engine.method import NotApplicable

    model = method.model
    start = launch(model, quantity)
    found = ACCELERATIONS.get(method.name, _coordinate_acceleration)(method, quantity.target)
    moving = model.moving_symbols
    if any(a.free_symbols & moving for a in found.values()):
        raise NotApplicable(
            f"the acceleration of {quantity.target} ({typed_text(found)}) changes along the flight (drag, a force that "
            "depends on the motion): not constant-acceleration kinematics"
        )
    acceleration = {a: found.get(a, sympy.Integer(0)) for a in ("x", "y")}
    t = sympy.Symbol("t")
    path = {a: start.position[a] + start.velocity[a] * t + acceleration[a] * t**2 / 2 for a in ("x", "y")}
    method.step(
        f"Constant acceleration of «{quantity.target}»: its position at the time $t$",
        r",\quad ".join(
            method.tex(sympy.Eq(model.cartesian_symbol(f"{a}_{quantity.target}"), path[a]))
            for a in ("x", "y")
            if path[a] != 0 and f"{a}_{quantity.target}" in dict(model.cartesian)
        ),
    )
    if acceleration["y"] == 0:
        raise DerivationError(f"{quantity.name}: nothing pulls {quantity.target} down: it never lands")
    if quantity.kind is QuantityKind.MAX_HEIGHT:
        apex = -start.velocity["y"] / acceleration["y"]
        height = tidy.simplify(path["y"].subs(t, apex) - start.position["y"])
        method.step(
            "Apex where the vertical velocity vanishes",
            method.tex(sympy.Eq(sympy.diff(path["y"], t), 0))
            + r"\Rightarrow t = "
            + method.tex(apex)
            + r",\ H = y(t) - y_0 = "
            + method.tex(height),
        )
        return height
    if start.slope is not None:
        return _onto_slope(method, quantity, start, acceleration, path, t)
    flight = later_root(
        model,
        _quadratic_roots(acceleration["y"] / 2, start.velocity["y"], start.position["y"] - start.level),
        quantity.name,
    )
    method.step(
        "Landing",
        method.tex(sympy.Eq(path["y"], start.level)) + r"\Rightarrow T = " + method.tex(flight),
    )
    if quantity.kind is QuantityKind.TIME_OF_FLIGHT:
        return flight
    distance = tidy.simplify(path["x"].subs(t, flight) - start.position["x"])
    method.step("Range", r"x(T) - x_0 = " + method.tex(distance))
    return distance


def _onto_slope(
    method: Method, quantity: Quantity, start: Launch, acceleration: Vector, path: Vector, t: sympy.Symbol
) -> sympy.Expr:
    """Kinematics down (or up) to the line through the launch point at the angle `slope`."""
    assert start.slope is not None
    tan = sympy.tan(start.slope)
    roots = _quadratic_roots(
        (acceleration["y"] - acceleration["x"] * tan) / 2,
        start.velocity["y"] - start.velocity["x"] * tan,
        sympy.Integer(0),
    )
    flight = later_root(method.model, roots, quantity.name, ONTO_SLOPE)
    x0, y0 = start.position["x"], start.position["y"]
    method.step(
        "Landing on the slope through the launch point",
        method.tex(sympy.Eq(path["y"] - y0, (path["x"] - x0) * tan))
        + r"\Rightarrow T = "
        + method.tex(flight),
    )
    if quantity.kind is QuantityKind.TIME_OF_FLIGHT:
        return flight
    distance = tidy.simplify((path["x"].subs(t, flight) - x0) / sympy.cos(start.slope))
    method.step(
        "Range along the slope",
        rf"\frac{{x(T) - x_0}}{{\cos\left({method.tex(start.slope)}\right)}} = " + method.tex(distance),
    )
    return distance


def _quadratic_roots(a: sympy.Expr, b: sympy.Expr, c: sympy.Expr) -> list[sympy.Expr]:
    """Roots of a t^2 + b t + c = 0 (a != 0) by the formula: sympy's general solver is slow here."""
    if tidy.simplify(c) == 0:
        return [sympy.Integer(0), -b / a]
    root = sympy.sqrt(b**2 - 4 * a * c)
    return [(-b + root) / (2 * a), (-b - root) / (2 * a)]


# why a landing on a slope has no root, and what the model must declare
ONTO_SLOPE = (
    "the body never comes down to the slope through the launch point: it leaves on the slope's lower side, "
    "into the incline",
    "; declare the launch steeper than the slope under domain.positive",
)


def later_root(
    model: Model,
    roots: list[sympy.Expr],
    name: str,
    missed: tuple[str, str] = ("the body never comes down to the landing level", ""),
) -> sympy.Expr:
    """The landing: the root that is positive and latest at every domain point (not the launch, t = 0).
    `missed`: why there is none, and what to declare."""
    points = domain_points(model, POINTS, seed=19)
    chosen: set[int] = set()
    for point in points:
        values = []
        for index, root in enumerate(roots):
            value = complex(sympy.N(root.subs(point), 15))
            if abs(value.imag) <= 1e-12 * max(1.0, abs(value)) and value.real > 1e-12:
                values.append((value.real, index))
        if not values:
            raise DerivationError(
                f"{name}: {missed[0]} (roots {typed_text(roots)}) at "
                + ", ".join(f"{s}={v:.4g}" for s, v in point.items())
                + missed[1],
                quantity=name,
            )
        chosen.add(max(values)[1])
    if len(chosen) != 1:
        raise DerivationError(
            f"{name}: the landing time is not one root over the domain ({typed_text(roots)})", quantity=name
        )
    return tidy.simplify(roots[chosen.pop()])


# --- energy and momentum ------------------------------------------------------------------------


def by_energy(method: Method, quantity: Quantity) -> sympy.Expr:
    from physics.engine.method import NotApplicable

    model, mech = method.model, method.mech
    body = model.body(quantity.target)
    if model.loads_where(lambda traits: not traits.conservative and body.name in traits.bodies):
        raise NotApplicable(
            f"drag or a force that depends on the motion acts on {body.name}: energy is not conserved"
        )
    own = [d for d in mech.dofs if d.body == body.name and not d.name.startswith("phi_")]
    holding = [c.name for c in model.constraints if any(c.gap.has(d.symbol) for d in own)]
    if holding:
        raise NotApplicable(f"{body.name} is held by {holding}: not in free flight")
    force = {
        d.name.split("_", 1)[0]: tidy.simplify(-sympy.diff(mech.cartesian_potential, d.symbol)) for d in own
    }
    cartesian = {d.symbol for d in mech.dofs}
    if any(f.free_symbols & cartesian for f in force.values()):
        raise NotApplicable(f"the force on {body.name} ({typed_text(force)}) changes along the path")
    fx, fy = force.get("x", sympy.Integer(0)), force.get("y", sympy.Integer(0))
    if fx != 0:
        raise NotApplicable(
            f"a horizontal force ({typed_text(fx)}) acts: horizontal momentum is not conserved"
        )
    if fy == 0:
        raise DerivationError(f"{quantity.name}: nothing pulls {body.name} down: it never lands")
    start = launch(model, quantity)
    m, vx, vy = body.mass, start.velocity["x"], start.velocity["y"]
    method.step(
        "Horizontal momentum is conserved",
        rf"F_x = 0 \Rightarrow m v_x = m\,{method.tex(vx)}" if vx != 0 else r"F_x = 0 \Rightarrow v_x = 0",
    )
    if quantity.kind is QuantityKind.MAX_HEIGHT:
        height = sympy.Symbol("H")
        energy = sympy.Eq(m * (vx**2 + vy**2) / 2, m * vx**2 / 2 - fy * height)
        found = m * vy**2 / (2 * -fy)  # the one root of that linear equation
        method.step(
            "Energy from the launch to the apex, at the height $H$ above the launch (vertical velocity zero)",
            method.tex(energy) + r"\Rightarrow H = " + method.tex(found),
        )
        return tidy.simplify(found)
    if start.slope is not None:
        return _energy_onto_slope(method, quantity, start, fy)
    landing = sympy.Symbol("v_y1", real=True)
    energy = sympy.Eq(m * landing**2 / 2, m * vy**2 / 2 + fy * (start.level - start.position["y"]))
    size = sympy.sqrt(vy**2 + 2 * fy * (start.level - start.position["y"]) / m)
    roots = [size, -size]
    descending = _with_sign(model, roots, fy, quantity.name)
    flight = tidy.simplify(m * (descending - vy) / fy)
    method.step(
        "Energy from the launch to the landing level, where the vertical velocity is $v_{y1}$ "
        "(the horizontal velocity does not change)",
        method.tex(energy) + r"\Rightarrow v_{y1} = " + method.tex(descending),
    )
    method.step(
        "Vertical impulse over the flight",
        r"F_y T = m (v_{y1} - v_{y0}) \Rightarrow T = " + method.tex(flight),
    )
    if quantity.kind is QuantityKind.TIME_OF_FLIGHT:
        return flight
    distance = tidy.simplify(vx * flight)
    method.step("Range at the conserved horizontal velocity", r"R = v_x T = " + method.tex(distance))
    return distance


def _energy_onto_slope(method: Method, quantity: Quantity, start: Launch, fy: sympy.Expr) -> sympy.Expr:
    """Energy and the vertical impulse to the slope through the launch point: the drop is vx T tan θ."""
    assert start.slope is not None
    body = method.model.body(quantity.target)
    m, vx, vy = body.mass, start.velocity["x"], start.velocity["y"]
    tan = sympy.tan(start.slope)
    angle = rf"\tan\left({method.tex(start.slope)}\right)"
    descending = 2 * vx * tan - vy  # the other root: the two sum to 2 vx tan θ, and one is the launch's vy0
    method.step(
        f"Energy from the launch to the landing on the slope, a height $v_x T {angle}$ above the launch, "
        "and the vertical impulse over the flight",
        rf"\tfrac12 m v_{{y1}}^2 = \tfrac12 m v_{{y0}}^2 + F_y v_x T {angle},\quad F_y T = m (v_{{y1}} - v_{{y0}})"
        + rf"\Rightarrow v_{{y1}}^2 - 2 v_x {angle}\, v_{{y1}} = v_{{y0}}^2 - 2 v_x {angle}\, v_{{y0}}"
        + r"\Rightarrow v_{y1} = "
        + method.tex(descending),
    )
    time = later_root(method.model, [tidy.simplify(m * (descending - vy) / fy)], quantity.name, ONTO_SLOPE)
    method.step(
        "Time of flight from the impulse", r"T = \frac{m (v_{y1} - v_{y0})}{F_y} = " + method.tex(time)
    )
    if quantity.kind is QuantityKind.TIME_OF_FLIGHT:
        return time
    distance = tidy.simplify(vx * time / sympy.cos(start.slope))
    method.step(
        "Range along the slope at the conserved horizontal velocity",
        rf"R = \frac{{v_x T}}{{\cos\left({method.tex(start.slope)}\right)}} = " + method.tex(distance),
    )
    return distance


def _with_sign(model: Model, roots: list[sympy.Expr], like: sympy.Expr, name: str) -> sympy.Expr:
    """The root with the sign of `like` at every domain point (the body lands moving the way it is pulled)."""
    points = domain_points(model, POINTS, seed=23)
    for root in roots:
        values = [complex(sympy.N((root * like).subs(p), 15)) for p in points]
        if all(v.real > 0 and abs(v.imag) <= 1e-12 * abs(v) for v in values):
            return root
    raise DerivationError(
        f"{name}: the body does not come down to the landing level (roots {typed_text(roots)})", quantity=name
    )


# every other method (Lagrange's, d'Alembert's principle, ...) integrates its own constant acceleration
ROUTES: dict[str, Callable[[Method, Quantity], sympy.Expr]] = {"conservation": by_energy}
