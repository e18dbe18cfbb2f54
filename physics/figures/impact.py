"""An impact: two bodies about to meet (or to be pushed apart), their velocities before labelled, a
fixed floor or wall hatched where the body meets it, or the incline (an element) at whose foot the
body that is hit rests."""

from __future__ import annotations

import math

import sympy

from physics.engine import tidy
from physics.engine.impact import velocities_before
from physics.engine.model import AXES, AuthoredElement, Body, Model
from physics.figures.figure import BLOCK, Figure, Values, body_label
from physics.figures.geometry import element_body, linear_surface, of_kind, written_symbol
from physics.figures.shapes import angle_mark, draw_block, square
from physics.figures.svg import FILLS
from physics.wording import symbol_label


def draw_impact(figure: Figure, model: Model, values: Values) -> None:
    """Two bodies about to meet (or, for an explosion, about to part), each with its velocity before
    labelled; in the plane, the impact's normal dashed through the second body."""
    hit = model.impact
    assert hit is not None
    if (ramp := _incline_at_foot(model)) is not None:
        _draw_hit_at_incline_foot(figure, model, values, ramp)
        return
    canvas = figure.canvas
    plane = any(len(model.body(name).position) > 1 for name in hit.bodies)
    gap = 3.0 if hit.restitution is not None else 1.2
    before = velocities_before(model)
    speeds: list[str] = []
    # A body against a fixed floor or wall is drawn round, a ball, as are pucks in the plane.
    round_ = plane or hit.fixed is not None
    rods: list[tuple[str, bool]] = []  # each rigid body's label, and whether it turns about a pivot
    for index, name in enumerate(hit.bodies):
        body = model.body(name)
        centre = (index * gap, 0.0)
        if body.angle is not None:  # a rigid body: a rod, struck where the other body meets it
            rods.append((body_label(body, model), _draw_rod(figure, model, body, centre, values)))
            continue
        if round_:
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
        falling = before[name].get("y", sympy.Integer(0)) if velocity == 0 else sympy.Integer(0)
        if velocity != 0:
            canvas.arrow((centre[0], 0.85), (centre[0] + 1.1, 0.85), width=0.04)
            label = symbol_label(velocity.name) if isinstance(velocity, sympy.Symbol) else ""
            canvas.text((centre[0] + 0.55, 1.2), label, size=0.36)
            speeds.append(f"{body_label(body, model)} moving at {label or 'its speed'}")
        elif falling != 0:  # up or down the page, beside the body (a ball dropped on the floor)
            way = 1.0 if values.number(falling) > 0 else -1.0
            canvas.arrow(
                (centre[0] + 0.85, 0.25 - 0.5 * way), (centre[0] + 0.85, 0.25 + 0.5 * way), width=0.04
            )
            label = symbol_label(falling.name) if isinstance(falling, sympy.Symbol) else ""
            if label:
                canvas.text((centre[0] + 1.25, 0.0), label, size=0.36)
            moving = "up" if way > 0 else "down"
            speeds.append(f"{body_label(body, model)} moving {moving}" + (f" at {label}" if label else ""))
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
    for rod, pivoted in rods:
        turning = " turning about a fixed pivot" if pivoted else ""
        figure.say(
            f"{rod} is a rigid body{turning}, drawn as a rod, met at the point where the other body reaches it."
        )


def _draw_rod(figure: Figure, model: Model, body: Body, centre: tuple[float, float], values: Values) -> bool:
    """A rod through the meeting point (at the other body's height), reaching towards the body's centre
    of mass and as far beyond it: a rod struck at its end is drawn from that end; with its pivot, when it
    turns about a fixed one (True)."""
    hit = model.impact
    assert hit is not None
    state = dict(model.state)
    point = dict(dict(hit.points).get(body.name, body.position))
    position = dict(body.position)
    offset = [
        values.number((point.get(a, sympy.Integer(0)) - position.get(a, sympy.Integer(0))).subs(state))
        for a in AXES
    ]
    length = math.hypot(*offset)
    # from the point through the centre; a rod struck at its centre is drawn upright, centred there
    direction = (-offset[0] / length, -offset[1] / length) if length > 1e-9 else (0.0, 1.0)
    half = 1.6
    start = (
        centre[0] - direction[0] * (half if length <= 1e-9 else 0.0),
        -direction[1] * (half if length <= 1e-9 else 0.0),
    )
    end = (start[0] + direction[0] * 2 * half, start[1] + direction[1] * 2 * half)
    figure.canvas.line(start, end, width=0.35, color="#8aa9cf")
    figure.canvas.circle(centre, 0.08, fill="#1b1b1b")  # where it is met
    middle = ((start[0] + end[0]) / 2, (start[1] + end[1]) / 2)
    figure.canvas.text((middle[0] + 0.45, middle[1]), body_label(body, model), anchor="start")
    pivot = _fixed_pivot(model, body, values)
    if pivot is not None and length > 1e-9:  # drawn to the rod's scale, from the struck point
        here = [values.number(point.get(a, sympy.Integer(0)).subs(state)) for a in AXES]
        scale = half / length
        at = (centre[0] + (pivot[0] - here[0]) * scale, centre[1] + (pivot[1] - here[1]) * scale)
        figure.canvas.ground((at[0] - 0.6, at[1]), (at[0] + 0.6, at[1]), below=False)
        figure.canvas.circle(at, 0.1, fill="#1b1b1b")
        return True
    return False


