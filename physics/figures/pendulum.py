"""A pendulum: a bob on a string or rod from a fixed point or a cart, swung aside (or drawn at the
state's angle, whirled round a vertical circle, or sweeping a cone in a turning frame), with a bullet
flying into it when the model has a collision."""

from __future__ import annotations

import math

import sympy

from physics.engine.depth import DEPTH
from physics.engine.model import AuthoredElement, Body, Constraint, Model
from physics.figures.chain import draw_pendulum_chain
from physics.figures.figure import BLOCK, Figure, NotNumeric, Values, body_label
from physics.figures.geometry import element_body, of_kind, written_symbol
from physics.figures.path import draw_path
from physics.figures.shapes import angle_mark, draw_bullet, square
from physics.figures.svg import FILLS, Point
from physics.wording import symbol_label


def _cart(figure: Figure, pivot: Point, label: str) -> None:
    """A cart on wheels below `pivot`, carrying a gallows whose beam holds the pendulum at `pivot`."""
    canvas = figure.canvas
    width, height = 3.6, 0.9
    centre = (pivot[0], pivot[1] - 5.0)
    top = centre[1]
    mast = centre[0] - width / 2 + 0.2
    canvas.line((mast, top), (mast, pivot[1]), width=0.12)
    canvas.line((mast, pivot[1]), pivot, width=0.12)
    canvas.polygon(
        [(centre[0] - width / 2, top - height), (centre[0] + width / 2, top - height),
         (centre[0] + width / 2, top), (centre[0] - width / 2, top)],
        fill=FILLS[1],
    )  # fmt: skip
    for dx in (-0.7, 0.7):
        canvas.circle((centre[0] + dx, top - height - 0.25), 0.25, fill="#ffffff")
    canvas.ground((centre[0] - 3.0, top - height - 0.5), (centre[0] + 3.0, top - height - 0.5))
    if label:
        canvas.text((centre[0], top - height / 2), label)


# What a pendulum's swinging body is called when the model's name for it says so; otherwise a bob.
PENDULUM_BODIES = ("ball", "block", "bob", "sphere", "stone")


def pendulum_words(body: Body, string: Constraint) -> tuple[str, str]:
    """(what swings, what holds it): ("ball", "string"), ("bob", "rod")... from the model's names."""
    name = body.name.lower()
    noun = next((word for word in PENDULUM_BODIES if word in name), "bob")
    return noun, "rod" if "rod" in string.name.lower() else "string"


def _turning_rate(model: Model, body: Body) -> sympy.Expr | None:
    """The rate of a rotating frame the body turns with (a conical pendulum), else None."""
    frame = model.frame
    if frame is None or frame.rate is None or body.name not in frame.bodies:
        return None
    return frame.rate


def _state_of(model: Model, body: Body) -> sympy.Expr | None:
    """The state's value of the pendulum's angle from the downward vertical, when the state gives it."""
    state = dict(model.state)
    return next(
        (state[c.symbol] for c in model.coordinates if c.symbol in state and _moves(body, c.symbol)), None
    )


def _moves(body: Body, symbol: sympy.Symbol) -> bool:
    return any(expr.has(symbol) for _, expr in body.position)


def _state_angle(model: Model, body: Body, values: Values) -> float | None:
    """The pendulum's angle from the downward vertical at the model's state, when the state gives it."""
    value = _state_of(model, body)
    try:
        return None if value is None else values.number(value)
    except NotNumeric:
        return None


def _lift(model: Model, body: Body, string: Constraint) -> sympy.Expr | None:
    """The upward acceleration of a support moving up and down in the time (a lift's ceiling), else None."""
    time = model.time
    if time is None or time not in string.gap.free_symbols:
        return None
    along = {axis: sympy.diff(expr, time, 2) for axis, expr in body.position}
    rise = along.get("y", sympy.Integer(0))
    return rise if rise != 0 and all(a == 0 for axis, a in along.items() if axis != "y") else None


