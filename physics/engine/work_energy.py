"""Speed at a position: the velocity a coordinate has when the motion from the model's state reaches a
stated value of it (`at`), worked two ways; then a body's speed, or a force or acceleration there.

Work and energy (the conservation method): T + V where the motion arrives equals T + V at the state
plus the work of the non-conservative forces along the way, the integral of their generalized force;
kinetic friction's normal force comes from Newton's law across the surface. On a curved surface that
force changes with the speed, so the theorem alone does not give friction's work: it then stops.

Integrating the equation of motion (Lagrange's, Newton's and d'Alembert's methods, each its own): with the
state left free, the coordinate's acceleration is A(q) + B(q) q'^2 (friction on a curve and quadratic
drag bring the B term); v dv/dq = q'' is then linear in w = v^2, dw/dq = 2A + 2Bw, integrated from the
state to the configuration with the factor exp(-integral of 2B).

With several coordinates, every one but the moving coordinate must be cyclic (neither the potential nor
the inertia involves it) in a model without friction or drag: each one's momentum keeps its value at the
state, which fixes its velocity as a linear function of the moving coordinate's (`held`). Both routes
then work with that one degree of freedom (energy: T with the held velocities is (1/2) a(q) q'^2 + c(q),
no cross term, Routh's reduction; integration: the held velocities put into the equation of motion).
Any other coordinate is not determined where the motion arrives: refused at the quantity's `at`.
"""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING

import sympy

from physics import typeset
from physics.answer_text import typed_text
from physics.engine import impact, tidy
from physics.engine.mechanics import Mechanics, solve_linear
from physics.engine.model import REACH_KINDS, Coordinate, Model, Quantity, QuantityKind
from physics.engine.proof import domain_points
from physics.engine.quantity_table import derives
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.method import Method

POINTS = 8


@dataclasses.dataclass(frozen=True)
class Journey:
    """The coordinate that moves, where it starts and arrives, its velocity at the start, and which way
    it goes (+1 towards increasing values)."""

    coordinate: Coordinate
    start: sympy.Expr
    end: sympy.Expr
    velocity: sympy.Expr
    sign: int
    # every other coordinate's velocity, held by its conserved momentum, in the moving one's q and q'
    held: dict[sympy.Symbol, sympy.Expr] = dataclasses.field(default_factory=dict)


def journey(method: Method, quantity: Quantity) -> Journey:
    model = method.model
    ((name, end),) = quantity.at
    c = model.coordinate(name)
    state = dict(model.state)
    start = state[c.symbol]
    held = held_velocities(method, c, quantity) if len(model.coordinates) > 1 else {}
    return Journey(
        c, start, end, state.get(c.velocity, sympy.Integer(0)), _direction(model, start, end, name), held
    )


def held_velocities(method: Method, c: Coordinate, quantity: Quantity) -> dict[sympy.Symbol, sympy.Expr]:
    """The other coordinates' velocities from their conserved momenta (each cyclic), as functions of c
    and c'; refused at the quantity's `at` (a turning point: at the quantity) when a coordinate is not
    fixed that way."""
    from physics.engine.conservation import cyclic_indices

    model, mech = method.model, method.mech
    where = ("quantities", quantity.name, "at") if quantity.at else ("quantities", quantity.name)
    arrival = typed_text(quantity.at[0][1]) if quantity.at else "its turning point"
    if model.nonconservative_loads:
        raise DerivationError(
            f"{quantity.name}: with several coordinates the state where {c.name} arrives is fixed by conserved "
            "momenta, which friction, drag and forces in the time do not keep: declare a model with "
            f"{c.name} alone, or one without them",
            quantity=quantity.name,
            path=where,
        )
    cyclic = cyclic_indices(mech)
    loose = [o.name for i, o in enumerate(model.coordinates) if o != c and i not in cyclic]
    if loose:
        raise DerivationError(
            f"{quantity.name}: where {c.name} reaches {arrival}, {', '.join(loose)} is not "
            "determined: the potential or the inertia depends on it, so no conserved momentum fixes it (two "
            f"coupled coordinates exchange energy). Declare {', '.join(loose)} fixed (a symbol, not a "
            f"coordinate), or a model whose other coordinates the potential and the inertia do not involve",
            quantity=quantity.name,
            path=where,
        )
    mass = mech.mass_matrix
    n = len(mech.q)
    state = {**{v: sympy.Integer(0) for v in mech.qd}, **dict(model.state)}
    others = [i for i in range(n) if mech.q[i] != c.symbol]
    equations = []
    for i in others:
        momentum = sympy.Add(*(mass[i, j] * mech.qd[j] for j in range(n)))
        initial = tidy.simplify(momentum.subs(state))
        method.step(
            f"The momentum conjugate to {method.named(method.model.coordinates[i].name)} is conserved "
            "(no force acts along it)",
            method.tex(sympy.Eq(momentum, initial)),
        )
        equations.append(momentum - initial)
    return solve_linear(equations, [mech.qd[i] for i in others], "the conserved momenta")


