"""Blocks joined in a line by springs, to each other and to fixed points: on a horizontal floor between
walls, or one above another between a floor and a ceiling. Every spring is drawn between its two ends,
a hatched wall (or floor, or ceiling) at each fixed end, each spring labelled with its constant.

The springs must form one chain (a block between two walls, two blocks and three springs...) along one
axis; the chain is laid out from the fixed ends' positions, or from the side of its anchor that each
spring's length keeps the block on.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TypeAlias

import sympy

from physics.engine.model import Model, PairPotential
from physics.figures.figure import BLOCK, Figure, Values, body_label
from physics.figures.geometry import spring_sign, stiffness_symbols
from physics.figures.shapes import draw_block
from physics.figures.svg import FILLS, Point
from physics.wording import symbol_label

SPRING = 3.0  # a spring's drawn length
WALL = 2.0  # a wall's height

# A node of the chain: a body's name, or a fixed point's x or y (as the model writes it).
Node: TypeAlias = "str | sympy.Expr"


@dataclass(frozen=True)
class SpringLine:
    axis: str  # "x" (left to right) or "y" (bottom to top)
    nodes: tuple[Node, ...]  # in that order; fixed points only at the ends
    springs: tuple[PairPotential, ...]  # springs[i] joins nodes[i] and nodes[i + 1]


def _ends(potential: PairPotential, axis: str) -> tuple[Node, Node]:
    """The spring's two ends, anchor first when there is one."""
    if len(potential.bodies) == 2:
        return potential.bodies[0], potential.bodies[1]
    return dict(potential.anchor)[axis], potential.bodies[0]


def spring_line_of(model: Model, values: Values) -> SpringLine | None:
    """The chain, if the model is two or more springs in a line along one axis (and gravity) only."""
    springs = model.potentials
    if len(springs) < 2 or model.constraints or model.forces or model.collision is not None:
        return None
    if any(spring_sign(p, values) <= 0 for p in springs):
        return None
    axes = {tuple(axis for axis, _ in body.position) for body in model.bodies}
    if len(axes) != 1 or (axis := next(iter(axes))) not in (("x",), ("y",)):
        return None
    if any(body.angle is not None for body in model.bodies):
        return None
    if any(p.anchor and [a for a, _ in p.anchor] != list(axis) for p in springs):
        return None
    links: dict[Node, list[tuple[Node, PairPotential]]] = {}
    for potential in springs:
        a, b = _ends(potential, axis[0])
        links.setdefault(a, []).append((b, potential))
        links.setdefault(b, []).append((a, potential))
    if any(len(joined) > 2 for joined in links.values()):
        return None
    fixed = [node for node in links if not isinstance(node, str)]
    if any(len(links[node]) != 1 for node in fixed) or {b.name for b in model.bodies} - set(links):
        return None
    ends = [node for node, joined in links.items() if len(joined) == 1]
    if len(ends) != 2:
        return None  # a ring of springs
    start = _left_end(ends, links, values)
    nodes, chain = [start], []
    while len(nodes) < len(links):
        step = next(((n, p) for n, p in links[nodes[-1]] if p not in chain), None)
        if step is None:
            return None  # not all one chain
        nodes.append(step[0])
        chain.append(step[1])
    return SpringLine(axis[0], tuple(nodes), tuple(chain))


def _left_end(ends: list[Node], links: dict[Node, list[tuple[Node, PairPotential]]], values: Values) -> Node:
    """The fixed end further left (down); or the fixed end a spring keeps its block to the right of."""
    fixed = [node for node in ends if not isinstance(node, str)]
    if len(fixed) == 2:
        return min(fixed, key=lambda node: values.number(node))
    if fixed:
        anchor = fixed[0]
        ((_, spring),) = links[anchor]
        # side +1: the block's x minus the anchor's stays positive; 0: either, drawn to the right
        return anchor if spring.side >= 0 else next(node for node in ends if node is not anchor)
    return ends[0]


