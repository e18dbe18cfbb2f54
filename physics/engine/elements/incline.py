"""`incline`: a block on an incline, fixed or on a movable wedge, optionally with kinetic friction.

    ramp: {kind: incline, body: block, mass: m, angle: theta, coordinate: s}
      direction: down | up     the coordinate increases down the slope (default) or up it, towards +x
      at: {x: 0, y: 0}         where the coordinate is 0 (a point of the incline)
      friction: mu             kinetic friction, opposing sliding towards increasing coordinate
      wedge: {body: wedge, mass: M, coordinate: X}   the incline is a wedge free to slide on a floor

Generates the block (and wedge), the contact `ramp` (its force is the normal force) and, with a wedge,
the floor contact `rampFloor`. A wedge implies the model's frame (`frame: {body: wedge}`, unless another
is declared): the fictitious-forces method works in it.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from physics.engine.elements.base import Builder, Fields
from physics.engine.elements.line import Line
from physics.engine.text import Path

KIND = "incline"
FIELDS = {"body", "mass", "angle", "coordinate", "direction", "at", "friction", "wedge"}
REQUIRED = {"mass", "angle", "coordinate"}


def expand(name: str, spec: Mapping[str, Any], builder: Builder, path: Path) -> None:
    fields = Fields(spec, path, builder, FIELDS, REQUIRED)
    block_on_line(name, fields, builder, path)


def block_on_line(
    name: str, fields: Fields, builder: Builder, path: Path, angle_default: str | None = None
) -> str:
    """The block and its contact; returns the block's name. Shared with `surface`."""
    body = fields.name("body", name)
    coordinate = fields.name("coordinate")
    angle = fields.slope("angle", angle_default)
    direction = fields.choice("direction", ("down", "up"))
    origin = fields.point("at")
    wedge = fields.sub("wedge")
    if wedge is None:
        builder.coordinate(coordinate, (*path, "coordinate"))
        line = Line(angle, direction, origin, origin)
    else:
        parts = Fields(
            wedge, (*path, "wedge"), builder, {"body", "mass", "coordinate"}, {"mass", "coordinate"}
        )
        wedge_body = parts.name("body", "wedge")
        wedge_coordinate = parts.name("coordinate")
        builder.coordinate(wedge_coordinate, (*path, "wedge", "coordinate"))
        builder.coordinate(coordinate, (*path, "coordinate"))
        builder.body(
            wedge_body,
            {"mass": parts.text("mass"), "position": {"x": wedge_coordinate, "y": origin[1]}},
            (*path, "wedge"),
        )
        builder.frame({"body": wedge_body}, (*path, "wedge"), implied=True)
        builder.constraint(
            f"{name}Floor",
            "surface",
            f"y_{wedge_body}" if origin[1] == "0" else f"y_{wedge_body} - ({origin[1]})",
            (*path, "wedge"),
        )
        line = Line(angle, direction, (wedge_coordinate, origin[1]), (f"x_{wedge_body}", f"y_{wedge_body}"))
    builder.body(body, {"mass": fields.text("mass"), "position": line.position(coordinate)}, path)
    builder.constraint(name, "surface", line.clearance(body), path)
    if fields.has("friction"):
        if wedge is not None:
            fields.error("kinetic friction is supported on a fixed incline only", "friction")
        else:
            builder.friction(
                {
                    "constraint": name,
                    "body": body,
                    "coefficient": fields.text("friction"),
                    "sliding": coordinate,
                },
                (*path, "friction"),
            )
    return body
