"""Steady circular motion and orbits under a central force, in polar (or any) coordinates.

Every quantity here is reached through each method's own acceleration of a coordinate, so Lagrange's
radial equation, Newton's radial law on the Cartesian axes and the energy with the conserved momenta
(the effective potential) each give it their own way:

- steady motion (`circular_speed`, `revolution_period`, `circular_energy`, target an angle coordinate
  theta): the rate theta' = w at which every other coordinate, held at its state value at rest, stops
  accelerating (w > 0: the force must pull inwards); the turning body's speed |dx/dtheta| w, the period
  2 pi / w, the energy T + V of that motion;
- the effective potential (`circular_radius`, `epicyclic_frequency`, target the radial coordinate r):
  the momenta of the cyclic coordinates (those neither the potential nor the inertia depends on) are
  held at their state values; with the cyclic velocities written through them, r'' = f(r). The
  circular orbit is the root with f'(r0) < 0 (the minimum of the effective potential) and small radial
  oscillations about it have omega^2 = -f'(r0);
- `mechanical_energy: state`: T + V at the state (in the coordinates, on the Cartesian axes, or with
  the conserved momenta, one per method).
"""

from __future__ import annotations

import dataclasses
import weakref
from collections.abc import Callable
from typing import Any, TypeVar, cast

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.conservation import ConservationMethod, cyclic_indices
from physics.engine.mechanics import Mechanics, solve_linear, time_derivative
from physics.engine.method import Method, NotApplicable
from physics.engine.model import EFFECTIVE_KINDS, ORBIT_KINDS, REACH_KINDS, Model, Quantity, QuantityKind
from physics.engine.newton import NewtonMethod
from physics.engine.proof import domain_points
from physics.engine.quantity_table import derives
from physics.engine.results import StepKind
from physics.errors import DerivationError

FRAME = "frame"  # `revolution_period: frame`: one turn of the model's rotating frame
# the unknown steady rate; positive, so that of the pair +-w sympy returns the forward turning
RATE = sympy.Symbol("w_steady", positive=True)

MISSING_TWO_PI = "One revolution is 2π radians: the period is 2π divided by the angular velocity."
ENERGY_SIGN = (
    "Check the sign: the potential energy of an attractive force is negative, and in a bound orbit the "
    "total energy is negative too."
)
KINETIC_ONLY = "That is the kinetic energy only: the total mechanical energy adds the potential energy."
POTENTIAL_ONLY = "That is the potential energy only: the total mechanical energy adds the kinetic energy."


@derives(*ORBIT_KINDS)
def answer(method: Method, quantity: Quantity) -> sympy.Expr:
    """The orbit quantity as `method` derives it."""
    kind = quantity.kind
    if kind is QuantityKind.MECHANICAL_ENERGY:
        energy = energy_of(method)
        method.step("Mechanical energy at the state", _energy_sum(method) + method.tex(energy))
        return energy
    if kind in EFFECTIVE_KINDS:
        radius, slope = circular_orbit(method, quantity.target)
        if kind is QuantityKind.CIRCULAR_RADIUS:
            return radius
        omega = tidy.simplify(sympy.sqrt(-slope))
        method.step(
            f"Small oscillations of {quantity.target} about the circular orbit",
            rf"\omega^2 = -f'({method.tex(model_symbol(method.model, quantity.target))}_0) = "
            + method.tex(tidy.simplify(-slope)),
        )
        return omega
    if quantity.target == FRAME:
        period = tidy.simplify(2 * sympy.pi / frame_rate(method))
        method.step("Period of one turn of the frame", r"\frac{2\pi}{\omega} = " + method.tex(period))
        return period
    rate, steady = steady_rate(method, quantity.target)
    if kind is QuantityKind.REVOLUTION_PERIOD:
        period = tidy.simplify(2 * sympy.pi / rate)
        method.step("Period of one revolution", r"\frac{2\pi}{\omega} = " + method.tex(period))
        return period
    if kind is QuantityKind.CIRCULAR_SPEED:
        speed = tidy.simplify(_speed(steady.model, quantity.target).subs(RATE, rate))
        method.step("Speed on the circle", "v = " + method.tex(speed))
        return speed
    energy = tidy.simplify(energy_of(steady).subs(RATE, rate))
    method.step("Energy of the circular motion", _energy_sum(method) + method.tex(energy))
    return energy