def _fixed_pivot(model: Model, body: Body, values: Values) -> tuple[float, float] | None:
    """The point of a rigid body that stays still as its one coordinate turns it (a pivot), found from
    its motion: c = p + R(θ) b with dc/dq = 0; None when no such point is fixed."""
    assert body.angle is not None
    turning = [c.symbol for c in model.coordinates if body.angle.has(c.symbol)]
    if len(turning) != 1:
        return None
    (q,) = turning
    rate = sympy.diff(body.angle, q)
    position = dict(body.position)
    px, py = (position.get(a, sympy.Integer(0)) for a in AXES)
    if rate == 0:
        return None
    cos, sin = sympy.cos(body.angle), sympy.sin(body.angle)
    dx, dy = sympy.diff(px, q) / rate, sympy.diff(py, q) / rate
    vx, vy = cos * dx + sin * dy, -sin * dx + cos * dy  # R(-θ) dp/dθ
    bx, by = -vy, vx  # the body-frame point that R(θ) turns into -dp/dθ's perpendicular
    cx = tidy.simplify(px + cos * bx - sin * by)
    cy = tidy.simplify(py + sin * bx + cos * by)
    if (cx.free_symbols | cy.free_symbols) & {c.symbol for c in model.coordinates}:
        return None  # it moves: a free body's centre, a rolling body's contact
    state = dict(model.state)
    return values.number(cx.subs(state)), values.number(cy.subs(state))


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


def _incline_at_foot(model: Model) -> AuthoredElement | None:
    """The incline element (rising towards +x, fixed) whose body the other body of a collision hits
    moving along +x: the block is drawn at the incline's foot, which pushes on it during the impact."""
    hit = model.impact
    assert hit is not None
    if hit.fixed is not None or hit.restitution is None or len(hit.bodies) != 2:
        return None
    ramps = [
        element
        for element in of_kind(model.elements, "incline")
        if element.fields.get("direction") == "up" and "wedge" not in element.fields
    ]
    return next((r for r in ramps if element_body(model, r).name == hit.bodies[1]), None)


def _draw_hit_at_incline_foot(figure: Figure, model: Model, values: Values, ramp: AuthoredElement) -> None:
    """The first body on a level track moving towards the second, which rests at the foot of the incline."""
    hit = model.impact
    assert hit is not None
    canvas = figure.canvas
    mover, block = (model.body(name) for name in hit.bodies)
    symbol = written_symbol(model, ramp.fields.get("angle"))
    surface = linear_surface(model.constraint(ramp.name), block, model, values)
    if surface is None:  # an incline's clearance always has a normal
        raise AssertionError(f"{ramp.name}: the contact has no normal")
    across, up = surface.normal
    slope = figure.readable_angle(math.atan2(-across, up), symbol)
    foot, length = (2.5, 0.0), 4.5
    top = (foot[0] + length * math.cos(slope), length * math.sin(slope))
    canvas.polygon([foot, top, (top[0], 0.0)], fill="#eeeeee")
    canvas.ground((-1.2, 0.0), (top[0], 0.0))
    angle_mark(figure, foot, 0.0, slope, symbol)
    tangent = (math.cos(slope), math.sin(slope))
    draw_block(
        figure, (foot[0] + tangent[0] * 0.6, tangent[1] * 0.6), tangent, body_label(block, model), FILLS[1]
    )
    draw_block(figure, (0.0, 0.0), (1.0, 0.0), body_label(mover, model), FILLS[0])
    velocity = velocities_before(model)[mover.name].get("x", sympy.Integer(0))
    speed = symbol_label(velocity.name) if isinstance(velocity, sympy.Symbol) else ""
    canvas.arrow((-0.55, BLOCK + 0.4), (0.75, BLOCK + 0.4), width=0.04)
    canvas.text((0.1, BLOCK + 0.75), speed, size=0.36)
    kind = "a collision" if hit.restitution != 1 else "an elastic collision"
    names = f"{body_label(mover, model)} and {body_label(block, model)}"
    figure.say(
        f"{names} about to meet in {kind}: {body_label(mover, model)} moving at {speed or 'its speed'} "
        f"along a level track, {body_label(block, model)} resting at the foot of a fixed incline"
        + (f" at angle {symbol_label(symbol.name)}" if symbol is not None else "")
        + ", which pushes on it during the impact."
    )