def _draw_lift(figure: Figure, reach: float, length: float, rise: sympy.Expr) -> None:
    """The lift's car round the pendulum, hung from its ceiling at the origin, and its acceleration."""
    canvas = figure.canvas
    half, floor = reach + 1.2, -length - 1.4
    canvas.ground((-half, 0.0), (half, 0.0), below=False)
    canvas.polyline([(-half, 0.0), (-half, floor), (half, floor), (half, 0.0)], width=0.06)
    canvas.arrow((half + 0.6, floor / 2 - 0.7), (half + 0.6, floor / 2 + 0.7), width=0.05)
    canvas.text((half + 1.0, floor / 2), _name(rise, "A"), anchor="start")


def _name(expr: sympy.Expr, otherwise: str) -> str:
    return symbol_label(expr.name) if isinstance(expr, sympy.Symbol) else otherwise


def _swung_to(model: Model, body: Body, angle: float, values: Values) -> dict[sympy.Symbol, float]:
    """The value of the coordinate that swings the body (its angle from the downward vertical, in
    the model's sense) that puts it `angle` from the vertical, on the side the figure draws it: +x."""
    swinging = [
        c.symbol
        for c in model.coordinates
        if any(sympy.diff(expr, c.symbol, 2) != 0 for _, expr in body.position)
    ]
    if len(swinging) != 1:
        return {}
    q = swinging[0]
    x = dict(body.position).get("x", sympy.Integer(0))
    rest = {c.symbol: 0.0 for c in model.coordinates}
    try:
        hanging = values.number(x, rest)
        aside = {s: (values.number(x, {**rest, q: s}) - hanging) * math.sin(angle) for s in (angle, -angle)}
    except NotNumeric:
        return {q: angle}
    return {q: angle if aside[angle] >= aside[-angle] else -angle}


