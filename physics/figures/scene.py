"""A problem's figure drawn from its engine model: each element of the model draws itself.

Bodies on a fixed surface constraint sit on an incline (or floor) whose slope comes from the
constraint's gap; a surface between two bodies makes a wedge; a string joining two bodies runs over a
pulley; a string whose gap turns a body makes a yo-yo; a string of fixed length makes a pendulum; a
potential with an anchor is a spring from a wall (with a dashpot beside it when the body feels linear
drag), between two bodies an interaction across a distance. A given force on a body on a slope is an
arrow pushing on it. In their own modules: a body launched under gravity alone (projectile.py), a rod at
rest against a floor and a wall (ladder.py), a body on a curved track from its start to where a quantity
asks about it (track.py), springs in a line (springs.py), bodies falling with drag (falling.py),
pendulums hung one from another (chain.py).
Angles are labelled with the problem's symbol that sets them, bodies with their mass symbols. Values
are the student's (angles set the drawing's slopes) or typical ones; sizes are the figure's own.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy

from physics.engine.impact import velocities_before
from physics.engine.model import Body, Constraint, ConstraintKind, ForceKind, Model, PairPotential
from physics.figures.svg import FILLS, Canvas, Point

GREEK = [
    "alpha",
    "beta",
    "gamma",
    "delta",
    "epsilon",
    "zeta",
    "eta",
    "theta",
    "iota",
    "kappa",
    "lambda",
    "mu",
    "nu",
    "xi",
    "omicron",
    "pi",
    "rho",
    "sigma",
    "tau",
    "upsilon",
    "phi",
    "chi",
    "psi",
    "omega",
]
_SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
BLOCK = 1.0  # side of a block, in figure units
SLOPE = 7.0  # length of an incline's surface
# Angles are drawn at their values within this range; outside it the figure says it is not to scale.
READABLE_ANGLES = (math.radians(5), math.radians(75))


def symbol_label(name: str) -> str:
    """`theta` -> θ, `m1` -> m₁, `Omega` -> Ω, `v_0` -> v₀: how the statement typesets the name."""
    base, _, sub = name.partition("_")
    digits = ""
    while base and base[-1].isdigit() and len(base) > 1:
        digits, base = base[-1] + digits, base[:-1]
    if base.lower() in GREEK:
        letter = chr(0x3B1 + GREEK.index(base.lower()) + (base.lower() in GREEK[17:]))
        base = letter.upper() if base[0].isupper() else letter
    return base + (digits + sub).translate(_SUBSCRIPT)


@dataclass
class Figure:
    canvas: Canvas = field(default_factory=Canvas)
    said: list[str] = field(default_factory=list)
    # Coordinates a drawing placed its bodies at where it does not draw the model's state (a pendulum
    # swung aside to show that it swings): the free-body diagrams are drawn there too.
    placed: dict[sympy.Symbol, float] = field(default_factory=dict)
    # what is not drawn at its value ("α = 2.0° drawn as 8°"): the figure then says it is not to scale
    unscaled: list[str] = field(default_factory=list)

    def say(self, sentence: str) -> None:
        self.said.append(sentence)

    def readable_angle(self, angle: float, symbol: sympy.Symbol | None, low: float | None = None) -> float:
        """`angle` (radians, either sign) as drawn: itself within READABLE_ANGLES (or from `low`),
        else the nearest readable angle, noted as not to scale."""
        floor, ceiling = READABLE_ANGLES if low is None else (low, READABLE_ANGLES[1])
        size = abs(angle)
        if size < 1e-9 or floor <= size <= ceiling:
            return angle
        drawn = min(max(size, floor), ceiling)
        name = symbol_label(symbol.name) if symbol is not None else "the angle"
        self.unscaled.append(f"{name} = {math.degrees(size):.3g}° is drawn as {math.degrees(drawn):.0f}°")
        return math.copysign(drawn, angle)


class Values:
    """Numbers for the model's parameters: the student's, else typical (an angle a third of its range,
    others 1, or 2 or 1/2 where 1 leaves the domain: a ball of radius r = 1 in a bowl of radius R = 1
    has no bowl to roll in)."""

    def __init__(self, model: Model, given: Mapping[str, float]) -> None:
        self.subs: dict[sympy.Symbol, float] = {}
        ranges = {symbol: (low, high) for symbol, low, high in model.ranges}
        typical = set()
        for symbol in model.parameters:
            if symbol.name in given:
                self.subs[symbol] = float(given[symbol.name])
            elif symbol in ranges:
                low, high = (float(bound) for bound in ranges[symbol])
                self.subs[symbol] = low + (high - low) / 3
            else:
                self.subs[symbol] = 1.0
                typical.add(symbol)
        self.angles = set(ranges)
        for expr in model.positive:
            self._into_domain(expr, model.positive, typical)

    def _into_domain(
        self, expr: sympy.Expr, positive: tuple[sympy.Expr, ...], typical: set[sympy.Symbol]
    ) -> None:
        """Change one typical value, if need be, so that `expr` is positive and no other expression of
        the domain stops being so."""
        if self._positive(expr):
            return
        for symbol in sorted(expr.free_symbols & typical, key=lambda s: s.name):
            for value in (2.0, 0.5):
                before = self.subs[symbol]
                kept = [e for e in positive if self._positive(e)]
                self.subs[symbol] = value
                if self._positive(expr) and all(self._positive(e) for e in kept):
                    return
                self.subs[symbol] = before

    def _positive(self, expr: sympy.Expr) -> bool:
        try:
            return self.number(expr) > 0
        except (TypeError, ValueError, ZeroDivisionError):
            return False

    def number(self, expr: sympy.Expr, extra: Mapping[sympy.Symbol, float] | None = None) -> float:
        return float(expr.subs({**self.subs, **(extra or {})}))

    def at_state(self, model: Model, place: dict[sympy.Symbol, float]) -> dict[sympy.Symbol, float]:
        """`place` with each coordinate the model's state gives a number moved there (a state that
        cannot be evaluated with these values is left out)."""
        for symbol, value in model.state:
            if symbol in place:
                try:
                    place[symbol] = self.number(value)
                except (TypeError, ValueError, ZeroDivisionError, OverflowError):
                    continue
        return place


def body_label(body: Body, model: Model) -> str:
    masses = [b.mass for b in model.bodies]
    if isinstance(body.mass, sympy.Symbol) and masses.count(body.mass) == 1:
        return symbol_label(body.mass.name)
    return body.name


def _own_symbols(body: Body, model: Model) -> set[sympy.Symbol]:
    return {model.cartesian_symbol(name) for name in body.cartesian_names()}


def _bodies_in(gap: sympy.Expr, model: Model) -> list[Body]:
    free = gap.free_symbols
    return [body for body in model.bodies if _own_symbols(body, model) & free]


def _angle_symbol(expr: sympy.Expr, values: Values) -> sympy.Symbol | None:
    found = sorted(expr.free_symbols & values.angles, key=lambda s: s.name)
    return found[0] if found else None


@dataclass(frozen=True)
class Surface:
    """gap = a x + b y + c in one body's own coordinates: the normal (a, b) points to the free side."""

    constraint: Constraint
    body: Body
    normal: Point
    angle_symbol: sympy.Symbol | None


def _linear_surface(constraint: Constraint, body: Body, model: Model, values: Values) -> Surface | None:
    x = model.cartesian_symbol(f"x_{body.name}") if f"x_{body.name}" in dict(model.cartesian) else None
    y = model.cartesian_symbol(f"y_{body.name}") if f"y_{body.name}" in dict(model.cartesian) else None
    a = values.number(sympy.diff(constraint.gap, x)) if x is not None else 0.0
    b = values.number(sympy.diff(constraint.gap, y)) if y is not None else 0.0
    norm = math.hypot(a, b)
    if norm == 0:
        return None
    return Surface(constraint, body, (a / norm, b / norm), _angle_symbol(constraint.gap, values))


def _is_linear(gap: sympy.Expr, model: Model) -> bool:
    """Is the gap linear in the bodies' Cartesian symbols (a straight surface or string)?"""
    cartesian = [symbol for _, symbol in model.cartesian if symbol in gap.free_symbols]
    return all(
        not (sympy.diff(gap, first, second).free_symbols & set(cartesian))
        and sympy.diff(gap, first, second) == 0
        for first in cartesian
        for second in cartesian
    )