def _energy_sum(method: Method) -> str:
    letters = method.mech.notation.letters
    return f"{letters.energy} = {letters.kinetic} + {letters.potential} = "


def model_symbol(model: Model, coordinate: str) -> sympy.Symbol:
    return model.coordinate(coordinate).symbol


def energy_of(method: Method) -> sympy.Expr:
    """T + V at the method's model's state, in the method's own terms."""
    model, mech = method.model, method.mech
    state = dict(model.state)
    if isinstance(method, NewtonMethod):  # on the Cartesian axes: sum of m v^2 / 2
        place = mech.cartesian_state()
        kinetic = sympy.Add(*(sympy.Rational(1, 2) * d.inertia * d.velocity**2 for d in mech.dofs)).subs(
            place
        )
        potential = mech.cartesian_potential.subs(place)
    elif isinstance(method, ConservationMethod):  # with the cyclic velocities through their momenta
        velocities, kinetic, _ = method.reduced
        potential = mech.potential
        kinetic = kinetic.subs(velocities)
    else:
        kinetic, potential = mech.kinetic, mech.potential
    return tidy.simplify((kinetic + potential).subs(state))


T = TypeVar("T")
# worked once per method and target, for all the quantities that use it (not across derivations)
_WORKED: weakref.WeakKeyDictionary[Method, dict[tuple[str, str], Any]] = weakref.WeakKeyDictionary()
# what a method computes before it reads the state: shared with the same method at another state
_STATELESS = ("system", "applied_forces")


def _worked(method: Method, key: tuple[str, str], work: Callable[[], T]) -> T:
    memo = _WORKED.setdefault(method, {})
    if key not in memo:
        memo[key] = work()
    return cast(T, memo[key])


def restated(method: Method, model: Model) -> Method:
    """The same method on the same system at another state (`model` differs from the method's only in
    its state), reusing the energies and equations that do not depend on the state."""
    mech = Mechanics(model)
    mech.__dict__.update({k: v for k, v in method.mech.__dict__.items() if k != "model"})
    solver = type(method)(model, mech)
    for name in _STATELESS:
        if hasattr(type(method), name):
            solver.__dict__[name] = getattr(method, name)
    return solver


def steady_rate(method: Method, target: str) -> tuple[sympy.Expr, Method]:
    """(w, the method at the state with target' = RATE and every other coordinate at rest): the rate at
    which the other coordinates, by this method's own accelerations, stay where the state puts them."""
    return _worked(method, ("steady", target), lambda: _steady_rate(method, target))


