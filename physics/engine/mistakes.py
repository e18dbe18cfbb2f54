"""Known mistakes and physical limits, generated from the model (never typed in by hand).

Each mistake is the answer a specific slip produces, re-derived where the slip changes the physics
(a moment of inertia forgotten, a support treated as fixed, energy conserved through an inelastic
collision), with feedback that names the slip, not the answer.
"""

from __future__ import annotations

import dataclasses
import enum
from collections.abc import Callable

import sympy

from physics.engine import bounces, collision, damping, impact, orbits, reach_mistakes, slipping, tidy
from physics.engine.mechanics import Mechanics
from physics.engine.model import (
    IMPACT_KINDS,
    MAGNITUDE_KINDS,
    ORBIT_KINDS,
    SLIP_KINDS,
    ConstraintKind,
    Model,
    Quantity,
    QuantityKind,
)
from physics.engine.proof import domain_points, proven_sign
from physics.engine.results import KnownMistake, LimitCase
from physics.engine.shape_inertia import confused_inertias
from physics.wording import symbol_label

Rederive = Callable[[Model, Quantity], sympy.Expr | None]

SWAPPED_TRIG = (
    "Check which component of each force lies along the surface and which is perpendicular to "
    "it: a sine and a cosine are swapped."
)
SWAPPED_ANGLE = (
    "Check where each angle is measured from: the side next to an angle goes with its cosine, the "
    "side opposite it with its sine. Here a sine and a cosine are swapped."
)
SWAPPED_DRIVE = (
    "Check the driving force's time dependence as the problem states it: a sine and a cosine of "
    "its phase are swapped."
)
DROPPED_PROJECTION = (
    "A projection factor is missing: check each place where a force, a velocity or an acceleration "
    "is resolved into components."
)
DROPPED_DRIVE = "The driving force changes with time: use its value at the given moment, not its amplitude."
FRICTION_SIGN = "Kinetic friction opposes the sliding: check the direction of the friction force."
FIXED_SUPPORT = (
    "This treats the {body} as fixed. It moves too, which changes the accelerations and the contact force."
)
FIXED_CONTACT = (
    "This uses the contact force that would act if the {body} were held fixed. The {body} "
    "recoils, which changes that force."
)
NO_INERTIA = (
    "A rolling or spinning body also has rotational kinetic energy, $\\tfrac12 I\\omega^2$, and needs a "
    "torque to spin up: include its moment of inertia."
)
INELASTIC_ENERGY = (
    "Kinetic energy is not conserved in a perfectly inelastic collision. Use the quantity that "
    "is conserved during the impact, then energy conservation afterwards."
)
STRUCK_AT_CENTRE = (
    "The projectile sticks where it strikes, not at the body's centre of mass: its angular momentum "
    "about the pivot is its momentum times that point's distance from the pivot, and the body turns "
    "with its mass there."
)
FRACTION_KEPT = (
    "That is the fraction of the kinetic energy that remains after the collision, not the fraction lost."
)
ONE_MASS = (
    "Both {bodies} move: the relative motion is governed by the reduced mass of the pair, not by the "
    "mass of one of them."
)
TOTAL_MASS = "The relative motion is governed by the reduced mass of the pair, not by the total mass."


def supports(model: Model) -> list[str]:
    """Bodies another body rests on: in a two-body surface contact, the one placed by fewer coordinates."""
    mech = Mechanics(model)
    found: list[str] = []
    coords = {
        b.name: set().union(*(e.free_symbols for _, e in b.position)) & set(mech.q) for b in model.bodies
    }
    for constraint in model.constraints:
        if constraint.kind is not ConstraintKind.SURFACE:
            continue
        names = sorted({d.body for d in mech.dofs if constraint.gap.has(d.symbol)})
        if len(names) == 2:
            a, b = names
            if coords[a] < coords[b]:
                found.append(a)
            elif coords[b] < coords[a]:
                found.append(b)
    return found