def draw_spring_line(figure: Figure, model: Model, line: SpringLine) -> None:
    """The chain drawn along its axis; `along` runs left to right, or bottom to top."""
    canvas = figure.canvas
    upright = line.axis == "y"

    def at(along: float, across: float) -> Point:
        return (across, along) if upright else (along, across)

    s = 0.0
    faces: list[tuple[float, float]] = []  # where each node starts and ends along the axis
    for index, node in enumerate(line.nodes):
        if isinstance(node, str):
            body = model.body(node)
            fill = FILLS[sum(isinstance(n, str) for n in line.nodes[:index]) % len(FILLS)]
            base = at(s, 0.0) if upright else at(s + BLOCK / 2, 0.0)
            draw_block(figure, base, (1.0, 0.0), body_label(body, model), fill)
            coordinate = dict(body.position)[line.axis]
            if isinstance(coordinate, sympy.Symbol):  # which way the coordinate grows, beside the block
                tail, head = at(s + BLOCK / 2 - 0.5, -1.1), at(s + BLOCK / 2 + 0.9, -1.1)
                if not upright:
                    tail, head = at(s + BLOCK / 2 - 0.5, -0.6), at(s + BLOCK / 2 + 0.9, -0.6)
                canvas.arrow(tail, head, width=0.04)
                label_at = (head[0], head[1] + 0.35) if upright else (head[0] + 0.3, head[1])
                canvas.text(label_at, symbol_label(coordinate.name), anchor="middle" if upright else "start")
            faces.append((s, s + BLOCK))
            s += BLOCK + SPRING
        else:
            first = index == 0
            # a wall hatched on its far side; upright, a floor below or a ceiling above
            ends = (at(s, -WALL / 2), at(s, WALL / 2)) if upright else (at(s, 0.0), at(s, WALL))
            canvas.ground(*ends, below=first if upright else not first)
            faces.append((s, s))
            s += SPRING
    low, high = faces[0][0], faces[-1][1]
    if not upright:  # the floor the blocks slide on
        canvas.ground(
            at(low - (1.0 if isinstance(line.nodes[0], str) else 0.0), 0.0),
            at(high + (1.0 if isinstance(line.nodes[-1], str) else 0.0), 0.0),
        )
    names = []
    middle_across = 0.0 if upright else BLOCK / 2
    for index, spring in enumerate(line.springs):
        start, end = faces[index][1], faces[index + 1][0]
        canvas.spring(at(start, middle_across), at(end, middle_across))
        stiffness = stiffness_symbols(spring, model)
        name = symbol_label(stiffness[0].name) if stiffness else ""
        if name:
            middle = (start + end) / 2
            canvas.text(at(middle, 0.65) if upright else at(middle, BLOCK / 2 + 0.55), name,
                        anchor="start" if upright else "middle")  # fmt: skip
        names.append(name)
    fixed = [node for node in line.nodes if not isinstance(node, str)]
    if len(fixed) == 2 and (fixed[1] - fixed[0]).free_symbols:
        _dimension(figure, at(low, -1.9 if upright else -1.4), at(high, -1.9 if upright else -1.4),
                   _length_label(fixed[1] - fixed[0]), upright)  # fmt: skip
    figure.say(_description(model, line, names))


def _dimension(figure: Figure, start: Point, end: Point, label: str, upright: bool) -> None:
    """The fixed ends' distance apart, as a dimension line beside the chain."""
    canvas = figure.canvas
    middle = ((start[0] + end[0]) / 2, (start[1] + end[1]) / 2)
    canvas.arrow(middle, start, width=0.03)
    canvas.arrow(middle, end, width=0.03)
    canvas.text((middle[0] - 0.3, middle[1]) if upright else (middle[0], middle[1] - 0.4), label,
                anchor="end" if upright else "middle")  # fmt: skip


def _length_label(length: sympy.Expr) -> str:
    return symbol_label(length.name) if isinstance(length, sympy.Symbol) else str(length)


def _description(model: Model, line: SpringLine, names: list[str]) -> str:
    upright = line.axis == "y"
    parts = []
    for index, node in enumerate(line.nodes):
        if isinstance(node, str):
            parts.append(body_label(model.body(node), model))
        else:
            fixed = ("the floor" if index == 0 else "the ceiling") if upright else "a wall"
            parts.append(fixed if node == 0 or index == 0 else f"{fixed} at {_length_label(node)}")
        if index < len(names):
            parts.append(f"a spring {names[index]}".rstrip())
    where = (
        "One above another, from bottom to top"
        if upright
        else "On a horizontal frictionless floor, from left to right"
    )
    return f"{where}: " + ", ".join(parts) + "."
