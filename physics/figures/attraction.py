"""Bodies held by a potential that is not a spring: a satellite about an attracting centre, two atoms
interacting across a distance."""

from __future__ import annotations

import sympy

from physics.engine.model import Body, Model, PairPotential
from physics.figures.figure import Figure, body_label
from physics.figures.geometry import other_symbols
from physics.figures.svg import FILLS, INK
from physics.wording import symbol_label


def draw_central(figure: Figure, model: Model, body: Body, potential: PairPotential) -> None:
    """A body at a distance from a fixed centre that attracts it (a planet and a satellite)."""
    canvas = figure.canvas
    canvas.circle((0.0, 0.0), 1.0, fill=FILLS[2])
    masses = [s for s in other_symbols(potential, body, model) if s.name[:1].isupper() and s.name != "G"]
    # the names clear of the distance's line from the centre and of the orbit's arc, which struck them
    if masses:
        canvas.text((0.0, 0.5), symbol_label(masses[0].name))
    canvas.circle((0.0, 0.0), 0.06, fill=INK)
    canvas.circle((5.5, 0.0), 0.35, fill=FILLS[0])
    canvas.text((6.2, -0.5), body_label(body, model))
    canvas.line((0.0, 0.0), (5.15, 0.0), dashed=True, width=0.03)
    coordinate = model.coordinates[0].name if model.coordinates else ""
    canvas.text((3.0, 0.35), coordinate)
    canvas.arc((0.0, 0.0), 5.5, -0.5, 0.5, width=0.03)
    figure.say(
        f"{body_label(body, model)} at a distance {coordinate} from a fixed centre"
        + (f" of mass {symbol_label(masses[0].name)}" if masses else "")
        + " that attracts it; it moves on an orbit about it."
    )


def draw_pair(figure: Figure, model: Model, first: Body, second: Body, distance_label: str) -> None:
    canvas = figure.canvas
    gap = 5.0
    for x, body, fill in ((0.0, first, FILLS[0]), (gap, second, FILLS[1])):
        canvas.circle((x, 0.0), 0.55, fill=fill)
        canvas.text((x, 0.0), body_label(body, model) if body_label(body, model) != body.name else "")
        if isinstance(body.mass, sympy.Symbol):
            canvas.text((x, -0.95), symbol_label(body.mass.name), size=0.36)
    canvas.line((0.55, 0.0), (gap - 0.55, 0.0), dashed=True, width=0.03)
    canvas.arrow((gap / 2, 1.0), (0.0, 1.0), width=0.03)
    canvas.arrow((gap / 2, 1.0), (gap, 1.0), width=0.03)
    canvas.line((0.0, 0.7), (0.0, 1.3), width=0.03)
    canvas.line((gap, 0.7), (gap, 1.3), width=0.03)
    canvas.text((gap / 2, 1.45), distance_label)
    figure.say(f"Two atoms a distance {distance_label} apart, interacting through a potential.")