def _block(figure: Figure, base: Point, tangent: Point, label: str, fill: str, size: float = BLOCK) -> Point:
    """A block resting with its bottom centre at `base` on a surface along `tangent`; returns its centre."""
    tx, ty = tangent
    nx, ny = -ty, tx
    if ny < 0:
        nx, ny = -nx, -ny
    half = size / 2
    corners = [
        (base[0] - tx * half, base[1] - ty * half),
        (base[0] + tx * half, base[1] + ty * half),
        (base[0] + tx * half + nx * size, base[1] + ty * half + ny * size),
        (base[0] - tx * half + nx * size, base[1] - ty * half + ny * size),
    ]
    figure.canvas.polygon(corners, fill=fill)
    centre = (base[0] + nx * half, base[1] + ny * half)
    if len(label) <= 3:
        figure.canvas.text(centre, label)
    else:  # a body's name does not fit inside it
        figure.canvas.text((centre[0] + nx * (half + 0.4), centre[1] + ny * (half + 0.4)), label, size=0.36)
    return centre


def _angle_mark(figure: Figure, vertex: Point, start: float, end: float, symbol: sympy.Symbol | None) -> None:
    if symbol is None:
        return
    low, high = min(start, end), max(start, end)
    # a small angle's mark is drawn further out, where its sides are far enough apart for its name
    radius = min(max(1.3, 0.5 / math.sin(max(high - low, 1e-3))), 3.5)
    figure.canvas.arc(vertex, radius, low, high)
    middle = (low + high) / 2
    figure.canvas.text(
        (vertex[0] + (radius + 0.45) * math.cos(middle), vertex[1] + (radius + 0.45) * math.sin(middle)),
        symbol_label(symbol.name),
    )


def _circle_body(figure: Figure, base: Point, normal: Point, body: Body, label: str, fill: str) -> Point:
    radius = 0.55
    centre = (base[0] + normal[0] * radius, base[1] + normal[1] * radius)
    hollow = "hoop" in body.name.lower() or "ring" in body.name.lower()
    figure.canvas.circle(centre, radius, fill="none" if hollow else fill, width=0.12 if hollow else 0.05)
    figure.canvas.line(centre, (centre[0] + radius * 0.7, centre[1]), width=0.03)  # shows it can turn
    figure.canvas.text((centre[0], centre[1] + radius + 0.35), label, size=0.36)
    return centre


@dataclass
class Slope:
    upper: Point | None  # the slope's upper end (None: a floor)
    tangent: Point  # along the surface, pointing right
    normal: Point  # out of the surface, upwards
    bases: dict[str, Point]  # where each body touches the surface


def _drawn_slope(surface: Surface, figure: Figure) -> float:
    """The surface's slope from its normal, at its value where that reads clearly (READABLE_ANGLES)."""
    a, b = surface.normal
    tangent = (b, -a) if b >= 0 else (-b, a)
    slope = math.atan2(tangent[1], tangent[0])
    if abs(slope) < 1e-9:
        return 0.0
    return figure.readable_angle(slope, surface.angle_symbol)


def draw_double_incline(figure: Figure, model: Model, surfaces: list[Surface], string: bool) -> None:
    """Two faces of one block meeting at the top, a body on each, a pulley at the apex."""
    canvas = figure.canvas
    first, second = surfaces
    left_angle, right_angle = (abs(_drawn_slope(s, figure)) or math.radians(30) for s in surfaces)
    height = 3.5
    apex = (height / math.tan(left_angle), height)
    left_foot, right_foot = (0.0, 0.0), (apex[0] + height / math.tan(right_angle), 0.0)
    canvas.polygon([left_foot, apex, right_foot], fill="#eeeeee")
    canvas.ground((-0.5, 0.0), (right_foot[0] + 0.5, 0.0))
    _angle_mark(figure, left_foot, 0.0, left_angle, first.angle_symbol)
    _angle_mark(figure, right_foot, math.pi - right_angle, math.pi, second.angle_symbol)
    spots = []
    for surface, foot, fill in ((first, left_foot, FILLS[0]), (second, right_foot, FILLS[1])):
        base = (foot[0] + (apex[0] - foot[0]) * 0.5, foot[1] + (apex[1] - foot[1]) * 0.5)
        length = math.hypot(apex[0] - foot[0], apex[1] - foot[1])
        tangent = ((apex[0] - foot[0]) / length, (apex[1] - foot[1]) / length)
        centre = _block(figure, base, tangent, body_label(surface.body, model), fill)
        spots.append((centre, tangent))
    if string:
        top = (apex[0], apex[1] + 0.45)
        canvas.circle(top, 0.3, fill="#ffffff")
        for centre, tangent in spots:
            canvas.line(centre, (top[0] - 0.3 * tangent[1] * 0, top[1] + 0.3), width=0.04)
    names = [body_label(s.body, model) for s in surfaces]
    angles = [symbol_label(s.angle_symbol.name) for s in surfaces if s.angle_symbol is not None]
    figure.say(
        f"{names[0]} and {names[1]} on two inclines at angles {' and '.join(angles)} meeting at the top"
        + (", joined by a string over a pulley there." if string else ".")
    )


def draw_incline(
    figure: Figure,
    model: Model,
    values: Values,
    surfaces: list[Surface],
    *,
    touching: bool = False,
    pushes: Mapping[str, list[tuple[str, Point]]] | None = None,
) -> Slope:
    """Bodies on one fixed slope (or floor), spaced along it; `pushes` are the given forces on each body
    (label, direction in the model's axes), drawn as arrows pushing on it."""
    first = surfaces[0]
    slope = _drawn_slope(first, figure)
    tangent = (math.cos(slope), math.sin(slope))
    normal = (-tangent[1], tangent[0])
    start: Point = (0.0, 0.0)
    end: Point = (SLOPE * tangent[0], SLOPE * tangent[1])
    upper, lower = (start, end) if slope < 0 else (end, start)
    canvas = figure.canvas
    flat = slope == 0
    if flat:
        canvas.ground(start, end)
    else:
        corner = (upper[0], lower[1])
        canvas.polygon([lower, upper, corner], fill="#eeeeee")
        canvas.ground(*sorted((lower, corner)))
        toward_upper = math.atan2(upper[1] - lower[1], upper[0] - lower[0])
        horizontal = 0.0 if corner[0] > lower[0] else math.pi
        _angle_mark(figure, lower, horizontal, toward_upper, first.angle_symbol)
    bodies = [s.body for s in surfaces]
    bases: dict[str, Point] = {}
    taken: list[_Taken] = []  # bodies and arrows, which a friction label must keep clear of
    count = len(bodies)
    for index, (surface, body) in enumerate(zip(surfaces, bodies, strict=True)):
        fraction = 0.2 + 0.6 * index / (count - 1) if count > 1 else 0.45
        if touching:  # bodies pushing on each other sit side by side
            fraction = 0.35 + index * 1.15 * BLOCK / SLOPE
        base = (start[0] + (end[0] - start[0]) * fraction, start[1] + (end[1] - start[1]) * fraction)
        bases[body.name] = base
        label = body_label(body, model)
        fill = FILLS[index % len(FILLS)]
        if body.angle is not None:
            centre = _circle_body(figure, base, normal, body, label, fill)
            reach = _CIRCLE
        else:
            centre = _block(figure, base, tangent, label, fill)
            reach = BLOCK / 2
        taken.append(_Taken(centre, centre, reach))
        for name, direction in (pushes or {}).get(body.name, []):
            drawn = (
                _on_drawn_slope(direction, surface, tangent)
                if _along_slope(model, body, surface)
                else direction
            )
            taken.append(
                _push(figure, centre, drawn, tangent, reach, round_body=body.angle is not None, label=name)
            )
    _friction_labels(figure, model, bodies, bases, taken, tangent, normal, touching=touching)
    angle = f" at angle {symbol_label(first.angle_symbol.name)}" if first.angle_symbol else ""
    names = ", ".join(body_label(b, model) for b in bodies)
    rough = " (with friction)" if model.frictions else ""
    figure.say(f"{'A floor' if flat else 'An incline' + angle}{rough} with {names} on it.")
    pushed = [
        f"{name} pushes {body_label(body, model)}"
        for body in bodies
        for name, _ in (pushes or {}).get(body.name, [])
    ]
    if pushed:
        figure.say("A force " + ", and a force ".join(pushed) + ", along the arrow drawn.")
    return Slope(None if flat else upper, tangent, normal, bases)