def generate_mistakes(
    model: Model, quantity: Quantity, reference: sympy.Expr, rederive: Rederive
) -> tuple[KnownMistake, ...]:
    candidates = reach_mistakes.candidates(model, quantity, reference, rederive)  # theirs first: named slips
    candidates += _trig_mistakes(model, reference)
    for friction in model.frictions:
        if reference.has(*friction.coefficient.free_symbols):
            candidates.append((reference.subs(friction.coefficient, -friction.coefficient), FRICTION_SIGN))
    for body in supports(model):
        mass = model.body(body).mass
        if isinstance(mass, sympy.Symbol):
            candidates.append((_limit(reference, mass, sympy.oo), FIXED_SUPPORT.format(body=body)))
            if quantity.kind is QuantityKind.ACCELERATION:
                candidates.append(
                    (
                        _support_with_fixed_contact(model, quantity, body, rederive),
                        FIXED_CONTACT.format(body=body),
                    )
                )
    if any(b.inertia != 0 for b in model.bodies):
        flat = dataclasses.replace(
            model, bodies=tuple(dataclasses.replace(b, inertia=sympy.Integer(0)) for b in model.bodies)
        )
        candidates.append((rederive(flat, quantity), NO_INERTIA))
        candidates += [(rederive(other, quantity), said) for other, said in confused_inertias(model)]
    if model.collision is not None and quantity.kind is QuantityKind.PROJECTILE_SPEED:
        candidates.append((_energy_conserved_speed(model), INELASTIC_ENERGY))
    if model.collision is not None and model.collision.point:
        at_centre = dataclasses.replace(model.collision, point=())
        candidates.append(
            (rederive(dataclasses.replace(model, collision=at_centre), quantity), STRUCK_AT_CENTRE)
        )
    if quantity.kind is QuantityKind.ENERGY_FRACTION_LOST:
        candidates.append((1 - reference, FRACTION_KEPT))
    if (
        quantity.kind in IMPACT_KINDS or quantity.kind is QuantityKind.VELOCITY_AFTER
    ) and model.impact is not None:
        candidates += impact.mistakes(model, reference)
        candidates += bounces.mistakes(model, quantity, rederive)
    if quantity.kind in SLIP_KINDS:
        candidates.append((slipping.without_torque(model, quantity, rederive), slipping.NO_TORQUE))
    if quantity.kind in ORBIT_KINDS:
        candidates += orbits.mistakes(model, quantity, reference)
    if quantity.kind in (QuantityKind.ANGULAR_FREQUENCY, QuantityKind.PERIOD):
        candidates += _mass_mistakes(model, quantity, reference, rederive)
    candidates += damping.mistakes(model, quantity, reference)
    return _distinct(model, quantity, reference, candidates)


class _Angle(enum.Enum):
    """What a sine or cosine in an answer comes from, which decides what its slips are called."""

    SURFACE = "surface"  # a slope's angle: components along and across the surface
    GEOMETRY = "geometry"  # any other angle: a swing, a launch, a line of centres
    DRIVE = "drive"  # the phase of a force that depends on the time


_SWAPPED = {_Angle.SURFACE: SWAPPED_TRIG, _Angle.GEOMETRY: SWAPPED_ANGLE, _Angle.DRIVE: SWAPPED_DRIVE}


def _trig_mistakes(model: Model, reference: sympy.Expr) -> list[tuple[sympy.Expr | None, str]]:
    """Sines and cosines swapped, and projection factors dropped, each named for what the angle is: a
    drive's phase is no component along a surface, and dropping it takes the drive's amplitude."""
    origin = {atom: _angle_origin(model, atom.args[0]) for atom in reference.atoms(sympy.sin, sympy.cos)}
    candidates: list[tuple[sympy.Expr | None, str]] = []
    for kind in _Angle:
        swap = {
            atom: (sympy.cos if isinstance(atom, sympy.sin) else sympy.sin)(atom.args[0])
            for atom, found in origin.items()
            if found is kind
        }
        if swap:
            candidates.append((reference.subs(swap, simultaneous=True), _SWAPPED[kind]))
    drive = {atom: sympy.Integer(1) for atom, found in origin.items() if found is _Angle.DRIVE}
    if drive:
        candidates.append((reference.subs(drive, simultaneous=True), DROPPED_DRIVE))
    if not origin:  # a bare tan (mu = tan(alpha)) has no component to drop
        return candidates
    numerator, _ = sympy.fraction(sympy.factor(reference))
    for factor in sympy.Mul.make_args(numerator):
        projection = isinstance(factor, sympy.sin | sympy.cos | sympy.tan)
        if projection and _angle_origin(model, factor.args[0]) is not _Angle.DRIVE:
            candidates.append((reference / factor, DROPPED_PROJECTION))
    return candidates


