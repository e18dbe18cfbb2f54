"""A string wound on a turning body: a wheel on a fixed axle holding a weight, a yo-yo falling from
its string."""

from __future__ import annotations

from physics.engine.model import Body, ConstraintKind, Model
from physics.figures.figure import Figure, Values, body_label
from physics.figures.geometry import coordinate_label, moving_coordinate
from physics.figures.shapes import hanging_block, mark_coordinate
from physics.figures.svg import FILLS
from physics.wording import symbol_label


def draw_wheel_and_weight(figure: Figure, model: Model, wheel: Body, weight: Body) -> None:
    canvas = figure.canvas
    radius = 1.4
    canvas.ground((-2.0, 2.2), (1.0, 2.2), below=False)
    canvas.line((-0.5, 2.2), (0.0, 0.0), width=0.1)
    canvas.circle((0.0, 0.0), radius, fill=FILLS[0])
    canvas.circle((0.0, 0.0), 0.1, fill="#1b1b1b")
    canvas.text((-0.4, -0.5), body_label(wheel, model))
    hanging_block(figure, (radius, 0.0), weight, model, FILLS[1])
    figure.say(
        f"A string wound on a wheel {body_label(wheel, model)} turning on a fixed axle holds "
        f"{body_label(weight, model)}, which hangs."
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
