"""A rigid body's inertia typed about the point it turns about, where `inertia` is about its centre.

A body's `inertia` is about its centre of mass; the positions carry the rest (the parallel-axis term
m d² comes from the centre's own motion). The slip instructors make is to type the inertia about the
pivot instead: a rod hung from its end given m L²/3, a hoop on a nail 2 m R², a ball rolling on its
contact point 7/5 m r², a ladder sliding down a wall m L²/3. Every method then counts m d² twice,
agrees with the others and with the simulation, and the answers are a body nobody posed (the rod swings
as if 7/4 as hard to turn).

The point a body turns about is found from its motion, not from how the model names it: for a body
that one coordinate moves, its centre's speed over its rate of turning is the distance d from the
centre to the point at rest at that instant (a pivot, a rolling contact, the corner a sliding ladder
turns about). Where that distance is fixed and the inertia less m d² is exactly a standard shape's
about its centre (shape_inertia.SHAPES: a number times the mass times the square of one of the model's
lengths), the inertia was typed about the pivot: refused where it was written, saying what it is about
the centre. A spool rolling on its thin axle (m R²/2 on an axle of radius r) has an inertia above m r²
and is no shape's plus m r², so it is left alone.

An inertia that is itself a shape's about its edge (m L²/3, a rod's about its end; 3/2 m R², a disk's
about its rim) is the same slip where the body turns about another point (a rod pivoted L/4 from its
centre, or at it): the first check misses it, the inertia less m d² being no shape's, and every method
would agree on a rod whose pivot is at its end. Refused too, saying what the inertia is and what the
pivot's distance implies (m L²/12 + m d² about it).

A body that skids (kinetic friction at its `contact` point, its angle a coordinate of its own) turns
about no fixed point yet, but it touches the surface a fixed distance from its centre and rolls about
that point once the slipping stops: a ball skidding with 7/5 m r² is the same slip, and its skid's
time and the speed it rolls at verified as those of a ball nobody posed (7 v/(12 μ g), 5 v/12).
"""

from __future__ import annotations

import sympy

from physics.answer_text import typed_text
from physics.engine.mechanics import time_derivative
from physics.engine.model import Body, Model
from physics.engine.shape_inertia import ABOUT_AN_EDGE, SHAPES, edge_shape, geometric_symbols, shape_factor
from physics.engine.sizes import body_path
from physics.errors import DerivationError


def check_pivot_inertias(model: Model) -> None:
    """DerivationError at the first rigid body whose inertia is a standard shape's about its centre plus
    m d², d the fixed distance from its centre to the point it turns about (or, skidding, its contact),
    or a shape's about its edge where d is not the edge's distance."""
    lengths = geometric_symbols(model)
    for body in model.bodies:
        found = _turning_point(model, body)
        if found is None:
            continue
        distance, point, aside = found
        about_centre = sympy.factor(body.inertia - body.mass * distance**2)
        factor = shape_factor(about_centre, body.mass, lengths) if distance != 0 else None
        if factor is None:
            _check_edge_inertia(model, body, lengths, distance, aside)
            continue
        raise DerivationError(
            f"{body.name}'s moment of inertia {typed_text(body.inertia)} is its inertia about {point}, "
            f"{typed_text(distance)} from its centre ({aside}): about its "
            f"centre it is {typed_text(about_centre)} ({SHAPES[factor]}), and `inertia` is about the centre "
            f"of mass (the positions add {typed_text(body.mass * distance**2)} themselves). Write "
            f"{typed_text(about_centre)}; a body whose inertia about its centre really is "
            f"{typed_text(body.inertia)} is written with a length of its own (m*k^2, k its radius of gyration)",
            path=body_path(model, body.name, "inertia"),
        )


def _check_edge_inertia(
    model: Model, body: Body, lengths: set[sympy.Symbol], distance: sympy.Expr, aside: str
) -> None:
    """DerivationError where the body's inertia is a shape's about its edge: it turns about a point
    `distance` from its centre that is not on that edge, or the first check would have caught it."""
    found = edge_shape(body.inertia, body.mass, lengths)
    if found is None:
        return
    factor, length = found
    centre_factor, edge, what = ABOUT_AN_EDGE[factor]
    about_centre = centre_factor * body.mass * length**2
    where, about_pivot = "its centre, on an axle", ""
    if distance != 0:
        where = f"a point {typed_text(distance)} from its centre ({aside})"
        total = sympy.factor(about_centre + body.mass * distance**2)
        about_pivot = (
            f" (about the point it turns about, {typed_text(about_centre)} + "
            f"{_parallel_axis(body.mass, distance)} = {typed_text(total)})"
        )
    raise DerivationError(
        f"{body.name}'s moment of inertia {typed_text(body.inertia)} is {what} "
        f"({typed_text(about_centre)} + {_parallel_axis(body.mass, edge * length)}), but it turns about "
        f"{where}, not on that edge: `inertia` is about the centre of mass, and the positions add "
        f"m d² themselves. Write {typed_text(about_centre)}{about_pivot}; a body whose inertia about its "
        f"centre really is {typed_text(body.inertia)} is written with a length of its own (m*k^2, k its "
        "radius of gyration)",
        path=body_path(model, body.name, "inertia"),
    )


def _parallel_axis(mass: sympy.Expr, distance: sympy.Expr) -> str:
    """m d² as typed, its distance kept whole: m*(L/4)^2."""
    return typed_text(sympy.Mul(mass, sympy.Pow(distance, 2, evaluate=False), evaluate=False))


def _turning_point(model: Model, body: Body) -> tuple[sympy.Expr, str, str] | None:
    """The fixed distance from the body's centre to the point it turns about (or will, once a skid turns
    to rolling), and what that point is; None where there is none."""
    distance = _turning_distance(model, body)
    if distance is not None:
        return distance, "the point it turns about", "a pivot, or a rolling contact"
    distance = _contact_distance(model, body)
    if distance is not None:
        return distance, "its contact point", "it rolls about it once it stops skidding"
    return None


def _contact_distance(model: Model, body: Body) -> sympy.Expr | None:
    """The distance from the body's centre to its friction's contact point, where that is one fixed
    length (a round body skidding on a surface); None otherwise."""
    if body.angle is None or body.inertia == 0:
        return None
    moving = {c.symbol for c in model.coordinates}
    for friction in model.frictions:
        if friction.body != body.name or not friction.contact:
            continue
        squared = sympy.simplify(sum((offset**2 for _, offset in friction.contact), sympy.Integer(0)))
        if squared != 0 and not squared.free_symbols & moving:
            return sympy.sqrt(squared)
    return None


def _turning_distance(model: Model, body: Body) -> sympy.Expr | None:
    """The distance from the body's centre to the point of it at rest, where that is one fixed length
    (the body moved by one coordinate, about a point fixed in it, maybe its centre); None otherwise."""
    if body.angle is None or body.inertia == 0:
        return None
    rate = time_derivative(body.angle, model)
    if rate == 0:
        return None
    speed_squared = sum((time_derivative(expr, model) ** 2 for _, expr in body.position), sympy.Integer(0))
    squared = sympy.simplify(speed_squared / rate**2)
    moving = {c.symbol for c in model.coordinates} | {c.velocity for c in model.coordinates}
    if model.time is not None:
        moving.add(model.time)
    if squared.free_symbols & moving:
        return None
    return sympy.sqrt(squared)  # 0 for a body turning about its centre
