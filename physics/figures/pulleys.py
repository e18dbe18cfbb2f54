"""Strings over fixed pulleys: an Atwood machine (with a massive pulley, or a second light pulley
carrying two bodies, or a string under a light movable pulley) and a string from a body on a slope or table over its edge to a hanging body."""

from __future__ import annotations

from physics.engine.model import AuthoredElement, Body, Model
from physics.figures.figure import BLOCK, SLOPE, Figure, Values, body_label
from physics.figures.geometry import of_kind
from physics.figures.shapes import draw_block, hanging_block
from physics.figures.slope import Slope
from physics.figures.svg import FILLS


def draw_pulley_to_hanging(
    figure: Figure,
    model: Model,
    slope: Slope,
    on_slope: Body,
    hanging: Body,
    *,
    left: bool = False,
    movable: bool = False,
    wheel: Body | None = None,
) -> None:
    """A pulley at the slope's upper end (or a table's edge); the string runs along it, then down to the
    hanging body, or (`movable`) down under a light movable pulley that carries it and up to a support.
    `wheel`: the pulley is a body of its own (it has inertia), drawn filled and labelled."""
    radius = 0.4 if wheel is None else 0.6
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
    canvas.circle(centre, radius, fill="#ffffff" if wheel is None else FILLS[2])
    canvas.circle(centre, 0.06, fill="#1b1b1b")
    if wheel is not None:
        canvas.text((centre[0], centre[1] - 0.3), body_label(wheel, model), size=0.3)
    side = radius if tx >= 0 else -radius
    edge = "top" if slope.upper is not None else "edge"
    pulley = "a pulley" if wheel is None else f"a pulley, {body_label(wheel, model)},"
    if movable:
        _under_movable_pulley(
            figure, model, (centre[0] + side, centre[1]), 1.0 if side > 0 else -1.0, hanging
        )
        figure.say(
            f"A string from {body_label(on_slope, model)} runs over {pulley} at the {edge}, down under a "
            f"light movable pulley carrying {body_label(hanging, model)}, and up to a fixed support."
        )
        return
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
        f"A string from {body_label(on_slope, model)} runs over {pulley} at the {edge} to "
        f"{body_label(hanging, model)}, which hangs."
    )


def draw_table_to_hanging(
    figure: Figure, model: Model, on_table: Body, hanging: Body, wheel: Body | None, *, left: bool
) -> None:
    """A body that slides at one height (a table's top, written by hand without a surface), its string
    over a pulley at the table's edge, on the `left` or the right, down to a hanging body."""
    figure.canvas.ground((0.0, 0.0), (SLOPE, 0.0))
    base = (SLOPE * (0.55 if left else 0.45), 0.0)
    draw_block(figure, base, (1.0, 0.0), body_label(on_table, model), FILLS[0])
    figure.say(f"A table with {body_label(on_table, model)} on it.")
    table = Slope(None, (1.0, 0.0), (0.0, 1.0), {on_table.name: base})
    draw_pulley_to_hanging(figure, model, table, on_table, hanging, left=left, wheel=wheel)


def _under_movable_pulley(
    figure: Figure, model: Model, start: tuple[float, float], way: float, carried: Body
) -> None:
    """From `start` (where the string leaves the fixed pulley) down under a movable pulley, `way` to the
    right (1) or left (-1), and up to a support level with the start; the pulley carries `carried`."""
    canvas = figure.canvas
    radius = 0.4
    lower = (start[0] + way * radius, start[1] - 2.2)
    far = lower[0] + way * radius
    support = start[1] + 0.6
    canvas.line(start, (start[0], lower[1]), width=0.04)
    canvas.line((far, lower[1]), (far, support), width=0.04)
    canvas.ground((far - 0.5, support), (far + 0.5, support), below=False)
    hanging_block(figure, lower, carried, model, FILLS[1])
    canvas.circle(lower, radius, fill="#ffffff")
    canvas.circle(lower, 0.06, fill="#1b1b1b")


def draw_double_atwood(figure: Figure, model: Model, hanging: list[Body]) -> None:
    """One body on one side of a fixed pulley; on the other, a pulley carrying the other two."""
    canvas = figure.canvas
    canvas.ground((-1.5, 1.6), (1.5, 1.6), below=False)
    canvas.line((0.0, 1.6), (0.0, 0.0), width=0.08)
    canvas.circle((0.0, 0.0), 1.0, fill="#ffffff")
    single, *pair = sorted(hanging, key=lambda b: b.name)
    hanging_block(figure, (-1.0, 0.0), single, model, FILLS[0])
    lower = (1.0, -2.5)
    canvas.line((1.0, 0.0), (1.0, lower[1] + 0.6), width=0.04)
    canvas.circle(lower, 0.6, fill="#ffffff")
    for side, body, fill in ((-0.6, pair[0], FILLS[1]), (0.6, pair[1], FILLS[2])):
        hanging_block(figure, (lower[0] + side, lower[1]), body, model, fill)
    figure.say(
        f"{body_label(single, model)} hangs on one side of a fixed pulley; on the other hangs a light pulley "
        f"carrying {body_label(pair[0], model)} and {body_label(pair[1], model)}."
    )


def draw_movable_pulley(figure: Figure, model: Model, single: Body, carried: Body) -> None:
    """One body on one side of a fixed pulley; on the other the string runs down under a light movable
    pulley, which carries the other body, and up to the ceiling."""
    canvas = figure.canvas
    canvas.ground((-1.5, 1.6), (2.8, 1.6), below=False)
    canvas.line((0.0, 1.6), (0.0, 0.0), width=0.08)
    canvas.circle((0.0, 0.0), 1.0, fill="#ffffff")
    hanging_block(figure, (-1.0, 0.0), single, model, FILLS[0])
    lower, radius = (1.6, -2.0), 0.6
    canvas.line((1.0, 0.0), (1.0, lower[1]), width=0.04)
    canvas.line((lower[0] + radius, lower[1]), (lower[0] + radius, 1.6), width=0.04)
    hanging_block(figure, lower, carried, model, FILLS[1])
    canvas.circle(lower, radius, fill="#ffffff")
    canvas.circle(lower, 0.06, fill="#1b1b1b")
    figure.say(
        f"{body_label(single, model)} hangs on one side of a fixed pulley; on the other the string runs down "
        f"under a light movable pulley carrying {body_label(carried, model)}, and up to the ceiling."
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


def from_elements(
    figure: Figure, model: Model, values: Values, elements: tuple[AuthoredElement, ...]
) -> bool:
    """One pulley element whose ends hang: an Atwood machine (with the pulley's wheel drawn when it has
    inertia), or one end running under a movable pulley that carries a body. False for other strings
    (those over a slope's edge are drawn with the slope)."""
    pulleys = of_kind(elements, "pulley")
    if len(pulleys) != 1 or any(end.get("pulls") != "up" for end in pulleys[0].fields["ends"]):
        return False
    ends = pulleys[0].fields["ends"]
    free = [model.body(str(end["body"])) for end in ends if "body" in end]
    carried = [model.body(str(end["under"])) for end in ends if "under" in end]
    if len(free) == 1 and len(carried) == 1:
        draw_movable_pulley(figure, model, free[0], carried[0])
        return True
    if len(free) != 2:
        return False
    wheel = model.body(pulleys[0].bodies[0]) if pulleys[0].bodies else None
    draw_atwood(figure, model, free[0], free[1], wheel)
    return True