def _direction(model: Model, start: sympy.Expr, end: sympy.Expr, name: str) -> int:
    """The sign of end - start over the whole domain: the coordinate moves that way (without turning)."""
    difference = tidy.simplify(end - start)
    if difference.is_positive:
        return 1
    if difference.is_negative:
        return -1
    values = [float(difference.subs(p)) for p in domain_points(model, POINTS, seed=13)]
    if all(v > 0 for v in values):
        return 1
    if all(v < 0 for v in values):
        return -1
    raise DerivationError(
        f"cannot tell which way {name} moves from its start {typed_text(start)} to {typed_text(end)}: the difference {typed_text(difference)} "
        "changes sign (or is zero) on the domain; declare which way it goes (domain.positive: "
        f"[{typed_text(difference)!r}], or its negative)",
        path=("state", name),
    )


@derives(*REACH_KINDS)  # always with `at` (reach_loading.py): Method.answer comes here for it
def answer(method: Method, quantity: Quantity) -> sympy.Expr:
    """The quantity where the motion arrives, by this method's own route to the velocity there."""
    model = method.model
    trip = journey(method, quantity)
    key = (trip.coordinate.name, trip.end)
    if key not in method.arrivals:
        from physics.engine.leaving import staged  # it builds on this module's routes

        method.arrivals[key] = staged(method, trip)[0]
        _check_reached(model, trip, method.arrivals[key], quantity.name)
        _say_which_arrival(method, trip, method.arrivals[key])
    square = method.arrivals[key]
    c = trip.coordinate
    velocity = tidy.simplify(trip.sign * sympy.sqrt(square))
    arrival = {c.symbol: trip.end, c.velocity: velocity}
    there = {c.velocity: velocity, **{v: tidy.simplify(e.subs(arrival)) for v, e in trip.held.items()}}
    if quantity.kind is QuantityKind.VELOCITY:
        return there[model.coordinate(quantity.target).velocity]
    if quantity.kind is QuantityKind.SPEED:
        position = dict(model.body(quantity.target).position)
        moved = [
            sympy.Add(*(sympy.diff(e, o.symbol) * o.velocity for o in model.coordinates))
            for e in position.values()
        ]
        rate = sympy.Add(*(sympy.expand(v.subs(trip.held)) ** 2 for v in moved)).subs(c.symbol, trip.end)
        # in q'^2 (odd powers only where momenta start non-zero): v^2 = square, v = the signed velocity
        squared = sympy.expand(rate).subs(c.velocity**2, square).subs(c.velocity, velocity)
        # |cos(theta)| of a wedge's speed written as cos(theta) where the domain keeps it positive
        speed = impact._signs_by_domain(model, sympy.sqrt(sympy.factor(tidy.simplify(squared))))
        method.step(
            f"Speed of «{quantity.target}» there",  # the body in the problem's words, not its engine name
            rf"v_{{\mathrm{{{quantity.target}}}}} = \sqrt{{{_squares(position)}}} = " + method.tex(speed),
        )
        return speed
    # the cyclic coordinates' positions stay as at the state: nothing depends on them
    arrived = {**dict(model.state), c.symbol: trip.end, **there}
    reached = dataclasses.replace(model, state=tuple(arrived.items()))
    solver = type(method)(reached, Mechanics(reached))
    result = solver.answer(dataclasses.replace(quantity, at=()))
    where = f"(where {method.named(c.name)} = ${method.tex(trip.end)}$)"
    method.adopt_after(solver.steps, where)
    return result


