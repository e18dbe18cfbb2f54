"""What every element shares: reading its fields, and writing low-level entries with their origin.

An element is data in, data out: it reads its own fields (text, as the author wrote them) and adds
entries to the model's low-level sections (coordinates, bodies, constraints, friction, potentials),
which `load_model` then validates and reads like hand-written ones. Each generated entry remembers the
element it came from, so a fault found later is reported at the element's path.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import sympy

from physics.engine.text import Path, read_expr
from physics.errors import SpecError

NAME = re.compile(r"^[A-Za-z][A-Za-z0-9]*$")
# The directions a string can pull in, as (x, y) text; anything else is a mapping {x: ..., y: ...}.
DIRECTIONS = {"up": ("0", "1"), "down": ("0", "-1"), "left": ("-1", "0"), "right": ("1", "0")}


def wrap(text: str) -> str:
    """Parenthesized, so an author's `a + b` stays one term inside the generated expressions."""
    return text if NAME.match(text) else f"({text})"


@dataclass
class Builder:
    """The model section being expanded; `origins` maps each generated entry to its element's path."""

    data: dict[str, Any]
    symbols: Mapping[str, sympy.Symbol]
    errors: list[SpecError] = field(default_factory=list)
    origins: dict[tuple[str, str | int], Path] = field(default_factory=dict)
    frame_implied: bool = False  # the model's frame came from an element that only implies one (a wedge)

    def _section(self, key: str, kind: type) -> Any:
        current = self.data.get(key)
        if current is None:
            current = kind()
        elif isinstance(current, Mapping | list):
            current = kind(current)  # a copy: the author's document is never changed
        else:
            return None  # load_model reports the malformed section itself
        self.data[key] = current
        return current

    def coordinate(self, name: str, path: Path) -> None:
        coordinates = self._section("coordinates", list)
        if coordinates is not None and name not in coordinates:
            self.origins[("coordinates", len(coordinates))] = path
            coordinates.append(name)

    def _named(self, section: str, name: str, entry: dict[str, Any], path: Path) -> None:
        entries = self._section(section, dict)
        if entries is None:
            return
        if name in entries:
            self.errors.append(SpecError(f"{section[:-1]} {name!r} is already defined", path))
            return
        entries[name] = entry
        self.origins[(section, name)] = path

    def body(self, name: str, entry: dict[str, Any], path: Path) -> None:
        self._named("bodies", name, entry, path)

    def constraint(self, name: str, kind: str, gap: str, path: Path) -> None:
        self._named("constraints", name, {"kind": kind, "gap": gap}, path)

    def _listed(self, section: str, entry: dict[str, Any], path: Path) -> None:
        entries = self._section(section, list)
        if entries is not None:
            self.origins[(section, len(entries))] = path
            entries.append(entry)

    def friction(self, entry: dict[str, Any], path: Path) -> None:
        self._listed("friction", entry, path)

    def potential(self, entry: dict[str, Any], path: Path) -> None:
        self._listed("potentials", entry, path)

    def frame(self, entry: dict[str, Any], path: Path, implied: bool = False) -> None:
        """The model's one frame: declared by an element (a rotating frame) or implied (a wedge's), which
        gives way to a declared one."""
        if "frame" in self.data and (implied or not self.frame_implied):
            if not implied:
                self.errors.append(SpecError("the model already has a frame", path))
            return
        self.data["frame"] = entry
        self.frame_implied = implied
        for key in entry:  # a declared frame's fields are the element's own (rate, axis, bodies)
            self.origins[("frame", key)] = path if implied else (*path, key)

    def position(self, body: str) -> dict[str, str] | None:
        """A body's position as text per axis (hand-written or generated), if it is defined yet."""
        entry = (
            (self.data.get("bodies") or {}).get(body)
            if isinstance(self.data.get("bodies"), Mapping)
            else None
        )
        if not isinstance(entry, Mapping) or not isinstance(entry.get("position"), Mapping):
            return None
        return {str(axis): text_of(value) for axis, value in entry["position"].items()}

    def expr(self, text: str, path: Path) -> sympy.Expr | None:
        """`text` read over the symbols and coordinates (to reason about geometry), or None after an error."""
        coordinates = self.data.get("coordinates")
        names = [c for c in coordinates if isinstance(c, str)] if isinstance(coordinates, list) else []
        scope = {**{c: sympy.Symbol(c, real=True) for c in names}, **self.symbols}
        try:
            return read_expr(text, scope, path)
        except SpecError as error:
            self.errors.append(error)
            return None


