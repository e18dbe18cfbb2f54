"""A block on a spring: from a wall (with a dashpot beside it under linear drag, or a bullet flying
into it), standing on a vertical spring, two blocks joined by one, or held along a slope."""

from __future__ import annotations

import sympy

from physics.engine.model import AuthoredElement, Body, ForceKind, Model, PairPotential
from physics.figures.figure import BLOCK, Figure, Values, body_label
from physics.figures.geometry import of_kind, stiffness_symbols, written_symbol
from physics.figures.shapes import draw_block, draw_bullet
from physics.figures.slope import Slope
from physics.figures.springs import draw_spring_line, spring_line_of
from physics.figures.svg import FILLS
from physics.wording import symbol_label


def draw_slope_spring(
    figure: Figure, model: Model, slope: Slope, body: Body, potential: PairPotential
) -> None:
    """A spring along the slope from a plate fixed at its upper end to the body's uphill face."""
    if slope.upper is None:
        return
    tx, ty = slope.tangent
    up = (tx, ty) if ty > 0 else (-tx, -ty)
    nx, ny = slope.normal
    base = slope.bases[body.name]
    face = (base[0] + up[0] * BLOCK / 2 + nx * BLOCK / 2, base[1] + up[1] * BLOCK / 2 + ny * BLOCK / 2)
    anchor = (slope.upper[0] + nx * BLOCK / 2 - up[0] * 0.1, slope.upper[1] + ny * BLOCK / 2 - up[1] * 0.1)
    figure.canvas.line(
        (anchor[0] - nx * 0.6, anchor[1] - ny * 0.6), (anchor[0] + nx * 0.6, anchor[1] + ny * 0.6), width=0.1
    )
    figure.canvas.spring(anchor, face, amplitude=0.18)
    stiffness = stiffness_symbols(potential, model)
    middle = ((anchor[0] + face[0]) / 2 + nx * 0.55, (anchor[1] + face[1]) / 2 + ny * 0.55)
    name = symbol_label(stiffness[0].name) if stiffness else ""
    if name:
        figure.canvas.text(middle, name)
    figure.say(
        f"A spring {name} along the incline holds {body_label(body, model)} from a point fixed up the slope."
    )


def draw_two_blocks_spring(
    figure: Figure, model: Model, first: Body, second: Body, spring_symbol: sympy.Symbol | None
) -> None:
    canvas = figure.canvas
    canvas.ground((-1.0, 0.0), (7.0, 0.0))
    draw_block(figure, (0.5, 0.0), (1.0, 0.0), body_label(first, model), FILLS[0])
    draw_block(figure, (5.5, 0.0), (1.0, 0.0), body_label(second, model), FILLS[1])
    canvas.spring((1.0, BLOCK / 2), (5.0, BLOCK / 2))
    name = symbol_label(spring_symbol.name) if spring_symbol is not None else ""
    if name:
        canvas.text((3.0, BLOCK / 2 + 0.55), name)
    figure.say(
        f"{body_label(first, model)} and {body_label(second, model)} on a frictionless floor, joined by a spring {name}."
    )


def draw_spring(
    figure: Figure,
    model: Model,
    body: Body,
    spring_symbol: sympy.Symbol | None,
    *,
    vertical: bool = False,
    damping: sympy.Expr | None = None,
    drop: sympy.Expr | None = None,
) -> None:
    """`drop`: the height a block on a vertical spring falls from onto it (drawn that far above it)."""
    canvas = figure.canvas
    if vertical:
        _vertical_spring(figure, model, body, spring_symbol, drop)
        return
    if damping is not None:  # a dashpot above the spring, both from the wall to a taller block
        size = 2 * BLOCK
        canvas.ground((0.0, 0.0), (0.0, size + 0.6), below=False)
        canvas.ground((0.0, 0.0), (7.0, 0.0))
        canvas.spring((0.0, 0.45), (4.0, 0.45), amplitude=0.18)
        canvas.dashpot((0.0, 1.55), (4.0, 1.55))
        centre = draw_block(
            figure, (4.0 + size / 2, 0.0), (1.0, 0.0), body_label(body, model), FILLS[0], size
        )
        if spring_symbol is not None:
            canvas.text((2.0, 1.0), symbol_label(spring_symbol.name))
        if isinstance(damping, sympy.Symbol):
            canvas.text((2.1, 2.15), symbol_label(damping.name))
    else:
        canvas.ground((0.0, 0.0), (0.0, 2.0), below=False)
        canvas.ground((0.0, 0.0), (7.0, 0.0))
        canvas.spring((0.0, BLOCK / 2), (4.0, BLOCK / 2))
        centre = draw_block(figure, (4.0 + BLOCK / 2, 0.0), (1.0, 0.0), body_label(body, model), FILLS[0])
        if spring_symbol is not None:
            canvas.text((2.0, BLOCK / 2 + 0.55), symbol_label(spring_symbol.name))
    canvas.arrow((centre[0], -0.6), (centre[0] + 1.6, -0.6), width=0.04)
    coordinates = [c.name for c in model.coordinates]
    if coordinates:
        canvas.text((centre[0] + 2.0, -0.6), coordinates[0], anchor="start")
    collision = model.collision
    if collision is not None:
        draw_bullet(figure, (centre[0] + 4.2, centre[1]), -1, collision.projectile_mass, 0.45)
        figure.say("A bullet flies into the block along the spring's line and sticks.")
    figure.say(
        f"A block {body_label(body, model)} on a horizontal frictionless floor, tied to a wall by a spring"
        + (f" {symbol_label(spring_symbol.name)}" if spring_symbol is not None else "")
        + (
            " and, beside it, a dashpot"
            + (f" {symbol_label(damping.name)}" if isinstance(damping, sympy.Symbol) else "")
            if damping is not None
            else ""
        )
        + "."
    )


