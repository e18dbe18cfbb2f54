"""Damped oscillations: a coordinate with viscous damping, about its stable equilibrium.

Each method linearizes the motion about the equilibrium in its own description, M q'' + C q' + K q = 0:
Lagrange's equations with the dissipative generalized forces (`lagrange`), Newton's law on each body's
Cartesian axes (`newton`, without constraints), or the energy balance d(T + V)/dt = P with T, V to
second order and the drag's power P = -q'^T C q' (`conservation`, drag only). The characteristic
equation det(M s^2 + C s + K) = 0 must have exactly one oscillating factor a s^2 + b s + c; with
s = -1/tau + i omega_d its real and imaginary parts give the decay rate b/(2a) and
omega_d^2 = c/a - b^2/(4a^2) (sqrt(omega0^2 - gamma^2/4), gamma = b/a). The motion must be underdamped
on the whole declared domain (`domain.positive`, e.g. "4*k*m - b^2"), else the model is refused. The
decay time is the amplitude's e-folding time, 2a/b (2m/b for a mass on a spring).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.loads import Traits
from physics.engine.mechanics import time_derivative
from physics.engine.model import Model, Quantity, QuantityKind
from physics.engine.proof import domain_points
from physics.engine.quantity_table import derives
from physics.errors import DerivationError
from physics.wording import symbol_label

if TYPE_CHECKING:
    from physics.engine.method import Method

KINDS = frozenset({QuantityKind.DAMPED_FREQUENCY, QuantityKind.DECAY_TIME})
Point = dict[sympy.Symbol, sympy.Expr]
Matrices = tuple[sympy.Matrix, sympy.Matrix, sympy.Matrix]  # (M, C, K)
UNDERDAMPED_POINTS = 24

ROOT = sympy.Symbol("lambda")  # a root of the characteristic equation (notation.METHOD_SYMBOLS)


class NotThisWay(Exception):
    """The method cannot linearize this model (reported by `Method.answer` as not applicable)."""


def refusal(model: Model) -> str | None:
    """Why a damped frequency or decay time cannot be asked of this model at all (None: it can)."""
    if model.contact_loads:
        return "kinetic friction does not decay exponentially: damped oscillations need viscous damping"
    if model.loads_where(lambda traits: traits.dissipates and not traits.viscous):
        return "quadratic drag is not linear in the velocity: its oscillations do not decay exponentially"
    if model.time is not None:
        return "a force that depends on the time drives the oscillation: its free decay is not defined"
    return None


def linearization(method: Method, point: Point) -> tuple[sympy.Expr, sympy.Expr, sympy.Expr]:
    """(a, b, c) of the one oscillating factor a s^2 + b s + c of this method's characteristic equation."""
    why = refusal(method.model)
    if why is not None:
        raise DerivationError(why)
    build = METHODS.get(method.name)
    if build is None:
        *others, last = METHODS
        raise NotThisWay(f"damped motion is linearized only by the {', '.join(others)} and {last} methods")
    mass, damping, stiffness = build(method, point)
    s = sympy.Symbol("s")
    polynomial = sympy.expand((mass * s**2 + damping * s + stiffness).det())
    factors = [f for f, _ in sympy.factor_list(polynomial, s)[1] if f.has(s)]
    oscillating = [f for f in factors if sympy.degree(f, s) >= 2 and f.subs(s, 0) != 0]
    if len(oscillating) != 1 or sympy.degree(oscillating[0], s) != 2:
        raise NotThisWay(
            f"expected one damped oscillating mode, found the characteristic factors {typed_text(factors)}"
        )
    a, b, c = (oscillating[0].coeff(s, k) for k in (2, 1, 0))
    if tidy.simplify(b) == 0:
        raise DerivationError("no viscous damping acts on this motion (add `drag:` to a moving body)")
    method.step(
        "Linearized about the equilibrium",
        r"\mathbf{M}\ddot{\mathbf{q}} + \mathbf{C}\dot{\mathbf{q}} + \mathbf{K}\mathbf{q} = 0,\ \mathbf{M} = "
        + method.tex(mass)
        + r",\ C = "
        + method.tex(damping)
        + r",\ K = "
        + method.tex(stiffness),
    )
    return a, b, c