def _steady_rate(method: Method, target: str) -> tuple[sympy.Expr, Method]:
    model = method.model
    turning = model.coordinate(target)
    others = [c for c in model.coordinates if c is not turning]
    if not others:
        raise NotApplicable("a steady rotation holds other coordinates still, and there are none")
    still = {c.velocity for c in others} | {turning.velocity}
    state = {s: v for s, v in model.state if s not in still}
    state.update({c.velocity: sympy.Integer(0) for c in others})
    state[turning.velocity] = RATE
    solver = restated(method, dataclasses.replace(model, state=tuple(state.items())))
    # the rate sought is the turning coordinate's rate, and its steps are read as such
    turning_tex = method.tex(turning.velocity)
    solver.mech.__dict__["latex_names"] = {**method.mech.latex_names, RATE: turning_tex}
    spin = tidy.simplify(solver.acceleration(target))
    if spin != 0:
        raise DerivationError(
            f"{target} does not turn uniformly ({target}'' = {typed_text(spin)}): a steady rotation needs a coordinate on "
            "which neither the potential nor the inertia depends",
            quantity=target,
        )
    accelerations = [(c, tidy.simplify(solver.acceleration(c.name))) for c in others]
    moving = [(c, a) for c, a in accelerations if a != 0]
    if not moving:
        raise DerivationError(f"every rate of {target} keeps the other coordinates still", quantity=target)
    first, acceleration = moving[0]
    found = [r for r in tidy.solve(acceleration, RATE) if r.is_real is not False]
    # ±sqrt(g/(L cos(alpha))): sympy cannot sign cos(alpha) by itself, the domain can
    roots = [r for r in found if _positive_on_domain(r, model)]
    if len(roots) != 1:
        raise DerivationError(
            f"no steady rotation of {target}: {first.name}'' = {typed_text(acceleration)} has no single positive root in "
            f"{target}' (found {typed_text(found)}); the force must pull towards the centre",
            quantity=target,
        )
    rate = tidy.simplify(roots[0])
    for c, a in moving[1:]:
        if tidy.simplify(a.subs(RATE, rate)) != 0:
            raise DerivationError(
                f"no steady rotation of {target}: at {target}' = {typed_text(rate)}, {c.name}'' = {typed_text(a)} does not vanish",
                quantity=target,
            )
    # a rate the state leaves out is 0, and the circular quantities find the rate themselves; but a
    # force or an acceleration beside them is taken at the state's rate, which must then be this one
    given = dict(model.state).get(turning.velocity, sympy.Integer(0))
    if (given != 0 or _asks_of_the_state(model)) and not _same_on_domain(given, rate, model):
        at_rest = f" (a {turning.velocity} left out of the state is 0)" if given == 0 else ""
        raise DerivationError(
            f"the state gives {target}' = {typed_text(given)}{at_rest}, but {target} turns steadily, the other "
            f"coordinates held at the state, at {target}' = {typed_text(rate)}: a steady quantity (its period, "
            "speed or energy) would not be of the state's motion, where forces and accelerations are taken. "
            f"For the steady motion give {turning.velocity}: {typed_text(rate)} in the state; for the motion "
            f"at {target}' = {typed_text(given)}, ask for no steady quantity of {target}",
            quantity=target,
        )
    rate_name = {RATE.name: str(turning.velocity)}
    # a solve at the steady rate is not the method's solve at the state (a force asked for logs that)
    steady = f", for a steady rate ${turning_tex}$"
    method.adopt(
        dataclasses.replace(
            step,
            title=step.title + (steady if step.kind is StepKind.SOLVE else ""),
            symbols=tuple(sorted({rate_name.get(s, s) for s in step.symbols})),
        )
        for step in solver.steps
    )
    method.step(
        f"Steady rotation of {method.named(target)}",
        method.tex(sympy.Eq(first.acceleration, acceleration.subs(RATE, turning.velocity)))
        + rf" = 0 \Rightarrow \omega = {turning_tex} = "
        + method.tex(rate),
    )
    return rate, solver


def frame_rate(method: Method) -> sympy.Expr:
    """The rotating frame's rate with the bodies at rest in it at the state: the rate as written when
    every coordinate's acceleration there vanishes for any rate, else with the rate's own symbol (the
    one that appears nowhere but in the rate and the centrifugal potential) solved so that they do."""
    model = method.model
    rate = model.frame.rate if model.frame is not None else None
    if rate is None:
        raise DerivationError(
            "revolution_period: frame needs a rotating frame (the `rotating` element)", quantity=FRAME
        )
    accelerations = [(c, method.acceleration(c.name)) for c in model.coordinates]
    moving = [(c, a) for c, a in accelerations if not _vanishes(a, model)]
    if not moving:
        method.step("At rest in the frame at the state", r"\ddot q = 0,\ \omega = " + method.tex(rate))
        return rate
    own = [s for s in rate.free_symbols if s in model.parameters and not elsewhere(model, s)]
    if len(own) != 1:
        raise DerivationError(
            f"the bodies are not at rest in the frame at the state, and the rate {typed_text(rate)} has {len(own)} symbols "
            "of its own to solve for (one, found nowhere else in the model, is needed)",
            quantity=FRAME,
        )
    (symbol,) = own
    first, acceleration = moving[0]
    roots = [r for r in tidy.solve(acceleration, symbol) if _positive_on_domain(r, model)]
    if len(roots) != 1:
        raise DerivationError(
            f"no single rate {symbol} > 0 holds {first.name} at rest in the frame ({first.name}'' = {typed_text(acceleration)})",
            quantity=FRAME,
        )
    value = tidy.simplify(roots[0])
    for c, a in moving[1:]:
        if tidy.simplify(a.subs(symbol, value)) != 0:
            raise DerivationError(
                f"at {symbol} = {typed_text(value)}, {c.name}'' = {typed_text(a)} does not vanish",
                quantity=FRAME,
            )
    method.step(
        "At rest in the frame at the state",
        method.tex(sympy.Eq(first.acceleration, acceleration))
        + rf" = 0 \Rightarrow {method.tex(symbol)} = "
        + method.tex(value),
    )
    return tidy.simplify(rate.subs(symbol, value))


