"""Bodies on one fixed slope or floor (incline, surface and rolling elements): spaced along it, with
the given forces pushing on them and each coefficient of friction beside its body."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import sympy

from physics.engine.model import Body, ForceKind, Model
from physics.figures.figure import BLOCK, SLOPE, Figure, Values, body_label
from physics.figures.geometry import Surface
from physics.figures.shapes import angle_mark, circle_body, draw_block
from physics.figures.svg import FILLS, Point
from physics.wording import symbol_label

_CIRCLE = 0.55  # radius of a round body on a slope
_PUSH = 1.5  # length of a push's arrow


@dataclass
class Slope:
    upper: Point | None  # the slope's upper end (None: a floor)
    tangent: Point  # along the surface, pointing right
    normal: Point  # out of the surface, upwards
    bases: dict[str, Point]  # where each body touches the surface


def drawn_slope(surface: Surface, figure: Figure) -> float:
    """The surface's slope from its normal, at its value where that reads clearly (READABLE_ANGLES)."""
    a, b = surface.normal
    tangent = (b, -a) if b >= 0 else (-b, a)
    slope = math.atan2(tangent[1], tangent[0])
    if abs(slope) < 1e-9:
        return 0.0
    return figure.readable_angle(slope, surface.angle_symbol)


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
    slope = drawn_slope(first, figure)
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
        angle_mark(figure, lower, horizontal, toward_upper, first.angle_symbol)
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
            centre = circle_body(figure, base, normal, body, label, fill)
            reach = _CIRCLE
        else:
            centre = draw_block(figure, base, tangent, label, fill)
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


def _on_drawn_slope(direction: Point, surface: Surface, tangent: Point) -> Point:
    """A direction in the model's axes, turned to keep its angle to the surface on the drawn slope (which
    is steepened or flattened to read clearly)."""
    a, b = surface.normal
    along_model = (b, -a) if b >= 0 else (-b, a)  # as drawn_slope takes it, pointing right
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
