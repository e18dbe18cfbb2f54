"""`pendulum`: a simple pendulum (a bob on a light string or rod) or a rigid one (a body on a pivot).

    bob: {kind: pendulum, mass: m, length: L, coordinate: phi}
      pivot: {x: 0, y: 0}      the fixed pivot, or the name of a body it hangs from (a cart)
      body: bob                the swinging body's name (default: the element's)
      inertia: I, distance: d  a rigid pendulum: moment of inertia about its centre of mass, which is d
                               from the pivot (instead of `length`)

The coordinate is the angle from the downward vertical, counterclockwise. Simple: the constraint `bob`
(the string; its force is the tension). Rigid: `bobPivotX`, `bobPivotY` (the pivot's force on the body).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from physics.engine.elements.base import Builder, Fields, offset, plus, wrap
from physics.engine.text import Path

KIND = "pendulum"
FIELDS = {"body", "mass", "length", "coordinate", "pivot", "inertia", "distance"}
REQUIRED = {"mass", "coordinate"}


def expand(name: str, spec: Mapping[str, Any], builder: Builder, path: Path) -> None:
    fields = Fields(spec, path, builder, FIELDS, REQUIRED)
    body = fields.name("body", name)
    angle = fields.name("coordinate")
    px, py = fields.point("pivot") if not isinstance(spec.get("pivot"), str) else ("0", "0")
    cx, cy = px, py  # the pivot in Cartesian symbols, for the constraints
    if isinstance(spec.get("pivot"), str):  # hung from a moving body: its position is the pivot
        carrier = fields.name("pivot")
        where = builder.position(carrier)
        if where is None:
            fields.error(f"no body {carrier!r} defined before this element", "pivot")
            return
        px, py = where.get("x", "0"), where.get("y", "0")
        cx, cy = (f"x_{carrier}" if "x" in where else "0"), (f"y_{carrier}" if "y" in where else "0")
    rigid = fields.has("inertia")
    arm_key = "distance" if rigid else "length"
    if not fields.has(arm_key):
        fields.error(
            "required" + (" for a rigid pendulum" if rigid else " (or inertia and distance)"), arm_key
        )
    if rigid and fields.has("length"):
        fields.error("a rigid pendulum gives its pivot-to-centre distance, not a length", "length")
    arm = wrap(fields.text(arm_key))
    builder.coordinate(angle, (*path, "coordinate"))
    position = {"x": plus(px, f"{arm}*sin({angle})"), "y": _minus(py, f"{arm}*cos({angle})")}
    entry: dict[str, Any] = {"mass": fields.text("mass"), "position": position}
    if not rigid:
        builder.body(body, entry, path)
        dx, dy = offset(f"x_{body}", cx), offset(f"y_{body}", cy)
        builder.constraint(name, "string", f"{arm} - sqrt({dx}^2 + {dy}^2)", path)
        return
    builder.body(body, {**entry, "inertia": fields.text("inertia"), "angle": angle}, path)
    builder.constraint(f"{name}PivotX", "other", f"{offset(f'x_{body}', cx)} - {arm}*sin(phi_{body})", path)
    builder.constraint(f"{name}PivotY", "other", f"{offset(f'y_{body}', cy)} + {arm}*cos(phi_{body})", path)


def _minus(base: str, term: str) -> str:
    return f"-{term}" if base in ("0", "0.0") else f"{wrap(base)} - {term}"
