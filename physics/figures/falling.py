"""Bodies falling (or rising) under gravity and drag, each on its own vertical line: a ball with its
mass inside and its name beneath, an arrow of its velocity at the model's state, and its drag force
(bv, cv²) against that velocity, named as its free-body diagram names it."""

from __future__ import annotations

import sympy

from physics.engine.model import Body, ForceKind, Model
from physics.figures.figure import Figure, Values, body_label
from physics.figures.loads import applied_forces
from physics.figures.svg import FILLS
from physics.wording import symbol_label

RADIUS = 0.45
APART = 3.0  # between the bodies' lines
ARROW = 1.3


def falling_of(model: Model) -> list[Body] | None:
    """The bodies, if every one moves only up and down, under gravity and drag and nothing else."""
    if model.gravity is None or model.constraints or model.potentials or model.collision is not None:
        return None
    if model.impact is not None or not model.bodies:
        return None
    if any([axis for axis, _ in body.position] != ["y"] or body.angle is not None for body in model.bodies):
        return None
    drag = {f.body for f in model.forces if f.kind is not ForceKind.APPLIED}
    if drag != {body.name for body in model.bodies} or len(drag) != len(model.forces):
        return None
    return list(model.bodies)


def _speed_label(body: Body, model: Model) -> str:
    """The symbol of the body's speed in the state (y1_dot: -v gives v), or nothing."""
    state = dict(model.state)
    (_, height), *_ = body.position
    for coordinate in model.coordinates:
        if coordinate.symbol in height.free_symbols and coordinate.velocity in state:
            symbols = sorted(state[coordinate.velocity].free_symbols, key=lambda s: s.name)
            return symbol_label(symbols[0].name) if len(symbols) == 1 else ""
    return ""


def draw_falling(figure: Figure, model: Model, bodies: list[Body], values: Values) -> None:
    canvas = figure.canvas
    said = []
    for index, body in enumerate(bodies):
        x = index * APART
        canvas.circle((x, 0.0), RADIUS, fill=FILLS[index % len(FILLS)])
        label = body_label(body, model)
        mass = symbol_label(body.mass.name) if isinstance(body.mass, sympy.Symbol) else ""
        if label == body.name:  # equal masses: the mass inside, the name beneath
            canvas.text((x, 0.0), mass, size=0.36)
            canvas.text((x, -RADIUS - 0.35), label, size=0.32)
        else:
            canvas.text((x, 0.0), label, size=0.36)
        drags = applied_forces(model, body.name, values)
        for name, (dx, dy) in drags:  # the drag, from the ball's rim, against the velocity
            start = (x + dx * RADIUS, dy * RADIUS)
            tip = (start[0] + dx * ARROW, start[1] + dy * ARROW)
            canvas.arrow(start, tip, width=0.05, color="#a11111")
            canvas.text((tip[0] + 0.25, tip[1]), name, size=0.36, anchor="start")
        speed = _speed_label(body, model)
        if drags and speed:  # the velocity beside the ball, opposite the drag
            dx, dy = drags[0][1]
            middle = (x + RADIUS + 0.35, 0.0)
            canvas.arrow(
                (middle[0] + dx * ARROW / 2, middle[1] + dy * ARROW / 2),
                (middle[0] - dx * ARROW / 2, middle[1] - dy * ARROW / 2),
                width=0.04,
            )
            canvas.text((middle[0] + 0.2, middle[1]), speed, size=0.36, anchor="start")
        way = " down" if drags and drags[0][1][1] > 0 else " up" if drags else ""
        moving = f"moving{way}" + (f" at {speed}" if speed else "")
        said.append(f"{label} {moving}, with drag {' and '.join(n for n, _ in drags)} against its velocity")
    figure.say("Under gravity and drag, each on its own vertical line: " + "; ".join(said) + ".")