def answer(method: Method, quantity: Quantity, point: Point) -> sympy.Expr:
    """The damped angular frequency or the decay time, from this method's own linearization."""
    a, b, c = linearization(method, point)
    alpha, omega, squared_symbol = sympy.symbols("alpha omega W", real=True)
    characteristic = sympy.expand(a * (-alpha + sympy.I * omega) ** 2 + b * (-alpha + sympy.I * omega) + c)
    imaginary = characteristic.coeff(sympy.I)
    real = sympy.expand(characteristic - sympy.I * imaginary)
    # the imaginary part vanishes (omega != 0) only at one decay rate; the real part then gives omega^2
    rate = tidy.simplify(sympy.solve(sympy.cancel(imaginary / omega), alpha)[0])
    squared = tidy.simplify(
        sympy.solve(real.subs(alpha, rate).subs(omega**2, squared_symbol), squared_symbol)[0]
    )
    method.step(
        "Characteristic equation",
        method.tex(sympy.Eq(a * ROOT**2 + b * ROOT + c, 0))
        + r",\ \lambda = -\frac{1}{\tau} \pm i\omega_d \Rightarrow \frac{1}{\tau} = "
        + method.tex(rate)
        + r",\ \omega_d^2 = "
        + method.tex(squared),
    )
    _require_underdamped(method.model, squared, quantity.name)
    if quantity.kind is QuantityKind.DECAY_TIME:
        return tidy.simplify(1 / rate)
    return tidy.simplify(sympy.sqrt(sympy.together(squared)))


def _require_underdamped(model: Model, squared: sympy.Expr, name: str) -> None:
    for at in domain_points(model, UNDERDAMPED_POINTS, seed=17):
        value = complex(sympy.N(squared.subs(at)))
        if not value.real > 0:
            shown = ", ".join(f"{s}={v:.4g}" for s, v in at.items())
            raise DerivationError(
                f"{name}: the motion is not underdamped on the whole domain: omega_d^2 = {typed_text(squared)} is "
                f"{value.real:.4g} at {shown}; declare the underdamped condition under domain.positive "
                "(for a mass on a spring with drag b: 4*k*m - b^2)",
                quantity=name,
            )


def _at_rest(model: Model, point: Point) -> dict[sympy.Symbol, sympy.Expr]:
    rest: dict[sympy.Symbol, sympy.Expr] = dict(point)
    for c in model.coordinates:
        rest[c.velocity] = sympy.Integer(0)
        rest[c.acceleration] = sympy.Integer(0)
    return rest


def _linearize(equations: list[sympy.Expr], model: Model, point: Point, where: str) -> Matrices:
    """(M, C, K): the equations' derivatives in q'', q', q at rest at the equilibrium, where they must vanish."""
    rest = _at_rest(model, point)
    for equation in equations:
        if tidy.simplify(equation.subs(rest)) != 0:
            raise DerivationError(
                f"{where}: the forces do not balance at the equilibrium of the potentials; write forces that "
                "depend on the coordinates as potentials"
            )

    def matrix(symbols: list[sympy.Symbol]) -> sympy.Matrix:
        return sympy.Matrix(
            [[tidy.simplify(sympy.diff(e, v).subs(rest)) for v in symbols] for e in equations]
        )

    coords = model.coordinates
    return (
        matrix([c.acceleration for c in coords]),
        matrix([c.velocity for c in coords]),
        matrix([c.symbol for c in coords]),
    )


def by_lagrange(method: Method, point: Point) -> Matrices:
    """Lagrange's equations with the generalized forces of drag and of forces given in the velocities."""
    mech, model = method.mech, method.model
    lagrangian = mech.kinetic - mech.potential
    forces = mech.generalized(mech.load_forces(False, mech.multipliers))
    equations = [
        time_derivative(sympy.diff(lagrangian, c.velocity), model) - sympy.diff(lagrangian, c.symbol) - force
        for c, force in zip(model.coordinates, forces, strict=True)
    ]
    method.step(
        "Lagrange's equations with the dissipative generalized forces",
        r"\frac{\mathrm{d}}{\mathrm{d}t}\frac{\partial \mathcal{L}}{\partial \dot q_j} - \frac{\partial \mathcal{L}}"
        r"{\partial q_j} = Q_j,\ Q = " + method.tex(sympy.Matrix(forces).applyfunc(tidy.simplify)),
    )
    return _linearize(equations, model, point, method.title)


