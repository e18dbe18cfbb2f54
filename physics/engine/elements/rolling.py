"""`rolling`: a round body rolling without slipping along a fixed straight surface (level or inclined).

    wheel: {kind: rolling, mass: m, radius: R, inertia: "m*R^2/2", coordinate: s}
      angle: theta             the surface's angle above the horizontal (default 0)
      direction: down | up     the coordinate runs down (default) or up the slope, towards +x
      at: {x: 0, y: 0}         where the centre is when the coordinate is 0
      body: wheel              the body's name (default: the element's)
      friction: mu, spin: phi  instead of rolling, the body slides with kinetic friction mu at its contact
                               point, turning by its own angle coordinate `spin` (counterclockwise)

The centre moves parallel to the surface; the body turns clockwise as it moves towards +x. Generates
the contact `wheel` (normal force) and `wheelRolling` (the friction force the surface exerts, positive
pointing back along the coordinate's direction). With `friction`, no `<name>Rolling`: the friction
opposes the contact point's slip towards increasing coordinate, and its torque turns the body.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from physics.engine.elements.base import Builder, Fields, wrap
from physics.engine.elements.line import Line
from physics.engine.text import Path

KIND = "rolling"
FIELDS = {"body", "mass", "radius", "inertia", "angle", "coordinate", "direction", "at", "friction", "spin"}
REQUIRED = {"mass", "radius", "inertia", "coordinate"}


def expand(name: str, spec: Mapping[str, Any], builder: Builder, path: Path) -> None:
    fields = Fields(spec, path, builder, FIELDS, REQUIRED)
    body = fields.name("body", name)
    coordinate = fields.name("coordinate")
    radius = wrap(fields.text("radius"))
    origin = fields.point("at")
    angle = fields.slope("angle", "0")
    direction = fields.choice("direction", ("down", "up"))
    line = Line(angle, direction, origin, origin)
    sliding = fields.has("friction")
    if sliding != fields.has("spin"):
        fields.error("a sliding body needs both `friction` and `spin` (its angle coordinate)", "spin")
    spin = fields.name("spin") if sliding else ""
    builder.coordinate(coordinate, (*path, "coordinate"))
    if sliding:
        builder.coordinate(spin, (*path, "spin"))
    builder.body(
        body,
        {
            "mass": fields.text("mass"),
            "inertia": fields.text("inertia"),
            "position": line.position(coordinate),
            "angle": spin if sliding else f"-{coordinate}/{radius}",
        },
        path,
    )
    builder.constraint(name, "surface", line.clearance(body), path)
    if not sliding:
        builder.constraint(f"{name}Rolling", "rolling", f"-({line.along(body)} + {radius}*phi_{body})", path)
        return
    # the contact point is a radius from the centre against the surface's normal
    wrapped = wrap(angle)
    sign = "-" if direction == "down" else ""
    contact = {"x": f"{sign}{radius}*sin({wrapped})", "y": f"-{radius}*cos({wrapped})"}
    builder.friction(
        {
            "constraint": name,
            "body": body,
            "coefficient": fields.text("friction"),
            "sliding": coordinate,
            "contact": contact,
        },
        (*path, "friction"),
    )