@dataclass(frozen=True)
class _Taken:
    """Part of the drawing a label must keep clear of: the segment from `start` to `end`, thickened by
    `reach` (a body is a point thickened by its half-size; an arrow, a line)."""

    start: Point
    end: Point
    reach: float

    def near(self, spot: Point, margin: float) -> bool:
        (ax, ay), (bx, by) = self.start, self.end
        dx, dy = bx - ax, by - ay
        length = dx * dx + dy * dy
        t = 0.0 if length == 0 else min(1.0, max(0.0, ((spot[0] - ax) * dx + (spot[1] - ay) * dy) / length))
        return math.hypot(spot[0] - ax - t * dx, spot[1] - ay - t * dy) < self.reach + margin


_CIRCLE = 0.55  # radius of a round body on a slope
_PUSH = 1.5  # length of a push's arrow


def _on_drawn_slope(direction: Point, surface: Surface, tangent: Point) -> Point:
    """A direction in the model's axes, turned to keep its angle to the surface on the drawn slope (which
    is steepened or flattened to read clearly)."""
    a, b = surface.normal
    along_model = (b, -a) if b >= 0 else (-b, a)  # as _drawn_slope takes it, pointing right
    across_model = (-along_model[1], along_model[0])
    along = direction[0] * along_model[0] + direction[1] * along_model[1]
    across = direction[0] * across_model[0] + direction[1] * across_model[1]
    normal = (-tangent[1], tangent[0])
    return (along * tangent[0] + across * normal[0], along * tangent[1] + across * normal[1])


def _along_slope(model: Model, body: Body, surface: Surface) -> bool:
    """Are the body's given forces written with the slope's angle (along or across it), so that they turn
    with the drawn slope? A force without it (a horizontal push) keeps its direction on the page."""
    angle = surface.angle_symbol
    return angle is not None and any(
        angle in expr.free_symbols
        for force in model.forces
        if force.body == body.name and force.kind is ForceKind.APPLIED
        for _, expr in force.components
    )


def _push(
    figure: Figure,
    centre: Point,
    direction: Point,
    tangent: Point,
    reach: float,
    *,
    round_body: bool,
    label: str,
) -> _Taken:
    """An arrow along `direction` whose head meets the body's face on the side the force comes from."""
    dx, dy = direction
    if round_body:
        depth = reach
    else:  # a block turned with the slope: its face is where the line leaves its square
        along = abs(dx * tangent[0] + dy * tangent[1])
        across = abs(-dx * tangent[1] + dy * tangent[0])
        depth = reach / max(along, across)
    head = (centre[0] - dx * (depth + 0.05), centre[1] - dy * (depth + 0.05))
    tail = (head[0] - dx * _PUSH, head[1] - dy * _PUSH)
    figure.canvas.arrow(tail, head, width=0.05)
    figure.canvas.text((tail[0] - dx * 0.35, tail[1] - dy * 0.35), label)
    return _Taken((tail[0] - dx * 0.35, tail[1] - dy * 0.35), head, 0.25)


def _friction_labels(
    figure: Figure,
    model: Model,
    bodies: list[Body],
    bases: dict[str, Point],
    taken: list[_Taken],
    tangent: Point,
    normal: Point,
    *,
    touching: bool,
) -> None:
    """Each body's coefficient of friction on the surface beside it, clear of the bodies and arrows;
    bodies side by side on one rough floor share one label."""
    labelled: set[sympy.Symbol] = set()
    for body in bodies:
        for friction in (f for f in model.frictions if f.body == body.name):
            coefficient = friction.coefficient
            if not isinstance(coefficient, sympy.Symbol) or (touching and coefficient in labelled):
                continue
            base = bases[body.name]
            # behind the body, else ahead of it, else further off either way
            spots = [
                (
                    base[0] + tangent[0] * along + normal[0] * 0.3,
                    base[1] + tangent[1] * along + normal[1] * 0.3,
                )
                for along in (-1.1, 1.1, -1.8, 1.8, -2.6, 2.6)
            ]
            spot = next((p for p in spots if not any(t.near(p, 0.25) for t in taken)), spots[0])
            figure.canvas.text(spot, symbol_label(coefficient.name), size=0.36)
            taken.append(_Taken(spot, spot, 0.2))
            labelled.add(coefficient)


def spring_sign(potential: PairPotential, values: Values) -> int:
    """+1 for a spring (energy quadratic in the distance, growing), -1 for a quadratic that falls (the
    centrifugal potential of a rotating frame), 0 for anything else (gravitation, Lennard-Jones...)."""
    energy = sympy.expand(potential.energy)
    if not energy.is_polynomial(potential.distance) or sympy.degree(energy, potential.distance) != 2:
        return 0
    leading = values.number(energy.coeff(potential.distance, 2))
    return 1 if leading > 0 else -1


def _other_symbols(potential: PairPotential, body: Body, model: Model) -> list[sympy.Symbol]:
    """The potential's parameters other than the body's own mass (ω, v and R, G and M...)."""
    own = body.mass.free_symbols
    return sorted(
        (s for s in potential.energy.free_symbols if s in set(model.parameters) and s not in own),
        key=lambda s: s.name,
    )


def draw_central(figure: Figure, model: Model, body: Body, potential: PairPotential) -> None:
    """A body at a distance from a fixed centre that attracts it (a planet and a satellite)."""
    canvas = figure.canvas
    canvas.circle((0.0, 0.0), 1.0, fill=FILLS[2])
    masses = [s for s in _other_symbols(potential, body, model) if s.name[:1].isupper() and s.name != "G"]
    if masses:
        canvas.text((0.0, 0.0), symbol_label(masses[0].name))
    canvas.circle((5.5, 0.0), 0.35, fill=FILLS[0])
    canvas.text((5.5, -0.75), body_label(body, model))
    canvas.line((0.0, 0.0), (5.15, 0.0), dashed=True, width=0.03)
    coordinate = model.coordinates[0].name if model.coordinates else ""
    canvas.text((3.0, 0.35), coordinate)
    canvas.arc((0.0, 0.0), 5.5, -0.5, 0.5, width=0.03)
    figure.say(
        f"{body_label(body, model)} at a distance {coordinate} from a fixed centre"
        + (f" of mass {symbol_label(masses[0].name)}" if masses else "")
        + " that attracts it; it moves on an orbit about it."
    )


def stiffness_symbols(potential: PairPotential, model: Model) -> list[sympy.Symbol]:
    """The symbols of the factor in front of the energy's distance term: k in k (d - L0)^2 / 2."""
    factor, _ = potential.energy.as_independent(potential.distance, as_Add=False)
    return sorted((s for s in factor.free_symbols if s in set(model.parameters)), key=lambda s: s.name)


def draw_slope_spring(
    figure: Figure, model: Model, slope: Slope, body: Body, potential: PairPotential
) -> None:
    """A spring along the slope from a plate fixed at its upper end to the body's uphill face."""
    if slope.upper is None:
        return
    tx, ty = slope.tangent
    up = (tx, ty) if ty > 0 else (-tx, -ty)
    nx, ny = slope.normal
    base = slope.bases[body.name]
    face = (base[0] + up[0] * BLOCK / 2 + nx * BLOCK / 2, base[1] + up[1] * BLOCK / 2 + ny * BLOCK / 2)
    anchor = (slope.upper[0] + nx * BLOCK / 2 - up[0] * 0.1, slope.upper[1] + ny * BLOCK / 2 - up[1] * 0.1)
    figure.canvas.line(
        (anchor[0] - nx * 0.6, anchor[1] - ny * 0.6), (anchor[0] + nx * 0.6, anchor[1] + ny * 0.6), width=0.1
    )
    figure.canvas.spring(anchor, face, amplitude=0.18)
    stiffness = stiffness_symbols(potential, model)
    middle = ((anchor[0] + face[0]) / 2 + nx * 0.55, (anchor[1] + face[1]) / 2 + ny * 0.55)
    name = symbol_label(stiffness[0].name) if stiffness else ""
    if name:
        figure.canvas.text(middle, name)
    figure.say(
        f"A spring {name} along the incline holds {body_label(body, model)} from a point fixed up the slope."
    )


