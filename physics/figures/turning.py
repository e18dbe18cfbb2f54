"""A rotating frame's element drawn with the body that turns in it: a bob on a string sweeping a cone
(a conical pendulum), a body on a curve turning about the vertical axis (a bead on a spinning hoop),
or the axis of the curve a body on a slope follows (a car on a banked road)."""

from __future__ import annotations

import sympy

from physics.engine.model import AuthoredElement, ConstraintKind, Model
from physics.figures.figure import Figure, Values, body_label
from physics.figures.geometry import bodies_in, is_linear, of_kind
from physics.figures.path import draw_path
from physics.figures.pendulum import draw_pendulum
from physics.figures.slope import Slope
from physics.wording import symbol_label

AXIS_GAP = 1.8  # from the body to the axis drawn beside it: the true radius is far larger


def from_elements(
    figure: Figure, model: Model, values: Values, elements: tuple[AuthoredElement, ...]
) -> bool:
    """False unless one body turns with the frame, held by a string or moving on one coordinate."""
    frame = of_kind(elements, "rotating")[0]
    if len(frame.fields["bodies"]) != 1:
        return False
    body = model.body(str(frame.fields["bodies"][0]))
    strings = [
        c
        for c in model.constraints
        if c.kind is ConstraintKind.STRING and body in bodies_in(c.gap, model) and not is_linear(c.gap, model)
    ]
    if strings:
        draw_pendulum(figure, model, body, strings[0], values)
        return True
    if len(model.coordinates) != 1:
        return False
    spin = next(p for p in model.potentials if p.name == frame.potentials[0])
    draw_path(figure, model, body, values, spin=spin)
    return True


def draw_curve_axis(
    figure: Figure, model: Model, values: Values, slope: Slope, frame: AuthoredElement, at: object
) -> None:
    """The vertical axis the slope's body turns about, dashed beside the slope on the side of the
    curve's centre, with the distance to it labelled (`at`, the slope's place, says it) and not to scale."""
    body = model.body(str(frame.fields["bodies"][0]))
    base = slope.bases[body.name]
    x_expr = dict(body.position).get("x", sympy.Integer(0))
    outward = values.number(x_expr.subs({c.symbol: 0 for c in model.coordinates})) >= 0
    top = max(base[1], slope.upper[1] if slope.upper is not None else 0.0) + 1.0
    x = min(0.0, base[0]) - AXIS_GAP if outward else max(base[0], (slope.upper or base)[0]) + AXIS_GAP
    canvas = figure.canvas
    below = -0.7  # the distance to the axis is marked under the ground, as a drawing's dimension is
    canvas.line((x, below), (x, top), dashed=True, width=0.04)
    canvas.turning((x, top - 0.3), 0.5)
    radius = dict(at).get("x") if isinstance(at, dict) else None
    label = symbol_label(str(radius)) if isinstance(radius, str) and radius.isidentifier() else ""
    canvas.line((base[0], base[1]), (base[0], below), dashed=True, width=0.02)
    canvas.line((x, below), (base[0], below), width=0.02)
    for end in (x, base[0]):
        canvas.line((end, below - 0.12), (end, below + 0.12), width=0.02)
    if label:
        canvas.text(((x + base[0]) / 2, below - 0.35), label, size=0.36)
        figure.unscaled.append(f"the distance {label} to the axis")
    figure.say(
        f"{body_label(body, model)} goes round a curve about the vertical axis drawn dashed"
        + (f", a distance {label} away." if label else ".")
    )
