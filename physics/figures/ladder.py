"""A rigid rod held at rest against two fixed surfaces, a floor and a wall: a leaning ladder, drawn at the
student's angle with the floor, the floor and wall hatched on their solid sides."""

from __future__ import annotations

import math
from dataclasses import dataclass

import sympy

from physics.engine.model import Body, Constraint, ConstraintKind, Model, QuantityKind
from physics.figures.figure import Figure, Values, body_label
from physics.figures.geometry import angle_symbol_of
from physics.figures.shapes import angle_mark
from physics.figures.svg import FILLS
from physics.wording import symbol_label

LENGTH = 6.0  # the ladder's drawn length
THICK = 0.24  # the rod's drawn width


@dataclass(frozen=True)
class Leaning:
    body: Body
    floor: Constraint
    wall: Constraint
    side: int  # +1: the ladder stands to the right of the wall


def leaning_of(model: Model) -> Leaning | None:
    """No coordinate, one turning body, one surface in its height (a floor) and one in its x (a wall)."""
    if model.coordinates or len(model.bodies) != 1 or model.bodies[0].angle is None:
        return None
    body = model.bodies[0]
    names = dict(model.cartesian)
    x, y = names.get(f"x_{body.name}"), names.get(f"y_{body.name}")
    if x is None or y is None:
        return None
    surfaces = [c for c in model.constraints if c.kind is ConstraintKind.SURFACE]
    floors = [c for c in surfaces if y in c.gap.free_symbols and x not in c.gap.free_symbols]
    walls = [c for c in surfaces if x in c.gap.free_symbols and y not in c.gap.free_symbols]
    if len(floors) != 1 or len(walls) != 1:
        return None
    away = sympy.diff(walls[0].gap, x)  # the gap grows away from the wall, on the ladder's side
    return Leaning(body, floors[0], walls[0], 1 if away.is_positive else -1)


def draw_ladder(figure: Figure, model: Model, leaning: Leaning, values: Values) -> None:
    canvas = figure.canvas
    body, side = leaning.body, leaning.side
    assert body.angle is not None
    symbol = angle_symbol_of(body.angle, values)
    angle = values.number(body.angle) if not body.angle.free_symbols - set(values.subs) else math.radians(60)
    angle = figure.readable_angle(angle, symbol, low=math.radians(15))
    foot = (side * LENGTH * math.cos(angle), 0.0)
    top = (0.0, LENGTH * math.sin(angle))
    canvas.ground((-side * 0.8, 0.0), (foot[0] + side * 1.8, 0.0))
    canvas.ground((0.0, 0.0), (0.0, top[1] + 0.8), below=side < 0)
    along = (-side * math.cos(angle), math.sin(angle))  # from the foot up to the top
    out = (along[1] * side, -along[0] * side)  # across the rod, away from the corner
    half = THICK / 2
    canvas.polygon(
        [
            (foot[0] - out[0] * half, foot[1] - out[1] * half),
            (foot[0] + out[0] * half, foot[1] + out[1] * half),
            (top[0] + out[0] * half, top[1] + out[1] * half),
            (top[0] - out[0] * half, top[1] - out[1] * half),
        ],
        fill=FILLS[1],
        width=0.04,
    )
    middle = ((foot[0] + top[0]) / 2, (foot[1] + top[1]) / 2)
    canvas.circle(middle, 0.07, fill="#1b1b1b")  # its centre, where the weight acts
    label = body_label(body, model)
    canvas.text((middle[0] - out[0] * 0.55, middle[1] - out[1] * 0.55), label)
    lengths = sorted(
        (s for s in leaning.floor.gap.free_symbols if s in set(model.parameters) and s != symbol),
        key=lambda s: s.name,
    )
    if lengths:
        spot = (
            foot[0] + along[0] * LENGTH * 0.7 + out[0] * 0.5,
            foot[1] + along[1] * LENGTH * 0.7 + out[1] * 0.5,
        )
        canvas.text(spot, symbol_label(lengths[0].name))
    angle_mark(figure, foot, math.pi / 2 + side * math.pi / 2, math.atan2(along[1], along[0]), symbol)
    coefficients = [
        q.coefficient
        for q in model.quantities
        if q.kind is QuantityKind.SLIPPING and q.coefficient is not None
    ] + [f.coefficient for f in model.frictions]
    rough = next((c for c in coefficients if isinstance(c, sympy.Symbol)), None)
    if rough is not None:
        canvas.text((foot[0] + side * 0.9, 0.35), symbol_label(rough.name), size=0.36)
    figure.say(
        f"A ladder {label}"
        + (f" of length {symbol_label(lengths[0].name)}" if lengths else "")
        + " leans against a vertical wall, its foot on the floor"
        + (f" (rough, {symbol_label(rough.name)})" if rough is not None else "")
        + (f", at an angle {symbol_label(symbol.name)} with the floor." if symbol is not None else ".")
    )