def draw_pulley_to_hanging(
    figure: Figure, model: Model, slope: Slope, on_slope: Body, hanging: Body, *, left: bool = False
) -> None:
    """A pulley at the slope's upper end (or a table's edge); the string runs along it, then down."""
    radius = 0.4
    canvas = figure.canvas
    tx, ty = slope.tangent
    table_edge = (0.0, 0.0) if left else (SLOPE * tx, SLOPE * ty)
    top = slope.upper if slope.upper is not None else table_edge
    if left:
        tx, ty = -tx, -ty
    nx, ny = slope.normal
    # The string runs BLOCK/2 above the surface, so it meets the pulley's rim there.
    centre = (top[0] + tx * 0.3 + nx * (BLOCK / 2 - radius), top[1] + ty * 0.3 + ny * (BLOCK / 2 - radius))
    canvas.line(top, centre, width=0.08)  # the pulley's bracket
    base = slope.bases[on_slope.name]
    attach = (base[0] + tx * BLOCK / 2 + nx * BLOCK / 2, base[1] + ty * BLOCK / 2 + ny * BLOCK / 2)
    touch = (centre[0] + nx * radius, centre[1] + ny * radius)
    canvas.line(attach, touch, width=0.04)
    canvas.circle(centre, radius, fill="#ffffff")
    canvas.circle(centre, 0.06, fill="#1b1b1b")
    side = radius if tx >= 0 else -radius
    drop = (centre[0] + side, centre[1] - 3.0)
    canvas.line((centre[0] + side, centre[1]), (drop[0], drop[1] + BLOCK / 2), width=0.04)
    canvas.polygon(
        [
            (drop[0] - BLOCK / 2, drop[1] - BLOCK / 2),
            (drop[0] + BLOCK / 2, drop[1] - BLOCK / 2),
            (drop[0] + BLOCK / 2, drop[1] + BLOCK / 2),
            (drop[0] - BLOCK / 2, drop[1] + BLOCK / 2),
        ],
        fill=FILLS[1],
    )
    canvas.text(drop, body_label(hanging, model))
    figure.say(
        f"A string from {body_label(on_slope, model)} runs over a pulley at the "
        f"{'top' if slope.upper is not None else 'edge'} to {body_label(hanging, model)}, which hangs."
    )


def _hanging_block(figure: Figure, top: Point, body: Body, model: Model, fill: str) -> None:
    """A string from `top` down to a block hanging 2.5 below it."""
    x, y = top
    depth = 2.5
    figure.canvas.line(top, (x, y - depth + BLOCK / 2), width=0.04)
    figure.canvas.polygon(_square((x, y - depth), BLOCK), fill=fill)
    figure.canvas.text((x, y - depth), body_label(body, model))


def draw_double_atwood(figure: Figure, model: Model, hanging: list[Body]) -> None:
    """One body on one side of a fixed pulley; on the other, a pulley carrying the other two."""
    canvas = figure.canvas
    canvas.ground((-1.5, 1.6), (1.5, 1.6), below=False)
    canvas.line((0.0, 1.6), (0.0, 0.0), width=0.08)
    canvas.circle((0.0, 0.0), 1.0, fill="#ffffff")
    single, *pair = sorted(hanging, key=lambda b: b.name)
    _hanging_block(figure, (-1.0, 0.0), single, model, FILLS[0])
    lower = (1.0, -2.5)
    canvas.line((1.0, 0.0), (1.0, lower[1] + 0.6), width=0.04)
    canvas.circle(lower, 0.6, fill="#ffffff")
    for side, body, fill in ((-0.6, pair[0], FILLS[1]), (0.6, pair[1], FILLS[2])):
        _hanging_block(figure, (lower[0] + side, lower[1]), body, model, fill)
    figure.say(
        f"{body_label(single, model)} hangs on one side of a fixed pulley; on the other hangs a light pulley "
        f"carrying {body_label(pair[0], model)} and {body_label(pair[1], model)}."
    )


def draw_wheel_and_weight(figure: Figure, model: Model, wheel: Body, weight: Body) -> None:
    canvas = figure.canvas
    radius = 1.4
    canvas.ground((-2.0, 2.2), (1.0, 2.2), below=False)
    canvas.line((-0.5, 2.2), (0.0, 0.0), width=0.1)
    canvas.circle((0.0, 0.0), radius, fill=FILLS[0])
    canvas.circle((0.0, 0.0), 0.1, fill="#1b1b1b")
    canvas.text((-0.4, -0.5), body_label(wheel, model))
    _hanging_block(figure, (radius, 0.0), weight, model, FILLS[1])
    figure.say(
        f"A string wound on a wheel {body_label(wheel, model)} turning on a fixed axle holds "
        f"{body_label(weight, model)}, which hangs."
    )


def draw_atwood(figure: Figure, model: Model, left: Body, right: Body, wheel: Body | None = None) -> None:
    canvas = figure.canvas
    radius = 1.0
    centre = (0.0, 0.0)
    canvas.ground((-1.5, 1.6), (1.5, 1.6), below=False)
    canvas.line((0.0, 1.6), centre, width=0.08)
    canvas.circle(centre, radius, fill="#ffffff" if wheel is None else FILLS[2])
    canvas.circle(centre, 0.08, fill="#1b1b1b")
    if wheel is not None:
        canvas.text((0.0, -0.45), body_label(wheel, model), size=0.36)
    for side, body, depth, fill in ((-1, left, 3.0, FILLS[0]), (1, right, 4.2, FILLS[1])):
        x = side * radius
        canvas.line((x, 0.0), (x, -depth + BLOCK / 2), width=0.04)
        canvas.polygon(
            [
                (x - BLOCK / 2, -depth - BLOCK / 2),
                (x + BLOCK / 2, -depth - BLOCK / 2),
                (x + BLOCK / 2, -depth + BLOCK / 2),
                (x - BLOCK / 2, -depth + BLOCK / 2),
            ],
            fill=fill,
        )
        canvas.text((x, -depth), body_label(body, model))
    figure.say(
        f"{body_label(left, model)} and {body_label(right, model)} hang on either side of a pulley, joined by a string."
    )


def draw_yoyo(figure: Figure, model: Model, body: Body, values: Values) -> None:
    canvas = figure.canvas
    outer, axle = 1.4, 0.45
    centre = (0.0, -3.0)
    canvas.ground((-2.0, 0.0), (1.0, 0.0), below=False)
    canvas.circle(centre, outer, fill=FILLS[0])
    canvas.circle(centre, axle, fill=FILLS[3])
    canvas.line((centre[0] - axle, 0.0), (centre[0] - axle, centre[1]), width=0.05)
    canvas.line(centre, (centre[0] + axle, centre[1]), width=0.03)
    radius_symbols = sorted(
        (s for c in model.constraints if c.kind is ConstraintKind.STRING for s in c.gap.free_symbols
         if s in set(model.parameters)),
        key=lambda s: s.name,
    )  # fmt: skip
    if radius_symbols:
        canvas.text((centre[0] + axle / 2, centre[1] + 0.3), symbol_label(radius_symbols[0].name), size=0.36)
    canvas.text((centre[0] + outer * 0.55, centre[1] - outer * 0.55), body_label(body, model))
    falling = moving_coordinate(model, body, exclude=())
    if falling is not None:  # how far it has fallen, positive downwards
        side = centre[0] + outer + 0.5
        mark_coordinate(
            figure, (side, centre[1] + 1.0), (side, centre[1] - 0.4), coordinate_label(model, falling)
        )
    figure.say(
        f"A yo-yo {body_label(body, model)} hangs from a string wound on its axle"
        + (f" of radius {symbol_label(radius_symbols[0].name)}" if radius_symbols else "")
        + "; the string's upper end is held fixed."
    )


def _moves_linearly(body: Body, model: Model) -> bool:
    coordinates = [c.symbol for c in model.coordinates]
    return all(
        sympy.diff(expr, a, b) == 0 for _, expr in body.position for a in coordinates for b in coordinates
    )


