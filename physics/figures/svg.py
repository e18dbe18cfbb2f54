"""A small drawing surface in world coordinates (y up, lengths in figure units) written out as SVG text:
lines, polygons, circles, arcs, zigzag springs, arrows, hatched ground and labels. Only presentation
attributes are used (no style attributes), so pages with a strict Content-Security-Policy show it."""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass, field
from html import escape

Point = tuple[float, float]
INK = "#1b1b1b"
FILLS = ("#cfe0f5", "#f6dcc2", "#d6ecd2", "#eadcf2", "#f3efc4", "#f5d0d0")
LABEL_SIZE = 0.42


@dataclass
class Canvas:
    """Shapes kept as SVG elements with their world bounds; `svg()` fits the viewBox around them."""

    elements: list[str] = field(default_factory=list)
    xs: list[float] = field(default_factory=list)
    ys: list[float] = field(default_factory=list)

    def _y(self, y: float) -> float:
        return -y  # SVG's y grows downwards

    def _extend(self, *points: Point) -> None:
        for x, y in points:
            self.xs.append(x)
            self.ys.append(y)

    def _pts(self, points: list[Point]) -> str:
        return " ".join(f"{x:.3f},{self._y(y):.3f}" for x, y in points)

    def line(
        self, a: Point, b: Point, *, width: float = 0.05, dashed: bool = False, color: str = INK
    ) -> None:
        self._extend(a, b)
        dash = ' stroke-dasharray="0.15 0.12"' if dashed else ""
        self.elements.append(
            f'<line x1="{a[0]:.3f}" y1="{self._y(a[1]):.3f}" x2="{b[0]:.3f}" y2="{self._y(b[1]):.3f}" '
            f'stroke="{color}" stroke-width="{width}"{dash} stroke-linecap="round"/>'
        )

    def polyline(self, points: list[Point], *, width: float = 0.05, dashed: bool = False) -> None:
        self._extend(*points)
        dash = ' stroke-dasharray="0.15 0.12"' if dashed else ""
        self.elements.append(
            f'<polyline points="{self._pts(points)}" fill="none" stroke="{INK}" stroke-width="{width}"{dash} '
            'stroke-linejoin="round"/>'
        )

    def polygon(self, points: list[Point], *, fill: str = FILLS[0], width: float = 0.05) -> None:
        self._extend(*points)
        self.elements.append(
            f'<polygon points="{self._pts(points)}" fill="{fill}" stroke="{INK}" stroke-width="{width}" '
            'stroke-linejoin="round"/>'
        )

    def circle(self, c: Point, r: float, *, fill: str = FILLS[0], width: float = 0.05) -> None:
        self._extend((c[0] - r, c[1] - r), (c[0] + r, c[1] + r))
        self.elements.append(
            f'<circle cx="{c[0]:.3f}" cy="{self._y(c[1]):.3f}" r="{r:.3f}" fill="{fill}" stroke="{INK}" '
            f'stroke-width="{width}"/>'
        )

    def text(self, at: Point, label: str, *, size: float = LABEL_SIZE, anchor: str = "middle") -> None:
        """A label centred (vertically) on `at`; italic for symbols, as in the statement's maths."""
        width = size * 0.6 * len(label)
        left = {"start": 0.0, "middle": -width / 2, "end": -width}[anchor]
        self._extend((at[0] + left, at[1] - size / 2), (at[0] + left + width, at[1] + size / 2))
        self.elements.append(
            f'<text x="{at[0]:.3f}" y="{self._y(at[1]) + size * 0.35:.3f}" font-size="{size}" '
            f'text-anchor="{anchor}" font-family="serif" font-style="italic" fill="{INK}">'
            f"{escape(label)}</text>"
        )

    def arc(self, c: Point, r: float, start: float, end: float, *, width: float = 0.04) -> None:
        """An arc from angle `start` to `end` (radians, counter-clockwise from +x)."""
        a = (c[0] + r * math.cos(start), c[1] + r * math.sin(start))
        b = (c[0] + r * math.cos(end), c[1] + r * math.sin(end))
        self._extend(a, b)
        large = 1 if abs(end - start) > math.pi else 0
        sweep = 0 if end > start else 1  # counter-clockwise in world is clockwise on screen
        self.elements.append(
            f'<path d="M {a[0]:.3f} {self._y(a[1]):.3f} A {r:.3f} {r:.3f} 0 {large} {sweep} '
            f'{b[0]:.3f} {self._y(b[1]):.3f}" fill="none" stroke="{INK}" stroke-width="{width}"/>'
        )

    def spring(self, a: Point, b: Point, *, coils: int = 7, amplitude: float = 0.22) -> None:
        """A zigzag from `a` to `b` with short straight ends."""
        dx, dy = b[0] - a[0], b[1] - a[1]
        length = math.hypot(dx, dy) or 1.0
        ux, uy = dx / length, dy / length
        nx, ny = -uy, ux
        lead = 0.12 * length
        points = [a, (a[0] + ux * lead, a[1] + uy * lead)]
        steps = 2 * coils
        for i in range(1, steps):
            t = lead + (length - 2 * lead) * i / steps
            side = amplitude if i % 2 else -amplitude
            points.append((a[0] + ux * t + nx * side, a[1] + uy * t + ny * side))
        points += [(b[0] - ux * lead, b[1] - uy * lead), b]
        self.polyline(points, width=0.045)

    def dashpot(self, a: Point, b: Point, *, bore: float = 0.5) -> None:
        """A damper from `a` to `b`: a rod into an open cylinder from `a`, a piston on a rod from `b`."""
        dx, dy = b[0] - a[0], b[1] - a[1]
        length = math.hypot(dx, dy) or 1.0
        ux, uy = dx / length, dy / length
        nx, ny = -uy * bore / 2, ux * bore / 2

        def at(t: float, side: float = 0.0) -> Point:
            return (a[0] + ux * length * t + nx * side, a[1] + uy * length * t + ny * side)

        self.line(a, at(0.3), width=0.045)
        self.polyline([at(0.75, 1), at(0.3, 1), at(0.3, -1), at(0.75, -1)], width=0.045)  # open towards b
        self.line(at(0.58, 0.8), at(0.58, -0.8), width=0.07)  # the piston
        self.line(at(0.58), b, width=0.045)

    def turning(self, c: Point, r: float) -> None:
        """The sign of a rotation about a vertical axis through `c`, seen from the side: the arc in
        front of the axis, its head saying which way round."""
        start, end = math.radians(200), math.radians(340)
        self.arc(c, r, start, end)
        tip = (c[0] + r * math.cos(end), c[1] + r * math.sin(end))
        self._head(tip, -math.sin(end), math.cos(end), head=0.2)

    def arrow(self, a: Point, b: Point, *, width: float = 0.06, color: str = INK) -> None:
        self.line(a, b, width=width, color=color)
        dx, dy = b[0] - a[0], b[1] - a[1]
        length = math.hypot(dx, dy) or 1.0
        self._head(b, dx / length, dy / length, color=color)

    def _head(self, b: Point, ux: float, uy: float, *, head: float = 0.28, color: str = INK) -> None:
        """An arrowhead with its tip at `b`, pointing along the unit vector (ux, uy)."""
        left = (b[0] - ux * head - uy * head * 0.45, b[1] - uy * head + ux * head * 0.45)
        right = (b[0] - ux * head + uy * head * 0.45, b[1] - uy * head - ux * head * 0.45)
        self._extend(left, right)
        self.elements.append(
            f'<polygon points="{self._pts([b, left, right])}" fill="{color}" stroke="{color}" '
            f'stroke-width="0.02"/>'
        )

    def place(self, other: Canvas, gap: float = 1.0) -> None:
        """Draw `other` to the right of what is here, `gap` apart (independent systems side by side)."""
        if not other.xs:
            return
        shift = (max(self.xs) + gap - min(other.xs)) if self.xs else 0.0
        self.xs.extend(x + shift for x in other.xs)
        self.ys.extend(other.ys)
        self.elements.append(f'<g transform="translate({shift:.3f} 0)">{"".join(other.elements)}</g>')

    def ground(self, a: Point, b: Point, *, below: bool = True) -> None:
        """A fixed surface from `a` to `b`, hatched on its solid side (below, or above for a ceiling)."""
        self.line(a, b, width=0.07)
        dx, dy = b[0] - a[0], b[1] - a[1]
        length = math.hypot(dx, dy) or 1.0
        ux, uy = dx / length, dy / length
        nx, ny = (uy, -ux) if below else (-uy, ux)
        count = max(2, int(length / 0.35))
        for i in range(count + 1):
            t = length * i / count
            p = (a[0] + ux * t, a[1] + uy * t)
            q = (p[0] + 0.25 * nx - 0.2 * ux, p[1] + 0.25 * ny - 0.2 * uy)
            self.line(p, q, width=0.03)

    def svg(self, title: str, description: str, *, margin: float = 0.4, unit: float = 40.0) -> str:
        """The SVG document: role img, named by its <title>, described by its <desc>; `unit` pixels to
        the drawing's unit, its size where a page does not scale it."""
        if not self.xs:
            self._extend((0.0, 0.0), (1.0, 1.0))
        left, right = min(self.xs) - margin, max(self.xs) + margin
        bottom, top = min(self.ys) - margin, max(self.ys) + margin
        width, height = right - left, top - bottom
        view = f"{left:.3f} {-top:.3f} {width:.3f} {height:.3f}"
        # ids unique to the drawing, so that several figures on one page each keep their own names
        ident = "figure-" + hashlib.sha256((title + description).encode()).hexdigest()[:10]
        return (
            f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{view}" role="img" '
            f'width="{width * unit:.0f}" height="{height * unit:.0f}" '
            f'aria-labelledby="{ident}-title {ident}-desc" class="figure">'
            f'<title id="{ident}-title">{escape(title)}</title><desc id="{ident}-desc">{escape(description)}</desc>'
            + "".join(self.elements)
            + "</svg>"
        )
