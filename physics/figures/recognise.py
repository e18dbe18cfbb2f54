"""The picture of a hand-written low-level model, recognised from its constraints, potentials and
sections (a model written with elements is drawn from them: scene.py)."""

from __future__ import annotations

import sympy

from physics.engine.model import Body, Constraint, ConstraintKind, ForceKind, Model
from physics.figures.attraction import draw_central, draw_pair
from physics.figures.chain import draw_pendulum_chain, pendulum_chain_of
from physics.figures.falling import draw_falling, falling_of
from physics.figures.figure import Figure, Values
from physics.figures.geometry import (
    bodies_in,
    is_linear,
    linear_surface,
    moves_linearly,
    spring_sign,
    stiffness_symbols,
)
from physics.figures.ladder import draw_ladder, leaning_of
from physics.figures.loads import given_forces
from physics.figures.path import draw_path, draw_row
from physics.figures.pendulum import draw_pendulum
from physics.figures.projectile import draw_projectile, launch_of
from physics.figures.pulleys import (
    draw_atwood,
    draw_double_atwood,
    draw_movable_pulley,
    draw_pulley_to_hanging,
    draw_table_to_hanging,
)
from physics.figures.slope import draw_incline
from physics.figures.spring_block import draw_slope_spring, draw_spring, draw_two_blocks_spring
from physics.figures.springs import draw_spring_line, spring_line_of
from physics.figures.track import draw_track, track_of
from physics.figures.wedge import draw_double_incline, draw_wedge, wedge_roles
from physics.figures.wound import draw_wheel_and_weight, draw_yoyo