def _cart(figure: Figure, pivot: Point, label: str) -> None:
    """A cart on wheels below `pivot`, carrying a gallows whose beam holds the pendulum at `pivot`."""
    canvas = figure.canvas
    width, height = 3.6, 0.9
    centre = (pivot[0], pivot[1] - 5.0)
    top = centre[1]
    mast = centre[0] - width / 2 + 0.2
    canvas.line((mast, top), (mast, pivot[1]), width=0.12)
    canvas.line((mast, pivot[1]), pivot, width=0.12)
    canvas.polygon(
        [(centre[0] - width / 2, top - height), (centre[0] + width / 2, top - height),
         (centre[0] + width / 2, top), (centre[0] - width / 2, top)],
        fill=FILLS[1],
    )  # fmt: skip
    for dx in (-0.7, 0.7):
        canvas.circle((centre[0] + dx, top - height - 0.25), 0.25, fill="#ffffff")
    canvas.ground((centre[0] - 3.0, top - height - 0.5), (centre[0] + 3.0, top - height - 0.5))
    canvas.text((centre[0], top - height / 2), label)


# What a pendulum's swinging body is called when the model's name for it says so; otherwise a bob.
PENDULUM_BODIES = ("ball", "block", "bob", "sphere", "stone")


def pendulum_words(body: Body, string: Constraint) -> tuple[str, str]:
    """(what swings, what holds it): ("ball", "string"), ("bob", "rod")... from the model's names."""
    name = body.name.lower()
    noun = next((word for word in PENDULUM_BODIES if word in name), "bob")
    return noun, "rod" if "rod" in string.name.lower() else "string"


def _turning_rate(model: Model, body: Body) -> sympy.Expr | None:
    """The rate of a rotating frame the body turns with (a conical pendulum), else None."""
    frame = model.frame
    if frame is None or frame.rate is None or body.name not in frame.bodies:
        return None
    return frame.rate


def _state_angle(model: Model, body: Body, values: Values) -> float | None:
    """The pendulum's angle from the downward vertical at the model's state, when the state gives it."""
    state = dict(model.state)
    for c in model.coordinates:
        if c.symbol in state and any(expr.has(c.symbol) for _, expr in body.position):
            try:
                return values.number(state[c.symbol])
            except (TypeError, ValueError):
                return None
    return None


def _swung_to(model: Model, body: Body, angle: float, values: Values) -> dict[sympy.Symbol, float]:
    """The value of the coordinate that swings the body (its angle from the downward vertical, in
    the model's sense) that puts it `angle` from the vertical, on the side the figure draws it: +x."""
    swinging = [
        c.symbol
        for c in model.coordinates
        if any(sympy.diff(expr, c.symbol, 2) != 0 for _, expr in body.position)
    ]
    if len(swinging) != 1:
        return {}
    q = swinging[0]
    x = dict(body.position).get("x", sympy.Integer(0))
    rest = {c.symbol: 0.0 for c in model.coordinates}
    try:
        hanging = values.number(x, rest)
        aside = {s: (values.number(x, {**rest, q: s}) - hanging) * math.sin(angle) for s in (angle, -angle)}
    except (TypeError, ValueError, ZeroDivisionError):
        return {q: angle}
    return {q: angle if aside[angle] >= aside[-angle] else -angle}


def draw_pendulum(
    figure: Figure,
    model: Model,
    body: Body,
    string: Constraint,
    values: Values,
    pivot_body: Body | None = None,
) -> None:
    canvas = figure.canvas
    length = 4.0
    collision = model.collision
    reached = dict(collision.reaches) if collision else {}
    angle_symbol = next((expr for expr in reached.values() if isinstance(expr, sympy.Symbol)), None)
    angle = values.number(angle_symbol) if angle_symbol is not None else math.radians(30)
    angle = min(max(angle, math.radians(20)), math.radians(60))
    noun, support = pendulum_words(body, string)
    rate = _turning_rate(model, body)
    state_angle = _state_angle(model, body, values)
    # Drawn at the state's angle when the state gives one (a ball at the top of its circle, a bob
    # passing the bottom), else swung aside to show that it swings. In a turning frame the state is the
    # cone's angle that the problem asks for, which the figure does not give away.
    if rate is None and state_angle is not None:
        angle = state_angle
    # A string pendulum drawn above the pivot's level is whirled round a vertical circle.
    whirled = rate is None and math.cos(angle) < 0
    figure.placed.update(_swung_to(model, body, angle, values))
    pivot = (0.0, 0.0)
    if pivot_body is None:
        canvas.ground((-1.5, 0.0), (1.5, 0.0), below=False)
    else:
        _cart(figure, pivot, body_label(pivot_body, model))
    canvas.line(pivot, (0.0, -length - 0.3), dashed=True, width=0.03)
    raised = (length * math.sin(angle), -length * math.cos(angle))
    lowest = (0.0, -length)
    size = BLOCK * 0.9
    if whirled:
        circle = [
            (length * math.sin(i * math.pi / 24), -length * math.cos(i * math.pi / 24)) for i in range(49)
        ]
        canvas.polyline(circle, dashed=True, width=0.03)
    if rate is not None:  # the horizontal circle the bob goes round, seen obliquely, and the turning rate
        ring = [(raised[0] * math.cos(i * math.pi / 24), raised[1] + 0.3 * raised[0] * math.sin(i * math.pi / 24))
                for i in range(49)]  # fmt: skip
        canvas.polyline(ring, dashed=True, width=0.03)
        canvas.arc((0.0, -length - 0.3), 0.5, math.radians(200), math.radians(340))
        if isinstance(rate, sympy.Symbol):
            canvas.text((0.8, -length - 0.5), symbol_label(rate.name), anchor="start")
    canvas.line(pivot, raised, width=0.04)
    if noun == "block":
        canvas.polygon(_square(raised, size), fill=FILLS[0])
    else:
        canvas.circle(raised, size / 2, fill=FILLS[0])
    name = body_label(body, model)
    if len(name) <= 3:
        canvas.text(raised, name)
    else:  # a name does not fit inside the body: beside it, away from the string
        canvas.text((raised[0] + size / 2 + 0.15, raised[1]), name, size=0.36, anchor="start")
    length_symbols = sorted(
        (s for s in string.gap.free_symbols if s in set(model.parameters)), key=lambda s: s.name
    )
    if length_symbols:
        canvas.text(
            (raised[0] / 2 + 0.35, raised[1] / 2 + 0.1), symbol_label(length_symbols[0].name), anchor="start"
        )
    if angle_symbol is not None:
        _angle_mark(figure, pivot, -math.pi / 2, -math.pi / 2 + angle, angle_symbol)
    held = f"a {support}" + (f" of length {symbol_label(length_symbols[0].name)}" if length_symbols else "")
    if pivot_body is not None:
        said = (
            f"A cart {body_label(pivot_body, model)} rolls on a horizontal floor; "
            f"a {noun} {name} hangs from it on {held}"
        )
    elif whirled:
        said = (
            f"A {noun} {name} on {held} is whirled in a vertical circle (dashed) about the {support}'s "
            "fixed end; it is drawn at the top"
        )
    elif rate is not None:
        at = f" at the rate {symbol_label(rate.name)}" if isinstance(rate, sympy.Symbol) else ""
        said = (
            f"A {noun} {name} hangs from a fixed point on {held} and goes round a horizontal circle (dashed)"
            f"{at}, the {support} sweeping out a cone about the vertical (dashed) through that point"
        )
    else:
        said = f"A {noun} {name} hangs from a fixed point on {held}"
    if collision is not None:
        canvas.polygon(_square(lowest, size), fill="none")
        bullet = (-3.2, -length)
        canvas.polygon(
            [(bullet[0] - 0.3, bullet[1] - 0.1), (bullet[0] + 0.2, bullet[1] - 0.1), (bullet[0] + 0.35, bullet[1]),
             (bullet[0] + 0.2, bullet[1] + 0.1), (bullet[0] - 0.3, bullet[1] + 0.1)],
            fill="#888888",
        )  # fmt: skip
        canvas.arrow((bullet[0] + 0.5, bullet[1]), (bullet[0] + 1.8, bullet[1]))
        mass = collision.projectile_mass
        if isinstance(mass, sympy.Symbol):
            canvas.text((bullet[0], bullet[1] - 0.45), symbol_label(mass.name))
        said += "; a bullet" + (f" {symbol_label(mass.name)}" if isinstance(mass, sympy.Symbol) else "")
        said += " flies into it horizontally at its lowest point"
    if angle_symbol is not None:
        said += f", and it swings up to the angle {symbol_label(angle_symbol.name)} from the vertical"
    figure.say(said + ".")


