"""`spring`: a light spring between two bodies, or a body and a fixed point.

    spring: {kind: spring, between: [block, {x: 0}], stiffness: k}
      length: L0               natural length (default 0: the energy is k d^2/2 in the stretch d)
      distance: d              the name of its length in the energy (default: <element>Length)
      attached: false          a body meets its free end (a buffer): it only pushes, so the motion
                               asked about must keep it at or below its natural length (buffers.py)

Generates the potential k (d - L0)^2 / 2 of the distance d between its ends. d is a length: with a
natural length on one axis, the model declares which side of the anchor the body is on (a coordinate
range), as for any potential.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from physics.engine.elements.base import Builder, Fields, text_of, wrap
from physics.engine.text import Path

KIND = "spring"
FIELDS = {"between", "stiffness", "length", "distance", "attached"}
REQUIRED = {"between", "stiffness"}


def expand(name: str, spec: Mapping[str, Any], builder: Builder, path: Path) -> None:
    fields = Fields(spec, path, builder, FIELDS, REQUIRED)
    ends = spec.get("between")
    if not isinstance(ends, list) or len(ends) != 2:
        fields.error("two ends: body names, or one body and a point {x: ..., y: ...}", "between")
        return
    bodies = [end for end in ends if isinstance(end, str)]
    points = [end for end in ends if isinstance(end, Mapping)]
    if not bodies or len(bodies) + len(points) != 2:
        fields.error("two ends: body names, or one body and a point {x: ..., y: ...}", "between")
        return
    distance = fields.name("distance", f"{name}Length")
    stiffness = wrap(fields.text("stiffness"))
    stretch = f"({distance} - {wrap(fields.text('length'))})" if fields.has("length") else distance
    entry: dict[str, Any] = {"bodies": bodies, "distance": distance, "energy": f"{stiffness}*{stretch}^2/2"}
    attached = spec.get("attached", True)
    if not isinstance(attached, bool):
        fields.error(
            "true (the default: the body is fixed to the spring's end) or false (it only meets it)",
            "attached",
        )
    elif not attached:
        if not fields.has("length"):
            fields.error(
                "a spring that only pushes needs its natural length, where the body meets it", "attached"
            )
            return
        entry["reach"] = fields.text("length")
    if points:
        entry["anchor"] = {str(axis): text_of(value) for axis, value in points[0].items()}
    builder.potential(entry, path)
