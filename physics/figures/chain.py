"""Pendulums hung one from another (a double pendulum): from a fixed pivot, each bob on a light rod of
fixed length from the one above, every rod labelled with its length, and each angle marked from the
downward vertical at its pivot, named by its coordinate."""

from __future__ import annotations

import math

import sympy

from physics.engine.model import Body, Constraint, Model
from physics.figures.figure import Figure, body_label
from physics.figures.geometry import bodies_in, coordinate_label
from physics.figures.svg import FILLS, Point
from physics.wording import symbol_label

ROD = 3.0
BOB = 0.8
ANGLES = (25.0, 45.0)  # degrees from the downward vertical, the lower rod swung further


def pendulum_chain_of(model: Model, strings: list[Constraint]) -> list[tuple[Body, Constraint]] | None:
    """(bob, its rod) from the top, if the model is two or more pendulums hung one from another and
    nothing else holds them."""
    if len(strings) < 2 or len(model.constraints) != len(strings) or model.potentials or model.forces:
        return None
    joined = {string.name: bodies_in(string.gap, model) for string in strings}
    top = [s for s in strings if len(joined[s.name]) == 1]
    if len(top) != 1:
        return None
    chain = [(joined[top[0].name][0], top[0])]
    left = [s for s in strings if s is not top[0]]
    while left:
        above = chain[-1][0]
        step = next((s for s in left if len(joined[s.name]) == 2 and above in joined[s.name]), None)
        if step is None:
            return None
        below = next(b for b in joined[step.name] if b is not above)
        if any(below is bob for bob, _ in chain):
            return None
        chain.append((below, step))
        left.remove(step)
    if {b.name for b in model.bodies} != {bob.name for bob, _ in chain}:
        return None
    return chain


def _new_coordinate(body: Body, model: Model, above: set[sympy.Symbol]) -> sympy.Symbol | None:
    """The coordinate that swings this bob about the one above (p2 for the lower bob)."""
    own = set().union(*(expr.free_symbols for _, expr in body.position))
    found = sorted((c.symbol for c in model.coordinates if c.symbol in own - above), key=lambda s: s.name)
    return found[0] if found else None


def _length_symbol(rod: Constraint, model: Model) -> sympy.Symbol | None:
    found = sorted((s for s in rod.gap.free_symbols if s in set(model.parameters)), key=lambda s: s.name)
    return found[0] if found else None


def draw_pendulum_chain(figure: Figure, model: Model, chain: list[tuple[Body, Constraint]]) -> None:
    canvas = figure.canvas
    canvas.ground((-1.5, 0.0), (1.5, 0.0), below=False)
    pivots: list[Point] = [(0.0, 0.0)]
    for index in range(len(chain)):
        angle = math.radians(ANGLES[min(index, len(ANGLES) - 1)])
        x, y = pivots[-1]
        pivots.append((x + ROD * math.sin(angle), y - ROD * math.cos(angle)))
    seen: set[sympy.Symbol] = set()
    said = []
    half = BOB / 2
    for index, (body, rod) in enumerate(chain):  # rods, verticals and angles first: bobs cover their ends
        angle = math.radians(ANGLES[min(index, len(ANGLES) - 1)])
        pivot, bob = pivots[index], pivots[index + 1]
        below = pivot[1] - (half if index else 0.0)  # from under the bob above
        canvas.line((pivot[0], below), (pivot[0], pivot[1] - ROD * 0.6), dashed=True, width=0.03)
        canvas.line(pivot, bob, width=0.05)
        coordinate = _new_coordinate(body, model, seen)
        if coordinate is not None:
            seen.add(coordinate)
            figure.placed[coordinate] = angle  # the angle it is marked as: the diagrams are drawn there
            canvas.arc(pivot, 1.0, -math.pi / 2, -math.pi / 2 + angle)
            middle = -math.pi / 2 + angle / 2
            canvas.text(
                (pivot[0] + 1.4 * math.cos(middle), pivot[1] + 1.4 * math.sin(middle)),
                coordinate_label(model, coordinate.name),
                size=0.36,
            )
        length = _length_symbol(rod, model)
        if length is not None:  # on the rod's outer side, away from its angle
            middle_rod = ((pivot[0] + bob[0]) / 2, (pivot[1] + bob[1]) / 2)
            canvas.text(
                (middle_rod[0] + 0.4 * math.cos(angle), middle_rod[1] + 0.4 * math.sin(angle)),
                symbol_label(length.name),
                anchor="start",
            )
        above = "a fixed pivot" if index == 0 else body_label(chain[index - 1][0], model)
        said.append(
            f"{body_label(body, model)} hangs from {above} on a light rod"
            + (f" of length {symbol_label(length.name)}" if length is not None else "")
            + (
                f", at the angle {coordinate_label(model, coordinate.name)} from the vertical"
                if coordinate is not None
                else ""
            )
        )
    for index, (body, _) in enumerate(chain):
        bob = pivots[index + 1]
        canvas.polygon(
            [(bob[0] - half, bob[1] - half), (bob[0] + half, bob[1] - half),
             (bob[0] + half, bob[1] + half), (bob[0] - half, bob[1] + half)],
            fill=FILLS[index % len(FILLS)],
        )  # fmt: skip
        label = body_label(body, model)
        own_mass = isinstance(body.mass, sympy.Symbol) and label == symbol_label(body.mass.name)
        if own_mass and len(label) <= 3:
            canvas.text(bob, label)
        else:  # equal masses: the mass inside, the name (or the notation's letter) beside
            if isinstance(body.mass, sympy.Symbol):
                canvas.text(bob, symbol_label(body.mass.name), size=0.36)
            canvas.text((bob[0] + half + 0.15, bob[1] - 0.1), label, size=0.32, anchor="start")
    figure.say("; ".join(said) + ".")
