"""Composable elements: a classic problem's model in a few lines, expanded into the low-level sections.

    elements:
      ramp: {kind: incline, mass: m, angle: theta, coordinate: s, friction: mu}

Each kind is one module here (`incline`, `surface`, `pulley`, `spring`, `pendulum`, `rolling`,
`rotating`), registered in `KINDS`. `expand_elements` runs before `load_model` reads the model: every element adds ordinary
coordinates, bodies, constraints, friction and potentials, in order, after the hand-written ones (which
stay available and may be mixed with elements; a pulley may tie bodies from either). A fault in what an
element generated is reported at the element's path.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import ModuleType
from typing import Any

import sympy

from physics.engine.elements import incline, pendulum, pulley, rolling, rotating, spring, surface
from physics.engine.elements.base import NAME, Builder
from physics.engine.text import Path
from physics.errors import SpecError, SpecErrors

Expand = Callable[[str, Mapping[str, Any], Builder, Path], None]
_MODULES: tuple[ModuleType, ...] = (incline, surface, pulley, spring, pendulum, rolling, rotating)
KINDS: dict[str, Expand] = {module.KIND: module.expand for module in _MODULES}
MAX_ELEMENTS = 16


@dataclass(frozen=True)
class Expanded:
    """The low-level model section, and where each generated entry came from."""

    data: Mapping[str, Any]
    origins: Mapping[tuple[str, str | int], Path] = field(default_factory=dict)

    def relocate(self, errors: SpecErrors) -> SpecErrors:
        """The same faults, those inside generated entries moved to the element that generated them."""
        moved: list[SpecError] = []
        for error in errors.errors:
            key = (str(error.path[0]), error.path[1]) if len(error.path) >= 2 else None
            origin = self.origins.get(key) if key is not None else None
            if origin is None:
                moved.append(error)
            else:
                where = ".".join(map(str, error.path))
                moved.append(SpecError(f"{error.message} (in the generated {where})", origin))
        return SpecErrors(moved)


def expand_elements(data: Any, symbols: Mapping[str, sympy.Symbol]) -> Expanded:
    """The model with its `elements` expanded; SpecErrors (at the elements' paths) if any is malformed."""
    if not isinstance(data, Mapping) or "elements" not in data:
        return Expanded(data)
    elements = data["elements"]
    builder = Builder({k: v for k, v in data.items() if k != "elements"}, symbols)
    if not isinstance(elements, Mapping):
        raise SpecErrors([SpecError("expected a mapping of element names to elements", ("elements",))])
    if len(elements) > MAX_ELEMENTS:
        raise SpecErrors([SpecError(f"at most {MAX_ELEMENTS} entries", ("elements",))])
    for name, spec in elements.items():
        path: Path = ("elements", str(name))
        if not isinstance(name, str) or not NAME.match(name):
            builder.errors.append(SpecError("an element's name is a plain name (letters and digits)", path))
            continue
        if not isinstance(spec, Mapping):
            builder.errors.append(SpecError("expected a mapping with a kind", path))
            continue
        kind = spec.get("kind")
        if kind not in KINDS:
            builder.errors.append(
                SpecError(f"unknown kind {kind!r}; expected one of {sorted(KINDS)}", (*path, "kind"))
            )
            continue
        KINDS[str(kind)](name, spec, builder, path)
    if builder.errors:
        raise SpecErrors(builder.errors)
    return Expanded(builder.data, dict(builder.origins))