def _angle_origin(model: Model, angle: sympy.Expr) -> _Angle:
    if angle.free_symbols & _drive_symbols(model):
        return _Angle.DRIVE
    if angle.free_symbols & _surface_symbols(model):
        return _Angle.SURFACE
    return _Angle.GEOMETRY


def _drive_symbols(model: Model) -> set[sympy.Symbol]:
    """The time and what a drive's phase is made of (w in cos(w t)), with the state's time put in."""
    if model.time is None:
        return set()
    at = dict(model.state).get(model.time, model.time)
    found: set[sympy.Symbol] = {model.time}
    for force in model.force_entries:
        for component in force.expressions():
            for atom in component.atoms(sympy.sin, sympy.cos, sympy.tan):
                if atom.has(model.time):
                    found |= atom.args[0].subs(model.time, at).free_symbols | atom.args[0].free_symbols
    return found


def _surface_symbols(model: Model) -> set[sympy.Symbol]:
    """The parameters that tilt a surface: those in a surface constraint's gap."""
    found: set[sympy.Symbol] = set()
    for constraint in model.constraints:
        if constraint.kind is ConstraintKind.SURFACE:
            found |= constraint.gap.free_symbols & set(model.parameters)
    return found


def _support_with_fixed_contact(
    model: Model, quantity: Quantity, body: str, rederive: Rederive
) -> sympy.Expr | None:
    """The support's acceleration from its own equation, with the contact force it would feel if it
    were held fixed (e.g. N = m g cos(theta) pushing a free wedge)."""
    mech = Mechanics(model)
    q = model.coordinate(quantity.target).symbol
    mass = model.body(body).mass
    own = [d for d in mech.dofs if d.body == body and d.mapping == q]
    if len(own) != 1:
        return None
    dof = own[0]
    total = (-sympy.diff(mech.cartesian_potential, dof.symbol)).subs(mech.cartesian_state())
    for constraint in model.constraints:
        slope = sympy.diff(constraint.gap, dof.symbol)
        if slope == 0:
            continue
        contact = rederive(model, Quantity(quantity.name, QuantityKind.FORCE, constraint.name))
        if contact is None:
            return None
        fixed = _limit(contact, mass, sympy.oo) if contact.has(mass) else contact
        if fixed is None:
            return None
        total += fixed * slope.subs(mech.cartesian_state())
    return total / dof.inertia


def _mass_mistakes(
    model: Model, quantity: Quantity, reference: sympy.Expr, rederive: Rederive
) -> list[tuple[sympy.Expr | None, str]]:
    stiffness = rederive(model, Quantity(quantity.name, QuantityKind.STIFFNESS, quantity.target))
    if stiffness is None:
        return []
    result: list[tuple[sympy.Expr | None, str]] = []
    for pair in model.potentials:
        if len(pair.bodies) != 2:
            continue
        masses = [model.body(b).mass for b in pair.bodies]
        options = [
            (masses[0], ONE_MASS.format(bodies=" and ".join(pair.bodies))),
            (masses[0] + masses[1], TOTAL_MASS),
        ]
        for mass, feedback in options:
            omega = sympy.sqrt(stiffness / mass)
            result.append(
                (omega if quantity.kind is QuantityKind.ANGULAR_FREQUENCY else 2 * sympy.pi / omega, feedback)
            )
    return result


def _energy_conserved_speed(model: Model) -> sympy.Expr | None:
    hit = model.collision
    assert hit is not None
    after = collision.merged(model)
    mech = Mechanics(after)
    at, reaches = collision.event_points(model)
    rise = mech.potential.subs(reaches) - mech.potential.subs(at)
    return tidy.simplify(sympy.sqrt(2 * rise / hit.projectile_mass))


def _limit(expr: sympy.Expr, symbol: sympy.Symbol, value: sympy.Expr) -> sympy.Expr | None:
    try:
        result = sympy.limit(expr, symbol, value)
    except (NotImplementedError, ValueError):
        return None
    if result.has(sympy.oo, -sympy.oo, sympy.zoo, sympy.nan, sympy.AccumBounds):
        return None
    return tidy.simplify(result)


