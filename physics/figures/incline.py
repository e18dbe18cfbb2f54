"""The incline family drawn from its elements: a block on a wedge (an incline with `wedge:`), two
inclines meeting at a top, or bodies on one fixed slope or floor (incline, surface and rolling
elements) with the springs that hold them along it and the pulleys at its edge that lead their strings
down to hanging bodies."""

from __future__ import annotations

from physics.engine.model import AuthoredElement, Body, ConstraintKind, Model, PairPotential
from physics.figures.figure import Figure, Values
from physics.figures.geometry import (
    Surface,
    bodies_in,
    element_body,
    linear_surface,
    of_kind,
    written_symbol,
)
from physics.figures.loads import given_forces
from physics.figures.pulleys import draw_pulley_to_hanging
from physics.figures.slope import draw_incline
from physics.figures.spring_block import draw_slope_spring
from physics.figures.turning import draw_curve_axis
from physics.figures.wedge import draw_double_incline, draw_wedge

LINES = ("incline", "surface", "rolling")  # the kinds that put a body on a straight surface


def from_elements(
    figure: Figure, model: Model, values: Values, elements: tuple[AuthoredElement, ...]
) -> bool:
    """False when the elements hold something the slope cannot show (a spring between two bodies, a
    string whose ends are not one on the slope and one hanging)."""
    lines = of_kind(elements, *LINES)
    wedged = [element for element in lines if "wedge" in element.fields]
    if wedged:
        element = wedged[0]
        wedge = model.body(str(element.fields["wedge"].get("body", "wedge")))
        block = element_body(model, element)
        draw_wedge(figure, model, wedge, block, model.constraint(element.name), values)
        return True
    surfaces = [_surface(model, values, element) for element in lines]
    pulleys = of_kind(elements, "pulley")
    angles = {surface.angle_symbol for surface in surfaces}
    if len(surfaces) == 2 and len(angles) == 2 and None not in angles:
        draw_double_incline(figure, model, surfaces, bool(pulleys))
        return True
    on_slope = {surface.body.name for surface in surfaces}
    maybe_over_edge = [_over_edge(model, pulley, on_slope) for pulley in pulleys]
    maybe_held = [_held_along(model, spring, on_slope) for spring in of_kind(elements, "spring")]
    over_edge = [ends for ends in maybe_over_edge if ends is not None]
    held = [spring for spring in maybe_held if spring is not None]
    if len(over_edge) < len(pulleys) or len(held) < len(maybe_held):
        return False
    pushes = {surface.body.name: given_forces(model, surface.body.name, values) for surface in surfaces}
    slope = draw_incline(figure, model, values, surfaces, touching=_touching(model, on_slope), pushes=pushes)
    for body, potential in held:
        draw_slope_spring(figure, model, slope, body, potential)
    for index, (on, hanging, movable, wheel) in enumerate(over_edge):
        left = slope.upper is None and len(over_edge) == 2 and index == 0
        draw_pulley_to_hanging(figure, model, slope, on, hanging, left=left, movable=movable, wheel=wheel)
    for frame in of_kind(elements, "rotating"):
        turning = [str(name) for name in frame.fields["bodies"]]
        if len(turning) == 1 and turning[0] in on_slope:
            line = next(e for e in lines if element_body(model, e).name == turning[0])
            draw_curve_axis(figure, model, values, slope, frame, line.fields.get("at"))
    return True


def _surface(model: Model, values: Values, element: AuthoredElement) -> Surface:
    body = element_body(model, element)
    surface = linear_surface(model.constraint(element.name), body, model, values)
    if surface is None:  # a line element's clearance always has a normal
        raise AssertionError(f"{element.name}: the contact has no normal")
    return Surface(
        surface.constraint, body, surface.normal, written_symbol(model, element.fields.get("angle"))
    )


def _over_edge(
    model: Model, pulley: AuthoredElement, on_slope: set[str]
) -> tuple[Body, Body, bool, Body | None] | None:
    """(the body on the slope, the one hanging, whether it hangs from a movable pulley under the string,
    the pulley's wheel when it has inertia) at the pulley's ends, if that is what it joins."""
    wheel = model.body(pulley.bodies[0]) if "inertia" in pulley.fields and pulley.bodies else None
    ends = [(str(end.get("body", end.get("under"))), "under" in end) for end in pulley.fields["ends"]]
    hanging = [(name, movable) for name, movable in ends if name not in on_slope]
    if len(hanging) != 1 or len(ends) != 2:
        return None
    on = next((name for name, movable in ends if name in on_slope and not movable), None)
    return None if on is None else (model.body(on), model.body(hanging[0][0]), hanging[0][1], wheel)


def _held_along(
    model: Model, spring: AuthoredElement, on_slope: set[str]
) -> tuple[Body, PairPotential] | None:
    """(the body, the spring's potential) for a spring from a fixed point to a body on the slope."""
    ends = spring.fields["between"]
    bodies = [end for end in ends if isinstance(end, str)]
    if len(bodies) != 1 or bodies[0] not in on_slope:
        return None
    potential = next(p for p in model.potentials if p.name == spring.potentials[0])
    return model.body(bodies[0]), potential


def _touching(model: Model, on_slope: set[str]) -> bool:
    """Do two of the bodies on the slope push on each other (a contact the author wrote between them)?"""
    return any(
        len(joined := {b.name for b in bodies_in(c.gap, model)}) == 2 and joined <= on_slope
        for c in model.constraints
        if c.kind is ConstraintKind.SURFACE
    )
