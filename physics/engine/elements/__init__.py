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
from physics.engine.model import AuthoredElement
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
    elements: tuple[AuthoredElement, ...] = ()  # what the author wrote, for the figures

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


def _in_dependency_order(elements: Mapping[Any, Any], written: Any) -> list[tuple[Any, Any]]:
    """The elements, each after those that define the bodies it hangs from or pulls on (a pulley after
    the blocks at its ends, a pendulum after its pivot's), otherwise in the order written: a mapping has
    no order, and a tool that sorts the keys must not break the model."""
    defined = set(written) if isinstance(written, Mapping) else set()
    pending = list(elements.items())
    ordered: list[tuple[Any, Any]] = []
    while pending:
        ready = next((item for item in pending if _needs(item[1]) <= defined), pending[0])
        pending.remove(ready)
        ordered.append(ready)
        defined |= _defines(*ready)
    return ordered


def _needs(spec: Any) -> set[str]:
    """The bodies an element needs defined before it (by hand or by another element)."""
    if not isinstance(spec, Mapping):
        return set()
    named: list[Any] = []
    if spec.get("kind") == "pulley" and isinstance(spec.get("ends"), list):
        named = [end.get("body") for end in spec["ends"] if isinstance(end, Mapping)]
    elif spec.get("kind") == "pendulum":
        named = [spec.get("pivot")]
    elif spec.get("kind") == "rotating" and isinstance(spec.get("bodies"), list):
        named = spec["bodies"]
    return {n for n in named if isinstance(n, str)}


def _defines(name: Any, spec: Any) -> set[str]:
    """The bodies an element defines: its own (`body`, default its name) and a wedge's."""
    if not isinstance(spec, Mapping) or spec.get("kind") not in {"incline", "surface", "rolling", "pendulum"}:
        return set()
    found = {spec.get("body", name)}
    wedge = spec.get("wedge")
    if isinstance(wedge, Mapping):
        found.add(wedge.get("body"))
    return {n for n in found if isinstance(n, str)}


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
    ordered = _in_dependency_order(elements, builder.data.get("bodies"))
    for name, spec in ordered:
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
    return Expanded(builder.data, dict(builder.origins), _authored(ordered, builder))


def _authored(written: list[tuple[Any, Any]], builder: Builder) -> tuple[AuthoredElement, ...]:
    """Each element as written, with the names of the bodies, constraints, potentials and coordinates
    its expansion generated (read back from the origins the Builder kept)."""
    made: dict[str, dict[str, list[str]]] = {name: {} for name, _ in written}
    coordinates = builder.data.get("coordinates") or []
    for (section, key), path in builder.origins.items():
        if len(path) < 2 or path[1] not in made:
            continue
        if section == "coordinates" and isinstance(key, int):
            key = coordinates[key]
        elif section == "potentials":
            key = f"potential{key}"  # the name load_model gives the potential at that index
        made[str(path[1])].setdefault(section, []).append(str(key))
    return tuple(
        AuthoredElement(
            kind=str(spec["kind"]),
            name=name,
            fields=dict(spec),
            bodies=tuple(made[name].get("bodies", ())),
            constraints=tuple(made[name].get("constraints", ())),
            potentials=tuple(made[name].get("potentials", ())),
            coordinates=tuple(made[name].get("coordinates", ())),
        )
        for name, spec in written
    )