def _distinct(
    model: Model, quantity: Quantity, reference: sympy.Expr, candidates: list[tuple[sympy.Expr | None, str]]
) -> tuple[KnownMistake, ...]:
    """Drop candidates that vanish, equal the answer or repeat another, compared at a few domain points,
    and, for a time, length, speed or frequency the answer proves positive, those proven negative or not
    real: -2 v0/(7 g mu) for a skid's time (friction's sign flipped) is no answer a student would give."""
    points = domain_points(model, 4, seed=11)
    magnitude = quantity.kind in MAGNITUDE_KINDS and proven_sign(reference, model) == 1

    def values(expr: sympy.Expr) -> list[complex] | None:
        try:
            return [complex(sympy.N(expr.subs(p), 15)) for p in points]
        except (TypeError, ValueError):
            return None

    def same(a: list[complex], b: list[complex]) -> bool:
        return all(abs(x - y) <= 1e-9 * max(1.0, abs(x), abs(y)) for x, y in zip(a, b, strict=True))

    answer = values(reference)
    kept: list[tuple[KnownMistake, list[complex]]] = []
    for expr, feedback in candidates:
        if expr is None or (magnitude and proven_sign(expr, model) in (-1, 0)):
            continue
        seen = values(expr)
        if seen is None or answer is None or all(abs(v) < 1e-12 for v in seen) or same(seen, answer):
            continue
        if any(abs(v.imag) > 1e-12 * max(1.0, abs(v)) for v in seen) and not any(a.imag for a in answer):
            continue  # not real where the answer is: (-e)^n for a count of bounces n, no answer to type
        if any(same(seen, other) for _, other in kept):
            continue
        kept.append((KnownMistake(expr, feedback), seen))
    return tuple(k for k, _ in kept)


def generate_limits(model: Model, reference: sympy.Expr) -> tuple[LimitCase, ...]:
    """Physical limits in which the answer stays finite: supports held fixed, angles and friction to zero,
    a light body, an inertia parameter to zero."""
    cases: list[tuple[sympy.Symbol, sympy.Expr, str]] = []
    for body in supports(model):
        mass = model.body(body).mass
        if isinstance(mass, sympy.Symbol):
            cases.append((mass, sympy.oo, f"the {body} held fixed ({symbol_label(str(mass))} → ∞)"))
    for symbol, low, _ in model.ranges:
        if low == 0:
            cases.append((symbol, sympy.Integer(0), f"{symbol_label(symbol.name)} → 0"))
    for friction in model.frictions:
        if isinstance(friction.coefficient, sympy.Symbol):
            cases.append(
                (
                    friction.coefficient,
                    sympy.Integer(0),
                    f"no friction ({symbol_label(friction.coefficient.name)} → 0)",
                )
            )
    cases += damping.limit_cases(model)
    masses = list(dict.fromkeys(b.mass for b in model.bodies if isinstance(b.mass, sympy.Symbol)))
    for mass in masses if len(masses) >= 2 else []:
        others = [symbol_label(str(other)) for other in masses if other != mass]
        than = others[0] if len(others) == 1 else "the other masses"
        cases.append((mass, sympy.Integer(0), f"{symbol_label(str(mass))} much lighter than {than}"))
    placed = set().union(
        *(e.free_symbols for b in model.bodies for _, e in b.position),
        *(b.mass.free_symbols for b in model.bodies),
    )
    for rigid in model.bodies:
        for symbol in rigid.inertia.free_symbols - placed:
            cases.append(
                (symbol, sympy.Integer(0), f"{symbol_label(symbol.name)} → 0: no rotational inertia")
            )
    result: list[LimitCase] = []
    said: set[tuple[sympy.Symbol, sympy.Expr]] = set()
    for symbol, value, description in cases:
        if not reference.has(symbol) or (symbol, value) in said:  # two frictions may share one mu
            continue
        said.add((symbol, value))
        if _limit(reference, symbol, value) is not None:
            result.append(LimitCase({symbol: value}, description))
    return tuple(result)