def _square(centre: Point, size: float) -> list[Point]:
    h = size / 2
    return [
        (centre[0] - h, centre[1] - h),
        (centre[0] + h, centre[1] - h),
        (centre[0] + h, centre[1] + h),
        (centre[0] - h, centre[1] + h),
    ]


def draw_wedge(
    figure: Figure, model: Model, wedge: Body, block: Body, surface: Constraint, values: Values
) -> None:
    canvas = figure.canvas
    symbol = _angle_symbol(surface.gap, values)
    angle = values.number(symbol) if symbol is not None else math.radians(30)
    angle = figure.readable_angle(angle, symbol, low=math.radians(12))
    height = 3.2
    base = height / math.tan(angle)
    top, foot, corner = (0.0, height), (base, 0.0), (0.0, 0.0)
    canvas.ground((-1.5, 0.0), (base + 2.0, 0.0))
    canvas.polygon([corner, top, foot], fill=FILLS[0])
    canvas.text((base * 0.25, height * 0.3), body_label(wedge, model))
    tangent = (math.cos(angle), -math.sin(angle))
    along = 0.4
    spot = (top[0] + (foot[0] - top[0]) * along, top[1] + (foot[1] - top[1]) * along)
    _block(figure, spot, tangent, body_label(block, model), FILLS[1])
    _angle_mark(figure, foot, math.pi - angle, math.pi, symbol)
    # the axis the statement defines, and the coordinates with their positive directions
    axis_x(figure, (-1.4, -0.75))
    wedge_coordinate = moving_coordinate(model, wedge, exclude=())
    if wedge_coordinate is not None:
        mark_coordinate(figure, (0.0, 0.3), (1.2, 0.3), coordinate_label(model, wedge_coordinate))
    slide = moving_coordinate(model, block, exclude=(wedge_coordinate,))
    if slide is not None:
        lift = 1.45
        start = (spot[0] + tangent[1] * -lift, spot[1] + tangent[0] * lift)
        mark_coordinate(
            figure,
            start,
            (start[0] + tangent[0] * 1.3, start[1] + tangent[1] * 1.3),
            coordinate_label(model, slide),
        )
    figure.say(
        f"A block {body_label(block, model)} on the incline of a wedge {body_label(wedge, model)}"
        + (f" of angle {symbol_label(symbol.name)}" if symbol is not None else "")
        + "; the wedge stands on a frictionless floor and can slide."
    )


def axis_x(figure: Figure, at: Point) -> None:
    """The +x axis the statement defines, as an arrow with its name."""
    figure.canvas.arrow(at, (at[0] + 1.2, at[1]), width=0.04)
    figure.canvas.text((at[0] + 1.55, at[1]), "x", size=0.4)
    figure.say("The +x axis points to the right.")


def mark_coordinate(figure: Figure, start: Point, end: Point, label: str) -> None:
    """A coordinate's positive direction: a thin arrow with the coordinate's name beside its middle."""
    figure.canvas.arrow(start, end, width=0.035, color="#1a5fb4")
    dx, dy = end[0] - start[0], end[1] - start[1]
    length = math.hypot(dx, dy) or 1.0
    middle = ((start[0] + end[0]) / 2 - dy / length * 0.3, (start[1] + end[1]) / 2 + dx / length * 0.3)
    figure.canvas.text(middle, label, size=0.4)
    figure.say(f"The coordinate {label} grows along the blue arrow marked {label}.")


def moving_coordinate(model: Model, body: Body, exclude: tuple[str | None, ...]) -> str | None:
    """The coordinate that moves `body` (the first, other than those in `exclude`)."""
    for c in model.coordinates:
        if c.name not in exclude and any(sympy.diff(e, c.symbol) != 0 for _, e in body.position):
            return c.name
    return None


def coordinate_label(model: Model, name: str) -> str:
    """A coordinate as the worked solutions write it (the model's notation may rename it)."""
    symbol = next((symbol for key, symbol, _ in model.notation if key == name and symbol), None)
    return symbol_label(symbol or name)


def draw_two_blocks_spring(
    figure: Figure, model: Model, first: Body, second: Body, spring_symbol: sympy.Symbol | None
) -> None:
    canvas = figure.canvas
    canvas.ground((-1.0, 0.0), (7.0, 0.0))
    _block(figure, (0.5, 0.0), (1.0, 0.0), body_label(first, model), FILLS[0])
    _block(figure, (5.5, 0.0), (1.0, 0.0), body_label(second, model), FILLS[1])
    canvas.spring((1.0, BLOCK / 2), (5.0, BLOCK / 2))
    name = symbol_label(spring_symbol.name) if spring_symbol is not None else ""
    if name:
        canvas.text((3.0, BLOCK / 2 + 0.55), name)
    figure.say(
        f"{body_label(first, model)} and {body_label(second, model)} on a frictionless floor, joined by a spring {name}."
    )


def draw_spring(
    figure: Figure,
    model: Model,
    body: Body,
    spring_symbol: sympy.Symbol | None,
    *,
    vertical: bool = False,
    damping: sympy.Expr | None = None,
) -> None:
    canvas = figure.canvas
    if vertical:
        canvas.ground((-1.5, 0.0), (1.5, 0.0))
        canvas.spring((0.0, 0.0), (0.0, 3.5))
        centre = _block(figure, (0.0, 3.5), (1.0, 0.0), body_label(body, model), FILLS[0])
        if spring_symbol is not None:
            canvas.text((0.65, 1.75), symbol_label(spring_symbol.name), anchor="start")
        figure.say(
            f"A block {body_label(body, model)} rests on a vertical spring"
            + (f" {symbol_label(spring_symbol.name)}" if spring_symbol is not None else "")
            + " standing on the floor."
        )
        return
    if damping is not None:  # a dashpot above the spring, both from the wall to a taller block
        size = 2 * BLOCK
        canvas.ground((0.0, 0.0), (0.0, size + 0.6), below=False)
        canvas.ground((0.0, 0.0), (7.0, 0.0))
        canvas.spring((0.0, 0.45), (4.0, 0.45), amplitude=0.18)
        canvas.dashpot((0.0, 1.55), (4.0, 1.55))
        centre = _block(figure, (4.0 + size / 2, 0.0), (1.0, 0.0), body_label(body, model), FILLS[0], size)
        if spring_symbol is not None:
            canvas.text((2.0, 1.0), symbol_label(spring_symbol.name))
        if isinstance(damping, sympy.Symbol):
            canvas.text((2.1, 2.15), symbol_label(damping.name))
    else:
        canvas.ground((0.0, 0.0), (0.0, 2.0), below=False)
        canvas.ground((0.0, 0.0), (7.0, 0.0))
        canvas.spring((0.0, BLOCK / 2), (4.0, BLOCK / 2))
        centre = _block(figure, (4.0 + BLOCK / 2, 0.0), (1.0, 0.0), body_label(body, model), FILLS[0])
        if spring_symbol is not None:
            canvas.text((2.0, BLOCK / 2 + 0.55), symbol_label(spring_symbol.name))
    canvas.arrow((centre[0], -0.6), (centre[0] + 1.6, -0.6), width=0.04)
    coordinates = [c.name for c in model.coordinates]
    if coordinates:
        canvas.text((centre[0] + 2.0, -0.6), coordinates[0], anchor="start")
    collision = model.collision
    if collision is not None:
        bullet = (centre[0] + 4.2, centre[1])
        canvas.polygon(
            [(bullet[0] + 0.3, bullet[1] - 0.1), (bullet[0] - 0.2, bullet[1] - 0.1), (bullet[0] - 0.35, bullet[1]),
             (bullet[0] - 0.2, bullet[1] + 0.1), (bullet[0] + 0.3, bullet[1] + 0.1)],
            fill="#888888",
        )  # fmt: skip
        canvas.arrow((bullet[0] - 0.5, bullet[1]), (bullet[0] - 1.6, bullet[1]))
        if isinstance(collision.projectile_mass, sympy.Symbol):
            canvas.text((bullet[0], bullet[1] + 0.45), symbol_label(collision.projectile_mass.name))
        figure.say("A bullet flies into the block along the spring's line and sticks.")
    figure.say(
        f"A block {body_label(body, model)} on a horizontal frictionless floor, tied to a wall by a spring"
        + (f" {symbol_label(spring_symbol.name)}" if spring_symbol is not None else "")
        + (
            " and, beside it, a dashpot"
            + (f" {symbol_label(damping.name)}" if isinstance(damping, sympy.Symbol) else "")
            if damping is not None
            else ""
        )
        + "."
    )


