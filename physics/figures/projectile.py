"""A body launched under gravity alone: the launch point, the ground, the launch velocity at its angle
and the path, dashed and drawn to scale from the student's numbers, to where it lands."""

from __future__ import annotations

import math
from dataclasses import dataclass

import sympy

from physics.engine.model import Body, Model, QuantityKind
from physics.figures.figure import Figure, Values, body_label
from physics.figures.geometry import angle_symbol_of
from physics.figures.shapes import angle_mark
from physics.figures.svg import FILLS
from physics.wording import symbol_label

SPAN = 7.0  # the larger of the drawn range and height, in figure units
ARROW = 2.4  # the launch velocity's drawn length


@dataclass(frozen=True)
class Launch:
    body: Body
    height: sympy.Expr  # of the launch point, in the model's y
    landing: sympy.Expr  # the ground's y
    vx: sympy.Expr
    vy: sympy.Expr
    slope: sympy.Expr | None = None  # the ground is instead the line through the launch point at this angle


def launch_of(model: Model) -> Launch | None:
    """A single free body in the plane under gravity, launched from the state: a projectile."""
    if (
        model.gravity is None
        or len(model.bodies) != 1
        or model.constraints
        or model.potentials
        or model.forces
    ):
        return None
    body = model.bodies[0]
    position = dict(body.position)
    coordinates = {c.symbol: c for c in model.coordinates}
    axes = {axis: coordinates.get(position.get(axis)) for axis in ("x", "y")}
    state = dict(model.state)
    if any(c is None or c.velocity not in state for c in axes.values()):
        return None
    x, y = axes["x"], axes["y"]
    assert x is not None and y is not None
    height = state.get(y.symbol, sympy.Integer(0))
    levels = [
        q.level for q in model.quantities if q.kind in (QuantityKind.TIME_OF_FLIGHT, QuantityKind.RANGE)
    ]
    landing = next((level for level in levels if level is not None), height)
    slope = next((q.slope for q in model.quantities if q.slope is not None), None)
    return Launch(body, height, landing, state[x.velocity], state[y.velocity], slope)


def draw_projectile(figure: Figure, model: Model, launch: Launch, values: Values) -> None:
    canvas = figure.canvas
    g = values.number(model.gravity)
    vx, vy = values.number(launch.vx), values.number(launch.vy)
    drop = values.number(launch.height) - values.number(launch.landing)  # launch above the ground
    # The time to land: y(t) = drop + vy t - g t^2 / 2 = 0, the later root; on a slope through the launch
    # point, vy t - g t^2 / 2 = vx t tan(slope).
    rise = math.tan(values.number(launch.slope)) if launch.slope is not None else 0.0
    flight = (vy + math.sqrt(max(vy * vy + 2 * g * drop, 0.0))) / g
    if launch.slope is not None:
        flight = max(2 * (vy - vx * rise) / g, 0.0)
    top = drop + max(vy, 0.0) ** 2 / (2 * g)
    scale = SPAN / max(abs(vx) * flight, top, abs(vx * flight * rise), 1e-9)
    steps = 40
    path = [
        (
            vx * flight * i / steps * scale,
            (drop + vy * flight * i / steps - g * (flight * i / steps) ** 2 / 2) * scale,
        )
        for i in range(steps + 1)
    ]
    start = (0.0, drop * scale)
    land_x = path[-1][0]
    left, right = min(0.0, land_x) - 1.2, max(0.0, land_x) + 1.2
    canvas.ground((left, left * rise), (right, right * rise))
    height_symbols = sorted(launch.height.free_symbols & set(model.parameters), key=lambda s: s.name)
    if drop * scale > 0.05:  # a cliff (or tower) under the launch point, its height labelled
        canvas.polygon([(left, 0.0), (left, start[1]), (0.4, start[1]), (0.4, 0.0)], fill="#eeeeee")
        canvas.line((left + 0.1, start[1]), (0.4, start[1]), width=0.07)
        if height_symbols:
            canvas.text(((left + 0.4) / 2, start[1] / 2), symbol_label(height_symbols[0].name))
        canvas.line(start, (start[0] + 2.0, start[1]), dashed=True, width=0.03)  # the angle's horizontal
    canvas.polyline(path, width=0.04, dashed=True)
    land_y = land_x * rise
    canvas.line((land_x, land_y - 0.15), (land_x, land_y + 0.15), width=0.05)  # where it lands
    angle = math.atan2(vy, vx)
    tip = (start[0] + ARROW * math.cos(angle), start[1] + ARROW * math.sin(angle))
    canvas.arrow(start, tip, width=0.06)
    speed = sorted(
        (
            s
            for s in (launch.vx.free_symbols | launch.vy.free_symbols) - values.angles
            if s in set(model.parameters)
        ),
        key=lambda s: s.name,
    )
    if speed:
        side = (-math.sin(angle), math.cos(angle))
        canvas.text((tip[0] + 0.45 * side[0] + 0.2, tip[1] + 0.45 * side[1]), symbol_label(speed[0].name))
    symbol = angle_symbol_of(launch.vx + launch.vy, values)
    angle_mark(figure, start, 0.0, angle, symbol)
    canvas.circle(start, 0.25, fill=FILLS[0])
    label = body_label(launch.body, model)
    canvas.text((start[0] - 0.5, start[1] + 0.45), label, anchor="end")
    where = "from a height " + symbol_label(height_symbols[0].name) if drop > 0 and height_symbols else ""
    where = where or ("from above the ground" if drop > 0 else "from the ground")
    ground = "the ground"
    if launch.slope is not None:
        where, ground = "from a point on a slope", "the slope"
    figure.say(
        f"A ball {label} launched {where}"
        + (f" at speed {symbol_label(speed[0].name)}" if speed else "")
        + (f" at an angle {symbol_label(symbol.name)} above the horizontal" if symbol is not None else "")
        + f"; its path (dashed) lands on {ground}."
    )