def draw_pendulum(
    figure: Figure,
    model: Model,
    body: Body,
    string: Constraint,
    values: Values,
    pivot_body: Body | None = None,
    *,
    length_symbol: sympy.Symbol | None = None,
    truck: sympy.Expr | None = None,
) -> None:
    """`length_symbol`: the string's length as the author named it (else the first symbol of its gap);
    `truck`: the acceleration of a truck the pivot is fixed in (the pivot's prescribed motion)."""
    canvas = figure.canvas
    length = 4.0
    collision = model.collision
    reached = dict(collision.reaches) if collision else {}
    angle_symbol = next((expr for expr in reached.values() if isinstance(expr, sympy.Symbol)), None)
    angle = values.number(angle_symbol) if angle_symbol is not None else math.radians(30)
    angle = min(max(angle, math.radians(20)), math.radians(60))
    noun, support = pendulum_words(body, string)
    rate = _turning_rate(model, body)
    state_angle = _state_angle(model, body, values)
    # a bob on z goes round a cone, seen from the side where it crosses the page, at the state's angle
    cone = any(axis == DEPTH for axis, _ in body.position) and state_angle is not None
    lift = _lift(model, body, string) if cone else None
    if cone and state_angle is not None:
        given = _state_of(model, body)
        angle_symbol = given if isinstance(given, sympy.Symbol) else angle_symbol
        state_angle = figure.readable_angle(state_angle, angle_symbol)
    # Drawn at the state's angle when the state gives one (a ball at the top of its circle, a bob
    # passing the bottom), else swung aside to show that it swings. In a turning frame the state is the
    # cone's angle that the problem asks for, which the figure does not give away.
    if rate is None and state_angle is not None:
        angle = state_angle
    # A string pendulum drawn above the pivot's level is whirled round a vertical circle.
    whirled = rate is None and math.cos(angle) < 0
    figure.placed.update(_swung_to(model, body, angle, values))
    pivot = (0.0, 0.0)
    if pivot_body is not None:
        _cart(figure, pivot, body_label(pivot_body, model))
    elif lift is not None:
        _draw_lift(figure, length * abs(math.sin(angle)), length, lift)
    elif truck is not None:
        _cart(figure, pivot, "")
        canvas.arrow((-0.7, -5.45), (0.7, -5.45), width=0.05)
        canvas.text(
            (1.0, -5.45), symbol_label(truck.name) if isinstance(truck, sympy.Symbol) else "a", anchor="start"
        )
    else:
        canvas.ground((-1.5, 0.0), (1.5, 0.0), below=False)
    canvas.line(pivot, (0.0, -length - 0.3), dashed=True, width=0.03)
    raised = (length * math.sin(angle), -length * math.cos(angle))
    lowest = (0.0, -length)
    size = BLOCK * 0.9
    if whirled:
        circle = [
            (length * math.sin(i * math.pi / 24), -length * math.cos(i * math.pi / 24)) for i in range(49)
        ]
        canvas.polyline(circle, dashed=True, width=0.03)
    if rate is not None or cone:  # the horizontal circle the bob goes round, seen obliquely, and its rate
        ring = [(raised[0] * math.cos(i * math.pi / 24), raised[1] + 0.3 * raised[0] * math.sin(i * math.pi / 24))
                for i in range(49)]  # fmt: skip
        canvas.polyline(ring, dashed=True, width=0.03)
        canvas.turning((0.0, -length - 0.3), 0.5)
        if rate is not None and isinstance(rate, sympy.Symbol):
            canvas.text((0.8, -length - 0.5), symbol_label(rate.name), anchor="start")
    canvas.line(pivot, raised, width=0.04)
    if noun == "block":
        canvas.polygon(square(raised, size), fill=FILLS[0])
    else:
        canvas.circle(raised, size / 2, fill=FILLS[0])
    name = body_label(body, model)
    if len(name) <= 3:
        canvas.text(raised, name)
    else:  # a name does not fit inside the body: beside it, away from the string
        canvas.text((raised[0] + size / 2 + 0.15, raised[1]), name, size=0.36, anchor="start")
    # a pivot moving as prescribed (its position in the time) is drawn where it starts, at t = 0
    moving = model.time is not None and model.time in string.gap.free_symbols
    gap = string.gap.subs(model.time, 0) if moving else string.gap
    length_symbols = (
        [length_symbol]
        if length_symbol is not None
        else sorted((s for s in gap.free_symbols if s in set(model.parameters)), key=lambda s: s.name)
    )
    if length_symbols:
        canvas.text(
            (raised[0] / 2 + 0.35, raised[1] / 2 + 0.1), symbol_label(length_symbols[0].name), anchor="start"
        )
    if angle_symbol is not None:
        angle_mark(figure, pivot, -math.pi / 2, -math.pi / 2 + angle, angle_symbol)
    held = f"a {support}" + (f" of length {symbol_label(length_symbols[0].name)}" if length_symbols else "")
    if pivot_body is not None:
        said = (
            f"A cart {body_label(pivot_body, model)} rolls on a horizontal floor; "
            f"a {noun} {name} hangs from it on {held}"
        )
    elif truck is not None:
        rate = f" at {symbol_label(truck.name)}" if isinstance(truck, sympy.Symbol) else ""
        said = (
            f"A truck accelerates{rate} along a level road (the arrow); a {noun} {name} hangs from its roof "
            f"on {held}"
        )
    elif whirled:
        said = (
            f"A {noun} {name} on {held} is whirled in a vertical circle (dashed) about the {support}'s "
            "fixed end; it is drawn at the top"
        )
    elif cone:
        where = "a fixed point"
        if lift is not None:
            where = f"the ceiling of a lift that accelerates upwards at {_name(lift, 'a constant rate')} (the arrow)"
        slant = f" at the angle {symbol_label(angle_symbol.name)}" if angle_symbol is not None else ""
        said = (
            f"Seen from the side, z out of the page: a {noun} {name} hangs from {where} on {held} and goes "
            f"round a horizontal circle (dashed), the {support}{slant} from the vertical (dashed) through "
            "that point sweeping out a cone about it"
        )
    elif rate is not None:
        at = f" at the rate {symbol_label(rate.name)}" if isinstance(rate, sympy.Symbol) else ""
        said = (
            f"A {noun} {name} hangs from a fixed point on {held} and goes round a horizontal circle (dashed)"
            f"{at}, the {support} sweeping out a cone about the vertical (dashed) through that point"
        )
    else:
        point = "a point that moves as the problem says" if moving else "a fixed point"
        said = f"A {noun} {name} hangs from {point} on {held}"
    if collision is not None:
        canvas.polygon(square(lowest, size), fill="none")
        mass = collision.projectile_mass
        draw_bullet(figure, (-3.2, -length), 1, mass, -0.45)
        said += "; a bullet" + (f" {symbol_label(mass.name)}" if isinstance(mass, sympy.Symbol) else "")
        said += " flies into it horizontally at its lowest point"
    if angle_symbol is not None and not cone:
        said += f", and it swings up to the angle {symbol_label(angle_symbol.name)} from the vertical"
    figure.say(said + ".")


