"""`pulley`: a string over a fixed pulley, massless or with a moment of inertia.

    string: {kind: pulley, ends: [{body: m1, pulls: up}, {body: m2, pulls: up}]}
      pulls: up | down | left | right | {x: ..., y: ...}   the unit direction in which the string pulls
                               that body (towards the pulley), constant while it moves
      {under: m2, pulls: up}   instead of an end on a body: the string runs on under a light movable
                               pulley carried by m2 to a fixed point, so both its sides pull m2
      inertia: I, radius: R, mass: M, at: {x: 0, y: 0}, body: wheel
                               a pulley with inertia I turning without slipping on the string

Massless: one constraint `string` whose force is the tension. Under a movable pulley the string's two
sides both pull its body, so that body's displacement counts twice in the string's length (it moves
half as far as a free end would) and it feels twice the tension. With inertia the two sides have different
tensions, `string1` (first end) and `string2` (second end); the pulley is a body held by its axle
(`stringAxleX`, `stringAxleY`: the axle's force on the pulley) and turns counterclockwise as the string
pays out on the first end's side (the left side, for strings hanging down from it).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import sympy

from physics.answer_text import typed_text
from physics.engine.elements.base import DIRECTIONS, Builder, Fields, offset, text_of, wrap
from physics.engine.text import Path
from physics.errors import SpecError

KIND = "pulley"
FIELDS = {"ends", "inertia", "radius", "mass", "at", "body"}
REQUIRED = {"ends"}


def expand(name: str, spec: Mapping[str, Any], builder: Builder, path: Path) -> None:
    fields = Fields(spec, path, builder, FIELDS, REQUIRED)
    ends = spec.get("ends")
    if not isinstance(ends, list) or len(ends) != 2:
        fields.error("two ends, one on each side of the pulley", "ends")
        return
    massive = fields.has("inertia")
    wheel = fields.name("body", f"{name}Wheel")
    at = fields.point("at") if massive else ("0", "0")
    # each end's pull direction . (its position - the axle): Cartesian text, and in the coordinates
    slack: list[str] = []
    lengths: list[sympy.Expr] = []
    for index, end in enumerate(ends):
        where: Path = (*path, "ends", index)
        if not isinstance(end, Mapping):
            builder.errors.append(SpecError("expected {body: ..., pulls: ...}", where))
            return
        parts = Fields(end, where, builder, {"body", "pulls", "under"}, {"pulls"})
        under = "under" in end
        if under == ("body" in end):
            parts.error("either the body at this end or the body whose movable pulley it runs under", "body")
            return
        if under and massive:
            parts.error("a movable pulley is light here: give the pulley no inertia", "under")
            return
        body = parts.name("under" if under else "body")
        sides = 2 if under else 1  # both sides of a movable pulley's loop pull its body
        direction = _direction(end.get("pulls"), parts)
        position = builder.position(body)
        if position is None:
            parts.error(f"no body {body!r} defined before this element", "body")
            return
        if direction is None:
            return
        axes = [
            (axis, c, i) for i, (axis, c) in enumerate(zip(("x", "y"), direction, strict=True)) if c != "0"
        ]
        if any(axis not in position for axis, _, _ in axes):
            parts.error(f"body {body!r} has no position along the direction it is pulled", "pulls")
            return
        cartesian = [f"{axis}_{body}" for axis, _, _ in axes]
        if massive:
            cartesian = [
                offset(symbol, f"{axis}_{wheel}")
                for symbol, (axis, _, _) in zip(cartesian, axes, strict=True)
            ]
        slack.append(
            " + ".join(_scaled(c, symbol, sides) for symbol, (_, c, _) in zip(cartesian, axes, strict=True))
        )
        length = builder.expr(
            " + ".join(_scaled(c, f"({wrap(position[axis])} - {wrap(at[i])})", sides) for axis, c, i in axes),
            where,
        )
        if length is None:
            return
        lengths.append(length)
    constant = sympy.simplify(-(lengths[0] + lengths[1]))
    if constant.free_symbols - set(builder.symbols.values()):
        movable = any(isinstance(end, Mapping) and "under" in end for end in ends)
        fields.error(
            f"the ends' positions change the string's length by {typed_text(constant)}; "
            + (
                "a movable pulley moves half as far as the string's free end (both its sides shorten)"
                if movable
                else "make them move together"
            ),
            "ends",
        )
        return
    extra = "" if constant == 0 else f" + ({sympy.sstr(constant)})"
    if not massive:
        builder.constraint(name, "string", f"{slack[0]} + {slack[1]}{extra}", path)
        return
    for key in ("radius", "mass"):
        if not fields.has(key):
            fields.error("required with inertia", key)
    radius = wrap(fields.text("radius"))
    # the angle keeps the first segment's slack at 0: R phi = -(its pull . relative position)
    builder.body(
        wheel,
        {
            "mass": fields.text("mass"),
            "inertia": fields.text("inertia"),
            "position": {"x": at[0], "y": at[1]},
            "angle": f"-({sympy.sstr(lengths[0])})/{radius}",
        },
        path,
    )
    builder.constraint(f"{name}1", "string", f"{slack[0]} + {radius}*phi_{wheel}", path)
    builder.constraint(f"{name}2", "string", f"{slack[1]} - {radius}*phi_{wheel}{extra}", path)
    builder.constraint(f"{name}AxleX", "other", offset(f"x_{wheel}", at[0]), path)
    builder.constraint(f"{name}AxleY", "other", offset(f"y_{wheel}", at[1]), path)


def _direction(value: Any, fields: Fields) -> tuple[str, str] | None:
    if isinstance(value, str) and value in DIRECTIONS:
        return DIRECTIONS[value]
    if isinstance(value, Mapping) and set(value) <= {"x", "y"} and value:
        x, y = text_of(value.get("x", 0)), text_of(value.get("y", 0))
        unit = fields.builder.expr(f"({x})^2 + ({y})^2", (*fields.path, "pulls"))
        if unit is not None and sympy.simplify(unit - 1) != 0:
            fields.error("the direction must be a unit vector", "pulls")
            return None
        return (x, y)
    fields.error(f"expected one of {sorted(DIRECTIONS)} or a unit vector {{x: ..., y: ...}}", "pulls")
    return None


def _scaled(component: str, symbol: str, sides: int = 1) -> str:
    """`sides * component * symbol`, written plainly for the unit components of up, down, left and right."""
    if component in ("1", "-1"):
        sign = "-" if component == "-1" else ""
        return f"{sign}{symbol}" if sides == 1 else f"{sign}{sides}*{symbol}"
    return f"{wrap(component) if sides == 1 else f'{sides}*{wrap(component)}'}*{symbol}"
