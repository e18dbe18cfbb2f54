"""`surface`: a block sliding on a fixed flat surface with kinetic friction (horizontal by default).

    floor: {kind: surface, body: crate, mass: m, coordinate: x, friction: mu}
      angle: 0                 the surface's angle above the horizontal (then it is an incline)
      direction: down | up     as for `incline`; on a level surface both mean towards +x
      at: {x: 0, y: 0}         where the coordinate is 0

The contact `floor` gives the normal force; friction opposes sliding towards increasing coordinate.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from physics.engine.elements.base import Builder, Fields
from physics.engine.elements.incline import block_on_line
from physics.engine.text import Path

KIND = "surface"
FIELDS = {"body", "mass", "angle", "coordinate", "direction", "at", "friction"}
REQUIRED = {"mass", "coordinate", "friction"}


def expand(name: str, spec: Mapping[str, Any], builder: Builder, path: Path) -> None:
    fields = Fields(spec, path, builder, FIELDS, REQUIRED)
    block_on_line(name, fields, builder, path, angle_default="0")