def from_elements(
    figure: Figure, model: Model, values: Values, elements: tuple[AuthoredElement, ...]
) -> bool:
    """The pendulum elements: one pendulum (from a fixed point, or from the body named as its pivot), a
    rigid one turning about its pivot, or pendulums hung one from another; False for anything else."""
    pendulums = of_kind(elements, "pendulum")
    if len(pendulums) > 1:
        chain = _hung_in_order(pendulums)
        if chain is None and all(not isinstance(p.fields.get("pivot"), str) for p in pendulums):
            _side_by_side(figure, model, values, pendulums)
            return True
        if chain is None or any("inertia" in p.fields for p in chain):
            return False
        draw_pendulum_chain(
            figure, model, [(element_body(model, p), model.constraint(p.constraints[0])) for p in chain]
        )
        return True
    pendulum = pendulums[0]
    body = element_body(model, pendulum)
    if "inertia" in pendulum.fields:  # a rigid body turning about its pivot
        if len(model.coordinates) != 1:
            return False
        draw_path(figure, model, body, values)
        return True
    pivot = pendulum.fields.get("pivot")
    carrier = model.body(pivot) if isinstance(pivot, str) else None
    truck = None
    if model.time is not None and carrier is None:  # a pivot moving as the author prescribed
        truck = sympy.diff(dict(body.position).get("x", sympy.Integer(0)), model.time, 2)
    draw_pendulum(
        figure,
        model,
        body,
        model.constraint(pendulum.constraints[0]),
        values,
        carrier,
        length_symbol=written_symbol(model, pendulum.fields.get("length")),
        truck=truck if truck != 0 else None,
    )
    return True


def _side_by_side(figure: Figure, model: Model, values: Values, pendulums: list[AuthoredElement]) -> None:
    """Pendulums on fixed points of their own, none hanging from another: each drawn alone, in a row."""
    for pendulum in pendulums:
        alone = Figure()
        body = element_body(model, pendulum)
        string = model.constraint(pendulum.constraints[0])
        if "inertia" in pendulum.fields:  # a rigid body: a rod hanging from its pivot
            canvas = alone.canvas
            canvas.ground((-0.8, 0.0), (0.8, 0.0), below=False)
            canvas.line((0.0, 0.0), (0.0, -3.0), width=0.35, color="#8aa9cf")
            canvas.circle((0.0, 0.0), 0.1, fill="#1b1b1b")
            canvas.text((0.5, -1.5), body_label(body, model), anchor="start")
            alone.say(f"A rigid body {body_label(body, model)} hangs from a fixed pivot.")
        else:
            length = written_symbol(model, pendulum.fields.get("length"))
            draw_pendulum(alone, model, body, string, values, length_symbol=length)
        figure.canvas.place(alone.canvas, gap=1.5)
        figure.said.extend(alone.said)
        figure.placed.update(alone.placed)
        figure.unscaled.extend(alone.unscaled)
    figure.say("They hang apart and do not touch.")


def _hung_in_order(pendulums: list[AuthoredElement]) -> list[AuthoredElement] | None:
    """The pendulums from the one on a fixed point down, each hanging from the bob above; None unless
    they form one such chain."""
    top = [p for p in pendulums if not isinstance(p.fields.get("pivot"), str)]
    if len(top) != 1:
        return None
    chain = top
    while len(chain) < len(pendulums):
        above = str(chain[-1].fields.get("body", chain[-1].name))
        below = [p for p in pendulums if p.fields.get("pivot") == above]
        if len(below) != 1 or below[0] in chain:
            return None
        chain.append(below[0])
    return chain