def draw_pair(figure: Figure, model: Model, first: Body, second: Body, distance_label: str) -> None:
    canvas = figure.canvas
    gap = 5.0
    for x, body, fill in ((0.0, first, FILLS[0]), (gap, second, FILLS[1])):
        canvas.circle((x, 0.0), 0.55, fill=fill)
        canvas.text((x, 0.0), body_label(body, model) if body_label(body, model) != body.name else "")
        if isinstance(body.mass, sympy.Symbol):
            canvas.text((x, -0.95), symbol_label(body.mass.name), size=0.36)
    canvas.line((0.55, 0.0), (gap - 0.55, 0.0), dashed=True, width=0.03)
    canvas.arrow((gap / 2, 1.0), (0.0, 1.0), width=0.03)
    canvas.arrow((gap / 2, 1.0), (gap, 1.0), width=0.03)
    canvas.line((0.0, 0.7), (0.0, 1.3), width=0.03)
    canvas.line((gap, 0.7), (gap, 1.3), width=0.03)
    canvas.text((gap / 2, 1.45), distance_label)
    figure.say(f"Two atoms a distance {distance_label} apart, interacting through a potential.")


def draw_impact(figure: Figure, model: Model, values: Values) -> None:
    """Two bodies about to meet (or, for an explosion, about to part), each with its velocity before
    labelled; in the plane, the impact's normal dashed through the second body."""
    hit = model.impact
    assert hit is not None
    canvas = figure.canvas
    plane = any(len(model.body(name).position) > 1 for name in hit.bodies)
    gap = 3.0 if hit.restitution is not None else 1.2
    before = velocities_before(model)
    speeds: list[str] = []
    for index, name in enumerate(hit.bodies):
        body = model.body(name)
        centre = (index * gap, 0.0)
        if plane:
            canvas.circle(centre, BLOCK / 2, fill=FILLS[index])
        else:
            canvas.polygon(_square(centre, BLOCK), fill=FILLS[index])
        label = body_label(body, model)
        if plane and label == body.name:  # equal masses: the mass inside, the name beneath
            canvas.text(centre, symbol_label(body.mass.name) if isinstance(body.mass, sympy.Symbol) else "")
            canvas.text((centre[0], -0.9), label, size=0.32)
        else:
            canvas.text(centre, label)
        velocity = before[name].get("x", sympy.Integer(0))
        if velocity != 0:
            canvas.arrow((centre[0], 0.85), (centre[0] + 1.1, 0.85), width=0.04)
            label = symbol_label(velocity.name) if isinstance(velocity, sympy.Symbol) else ""
            canvas.text((centre[0] + 0.55, 1.2), label, size=0.36)
            speeds.append(f"{body_label(body, model)} moving at {label or 'its speed'}")
    if hit.fixed is not None:
        _draw_fixed_partner(figure, model, values)
    elif plane:
        n = dict(hit.normal)
        nx, ny = (values.number(n.get(a, sympy.Integer(0))) for a in ("x", "y"))
        norm = math.hypot(nx, ny) or 1.0
        edge = BLOCK / 2  # from the puck's rim, clear of its label
        canvas.line(
            (gap + edge * nx / norm, edge * ny / norm),
            (gap + 1.8 * nx / norm, 1.8 * ny / norm),
            dashed=True,
            width=0.03,
        )
        canvas.line((gap + edge, 0.0), (gap + 1.8, 0.0), dashed=True, width=0.02)
        angles = sorted(set().union(*(e.free_symbols for _, e in hit.normal)), key=str)
        if angles:
            middle = math.atan2(ny, nx) / 2
            canvas.text(
                (gap + 1.25 * math.cos(middle), 1.25 * math.sin(middle)),
                symbol_label(angles[0].name),
                size=0.36,
            )
    else:
        canvas.line((-BLOCK, -BLOCK / 2), (gap + BLOCK, -BLOCK / 2), width=0.05)
    names = " and ".join(body_label(model.body(name), model) for name in hit.bodies)
    if hit.fixed is not None:
        names += f" and the fixed {hit.fixed}"
    if hit.release is not None:
        figure.say(f"{names} together, about to be pushed apart by an explosion.")
    else:
        kind = "a collision" if hit.restitution != 1 else "an elastic collision"
        figure.say(f"{names} about to meet in {kind}" + (": " + ", ".join(speeds) if speeds else "") + ".")


def _draw_fixed_partner(figure: Figure, model: Model, values: Values) -> None:
    """The floor or wall the body hits: a hatched surface across the normal, where the body meets it."""
    hit = model.impact
    assert hit is not None
    n = dict(hit.normal)
    nx, ny = (values.number(n.get(a, sympy.Integer(0))) for a in ("x", "y"))
    norm = math.hypot(nx, ny) or 1.0
    nx, ny = nx / norm, ny / norm
    contact = (BLOCK / 2 * nx, BLOCK / 2 * ny)
    along = (-ny, nx)  # hatched on the +normal side, the solid one
    figure.canvas.ground(
        (contact[0] - along[0], contact[1] - along[1]), (contact[0] + along[0], contact[1] + along[1])
    )


def draw_row(figure: Figure, model: Model) -> None:
    """Any other model: its bodies side by side, labelled (the statement says how they move)."""
    for index, body in enumerate(model.bodies):
        centre = (index * 2.0, 0.0)
        figure.canvas.polygon(_square(centre, BLOCK), fill=FILLS[index % len(FILLS)])
        label = body_label(body, model)
        if len(label) <= 3:
            figure.canvas.text(centre, label)
        else:  # a name does not fit inside the block: beneath it
            figure.canvas.text((centre[0], centre[1] - BLOCK / 2 - 0.35), label, size=0.32)
    figure.say("The bodies of the problem: " + ", ".join(body_label(b, model) for b in model.bodies) + ".")


def compose(model: Model, given: Mapping[str, float]) -> Figure:
    """The figure for `model` with the parameters in `given` (SI, radians) or typical values; a model
    no element recognises (or whose numbers do not evaluate) gets its bodies side by side."""
    try:
        return _compose(model, given)
    except (TypeError, ValueError, ZeroDivisionError, StopIteration, KeyError, IndexError):
        figure = Figure()
        draw_row(figure, model)
        return figure