def by_newton(method: Method, point: Point) -> Matrices:
    """Newton's law on each Cartesian axis, drag from the Cartesian velocities, positions from the mapping."""
    mech, model = method.mech, method.model
    if model.constraints:
        raise NotThisWay("Cartesian damped oscillations are done here only without constraints")
    place = mech.cartesian_state()
    applied = mech.load_forces(True, mech.multipliers)
    equations = [
        d.inertia * time_derivative(time_derivative(d.mapping, model), model)
        - (-sympy.diff(mech.cartesian_potential, d.symbol) + force).subs(place)
        for d, force in zip(mech.dofs, applied, strict=True)
    ]
    method.step(
        "Newton's second law on each axis, with drag",
        r",\ ".join(
            method.tex(
                sympy.Eq(d.inertia * d.acceleration, -sympy.diff(mech.cartesian_potential, d.symbol) + f)
            )
            for d, f in zip(mech.dofs, applied, strict=True)
        ),
    )
    return _linearize(equations, model, point, method.title)


def by_energy(method: Method, point: Point) -> Matrices:
    """d(T + V)/dt = P: T and V to second order about the equilibrium, P the power of linear drag."""
    mech, model = method.mech, method.model
    if model.loads_where(lambda traits: not traits.conservative and not traits.viscous):
        raise NotThisWay("the energy balance is done here with linear drag only")
    velocities = list(mech.qd)
    drag = mech.load_forces(False, mech.multipliers, lambda traits: traits.dissipates)
    power = sympy.Add(*(f * time_derivative(d.mapping, model) for f, d in zip(drag, mech.dofs, strict=True)))
    rest = _at_rest(model, point)
    mass = sympy.hessian(mech.kinetic, velocities).subs(rest).applyfunc(tidy.simplify)
    stiffness = sympy.hessian(mech.potential, list(mech.q)).subs(rest).applyfunc(tidy.simplify)
    # P = -q'^T C q' for linear drag, so C is minus half its Hessian in the velocities
    damping = (-sympy.hessian(power, velocities) / 2).subs(rest).applyfunc(tidy.simplify)
    method.step(
        "Energy balance with the power of drag",
        rf"\frac{{\mathrm{{d}}}}{{\mathrm{{d}}t}}({method.mech.notation.letters.kinetic} + "
        rf"{method.mech.notation.letters.potential}) = P = "
        + method.tex(tidy.simplify(power))
        + r" = -\dot{\mathbf{q}}^{\mathsf{T}} \mathbf{C} \dot{\mathbf{q}}",
    )
    return mass, damping, stiffness


METHODS: dict[str, Callable[[Method, Point], Matrices]] = {
    "lagrange": by_lagrange,
    "newton": by_newton,
    "conservation": by_energy,
}


# --- what the derivation hands on: known mistakes, limits, the undamped check -------------------------

UNDAMPED = "That is the undamped angular frequency: damping lowers it to $\\sqrt{\\omega_0^2 - \\gamma^2/4}$."
RATE_NOT_HALVED = (
    "The amplitude decays at half the damping rate, $\\gamma/2 = b/(2m)$: the damped frequency is "
    "$\\sqrt{\\omega_0^2 - \\gamma^2/4}$, not $\\sqrt{\\omega_0^2 - \\gamma^2}$."
)
RAISED = "Damping slows the oscillation: the damped frequency is below the undamped one, not above it."
ENERGY_TIME = (
    "That is the e-folding time of the energy, which decays twice as fast as the amplitude: the "
    "amplitude's decay time is twice as long."
)
RATE_FOR_TIME = "That is the decay rate 1/tau; the decay time is its inverse."


def drag_coefficients(model: Model) -> list[sympy.Symbol]:
    """The symbols that are viscous loads' coefficients (b of `drag: b`)."""
    viscous = model.loads_where(lambda traits: traits.viscous)
    return [e for load in viscous for e in load.expressions() if isinstance(e, sympy.Symbol)]


