"""A straight line at an angle to the horizontal: where a body on it is, and its gaps (shared geometry)."""

from __future__ import annotations

from dataclasses import dataclass

from physics.engine.elements.base import offset, plus


@dataclass(frozen=True)
class Line:
    """A line through `origin` at `angle` above the horizontal; the coordinate runs `direction` along it
    (down: down the slope towards +x; up: up the slope towards +x). `origin` is written twice: in the
    coordinates (for positions) and in Cartesian symbols (for gaps), as a moving wedge needs."""

    angle: str
    direction: str  # "down" or "up"
    origin: tuple[str, str] = ("0", "0")
    cartesian_origin: tuple[str, str] = ("0", "0")

    def position(self, coordinate: str) -> dict[str, str]:
        """Where a point `coordinate` along the line is, in the coordinates."""
        sign = "-" if self.direction == "down" else ""
        x = plus(self.origin[0], f"{coordinate}*cos({self.angle})")
        y = f"{sign}{coordinate}*sin({self.angle})"
        if self.origin[1] not in ("0", "0.0"):
            y = f"({self.origin[1]}) {'-' if sign else '+'} {coordinate}*sin({self.angle})"
        return {"x": x, "y": y}

    def _relative(self, body: str) -> tuple[str, str]:
        return offset(f"x_{body}", self.cartesian_origin[0]), offset(f"y_{body}", self.cartesian_origin[1])

    def clearance(self, body: str) -> str:
        """Height of the body above the line, measured along its normal (a surface's gap)."""
        x, y = self._relative(body)
        if self.direction == "down":
            return f"{x}*sin({self.angle}) + {y}*cos({self.angle})"
        return f"{y}*cos({self.angle}) - {x}*sin({self.angle})"

    def along(self, body: str) -> str:
        """Distance of the body along the line in the coordinate's direction (for rolling)."""
        x, y = self._relative(body)
        sign = "-" if self.direction == "down" else "+"
        return f"{x}*cos({self.angle}) {sign} {y}*sin({self.angle})"
