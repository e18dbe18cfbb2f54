"""One body on one coordinate, drawn along the curve its centre follows; and the last resort, the
bodies side by side."""

from __future__ import annotations

import sympy

from physics.engine import embedding
from physics.engine.model import AXES, Body, ConstraintKind, Model, PairPotential
from physics.figures.figure import BLOCK, Figure, NotDrawable, NotNumeric, Values, body_label
from physics.figures.geometry import other_symbols
from physics.figures.shapes import draw_bullet, square
from physics.figures.svg import FILLS
from physics.wording import symbol_label


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
        except NotNumeric:
            continue
        reached.append(t)
    if len(points) < 2:
        raise NotDrawable(f"{body.name}'s path: fewer than two of its points evaluate")
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
        said = f"A rigid body {body_label(body, model)} swings about a fixed pivot at its end"
        figure.say(said + _struck(figure, model, body, values, scale) + ".")
        return
    figure.canvas.polyline(points, width=0.07)
    turning = ""
    if spin is not None:  # a rotating frame: the axis of rotation, with its rate
        top = max(p[1] for p in points) + 1.0
        bottom = min(p[1] for p in points) - 0.5
        figure.canvas.line((0.0, bottom), (0.0, top), dashed=True, width=0.04)
        figure.canvas.turning((0.0, top - 0.3), 0.5)
        rates = other_symbols(spin, body, model)
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


def draw_row(figure: Figure, model: Model) -> None:
    """Any other model: its bodies side by side, labelled (the statement says how they move)."""
    for index, body in enumerate(model.bodies):
        centre = (index * 2.0, 0.0)
        figure.canvas.polygon(square(centre, BLOCK), fill=FILLS[index % len(FILLS)])
        label = body_label(body, model)
        if len(label) <= 3:
            figure.canvas.text(centre, label)
        else:  # a name does not fit inside the block: beneath it
            figure.canvas.text((centre[0], centre[1] - BLOCK / 2 - 0.35), label, size=0.32)
    figure.say("The bodies of the problem: " + ", ".join(body_label(b, model) for b in model.bodies) + ".")


def _struck(figure: Figure, model: Model, body: Body, values: Values, scale: float) -> str:
    """The bullet of a collision with the body, flying at the point it strikes when the body is where
    it is struck (drawn dashed there); the words for it, or "" when nothing strikes the body."""
    hit = model.collision
    if hit is None or hit.target != body.name:
        return ""
    coordinate = model.coordinates[0]
    at = values.number(dict(hit.at).get(coordinate.name, sympy.Integer(0)))
    point = embedding.struck(model)
    x, y = (values.number(point.get(a, sympy.Integer(0)), {coordinate.symbol: at}) * scale for a in AXES)
    heading = 1 if values.number(dict(hit.direction).get("x", sympy.Integer(0))) >= 0 else -1
    figure.canvas.line((0.0, 0.0), (x, y), dashed=True, width=0.03)
    draw_bullet(figure, (x - 3.0 * heading, y), heading, hit.projectile_mass, 0.45)
    mass = hit.projectile_mass
    named = f" {symbol_label(mass.name)}" if isinstance(mass, sympy.Symbol) else ""
    return f"; a bullet{named} flies into it horizontally where it hangs (dashed), and sticks"