def text_of(value: Any) -> str:
    return repr(value) if isinstance(value, int | float) and not isinstance(value, bool) else str(value)


class Fields:
    """One element's fields: checked against what the element accepts, read with their paths."""

    def __init__(
        self, spec: Mapping[str, Any], path: Path, builder: Builder, allowed: set[str], required: set[str]
    ) -> None:
        self.spec, self.path, self.builder = spec, path, builder
        for key in spec:
            if key not in allowed | {"kind"}:
                self.error(f"unknown field {key!r}; expected one of {sorted(allowed)}", key)
        for key in sorted(required - set(spec)):
            self.error("required", key)

    def error(self, message: str, *where: str | int) -> None:
        self.builder.errors.append(SpecError(message, (*self.path, *where)))

    def has(self, key: str) -> bool:
        return key in self.spec

    def text(self, key: str, default: str | None = None) -> str:
        """An expression field as text ("" after an error: the element still expands, to find more faults)."""
        value = self.spec.get(key, default)
        if value is None:
            return ""
        if isinstance(value, bool) or not isinstance(value, str | int | float):
            self.error("expected an expression (text or number)", key)
            return ""
        return text_of(value)

    def slope(self, key: str, default: str | None = None) -> str:
        """A surface's angle above the horizontal, as text. A plain number is radians: one past a right
        angle (`angle: 30`, degrees meant) would be a surface steeper than vertical, derived as it is."""
        text = self.text(key, default)
        try:
            value = float(text)
        except ValueError:
            return text
        if abs(value) > math.pi / 2:
            self.error(
                f"{text} radians is {math.degrees(value):.0f}°, steeper than vertical: angles are in "
                f"radians, so {text}° is written {text}*pi/180",
                key,
            )
        return text

    def name(self, key: str, default: str | None = None) -> str:
        value = self.spec.get(key, default)
        if value is None:
            return "x"  # a required field: its absence is already reported
        if not isinstance(value, str) or not NAME.match(value):
            self.error("expected a plain name (letters and digits)", key)
            return default or "x"
        return value

    def choice(self, key: str, options: tuple[str, ...]) -> str:
        value = self.spec.get(key, options[0])
        if value not in options:
            self.error(f"expected one of {list(options)}", key)
            return options[0]
        return str(value)

    def point(self, key: str) -> tuple[str, str]:
        """A point {x, y} as text; (0, 0) when absent."""
        value = self.spec.get(key)
        if value is None:
            return ("0", "0")
        if not isinstance(value, Mapping) or set(value) - {"x", "y"}:
            self.error("expected a point {x: ..., y: ...}", key)
            return ("0", "0")
        return (text_of(value.get("x", 0)), text_of(value.get("y", 0)))

    def sub(self, key: str) -> Mapping[str, Any] | None:
        value = self.spec.get(key)
        if value is None:
            return None
        if not isinstance(value, Mapping):
            self.error("expected a mapping", key)
            return None
        return value


def offset(symbol: str, origin: str) -> str:
    """`symbol - origin`, written plainly when the origin is 0."""
    return symbol if origin in ("0", "0.0") else f"({symbol} - {wrap(origin)})"


def plus(base: str, term: str) -> str:
    """`base + term`, dropping a zero base."""
    return term if base in ("0", "0.0") else f"{wrap(base)} + {term}"