def _vertical_spring(
    figure: Figure, model: Model, body: Body, spring_symbol: sympy.Symbol | None, drop: sympy.Expr | None
) -> None:
    canvas = figure.canvas
    top = 3.5  # the spring's top
    base = top + (1.6 if drop is not None else 0.0)  # the block's bottom
    canvas.ground((-1.5, 0.0), (1.5, 0.0))
    canvas.spring((0.0, 0.0), (0.0, top))
    draw_block(figure, (0.0, base), (1.0, 0.0), body_label(body, model), FILLS[0])
    spring = f" {symbol_label(spring_symbol.name)}" if spring_symbol is not None else ""
    if spring_symbol is not None:
        canvas.text((0.65, top / 2), symbol_label(spring_symbol.name), anchor="start")
    if drop is None:
        figure.say(
            f"A block {body_label(body, model)} rests on a vertical spring{spring} standing on the floor."
        )
        return
    canvas.line((-0.7, top), (0.7, top), dashed=True, width=0.03)  # where the block lands
    canvas.arrow((-1.1, (top + base) / 2), (-1.1, base), width=0.03)
    canvas.arrow((-1.1, (top + base) / 2), (-1.1, top), width=0.03)
    height = symbol_label(drop.name) if isinstance(drop, sympy.Symbol) else ""
    if height:
        canvas.text((-1.35, (top + base) / 2), height, anchor="end")
    figure.say(
        f"A block {body_label(body, model)} falls from rest{f' from a height {height}' if height else ''} "
        f"onto a vertical spring{spring} standing on the floor; it is drawn where it is released."
    )


def _drop(model: Model, body: Body, values: Values) -> sympy.Expr | None:
    """How far a body on a vertical spring fell from rest onto it: v^2 / 2g of its speed downwards in
    the model's state (where it lands), if it is moving down there."""
    state = dict(model.state)
    height = dict(body.position).get("y", sympy.Integer(0))
    moving = [c for c in model.coordinates if height.has(c.symbol) and state.get(c.velocity, 0) != 0]
    if model.gravity is None or len(moving) != 1:
        return None
    rate = sympy.diff(height, moving[0].symbol) * state[moving[0].velocity]
    if values.number(rate) >= 0:
        return None
    return sympy.simplify(rate**2 / (2 * model.gravity))


def from_elements(
    figure: Figure, model: Model, values: Values, elements: tuple[AuthoredElement, ...]
) -> bool:
    """Springs in a line between walls, floor and ceiling (springs.py), or one spring: from a fixed point
    to a block (standing on it when the block moves up and down) or between two blocks."""
    if (line := spring_line_of(model, values)) is not None:
        draw_spring_line(figure, model, line)
        return True
    springs = of_kind(elements, "spring")
    if len(springs) != 1:
        return False
    potential = next(p for p in model.potentials if p.name == springs[0].potentials[0])
    stiffness = written_symbol(model, springs[0].fields.get("stiffness")) or next(
        iter(stiffness_symbols(potential, model)), None
    )
    bodies = [model.body(name) for name in potential.bodies]
    if len(bodies) == 2:
        draw_two_blocks_spring(figure, model, bodies[0], bodies[1], stiffness)
        return True
    body = bodies[0]
    damping = next(
        (f.coefficient for f in model.forces if f.body == body.name and f.kind is ForceKind.LINEAR_DRAG), None
    )
    vertical = [axis for axis, _ in body.position] == ["y"]
    drop = _drop(model, body, values) if vertical else None
    draw_spring(figure, model, body, stiffness, vertical=vertical, damping=damping, drop=drop)
    return True