def by_energy(method: Method, trip: Journey) -> sympy.Expr:
    """q'^2 at the end from T1 + V1 = T0 + V0 + W (work of the non-conservative forces)."""
    from physics.engine.method import NotApplicable
    from physics.engine.newton import NewtonMethod

    model, mech, c = method.model, method.mech, trip.coordinate
    q, qd = c.symbol, c.velocity
    work = sympy.Integer(0)
    if model.nonconservative_loads:
        multipliers: list[sympy.Expr] = list(mech.multipliers)
        if model.contact_loads:
            _straight_surfaces(model, mech, c)
            free = dataclasses.replace(model, state=())
            across = NewtonMethod(free, Mechanics(free)).solution  # Newton's law as a step of this method
            multipliers = [across[lam] for lam in mech.multipliers]
            method.step(
                "Normal forces from Newton's law across each surface",
                r",\quad ".join(
                    method.tex(sympy.Eq(lam, v)) for lam, v in zip(mech.multipliers, multipliers, strict=True)
                ),
            )
        forces = mech.load_forces(False, multipliers)
        generalized = tidy.simplify(mech.generalized(forces)[0])
        if generalized.has(qd):
            raise NotApplicable(
                f"the non-conservative force along {c.name} ({typed_text(generalized)}) depends on the speed along the way "
                "(a normal force on a curve, drag): its work needs the motion itself"
            )
        work = tidy.simplify(tidy.integrate(generalized, (q, trip.start, trip.end)))
        if work.has(sympy.Integral):
            raise NotApplicable(f"could not integrate the work of {typed_text(generalized)} along {c.name}")
        method.step(
            "Work of the non-conservative forces",
            rf"W = \int_{{{method.tex(trip.start)}}}^{{{method.tex(trip.end)}}} Q_{{\mathrm{{nc}}}}\,"
            rf"d{method.tex(q)} = " + method.tex(work),
        )
    kinetic, potential = sympy.expand(mech.kinetic.subs(trip.held)), mech.potential
    state = {**{v: sympy.Integer(0) for v in mech.qd}, **dict(model.state)}
    before = (mech.kinetic + potential).subs(state)
    if tidy.simplify(sympy.diff(kinetic, qd).subs(qd, 0)) != 0:
        raise NotApplicable(
            f"the kinetic energy with the conserved momenta is not even in {c.name}'s velocity"
        )
    inertia = sympy.diff(kinetic, qd, 2).subs(q, trip.end)
    # with held momenta, T keeps a part in the moving coordinate alone (the cyclic motion's own energy)
    rest = kinetic.subs(qd, 0).subs(q, trip.end) + potential.subs(q, trip.end)
    square = tidy.simplify(2 * (before + work - rest) / inertia)
    w = qd**2
    method.step(
        f"Work and energy from {method.named(c.name)} = ${method.tex(trip.start)}$ to ${method.tex(trip.end)}$",
        r"T_1 + V_1 = T_0 + V_0 + W:\quad "
        + method.tex(sympy.Eq(tidy.simplify(inertia * w / 2 + rest), tidy.simplify(before + work)))
        + r"\Rightarrow "
        + method.tex(sympy.Eq(w, square)),
    )
    return square


def _straight_surfaces(model: Model, mech: Mechanics, c: Coordinate) -> None:
    """Friction's normal force is the same at every speed only where the surface is straight along the
    path: the gap's second derivative along it (the curvature term of Newton's law across it) vanishes."""
    from physics.engine.method import NotApplicable

    place = {d.symbol: d.mapping for d in mech.dofs}
    for name in dict.fromkeys(k for load in model.contact_loads for k in load.traits(model).constraints):
        gap = model.constraint(name).gap
        curvature = sympy.Add(
            *(
                sympy.diff(gap, a.symbol, b.symbol).subs(place)
                * sympy.diff(a.mapping, c.symbol)
                * sympy.diff(b.mapping, c.symbol)
                for a in mech.dofs
                for b in mech.dofs
            )
        )
        if tidy.simplify(curvature) != 0:
            raise NotApplicable(
                f"the surface {name!r} curves along the path, so its normal force, and "
                "friction's work, depends on the speed along the way: the work needs the motion itself"
            )


def by_integration(method: Method, trip: Journey) -> sympy.Expr:
    """q'^2 at the end from v dv/dq = A(q) + B(q) v^2 (this method's equation of motion), integrated."""
    from physics.engine.method import NotApplicable

    c = trip.coordinate
    q, qd = c.symbol, c.velocity
    acceleration = _in_one_trig_function(method.free.acceleration(c.name), q)
    if trip.held:  # the other coordinates' equations of motion, integrated once: their momenta conserved
        acceleration = tidy.simplify(acceleration.subs(trip.held))
    u = sympy.Dummy("u", positive=True)  # the speed; qd = sign * u on the way
    moving = sympy.expand(acceleration.subs(qd, trip.sign * u))
    constant = moving.subs(u, 0)
    quadratic = sympy.expand((moving - constant) / u**2)
    if quadratic.has(u):
        raise NotApplicable(
            f"the acceleration {typed_text(acceleration)} is not A({c.name}) + B({c.name}) {c.name}_dot^2 (linear drag?): "
            "v dv/dq does not integrate in closed form"
        )
    t = sympy.Dummy("t", real=True)
    growth = (
        tidy.integrate(2 * quadratic.subs(q, t), (t, trip.start, q)) if quadratic != 0 else sympy.Integer(0)
    )
    driven = tidy.integrate(sympy.expand(2 * constant * sympy.exp(-growth)), (q, trip.start, trip.end))
    # simplified once, at the end: simplify on the integrands costs more than the integration
    square = tidy.simplify(sympy.exp(growth.subs(q, trip.end)) * (trip.velocity**2 + driven))
    if square.has(sympy.Integral):
        raise NotApplicable(f"could not integrate {c.name}'s equation of motion in closed form")
    w = qd**2
    method.step(
        f"The equation of motion of {method.named(c.name)}, written for the square of its rate",
        rf"\ddot{{{method.tex(q)}}} = " + method.tex(acceleration) + r"\Rightarrow "
        rf"\frac{{\mathrm{{d}}(\dot{{{method.tex(q)}}}^2)}}{{\mathrm{{d}}{method.tex(q)}}} = "
        + method.tex(2 * constant + 2 * quadratic * w),
    )
    method.step(
        f"Integrated from {method.named(c.name)} $= {typeset.latex(trip.start)}$ to ${typeset.latex(trip.end)}$",
        method.tex(sympy.Eq(w, square)),
    )
    return square


