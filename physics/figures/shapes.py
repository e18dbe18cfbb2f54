"""Small drawn parts shared by the pictures: a block on a surface, a round body, an angle's arc, a
hanging block, a coordinate's arrow."""

from __future__ import annotations

import math

import sympy

from physics.engine.model import Body, Model
from physics.figures.figure import BLOCK, Figure, body_label
from physics.figures.svg import Point
from physics.wording import symbol_label


def draw_block(
    figure: Figure, base: Point, tangent: Point, label: str, fill: str, size: float = BLOCK
) -> Point:
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


def angle_mark(figure: Figure, vertex: Point, start: float, end: float, symbol: sympy.Symbol | None) -> None:
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


def circle_body(figure: Figure, base: Point, normal: Point, body: Body, label: str, fill: str) -> Point:
    radius = 0.55
    centre = (base[0] + normal[0] * radius, base[1] + normal[1] * radius)
    hollow = "hoop" in body.name.lower() or "ring" in body.name.lower()
    figure.canvas.circle(centre, radius, fill="none" if hollow else fill, width=0.12 if hollow else 0.05)
    figure.canvas.line(centre, (centre[0] + radius * 0.7, centre[1]), width=0.03)  # shows it can turn
    figure.canvas.text((centre[0], centre[1] + radius + 0.35), label, size=0.36)
    return centre


def square(centre: Point, size: float) -> list[Point]:
    h = size / 2
    return [
        (centre[0] - h, centre[1] - h),
        (centre[0] + h, centre[1] - h),
        (centre[0] + h, centre[1] + h),
        (centre[0] - h, centre[1] + h),
    ]


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


def hanging_block(figure: Figure, top: Point, body: Body, model: Model, fill: str) -> None:
    """A string from `top` down to a block hanging 2.5 below it."""
    x, y = top
    depth = 2.5
    figure.canvas.line(top, (x, y - depth + BLOCK / 2), width=0.04)
    figure.canvas.polygon(square((x, y - depth), BLOCK), fill=fill)
    figure.canvas.text((x, y - depth), body_label(body, model))


def draw_bullet(figure: Figure, at: Point, heading: int, mass: sympy.Expr, label_dy: float) -> None:
    """A bullet centred at `at` flying along x (`heading` +1 to the right, -1 to the left), its arrow
    ahead of it, labelled with its mass symbol `label_dy` above (or below) it."""
    x, y = at
    h = heading
    figure.canvas.polygon(
        [(x - 0.3 * h, y - 0.1), (x + 0.2 * h, y - 0.1), (x + 0.35 * h, y), (x + 0.2 * h, y + 0.1),
         (x - 0.3 * h, y + 0.1)],
        fill="#888888",
    )  # fmt: skip
    figure.canvas.arrow((x + 0.5 * h, y), (x + 1.8 * h, y) if h > 0 else (x - 1.6, y))
    if isinstance(mass, sympy.Symbol):
        figure.canvas.text((x, y + label_dy), symbol_label(mass.name))
