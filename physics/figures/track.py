"""One body on a curved fixed track, from where the problem starts it (its state) to where a quantity
asks about it (`at`): that stretch of track drawn to scale, the body at its start; a circular track
shows its centre and its radius, labelled."""

from __future__ import annotations

import math
from dataclasses import dataclass

import sympy

from physics.engine.model import Body, Constraint, ConstraintKind, Model
from physics.figures.figure import Figure, Values, body_label
from physics.figures.geometry import is_linear
from physics.figures.svg import FILLS, Point
from physics.wording import symbol_label

SPAN = 5.0  # the track's larger extent, in figure units
SIZE = 0.8  # the block's side, about


@dataclass(frozen=True)
class Track:
    body: Body
    surface: Constraint
    start: sympy.Expr  # the coordinate where the body starts
    end: sympy.Expr  # where a quantity asks about it


def track_of(model: Model) -> Track | None:
    if len(model.bodies) != 1 or len(model.coordinates) != 1 or model.potentials:
        return None
    coordinate = model.coordinates[0]
    surfaces = [
        c for c in model.constraints if c.kind is ConstraintKind.SURFACE and not is_linear(c.gap, model)
    ]
    start = dict(model.state).get(coordinate.symbol)
    ends = [dict(q.at)[coordinate.name] for q in model.quantities if coordinate.name in dict(q.at)]
    if len(surfaces) != 1 or start is None or not ends or ends[0] == start:
        return None
    return Track(model.bodies[0], surfaces[0], start, ends[0])


def draw_track(figure: Figure, model: Model, track: Track, values: Values) -> None:
    canvas = figure.canvas
    coordinate = model.coordinates[0].symbol
    position = dict(track.body.position)
    x_expr, y_expr = position.get("x", sympy.Integer(0)), position.get("y", sympy.Integer(0))
    first, last = values.number(track.start), values.number(track.end)
    raw = [
        (values.number(x_expr, {coordinate: q}), values.number(y_expr, {coordinate: q}))
        for q in (first + (last - first) * i / 40 for i in range(41))
    ]
    span = max(
        max(p[0] for p in raw) - min(p[0] for p in raw), max(p[1] for p in raw) - min(p[1] for p in raw)
    )
    scale = SPAN / span if span > 0 else 1.0
    path = [(x * scale, y * scale) for x, y in raw]
    radii = [math.hypot(x, y) for x, y in path]
    circular = max(radii) - min(radii) < 1e-6 * max(radii) and max(radii) > 0
    begin, finish = path[0], path[-1]
    corners = [(begin[0], finish[1]), (finish[0], begin[1])]
    # The solid side of the track: outside a circle, else below the curve.
    corner = max(corners, key=lambda p: math.hypot(*p)) if circular else min(corners, key=lambda p: p[1])
    canvas.polygon([*path, corner], fill="#eeeeee", width=0.02)
    canvas.polyline(path, width=0.07)
    radius_symbols = sorted(
        (s for s in track.surface.gap.free_symbols if s in set(model.parameters)), key=lambda s: s.name
    )
    if circular:
        centre: Point = (0.0, 0.0)
        canvas.circle(centre, 0.07, fill="#1b1b1b")
        canvas.line(centre, finish, dashed=True, width=0.03)
        canvas.line(centre, begin, dashed=True, width=0.03)
        if radius_symbols:
            middle = (finish[0] / 2, finish[1] / 2)
            across = (-finish[1] / radii[-1], finish[0] / radii[-1])  # beside the radius line
            side = 1 if across[0] * -begin[0] + across[1] * -begin[1] >= 0 else -1  # away from the block
            canvas.text(
                (middle[0] + side * across[0] * 0.35, middle[1] + side * across[1] * 0.35),
                symbol_label(radius_symbols[0].name),
            )
    # The block at its start, its face a chord of the track (a flat face touches a curve at its ends).
    ahead = next((p for p in path if math.dist(p, begin) >= SIZE), finish)
    length = math.dist(ahead, begin) or 1.0
    tangent = ((ahead[0] - begin[0]) / length, (ahead[1] - begin[1]) / length)
    inward = (-tangent[1], tangent[0])
    if inward[0] * (corner[0] - begin[0]) + inward[1] * (corner[1] - begin[1]) > 0:
        inward = (-inward[0], -inward[1])
    canvas.polygon(
        [begin, ahead, (ahead[0] + inward[0] * length, ahead[1] + inward[1] * length),
         (begin[0] + inward[0] * length, begin[1] + inward[1] * length)],
        fill=FILLS[0],
    )  # fmt: skip
    centre_block = (
        (begin[0] + ahead[0]) / 2 + inward[0] * length / 2,
        (begin[1] + ahead[1]) / 2 + inward[1] * length / 2,
    )
    label = body_label(track.body, model)
    canvas.text(centre_block, label, size=0.36)
    turned = abs(math.atan2(finish[1], finish[0]) - math.atan2(begin[1], begin[0]))
    shape = "track"
    if circular:
        shape = "quarter-circle track" if abs(turned - math.pi / 2) < 1e-6 else "circular track"
    figure.say(
        f"A {shape}"
        + (f" of radius {symbol_label(radius_symbols[0].name)}" if circular and radius_symbols else "")
        + f", with {label} at its {'top' if begin[1] > finish[1] else 'start'}"
        + (" (its centre and radius dashed)." if circular else ".")
    )
