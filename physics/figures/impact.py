"""An impact: two bodies about to meet (or to be pushed apart), their velocities before labelled, a
fixed floor or wall hatched where the body meets it."""

from __future__ import annotations

import math

import sympy

from physics.engine.impact import velocities_before
from physics.engine.model import Model
from physics.figures.figure import BLOCK, Figure, Values, body_label, symbol_label
from physics.figures.shapes import square
from physics.figures.svg import FILLS


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
            canvas.polygon(square(centre, BLOCK), fill=FILLS[index])
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