def draw_recognised(figure: Figure, model: Model, values: Values) -> None:
    """The picture the model's low-level sections describe, in order of how specific the shape is; the
    bodies side by side (noted as the figure's fallback) when none is recognised."""
    if (launch := launch_of(model)) is not None:
        draw_projectile(figure, model, launch, values)
        return
    if (leaning := leaning_of(model)) is not None:
        draw_ladder(figure, model, leaning, values)
        return
    # a string gone slack (released) is drawn where it hung when it let go
    strings = [c for c in (*model.constraints, *model.released) if c.kind is ConstraintKind.STRING]
    pendulum = [c for c in strings if not is_linear(c.gap, model)]
    if (chain := pendulum_chain_of(model, pendulum)) is not None:
        draw_pendulum_chain(figure, model, chain)
        return
    if pendulum:
        joined = bodies_in(pendulum[0].gap, model)
        bobs = [b for b in joined if not moves_linearly(b, model)] or joined
        pivots = [b for b in joined if b not in bobs]
        draw_pendulum(figure, model, bobs[0], pendulum[0], values, pivots[0] if pivots else None)
        return
    surfaces = [c for c in model.constraints if c.kind is ConstraintKind.SURFACE]
    two_body = [c for c in surfaces if len(bodies_in(c.gap, model)) == 2]
    on_own_surface = {
        b.name for c in surfaces if len(bodies_in(c.gap, model)) == 1 for b in bodies_in(c.gap, model)
    }
    wedges = [c for c in two_body if not {b.name for b in bodies_in(c.gap, model)} <= on_own_surface]
    if wedges:
        block, wedge = wedge_roles(wedges[0], model)
        draw_wedge(figure, model, wedge, block, wedges[0], values)
        return
    fixed = [
        surface
        for c in surfaces
        if len(bodies := bodies_in(c.gap, model)) == 1
        and is_linear(c.gap, model)
        and (surface := linear_surface(c, bodies[0], model, values)) is not None
    ]
    angles = {surface.angle_symbol for surface in fixed}
    if len(fixed) == 2 and len(angles) == 2 and None not in angles:
        draw_double_incline(figure, model, fixed, bool(strings))
        return
    if fixed:
        touching = any(
            {b.name for b in bodies_in(c.gap, model)} <= {f.body.name for f in fixed} for c in two_body
        )
        pushes = {surface.body.name: given_forces(model, surface.body.name, values) for surface in fixed}
        slope = draw_incline(figure, model, values, fixed, touching=touching, pushes=pushes)
        for potential in model.potentials:
            if (
                potential.anchor
                and len(potential.bodies) == 1
                and potential.bodies[0] in slope.bases
                and spring_sign(potential, values) > 0
            ):
                draw_slope_spring(figure, model, slope, model.body(potential.bodies[0]), potential)
        over_edge = [
            (joined, hanging)
            for string in strings
            if len(joined := bodies_in(string.gap, model)) == 2
            and len(hanging := [b for b in joined if b.name not in slope.bases]) == 1
        ]
        for index, (joined, hanging) in enumerate(over_edge):
            slope_body = next(b for b in joined if b.name in slope.bases)
            left = slope.upper is None and len(over_edge) == 2 and index == 0
            draw_pulley_to_hanging(figure, model, slope, slope_body, hanging[0], left=left)
        return
    if strings:
        joined = bodies_in(strings[0].gap, model)
        every = list({b.name: b for c in strings for b in bodies_in(c.gap, model)}.values())
        hanging = [b for b in every if b.angle is None]
        wheels = [b for b in every if b.angle is not None]
        carried = [b for b in hanging if _loops_under(b, strings[0], model)]
        if len(strings) == 1 and len(hanging) == 2 and len(carried) == 1:
            free = next(b for b in hanging if b is not carried[0])
            draw_movable_pulley(figure, model, free, carried[0])
            return
        level = [b for b in hanging if _height(b, model) is None]
        if len(hanging) == 2 and len(level) == 1 and len(wheels) <= 1:
            on_table = level[0]
            down = next(b for b in hanging if b is not on_table)
            wheel = wheels[0] if wheels else None
            draw_table_to_hanging(
                figure, model, on_table, down, wheel, left=_pulley_left(on_table, down, model, values)
            )
            return
        if len(hanging) == 2:
            draw_atwood(figure, model, hanging[0], hanging[1], wheels[0] if wheels else None)
            if any(c.kind is ConstraintKind.STRING for c in model.released):
                figure.say("The string goes slack.")
            return
        if len(hanging) == 3:
            draw_double_atwood(figure, model, hanging)
            return
        if len(hanging) == 1 and wheels:
            draw_wheel_and_weight(figure, model, wheels[0], hanging[0])
            return
        if len(joined) == 1 and wheels:
            draw_yoyo(figure, model, joined[0], values)
            return
    if (line := spring_line_of(model, values)) is not None:
        draw_spring_line(figure, model, line)
        return
    if model.potentials:
        potential = model.potentials[0]
        bodies = [model.body(name) for name in potential.bodies]
        sign = spring_sign(potential, values)
        quadratic = sign > 0
        if potential.anchor and len(bodies) == 1 and sign < 0 and len(model.coordinates) == 1:
            draw_path(figure, model, bodies[0], values, spin=potential)
            return
        if potential.anchor and len(bodies) == 1 and sign == 0:
            draw_central(figure, model, bodies[0], potential)
            return
        if potential.anchor and len(bodies) == 1:
            spring = stiffness_symbols(potential, model)
            vertical = [axis for axis, _ in bodies[0].position] == ["y"]
            damping = next(
                (
                    f.coefficient
                    for f in model.forces
                    if f.body == bodies[0].name and f.kind is ForceKind.LINEAR_DRAG
                ),
                None,
            )
            draw_spring(
                figure, model, bodies[0], spring[0] if spring else None, vertical=vertical, damping=damping
            )
            return
        if len(bodies) == 2 and quadratic:
            spring = stiffness_symbols(potential, model)
            draw_two_blocks_spring(figure, model, bodies[0], bodies[1], spring[0] if spring else None)
            return
        if len(bodies) == 2:
            label = next((c.name for c in model.coordinates if c.name not in ("X",)), "d")
            draw_pair(figure, model, bodies[0], bodies[1], label)
            return
    if (track := track_of(model)) is not None:
        draw_track(figure, model, track, values)
        return
    if (falling := falling_of(model)) is not None:
        draw_falling(figure, model, falling, values)
        return
    if len(model.bodies) == 1 and len(model.coordinates) == 1:
        draw_path(figure, model, model.bodies[0], values)
        return
    figure.fallback = "no picture recognised in the hand-written model"
    draw_row(figure, model)


def _height(body: Body, model: Model) -> sympy.Expr | None:
    """The body's height where it changes with the coordinates; None when it never does (a body
    written to slide along a level line, such as a table's top)."""
    coordinates = {c.symbol for c in model.coordinates}
    height = dict(body.position).get("y")
    return None if height is None or not (height.free_symbols & coordinates) else height


def _pulley_left(on_table: Body, hanging: Body, model: Model, values: Values) -> bool:
    """Is the pulley to the left of the level body: does it move left as the hanging body descends?"""
    x = dict(on_table.position).get("x", sympy.Integer(0))
    y = _height(hanging, model)
    assert y is not None
    return any(
        values.number(sympy.diff(x, c.symbol) * sympy.diff(y, c.symbol)) > 0 for c in model.coordinates
    )


def _loops_under(body: Body, string: Constraint, model: Model) -> bool:
    """Does the string run under a movable pulley the body carries (its height counts twice in the
    string's length, as both sides of the loop shorten)?"""
    height = model.cartesian_symbol(f"y_{body.name}") if f"y_{body.name}" in dict(model.cartesian) else None
    return height is not None and abs(sympy.diff(string.gap, height)) == 2
