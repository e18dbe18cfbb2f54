"""`rotating`: the frame turning at a constant rate about a vertical axis, for bodies that stay in the
turning vertical plane (a bead on a spinning hoop, a conical pendulum, a car on a banked curve).

    frame: {kind: rotating, rate: omega, bodies: [bead]}
      axis: 0                  the axis is the vertical line x = axis

The element declares the model's frame (`frame: {rate, axis, bodies}`), in which the fictitious-forces
method works. In that frame each listed body feels the centrifugal force m rate^2 x away from the axis, which is the
potential -m rate^2 x^2 / 2 of its distance x from the axis. The Coriolis force is perpendicular to the
plane (the velocity and the axis both lie in it), so it only loads whatever keeps the body in the
plane and changes nothing in it.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from physics.engine.elements.base import NAME, Builder, Fields, text_of, wrap
from physics.engine.text import Path

KIND = "rotating"
FIELDS = {"rate", "bodies", "axis"}
REQUIRED = {"rate", "bodies"}


def expand(name: str, spec: Mapping[str, Any], builder: Builder, path: Path) -> None:
    fields = Fields(spec, path, builder, FIELDS, REQUIRED)
    bodies = spec.get("bodies")
    if (
        not isinstance(bodies, list)
        or not bodies
        or not all(isinstance(b, str) and NAME.match(b) for b in bodies)
    ):
        fields.error("a list of body names", "bodies")
        return
    rate = wrap(fields.text("rate"))
    axis = fields.text("axis", "0")
    builder.frame({"rate": fields.text("rate"), "axis": axis, "bodies": list(bodies)}, path)
    declared = builder.data.get("bodies")
    for index, body in enumerate(bodies):
        entry = declared.get(body) if isinstance(declared, Mapping) else None
        if not isinstance(entry, Mapping) or "mass" not in entry:
            fields.error(f"no body {body!r} defined before this element", "bodies", index)
            continue
        distance = f"{name}Radius{index + 1}"
        builder.potential(
            {
                "bodies": [body],
                "anchor": {"x": axis},
                "distance": distance,
                "energy": f"-{wrap(text_of(entry['mass']))}*{rate}^2*{distance}^2/2",
            },
            (*path, "bodies", index),
        )