def _in_one_trig_function(expr: sympy.Expr, q: sympy.Symbol) -> sympy.Expr:
    """expr with sin(q)^2 written 1 - cos(q)^2 and cancelled: an acceleration a method leaves as a ratio of
    trigonometric polynomials (Newton's, through a grip written with acos, for a ball rolling round a
    loop) is 5 g sin(q)/(7 (r - R)) once it is, and `integrate` would spend minutes on it as it was."""
    if not expr.has(sympy.sin(q), sympy.cos(q)):
        return expr
    return sympy.factor(sympy.cancel(expr.subs(sympy.sin(q) ** 2, 1 - sympy.cos(q) ** 2)))


def _check_reached(model: Model, trip: Journey, square: sympy.Expr, name: str) -> None:
    """v^2 must be positive where the motion arrives, or it never gets there; v^2 = 0 on the whole domain
    is the coordinate's turning point (a projectile's top), reached as the rate vanishes."""
    if tidy.simplify(square) == 0:
        return
    for point in domain_points(model, POINTS, seed=17):
        value = complex(sympy.N(square.subs(point), 15))
        if abs(value.imag) > 1e-9 * max(1.0, abs(value.real)) or value.real <= 0:
            raise DerivationError(
                f"{name}: the motion from the state does not reach {trip.coordinate.name} = {typed_text(trip.end)}: there "
                f"{trip.coordinate.name}_dot^2 = {typed_text(square)} = {value.real:.4g} at "
                + ", ".join(f"{s}={v:.4g}" for s, v in point.items()),
                quantity=name,
            )


def _say_which_arrival(method: Method, trip: Journey, square: sympy.Expr) -> None:
    """The worked solution says which arrival it takes where the coordinate could be there twice: the top,
    where the rate vanishes, or the first arrival while the potential slows it there (a projectile passes
    a lower height again on its way down)."""
    c, mech = trip.coordinate, method.mech
    velocity = tidy.simplify(trip.sign * sympy.sqrt(square))
    if tidy.simplify(square) == 0:
        title = f"{method.named(c.name)} reaches ${method.tex(trip.end)}$ where its rate vanishes: its turning point"
    else:
        # the effective potential: V with the held motion's kinetic energy in q alone (Routh's reduction)
        effective = mech.potential + sympy.expand(mech.kinetic.subs(trip.held)).subs(c.velocity, 0)
        pull = -sympy.diff(effective, c.symbol).subs(c.symbol, trip.end)
        values = [complex(sympy.N(pull.subs(p), 15)) for p in domain_points(method.model, POINTS, seed=17)]
        if not all(trip.sign * v.real < 0 and abs(v.imag) <= 1e-9 * abs(v.real) for v in values):
            return
        title = (
            f"{method.named(c.name)} reaches ${method.tex(trip.end)}$ slowing, so it may be there again later "
            "(on its way back, or round again): the velocity is taken at the first arrival"
        )
    method.step(title, method.tex(sympy.Eq(c.velocity, velocity)))


# every other method (d'Alembert's principle, ...) integrates its own equation of motion
ROUTES = {"conservation": by_energy}


def arrival_velocity(model: Model, quantity: Quantity) -> sympy.Expr:
    """The coordinate's velocity where the motion arrives, by energy (for mistakes: a slip's re-derivation)."""
    from physics.engine.conservation import ConservationMethod
    from physics.engine.leaving import staged

    method = ConservationMethod(model, Mechanics(model))
    trip = journey(method, quantity)
    return tidy.simplify(trip.sign * sympy.sqrt(staged(method, trip)[0]))


def _squares(position: dict[str, sympy.Expr]) -> str:
    """The squared velocity components in TeX: those of x and y, and of z for a body placed on z."""
    axes = [a for a in ("x", "y", "z") if a in position] if "z" in position else ["x", "y"]
    return " + ".join(rf"\dot {a}^2" for a in axes)