def mistakes(model: Model, quantity: Quantity, reference: sympy.Expr) -> list[tuple[sympy.Expr, str]]:
    """The answers of the classic slips with damping, with feedback naming the slip."""
    drag = drag_coefficients(model)
    if not drag or quantity.kind not in KINDS:
        return []
    if quantity.kind is QuantityKind.DECAY_TIME:
        return [(reference / 2, ENERGY_TIME), (1 / reference, RATE_FOR_TIME)]
    undamped = tidy.simplify(reference.subs(dict.fromkeys(drag, 0)))
    return [
        (undamped, UNDAMPED),
        (tidy.simplify(reference.subs({b: 2 * b for b in drag})), RATE_NOT_HALVED),
        (sympy.sqrt(tidy.simplify(2 * undamped**2 - reference**2)), RAISED),
    ]


def limit_cases(model: Model) -> list[tuple[sympy.Symbol, sympy.Expr, str]]:
    return [
        (b, sympy.Integer(0), f"no damping ({symbol_label(str(b))} → 0)") for b in drag_coefficients(model)
    ]


def undamped_checks(
    model: Model, quantities: Mapping[str, sympy.Expr], undamped_frequency: Callable[[Model, str], sympy.Expr]
) -> dict[str, str]:
    """A damped frequency tends, as every drag coefficient goes to zero, to the angular frequency the
    model without drag derives (`undamped_frequency(model, coordinate)`); DerivationError otherwise."""
    drag = drag_coefficients(model)
    checks: dict[str, str] = {}
    for quantity in model.quantities:
        if quantity.kind is not QuantityKind.DAMPED_FREQUENCY or not drag:
            continue
        free = dataclasses.replace(
            model, force_entries=tuple(f for f in model.force_entries if not set(f.expressions()) & set(drag))
        )
        expected = undamped_frequency(free, quantity.target)
        found = tidy.simplify(quantities[quantity.name].subs(dict.fromkeys(drag, 0)))
        if tidy.simplify(found - expected) != 0:
            raise DerivationError(
                f"{quantity.name} = {typed_text(quantities[quantity.name])} tends to {typed_text(found)} without drag, but the model "
                f"without drag oscillates at {typed_text(expected)}",
                path=("forces",),
            )
        checks[f"limit {quantity.name} (no damping)"] = (
            f"tends to the undamped model's angular frequency {typed_text(expected)}"
        )
    return checks


@derives(*KINDS)
def derived(method: Method, quantity: Quantity) -> sympy.Expr:
    """About the stable equilibrium all the methods share; a method that cannot see the drag says so."""
    from physics.engine.method import NotApplicable, stable_equilibrium

    try:
        return answer(method, quantity, stable_equilibrium(method.model))
    except NotThisWay as why:
        raise NotApplicable(str(why)) from None


def without_drag(model: Model, name: str) -> Model:
    """The model with its drag left out (the undamped oscillator a damped one is compared with)."""
    if not model.loads_where(_drag):
        raise DerivationError(
            f"{name}: the model has no drag to leave out: ask for its angular_frequency", quantity=name
        )
    kept = tuple(f for f in model.force_entries if not _drag(f.traits(model)))
    return dataclasses.replace(model, force_entries=kept)


def _drag(traits: Traits) -> bool:
    """A load that dissipates of itself, not through a contact's force (kinetic friction)."""
    return traits.dissipates and not traits.constraints


@derives(QuantityKind.UNDAMPED_FREQUENCY)
def undamped_frequency(method: Method, quantity: Quantity) -> sympy.Expr:
    """sqrt(k/m): this method's angular frequency of small oscillations of the model without its drag."""
    from physics.engine.mechanics import Mechanics

    why = refusal(method.model)
    if why is not None:
        raise DerivationError(f"{quantity.name}: {why}", quantity=quantity.name)
    free = without_drag(method.model, quantity.name)
    solver = type(method)(free, Mechanics(free))
    omega = solver.frequency(quantity.target, solver.equilibrium(quantity.target))
    method.adopt_after(solver.steps, "(the damping left out)")
    method.step(
        f"Undamped angular frequency of {method.named(quantity.target)}: the damping left out",
        r"\omega_0 = " + method.tex(omega),
    )
    return omega
