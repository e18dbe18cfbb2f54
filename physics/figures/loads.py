"""The forces on a body that come from neither gravity nor a constraint, for free-body diagrams: a
spring's pull or push along its line, another potential's force (gravitation, an interatomic force),
a given force, and drag against the body's velocity.

A spring's direction depends on where the body is, so it is taken where the body rests: the minimum of
the potential energy when that is quadratic in the coordinates (springs on straight lines, gravity),
else the model's state. A spring relaxed there is drawn pulling towards its other end, the convention
that makes its force k (d - L0) positive when stretched. The rotating frame's centrifugal potential is
left out: the diagram is drawn in the ground's frame.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy
import sympy

from physics.engine import depth
from physics.engine.mechanics import Mechanics
from physics.engine.model import AppliedForce, ForceKind, Model, PairPotential
from physics.figures.figure import Values
from physics.figures.geometry import spring_sign, stiffness_symbols
from physics.wording import symbol_label

Direction = tuple[float, float]
_SUBSCRIPTS = dict(zip("0123456789aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ", strict=True))
_EVALUATION_ERRORS = (TypeError, ValueError, ZeroDivisionError, OverflowError)
_AXES = ("x", "y", depth.DEPTH)


def _unit(x: float, y: float) -> Direction | None:
    norm = math.hypot(x, y)
    return None if not math.isfinite(norm) or norm < 1e-12 else (x / norm, y / norm)


def _in_the_page(force: Sequence[float], what: str) -> Direction | None:
    """The direction of a force (x, y, z) in the page; one with a part along z has none there: a
    ValueError, never its x–y part drawn (a wrong arrow)."""
    x, y, z = force
    if abs(z) > 1e-9 * math.hypot(x, y, z):
        raise ValueError(f"{what} has a part along z, out of the page")
    return _unit(x, y)


def spring_label(potential: PairPotential, model: Model) -> str:
    """F with the spring's constant as subscript (k₁ -> Fₖ₁), so the arrow names the spring the scene
    labels; a constant with no subscript form is written out, F(K)."""
    stiffness = stiffness_symbols(potential, model)
    if not stiffness:
        return "F"
    name = symbol_label(stiffness[0].name)
    if all(c in _SUBSCRIPTS or c in "₀₁₂₃₄₅₆₇₈₉" for c in name):
        return "F" + "".join(_SUBSCRIPTS.get(c, c) for c in name)
    return f"F({name})"


def resting_configuration(model: Model, values: Values) -> dict[sympy.Symbol, float]:
    """The coordinates where the potential energy is least, if it is a quadratic with one minimum in
    the coordinates it depends on; else the model's state. A coordinate left free stays at its value
    as a symbol of the table (a radius r), else at 0."""
    place = values.at_state(model, {c.symbol: values.subs.get(c.symbol, 0.0) for c in model.coordinates})
    parameters = {s: v for s, v in values.subs.items() if s not in place}  # a coordinate may be a symbol too
    try:
        energy = sympy.expand(Mechanics(model).potential.subs(parameters))
    except _EVALUATION_ERRORS:
        return place
    moving = sorted(energy.free_symbols & set(place), key=lambda s: s.name)
    if not moving or energy.free_symbols - set(moving) or not energy.is_polynomial(*moving):
        return place
    if sympy.Poly(energy, *moving).total_degree() != 2:
        return place
    gradient = [sympy.diff(energy, q) for q in moving]
    hessian = numpy.array([[float(sympy.diff(g, q)) for q in moving] for g in gradient])
    if numpy.any(numpy.linalg.eigvalsh(hessian) <= 0):
        return place  # no single resting place (a body free to drift, an unstable set-up)
    at_zero = numpy.array([float(g.subs(dict.fromkeys(moving, 0))) for g in gradient])
    for symbol, value in zip(moving, numpy.linalg.solve(hessian, -at_zero), strict=True):
        place[symbol] = float(value)
    return place


def _potential_direction(
    model: Model, potential: PairPotential, body_name: str, values: Values, place: dict[sympy.Symbol, float]
) -> Direction | None:
    """The potential's force on the body at `place`; pulling towards the other end where it vanishes.
    A force with a part along z has no direction in the page (_in_the_page)."""
    mechanics = Mechanics(model)
    own = {d.name: d.symbol for d in mechanics.dofs}
    distance = mechanics.distance(potential, own)
    energy = potential.energy.subs(potential.distance, distance)
    where = {d.symbol: values.number(d.mapping, place) for d in mechanics.dofs}
    symbols = [own.get(f"{axis}_{body_name}") for axis in _AXES]

    def along(expr: sympy.Expr) -> list[float]:
        return [values.number(-sympy.diff(expr, s), where) if s is not None else 0.0 for s in symbols]

    what = f"a potential's force on {body_name}"
    try:
        force = along(energy)
    except _EVALUATION_ERRORS:
        force = [math.nan] * 3
    if math.hypot(*force) > 1e-9 * _scale(energy, where, values):  # not a rounding error's: its way counts
        return _in_the_page(force, what)
    try:
        towards = along(distance)  # where the distance shrinks: towards the other end
    except _EVALUATION_ERRORS:
        return None
    return _in_the_page(towards, what)


def _scale(energy: sympy.Expr, where: dict[sympy.Symbol, float], values: Values) -> float:
    """A size for the energy's forces, so that a force rounding error leaves at zero counts as zero."""
    try:
        return max(1.0, abs(values.number(energy, where)))
    except _EVALUATION_ERRORS:
        return 1.0