def _vanishes(expr: sympy.Expr, model: Model) -> bool:
    """expr is identically 0; looked at numerically first, since simplifying every method's acceleration
    costs more than the rest of the quantity."""
    if expr == 0:
        return True
    try:
        values = [complex(sympy.N(expr.subs(point), 15)) for point in domain_points(model, 3, seed=13)]
    except (TypeError, ValueError):
        values = []
    if any(abs(v) > 1e-9 for v in values):
        return False
    return bool(tidy.simplify(expr) == 0)


def elsewhere(model: Model, symbol: sympy.Symbol) -> bool:
    """`symbol` appears in the model beside the frame's rate (positions, masses, gaps, the state...)."""
    places: list[sympy.Expr] = [e for b in model.bodies for _, e in b.position]
    places += [b.mass for b in model.bodies] + [b.inertia for b in model.bodies]
    places += [c.gap for c in model.constraints] + [v for _, v in model.state]
    places += [model.gravity] if model.gravity is not None else []
    return any(e.has(symbol) for e in places)


def _speed(steady: Model, target: str) -> sympy.Expr:
    """|v| of the one body that turns with `target`, in the steady motion (velocities from the state)."""
    q = steady.coordinate(target).symbol
    turning = [b for b in steady.bodies if any(e.has(q) for _, e in b.position)]
    if len(turning) != 1:
        raise DerivationError(
            f"circular_speed is the speed of the one body that turns with {target}; {len(turning)} bodies do",
            quantity=target,
        )
    velocity = [time_derivative(e, steady) for _, e in turning[0].position]
    squared = sympy.Add(*(v**2 for v in velocity)).subs(dict(steady.state))
    return sympy.sqrt(tidy.simplify(squared))


def conserved_state(method: Method, target: str) -> Model:
    """The model with `target` free and at rest, the other non-cyclic coordinates at rest, and the cyclic
    velocities written through their momenta, held at the values the state gives them."""
    model, mech = method.model, method.mech
    cyclic = cyclic_indices(mech)
    radial = model.coordinate(target)
    if not cyclic:
        raise DerivationError(
            "no coordinate is cyclic (free of the potential and the inertia), so no momentum is conserved "
            f"to hold: ask for the equilibrium of {target} instead",
            quantity=target,
        )
    if any(mech.q[i] == radial.symbol for i in cyclic):
        raise DerivationError(f"{target} is cyclic: it has no circular orbit", quantity=target)
    state = dict(model.state)
    mass = mech.mass_matrix.applyfunc(tidy.simplify)
    velocities = sympy.Matrix(mech.qd)
    momenta = [tidy.simplify((mass[i, :] * velocities)[0].subs(state)) for i in cyclic]
    rest = {mech.qd[j]: sympy.Integer(0) for j in range(len(mech.q)) if j not in cyclic}
    equations = [(mass[i, :] * velocities)[0].subs(rest) - p for i, p in zip(cyclic, momenta, strict=True)]
    held = solve_linear(equations, [mech.qd[i] for i in cyclic], "the conserved momenta")
    free = {s: v for s, v in state.items() if s != radial.symbol}
    free.update(rest)
    free.update(held)
    return dataclasses.replace(model, state=tuple(free.items()))