def _compose(model: Model, given: Mapping[str, float]) -> Figure:
    # Elements in their own modules use this module's helpers, so they are imported here.
    from physics.figures.chain import draw_pendulum_chain, pendulum_chain_of
    from physics.figures.falling import draw_falling, falling_of
    from physics.figures.ladder import draw_ladder, leaning_of
    from physics.figures.loads import given_forces
    from physics.figures.projectile import draw_projectile, launch_of
    from physics.figures.springs import draw_spring_line, spring_line_of
    from physics.figures.track import draw_track, track_of

    figure = Figure()
    values = Values(model, given)
    if (launch := launch_of(model)) is not None:
        draw_projectile(figure, model, launch, values)
        return figure
    if (leaning := leaning_of(model)) is not None:
        draw_ladder(figure, model, leaning, values)
        return figure
    if model.impact is not None:
        draw_impact(figure, model, values)
        return figure
    strings = [c for c in model.constraints if c.kind is ConstraintKind.STRING]
    pendulum = [c for c in strings if not _is_linear(c.gap, model)]
    if (chain := pendulum_chain_of(model, pendulum)) is not None:
        draw_pendulum_chain(figure, model, chain)
        return figure
    if pendulum:
        joined = _bodies_in(pendulum[0].gap, model)
        bobs = [b for b in joined if not _moves_linearly(b, model)] or joined
        pivots = [b for b in joined if b not in bobs]
        draw_pendulum(figure, model, bobs[0], pendulum[0], values, pivots[0] if pivots else None)
        return figure
    surfaces = [c for c in model.constraints if c.kind is ConstraintKind.SURFACE]
    two_body = [c for c in surfaces if len(_bodies_in(c.gap, model)) == 2]
    on_own_surface = {
        b.name for c in surfaces if len(_bodies_in(c.gap, model)) == 1 for b in _bodies_in(c.gap, model)
    }
    wedges = [c for c in two_body if not {b.name for b in _bodies_in(c.gap, model)} <= on_own_surface]
    if wedges:
        block, wedge = _wedge_roles(wedges[0], model)
        draw_wedge(figure, model, wedge, block, wedges[0], values)
        return figure
    fixed = [
        surface
        for c in surfaces
        if len(bodies := _bodies_in(c.gap, model)) == 1
        and _is_linear(c.gap, model)
        and (surface := _linear_surface(c, bodies[0], model, values)) is not None
    ]
    angles = {surface.angle_symbol for surface in fixed}
    if len(fixed) == 2 and len(angles) == 2 and None not in angles:
        draw_double_incline(figure, model, fixed, bool(strings))
        return figure
    if fixed:
        touching = any(
            {b.name for b in _bodies_in(c.gap, model)} <= {f.body.name for f in fixed} for c in two_body
        )
        pushes = {surface.body.name: given_forces(model, surface.body.name, values) for surface in fixed}
        slope = draw_incline(figure, model, values, fixed, touching=touching, pushes=pushes)
        for potential in model.potentials:
            if (
                potential.anchor
                and len(potential.bodies) == 1
                and potential.bodies[0] in slope.bases
                and spring_sign(potential, values) > 0
            ):
                draw_slope_spring(figure, model, slope, model.body(potential.bodies[0]), potential)
        over_edge = [
            (joined, hanging)
            for string in strings
            if len(joined := _bodies_in(string.gap, model)) == 2
            and len(hanging := [b for b in joined if b.name not in slope.bases]) == 1
        ]
        for index, (joined, hanging) in enumerate(over_edge):
            slope_body = next(b for b in joined if b.name in slope.bases)
            left = slope.upper is None and len(over_edge) == 2 and index == 0
            draw_pulley_to_hanging(figure, model, slope, slope_body, hanging[0], left=left)
        return figure
    if strings:
        joined = _bodies_in(strings[0].gap, model)
        every = list({b.name: b for c in strings for b in _bodies_in(c.gap, model)}.values())
        hanging = [b for b in every if b.angle is None]
        wheels = [b for b in every if b.angle is not None]
        if len(hanging) == 2:
            draw_atwood(figure, model, hanging[0], hanging[1], wheels[0] if wheels else None)
            return figure
        if len(hanging) == 3:
            draw_double_atwood(figure, model, hanging)
            return figure
        if len(hanging) == 1 and wheels:
            draw_wheel_and_weight(figure, model, wheels[0], hanging[0])
            return figure
        if len(joined) == 1 and wheels:
            draw_yoyo(figure, model, joined[0], values)
            return figure
    if (line := spring_line_of(model, values)) is not None:
        draw_spring_line(figure, model, line)
        return figure
    if model.potentials:
        potential = model.potentials[0]
        bodies = [model.body(name) for name in potential.bodies]
        sign = spring_sign(potential, values)
        quadratic = sign > 0
        if potential.anchor and len(bodies) == 1 and sign < 0 and len(model.coordinates) == 1:
            draw_path(figure, model, bodies[0], values, spin=potential)
            return figure
        if potential.anchor and len(bodies) == 1 and sign == 0:
            draw_central(figure, model, bodies[0], potential)
            return figure
        if potential.anchor and len(bodies) == 1:
            spring = stiffness_symbols(potential, model)
            vertical = [axis for axis, _ in bodies[0].position] == ["y"]
            damping = next(
                (
                    f.coefficient
                    for f in model.forces
                    if f.body == bodies[0].name and f.kind is ForceKind.LINEAR_DRAG
                ),
                None,
            )
            draw_spring(
                figure, model, bodies[0], spring[0] if spring else None, vertical=vertical, damping=damping
            )
            return figure
        if len(bodies) == 2 and quadratic:
            spring = stiffness_symbols(potential, model)
            draw_two_blocks_spring(figure, model, bodies[0], bodies[1], spring[0] if spring else None)
            return figure
        if len(bodies) == 2:
            label = next((c.name for c in model.coordinates if c.name not in ("X",)), "d")
            draw_pair(figure, model, bodies[0], bodies[1], label)
            return figure
    if (track := track_of(model)) is not None:
        draw_track(figure, model, track, values)
        return figure
    if (falling := falling_of(model)) is not None:
        draw_falling(figure, model, falling, values)
        return figure
    if len(model.bodies) == 1 and len(model.coordinates) == 1:
        draw_path(figure, model, model.bodies[0], values)
        return figure
    draw_row(figure, model)
    return figure


def draw_path(
    figure: Figure, model: Model, body: Body, values: Values, spin: PairPotential | None = None
) -> None:
    """One body on one coordinate: the curve its centre follows (a wire, a bowl, a circle about a
    pivot), drawn to scale, with the body on it; a turning body on a pivot is a rod from the pivot."""
    coordinate = model.coordinates[0].symbol
    position = dict(body.position)
    x_expr, y_expr = position.get("x", sympy.Integer(0)), position.get("y", sympy.Integer(0))
    ranges = dict((name, (low, high)) for name, low, high in model.coordinate_ranges)
    samples = [i / 20 for i in range(-20, 21)]
    if model.coordinates[0].name in ranges or body.angle is not None:
        samples = [i / 20 for i in range(-16, 17)]
    points = []
    reached = []  # the coordinate's value at each point
    for t in samples:
        try:
            points.append((values.number(x_expr, {coordinate: t}), values.number(y_expr, {coordinate: t})))
        except (TypeError, ValueError):
            continue
        reached.append(t)
    if len(points) < 2:
        raise ValueError("no path")
    span = max(
        max(p[0] for p in points) - min(p[0] for p in points),
        max(p[1] for p in points) - min(p[1] for p in points),
    )
    scale = 5.0 / span if span > 0 else 1.0
    points = [(x * scale, y * scale) for x, y in points]
    pivot = body.angle is not None and not [c for c in model.constraints if c.kind is ConstraintKind.SURFACE]
    # The body is drawn two thirds of the way along its path.
    figure.placed[coordinate] = reached[len(points) * 2 // 3]
    if pivot:
        figure.canvas.polyline(points, width=0.03)
        figure.canvas.ground((-1.0, 0.0), (1.0, 0.0), below=False)
        here = points[len(points) * 2 // 3]
        far = (here[0] * 2, here[1] * 2)
        figure.canvas.line((0.0, 0.0), far, width=0.35, color="#8aa9cf")
        figure.canvas.circle((0.0, 0.0), 0.1, fill="#1b1b1b")
        figure.canvas.text((far[0] + 0.5, far[1]), body_label(body, model), anchor="start")
        figure.say(f"A rigid body {body_label(body, model)} swings about a fixed pivot at its end.")
        return
    figure.canvas.polyline(points, width=0.07)
    turning = ""
    if spin is not None:  # a rotating frame: the axis of rotation, with its rate
        top = max(p[1] for p in points) + 1.0
        bottom = min(p[1] for p in points) - 0.5
        figure.canvas.line((0.0, bottom), (0.0, top), dashed=True, width=0.04)
        figure.canvas.arc((0.0, top - 0.3), 0.5, math.radians(200), math.radians(340))
        rates = _other_symbols(spin, body, model)
        if rates:
            figure.canvas.text((0.9, top - 0.2), symbol_label(rates[0].name), anchor="start")
        turning = "The curve turns about the vertical axis drawn dashed" + (
            f" at the rate {symbol_label(rates[0].name)}." if rates else "."
        )
    here = points[len(points) * 2 // 3]
    radius = 0.45
    figure.canvas.circle((here[0], here[1] + radius), radius, fill=FILLS[0])
    figure.canvas.text(
        (here[0] + radius + 0.2, here[1] + radius * 2 + 0.2), body_label(body, model), anchor="start"
    )
    figure.say(f"{body_label(body, model)} moves along the curve drawn (a wire or a surface).")
    if turning:  # said after the curve it refers to
        figure.say(turning)


def _wedge_roles(surface: Constraint, model: Model) -> tuple[Body, Body]:
    """(block, wedge): the wedge is the one that also rests on another surface (the floor)."""
    first, second = _bodies_in(surface.gap, model)
    others = [c for c in model.constraints if c is not surface and c.kind is ConstraintKind.SURFACE]
    on_floor = {b.name for c in others for b in _bodies_in(c.gap, model)}
    return (first, second) if second.name in on_floor else (second, first)
