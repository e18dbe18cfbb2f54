"""Reading the low-level model for a drawing: which bodies a gap joins, whether it is straight, the
symbol that sets an angle, which coordinate moves a body, what a potential's stiffness is."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import sympy

from physics.engine.model import AuthoredElement, Body, Constraint, Model, PairPotential
from physics.figures.figure import Values
from physics.figures.svg import Point
from physics.wording import symbol_label


def own_symbols(body: Body, model: Model) -> set[sympy.Symbol]:
    return {model.cartesian_symbol(name) for name in body.cartesian_names()}


def bodies_in(gap: sympy.Expr, model: Model) -> list[Body]:
    free = gap.free_symbols
    return [body for body in model.bodies if own_symbols(body, model) & free]


def angle_symbol_of(expr: sympy.Expr, values: Values) -> sympy.Symbol | None:
    found = sorted(expr.free_symbols & values.angles, key=lambda s: s.name)
    return found[0] if found else None


@dataclass(frozen=True)
class Surface:
    """gap = a x + b y + c in one body's own coordinates: the normal (a, b) points to the free side."""

    constraint: Constraint
    body: Body
    normal: Point
    angle_symbol: sympy.Symbol | None


def linear_surface(constraint: Constraint, body: Body, model: Model, values: Values) -> Surface | None:
    x = model.cartesian_symbol(f"x_{body.name}") if f"x_{body.name}" in dict(model.cartesian) else None
    y = model.cartesian_symbol(f"y_{body.name}") if f"y_{body.name}" in dict(model.cartesian) else None
    a = values.number(sympy.diff(constraint.gap, x)) if x is not None else 0.0
    b = values.number(sympy.diff(constraint.gap, y)) if y is not None else 0.0
    norm = math.hypot(a, b)
    if norm == 0:
        return None
    return Surface(constraint, body, (a / norm, b / norm), angle_symbol_of(constraint.gap, values))


def is_linear(gap: sympy.Expr, model: Model) -> bool:
    """Is the gap linear in the bodies' Cartesian symbols (a straight surface or string)?"""
    cartesian = [symbol for _, symbol in model.cartesian if symbol in gap.free_symbols]
    return all(
        not (sympy.diff(gap, first, second).free_symbols & set(cartesian))
        and sympy.diff(gap, first, second) == 0
        for first in cartesian
        for second in cartesian
    )


def moving_coordinate(model: Model, body: Body, exclude: tuple[str | None, ...]) -> str | None:
    """The coordinate that moves `body` (the first, other than those in `exclude`)."""
    for c in model.coordinates:
        if c.name not in exclude and any(sympy.diff(e, c.symbol) != 0 for _, e in body.position):
            return c.name
    return None


def coordinate_label(model: Model, name: str) -> str:
    """A coordinate as the worked solutions write it (the model's notation may rename it)."""
    symbol = next((symbol for key, symbol, _ in model.notation if key == name and symbol), None)
    return symbol_label(symbol or name)


def moves_linearly(body: Body, model: Model) -> bool:
    coordinates = [c.symbol for c in model.coordinates]
    return all(
        sympy.diff(expr, a, b) == 0 for _, expr in body.position for a in coordinates for b in coordinates
    )


def spring_sign(potential: PairPotential, values: Values) -> int:
    """+1 for a spring (energy quadratic in the distance, growing), -1 for a quadratic that falls (the
    centrifugal potential of a rotating frame), 0 for anything else (gravitation, Lennard-Jones...)."""
    energy = sympy.expand(potential.energy)
    if not energy.is_polynomial(potential.distance) or sympy.degree(energy, potential.distance) != 2:
        return 0
    leading = values.number(energy.coeff(potential.distance, 2))
    return 1 if leading > 0 else -1


def other_symbols(potential: PairPotential, body: Body, model: Model) -> list[sympy.Symbol]:
    """The potential's parameters other than the body's own mass (ω, v and R, G and M...)."""
    own = body.mass.free_symbols
    return sorted(
        (s for s in potential.energy.free_symbols if s in set(model.parameters) and s not in own),
        key=lambda s: s.name,
    )


def stiffness_symbols(potential: PairPotential, model: Model) -> list[sympy.Symbol]:
    """The symbols of the factor in front of the energy's distance term: k in k (d - L0)^2 / 2."""
    factor, _ = potential.energy.as_independent(potential.distance, as_Add=False)
    return sorted((s for s in factor.free_symbols if s in set(model.parameters)), key=lambda s: s.name)


def written_symbol(model: Model, value: Any) -> sympy.Symbol | None:
    """An element's field written as one of the problem's symbols (`angle: theta`), else None."""
    return next((s for s in model.parameters if isinstance(value, str) and s.name == value), None)


def element_body(model: Model, element: AuthoredElement) -> Body:
    """The body an element moves (`body:`, by default named as the element)."""
    return model.body(str(element.fields.get("body", element.name)))


def of_kind(elements: tuple[AuthoredElement, ...], *kinds: str) -> list[AuthoredElement]:
    return [element for element in elements if element.kind in kinds]