def circular_orbit(method: Method, target: str) -> tuple[sympy.Expr, sympy.Expr]:
    """(r0, f'(r0)): the stable root of r'' = f(r) with the cyclic momenta conserved."""
    return _worked(method, ("orbit", target), lambda: _circular_orbit(method, target))


def _circular_orbit(method: Method, target: str) -> tuple[sympy.Expr, sympy.Expr]:
    model = method.model
    r = model.coordinate(target).symbol
    solver = restated(method, conserved_state(method, target))
    radial = tidy.simplify(solver.acceleration(target))
    method.adopt(solver.steps)
    roots = tidy.solve(radial, r)
    slope = sympy.diff(radial, r)
    stable = [
        root
        for root in roots
        if root.is_real is not False
        and not (r.is_positive and root.is_positive is False)
        and _positive_on_domain(-tidy.simplify(slope.subs(r, root)), model)
    ]
    if len(stable) != 1:
        raise DerivationError(
            f"expected one circular orbit (a stable root of {target}'' = {typed_text(radial)} with the conserved momenta), "
            f"found {len(stable)} among {typed_text(roots)}",
            quantity=target,
        )
    radius = tidy.simplify(stable[0])
    method.step(
        f"Circular orbit: {target}'' = 0 with the conserved momenta",
        method.tex(sympy.Eq(model.coordinate(target).acceleration, radial))
        + rf" = 0 \Rightarrow {method.tex(r)}_0 = "
        + method.tex(radius),
    )
    return radius, tidy.simplify(slope.subs(r, radius))


# taken in the motion at the state, so at the state's rate of the turning coordinate
_OF_THE_STATE = REACH_KINDS | {QuantityKind.FORCE, QuantityKind.ACCELERATION, QuantityKind.MECHANICAL_ENERGY}


def _asks_of_the_state(model: Model) -> bool:
    def of_the_state(quantity: Quantity | None) -> bool:
        return quantity is not None and (quantity.kind in _OF_THE_STATE or of_the_state(quantity.inner))

    return any(of_the_state(q) for q in model.quantities)


def _same_on_domain(first: sympy.Expr, second: sympy.Expr, model: Model) -> bool:
    """Equal at sampled domain points: sympy alone may not see that sqrt(g/(L cos(alpha))) is
    sqrt(g)/sqrt(L cos(alpha)) without the domain's signs."""
    if tidy.simplify(first - second) == 0:
        return True
    try:
        return all(
            abs(complex(sympy.N((first - second).subs(point))))
            <= 1e-9 * max(1.0, abs(complex(sympy.N(second.subs(point)))))
            for point in domain_points(model, 12, seed=3)
        )
    except (TypeError, ValueError):
        return False


def _positive_on_domain(expr: sympy.Expr, model: Model) -> bool:
    if expr.is_positive is not None:
        return bool(expr.is_positive)
    try:
        return all(float(sympy.N(expr.subs(point))) > 0 for point in domain_points(model, 12, seed=3))
    except (TypeError, ValueError):
        return False


def mistakes(model: Model, quantity: Quantity, reference: sympy.Expr) -> list[tuple[sympy.Expr | None, str]]:
    """Slips with an orbit's period and energy: a missing 2 pi, the energy's sign, half of the energy."""
    kind = quantity.kind
    if kind is QuantityKind.REVOLUTION_PERIOD:
        return [(reference / (2 * sympy.pi), MISSING_TWO_PI)]
    if kind not in (QuantityKind.CIRCULAR_ENERGY, QuantityKind.MECHANICAL_ENERGY):
        return []
    result: list[tuple[sympy.Expr | None, str]] = []
    potential = tidy.simplify(Mechanics(model).potential.subs(dict(model.state)))
    if not potential.has(*(c.symbol for c in model.coordinates)):
        result += [(tidy.simplify(reference - potential), KINETIC_ONLY), (potential, POTENTIAL_ONLY)]
    return [*result, (-reference, ENERGY_SIGN)]
