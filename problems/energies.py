"""A model's energies in its generalized coordinates, as the energy and Lagrangian parts grade them:
T and V as the engine's Lagrange method uses them, T split by body (translation, rotation), and each
coordinate with its velocity and what it measures. The bank's one seam to the engine's mechanics
(read only: the engine derives, this reads)."""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import sympy

from physics.engine.mechanics import Mechanics
from physics.lagrangian import Coordinate, time_derivative
from physics.symbolic import SymbolSpec
from problems.modelinfo import load_doc_model

if TYPE_CHECKING:
    from problems.schema import ProblemDocument

_MARKED = re.compile(r"«([^»]*)»")


@dataclass(frozen=True)
class ModelEnergies:
    coordinates: tuple[Coordinate, ...]
    kinetic: sympy.Expr
    potential: sympy.Expr
    terms: tuple[tuple[str, sympy.Expr], ...]  # (words, term): each body's translation and rotation
    specs: Mapping[sympy.Symbol, SymbolSpec]  # the state's domain: coordinates, velocities, accelerations


def _words(text: str, bodies: Mapping[str, str]) -> str:
    return _MARKED.sub(lambda m: bodies.get(m.group(1), m.group(1)), text)


def _tidy(term: sympy.Expr) -> sympy.Expr:
    return sympy.trigsimp(sympy.expand(term)) if term.has(sympy.sin, sympy.cos) else sympy.factor(term)


def model_energies(
    doc: ProblemDocument, table: Mapping[str, sympy.Symbol], derivation: Any = None
) -> ModelEnergies:
    """The document's model's energies; `derivation` (the engine's, when derived) names things in words."""
    model = load_doc_model(doc, table)
    mechanics = Mechanics(model)
    notation = getattr(derivation, "notation", None)
    bodies: dict[str, str] = dict(getattr(notation, "bodies", {}) or {})
    named = dict(getattr(notation, "coordinates", {}) or {})
    ranges = {name: (low, high) for name, low, high in model.coordinate_ranges}
    coordinates: list[Coordinate] = []
    specs: dict[sympy.Symbol, SymbolSpec] = {}
    for c in model.coordinates:
        words = _words(named[c.name].words, bodies) if c.name in named else ""
        coordinates.append(Coordinate(c.name, c.symbol, c.velocity, c.acceleration, words))
        low, high = ranges.get(c.name, (None, None))
        if low is None and c.symbol.is_positive:
            low = sympy.Integer(0)
        specs[c.symbol] = SymbolSpec(c.symbol.name, real=True, low=low, high=high)
        specs[c.velocity] = SymbolSpec(c.velocity.name, real=True)
        specs[c.acceleration] = SymbolSpec(c.acceleration.name, real=True)
    state = tuple(coordinates)
    terms: list[tuple[str, sympy.Expr]] = []
    for body in model.bodies:
        who = bodies.get(body.name, f"the {body.name}")
        moving = (
            sympy.Rational(1, 2)
            * body.mass
            * sympy.Add(*(time_derivative(expr, state) ** 2 for _, expr in body.position))
        )
        if moving != 0:
            terms.append((f"{who}'s motion", _tidy(moving)))
        if body.angle is not None:
            turning = sympy.Rational(1, 2) * body.inertia * time_derivative(body.angle, state) ** 2
            if turning != 0:
                terms.append((f"{who}'s rotation", _tidy(turning)))
    return ModelEnergies(state, mechanics.kinetic, mechanics.potential, tuple(terms), specs)
