"""`rolling`: a round body rolling without slipping along a fixed straight surface (level or inclined).

    wheel: {kind: rolling, mass: m, radius: R, inertia: "m*R^2/2", coordinate: s}
      angle: theta             the surface's angle above the horizontal (default 0)
      direction: down | up     the coordinate runs down (default) or up the slope, towards +x
      at: {x: 0, y: 0}         where the centre is when the coordinate is 0
      body: wheel              the body's name (default: the element's)

The centre moves parallel to the surface; the body turns clockwise as it moves towards +x. Generates
the contact `wheel` (normal force) and `wheelRolling` (the friction force the surface exerts, positive
pointing back along the coordinate's direction).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from physics.engine.elements.base import Builder, Fields, wrap
from physics.engine.elements.line import Line
from physics.engine.text import Path

KIND = "rolling"
FIELDS = {"body", "mass", "radius", "inertia", "angle", "coordinate", "direction", "at"}
REQUIRED = {"mass", "radius", "inertia", "coordinate"}


def expand(name: str, spec: Mapping[str, Any], builder: Builder, path: Path) -> None:
    fields = Fields(spec, path, builder, FIELDS, REQUIRED)
    body = fields.name("body", name)
    coordinate = fields.name("coordinate")
    radius = wrap(fields.text("radius"))
    origin = fields.point("at")
    line = Line(fields.text("angle", "0"), fields.choice("direction", ("down", "up")), origin, origin)
    builder.coordinate(coordinate, (*path, "coordinate"))
    builder.body(
        body,
        {
            "mass": fields.text("mass"),
            "inertia": fields.text("inertia"),
            "position": line.position(coordinate),
            "angle": f"-{coordinate}/{radius}",
        },
        path,
    )
    builder.constraint(name, "surface", line.clearance(body), path)
    builder.constraint(f"{name}Rolling", "rolling", f"-({line.along(body)} + {radius}*phi_{body})", path)