def potential_forces(model: Model, body_name: str, values: Values) -> list[tuple[str, Direction]]:
    """Each spring's force on the body (Fₖ₁...) and any other potential's (F), with directions."""
    acting = [
        p for p in model.potentials if body_name in p.bodies and spring_sign(p, values) >= 0
    ]  # a falling quadratic is the centrifugal potential of a rotating frame
    if not acting:
        return []
    place = resting_configuration(model, values)
    found: list[tuple[str, Direction]] = []
    for potential in acting:
        direction = _potential_direction(model, potential, body_name, values, place)
        if direction is None:
            continue
        label = spring_label(potential, model) if spring_sign(potential, values) > 0 else "F"
        found.append((label, direction))
    return found


def _given_label(force: AppliedForce, values: Values) -> str:
    symbols = {s for _, e in force.components for s in e.free_symbols} - values.angles
    named = sorted((s for s in symbols if s in values.subs), key=lambda s: s.name)
    return symbol_label(named[0].name) if len(named) == 1 else "F"


def _moving_state(model: Model, values: Values) -> dict[sympy.Symbol, float]:
    """The coordinates and velocities of the model's state (0 where it gives none), and the time 0."""
    moving = {c.symbol: 0.0 for c in model.coordinates} | {c.velocity: 0.0 for c in model.coordinates}
    for symbol, value in model.state:
        try:
            moving[symbol] = values.number(value)
        except _EVALUATION_ERRORS:
            continue
    if model.time is not None:
        moving[model.time] = 0.0
    return moving


def given_forces(model: Model, body_name: str, values: Values) -> list[tuple[str, Direction]]:
    """The given forces on the body (a push F), with their directions at the model's state; the scene
    draws them too, so both figures name them alike."""
    moving = _moving_state(model, values)
    found: list[tuple[str, Direction]] = []
    for force in model.forces:
        if force.body != body_name or force.kind is not ForceKind.APPLIED:
            continue
        given = dict(force.components)
        try:
            pushing = [values.number(given.get(axis, sympy.Integer(0)), moving) for axis in _AXES]
        except _EVALUATION_ERRORS:
            continue
        direction = _in_the_page(pushing, f"a given force on {body_name}")
        if direction is not None:
            found.append((_given_label(force, values), direction))
    return found


def applied_forces(model: Model, body_name: str, values: Values) -> list[tuple[str, Direction]]:
    """Given forces on the body, at the model's state, and drag against its velocity there (against
    motion towards increasing coordinates when it starts at rest, like kinetic friction)."""
    found = given_forces(model, body_name, values)
    body = model.body(body_name)
    moving = _moving_state(model, values)
    position = dict(body.position)

    def velocity(speeds: dict[sympy.Symbol, float]) -> list[float]:
        return [
            sum(
                values.number(sympy.diff(position.get(axis, sympy.Integer(0)), c.symbol), moving)
                * speeds[c.velocity]
                for c in model.coordinates
            )
            for axis in _AXES
        ]

    for force in model.forces:
        if force.body != body_name or force.kind is ForceKind.APPLIED:
            continue
        try:
            moving_at = velocity(moving)
            if not math.hypot(*moving_at) >= 1e-12:  # at rest: as if moving towards increasing coordinates
                moving_at = velocity({c.velocity: 1.0 for c in model.coordinates})
        except _EVALUATION_ERRORS:
            continue
        direction = _in_the_page([-v for v in moving_at], f"the drag on {body_name}")
        if direction is not None:
            found.append((_drag_label(force), direction))
    return found


def _drag_label(force: AppliedForce) -> str:
    coefficient = symbol_label(force.coefficient.name) if isinstance(force.coefficient, sympy.Symbol) else ""
    return coefficient + ("v²" if force.kind is ForceKind.QUADRATIC_DRAG else "v")
