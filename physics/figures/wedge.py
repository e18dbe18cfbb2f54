"""A block on a wedge that slides on the floor, and two inclines meeting at a top."""

from __future__ import annotations

import math

from physics.engine.model import Body, Constraint, ConstraintKind, Model
from physics.figures.figure import Figure, Values, body_label
from physics.figures.geometry import Surface, angle_symbol_of, bodies_in, coordinate_label, moving_coordinate
from physics.figures.shapes import angle_mark, axis_x, draw_block, mark_coordinate
from physics.figures.slope import drawn_slope
from physics.figures.svg import FILLS
from physics.wording import symbol_label


def draw_double_incline(figure: Figure, model: Model, surfaces: list[Surface], string: bool) -> None:
    """Two faces of one block meeting at the top, a body on each, a pulley at the apex."""
    canvas = figure.canvas
    first, second = surfaces
    left_angle, right_angle = (abs(drawn_slope(s, figure)) or math.radians(30) for s in surfaces)
    height = 3.5
    apex = (height / math.tan(left_angle), height)
    left_foot, right_foot = (0.0, 0.0), (apex[0] + height / math.tan(right_angle), 0.0)
    canvas.polygon([left_foot, apex, right_foot], fill="#eeeeee")
    canvas.ground((-0.5, 0.0), (right_foot[0] + 0.5, 0.0))
    angle_mark(figure, left_foot, 0.0, left_angle, first.angle_symbol)
    angle_mark(figure, right_foot, math.pi - right_angle, math.pi, second.angle_symbol)
    spots = []
    for surface, foot, fill in ((first, left_foot, FILLS[0]), (second, right_foot, FILLS[1])):
        base = (foot[0] + (apex[0] - foot[0]) * 0.5, foot[1] + (apex[1] - foot[1]) * 0.5)
        length = math.hypot(apex[0] - foot[0], apex[1] - foot[1])
        tangent = ((apex[0] - foot[0]) / length, (apex[1] - foot[1]) / length)
        centre = draw_block(figure, base, tangent, body_label(surface.body, model), fill)
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


def draw_wedge(
    figure: Figure, model: Model, wedge: Body, block: Body, surface: Constraint, values: Values
) -> None:
    canvas = figure.canvas
    symbol = angle_symbol_of(surface.gap, values)
    angle = values.number(symbol) if symbol is not None else math.radians(30)
    angle = figure.readable_angle(angle, symbol, low=math.radians(12))
    height = 3.2
    base = height / math.tan(angle)
    top, foot, corner = (0.0, height), (base, 0.0), (0.0, 0.0)
    canvas.ground((-2.0, 0.0), (base + 2.0, 0.0))
    canvas.polygon([corner, top, foot], fill=FILLS[0])
    # high up by the vertical face, as the angle's mark fills the foot; beside it, if too narrow there
    name_at = (base * 0.15, height * 0.6) if base * 0.4 >= 1.0 else (-0.45, height * 0.6)
    canvas.text(name_at, body_label(wedge, model))
    tangent = (math.cos(angle), -math.sin(angle))
    along = 0.4
    spot = (top[0] + (foot[0] - top[0]) * along, top[1] + (foot[1] - top[1]) * along)
    draw_block(figure, spot, tangent, body_label(block, model), FILLS[1])
    angle_mark(figure, foot, math.pi - angle, math.pi, symbol)
    # the axis the statement defines, and the coordinates with their positive directions
    axis_x(figure, (-1.4, -0.75))
    wedge_coordinate = moving_coordinate(model, wedge, exclude=())
    if wedge_coordinate is not None:  # beside the wedge: inside, it crowded the name and the angle
        mark_coordinate(figure, (-1.6, 0.4), (-0.35, 0.4), coordinate_label(model, wedge_coordinate))
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


def wedge_roles(surface: Constraint, model: Model) -> tuple[Body, Body]:
    """(block, wedge): the wedge is the one that also rests on another surface (the floor)."""
    first, second = bodies_in(surface.gap, model)
    others = [c for c in model.constraints if c is not surface and c.kind is ConstraintKind.SURFACE]
    on_floor = {b.name for c in others for b in bodies_in(c.gap, model)}
    return (first, second) if second.name in on_floor else (second, first)
