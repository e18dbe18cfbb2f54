"""What every figure shares: the Figure being drawn, the numbers it is drawn at (Values), and how
symbols and bodies are labelled. The expected reasons a figure cannot be drawn are NotDrawable: a
parameter without a real number at those values (NotNumeric), a path none of whose points has one.
Every other failure is a bug."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy

from physics.engine.model import Body, Model
from physics.figures.svg import Canvas
from physics.wording import symbol_label

BLOCK = 1.0  # side of a block, in figure units
SLOPE = 7.0  # length of an incline's surface
# Angles are drawn at their values within this range; outside it the figure says it is not to scale.
READABLE_ANGLES = (math.radians(5), math.radians(75))


class NotDrawable(Exception):
    """The one expected reason a figure is drawn as its bodies side by side: it names what could not be
    drawn. Any other exception while drawing is a bug, and surfaces."""


class NotNumeric(NotDrawable, ValueError):
    """A parameter's expression has no real value at the figure's values (a symbol left over, a complex
    number). A ValueError too, for the free-body diagrams that skip such a force."""


@dataclass
class Figure:
    canvas: Canvas = field(default_factory=Canvas)
    said: list[str] = field(default_factory=list)
    # Coordinates a drawing placed its bodies at where it does not draw the model's state (a pendulum
    # swung aside to show that it swings): the free-body diagrams are drawn there too.
    placed: dict[sympy.Symbol, float] = field(default_factory=dict)
    # what is not drawn at its value ("α = 2.0° drawn as 8°"): the figure then says it is not to scale
    unscaled: list[str] = field(default_factory=list)
    # what the picture was chosen from: "elements" (those the author wrote), "low-level model"
    # (recognised from hand-written sections), or None before it is drawn
    drawn_from: str | None = None
    # why the bodies are drawn side by side instead of the picture, when they are
    fallback: str | None = None

    def say(self, sentence: str) -> None:
        self.said.append(sentence)

    def readable_angle(self, angle: float, symbol: sympy.Symbol | None, low: float | None = None) -> float:
        """`angle` (radians, either sign) as drawn: itself within READABLE_ANGLES (or from `low`),
        else the nearest readable angle, noted as not to scale."""
        floor, ceiling = READABLE_ANGLES if low is None else (low, READABLE_ANGLES[1])
        size = abs(angle)
        if size < 1e-9 or floor <= size <= ceiling:
            return angle
        drawn = min(max(size, floor), ceiling)
        name = symbol_label(symbol.name) if symbol is not None else "the angle"
        self.unscaled.append(f"{name} = {math.degrees(size):.3g}° is drawn as {math.degrees(drawn):.0f}°")
        return math.copysign(drawn, angle)


class Values:
    """Numbers for the model's parameters: the student's, else typical (an angle a third of its range,
    others 1, or 2 or 1/2 where 1 leaves the domain: a ball of radius r = 1 in a bowl of radius R = 1
    has no bowl to roll in)."""

    def __init__(self, model: Model, given: Mapping[str, float]) -> None:
        self.subs: dict[sympy.Symbol, float] = {}
        ranges = {symbol: (low, high) for symbol, low, high in model.ranges}
        typical = set()
        for symbol in model.parameters:
            if symbol.name in given:
                self.subs[symbol] = float(given[symbol.name])
            elif symbol in ranges:
                low, high = (float(bound) for bound in ranges[symbol])
                self.subs[symbol] = low + (high - low) / 3
            else:
                self.subs[symbol] = 1.0
                typical.add(symbol)
        self.angles = set(ranges)
        for expr in model.positive:
            self._into_domain(expr, model.positive, typical)

    def _into_domain(
        self, expr: sympy.Expr, positive: tuple[sympy.Expr, ...], typical: set[sympy.Symbol]
    ) -> None:
        """Change one typical value, if need be, so that `expr` is positive and no other expression of
        the domain stops being so."""
        if self._positive(expr):
            return
        for symbol in sorted(expr.free_symbols & typical, key=lambda s: s.name):
            for value in (2.0, 0.5):
                before = self.subs[symbol]
                kept = [e for e in positive if self._positive(e)]
                self.subs[symbol] = value
                if self._positive(expr) and all(self._positive(e) for e in kept):
                    return
                self.subs[symbol] = before

    def _positive(self, expr: sympy.Expr) -> bool:
        try:
            return self.number(expr) > 0
        except NotNumeric:
            return False

    def number(self, expr: sympy.Expr, extra: Mapping[sympy.Symbol, float] | None = None) -> float:
        value = expr.subs({**self.subs, **(extra or {})})
        try:
            return float(value)
        except TypeError:
            raise NotNumeric(f"{expr} is {value} at the figure's values") from None

    def at_state(self, model: Model, place: dict[sympy.Symbol, float]) -> dict[sympy.Symbol, float]:
        """`place` with each coordinate the model's state gives a number moved there (a state that
        cannot be evaluated with these values is left out)."""
        for symbol, value in model.state:
            if symbol in place:
                try:
                    place[symbol] = self.number(value)
                except NotNumeric:
                    continue
        return place


def body_label(body: Body, model: Model) -> str:
    """The body as a figure names it: the symbol the model's notation gives it, else its own mass's
    symbol, else its name (which the notation can spare a reader: two bobs of one mass m)."""
    symbol = next((symbol for key, symbol, _ in model.notation if key == body.name and symbol), None)
    if symbol is not None:
        return symbol_label(symbol)
    masses = [b.mass for b in model.bodies]
    if isinstance(body.mass, sympy.Symbol) and masses.count(body.mass) == 1:
        return symbol_label(body.mass.name)
    return body.name
