"""Blocks on a horizontal floor joined in a line by springs, to each other and to walls: every spring is
drawn between its two ends, a hatched wall at each fixed end, each spring labelled with its constant.

The springs must form one chain (a block between two walls, two blocks and three springs...); the
chain is laid out left to right from the walls' positions, or from the side of its anchor that each
spring's length keeps the block on.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TypeAlias

import sympy

from physics.engine.model import Model, PairPotential
from physics.figures.scene import (
    BLOCK,
    Figure,
    Values,
    _block,
    body_label,
    spring_sign,
    stiffness_symbols,
    symbol_label,
)
from physics.figures.svg import FILLS

SPRING = 3.0  # a spring's drawn length
WALL = 2.0  # a wall's height

# A node of the chain: a body's name, or a fixed point's x (as the model writes it).
Node: TypeAlias = "str | sympy.Expr"


@dataclass(frozen=True)
class SpringLine:
    nodes: tuple[Node, ...]  # left to right; fixed points only at the ends
    springs: tuple[PairPotential, ...]  # springs[i] joins nodes[i] and nodes[i + 1]


def _ends(potential: PairPotential) -> tuple[Node, Node]:
    """The spring's two ends, anchor first when there is one."""
    if len(potential.bodies) == 2:
        return potential.bodies[0], potential.bodies[1]
    return dict(potential.anchor)["x"], potential.bodies[0]


def spring_line_of(model: Model, values: Values) -> SpringLine | None:
    """The chain, if the model is two or more springs in a line along x and nothing else."""
    springs = model.potentials
    if len(springs) < 2 or model.constraints or model.forces or model.collision is not None:
        return None
    if any(spring_sign(p, values) <= 0 for p in springs):
        return None
    if any([axis for axis, _ in body.position] != ["x"] or body.angle is not None for body in model.bodies):
        return None
    if any(p.anchor and [axis for axis, _ in p.anchor] != ["x"] for p in springs):
        return None
    links: dict[Node, list[tuple[Node, PairPotential]]] = {}
    for potential in springs:
        a, b = _ends(potential)
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
    return SpringLine(tuple(nodes), tuple(chain))


def _left_end(ends: list[Node], links: dict[Node, list[tuple[Node, PairPotential]]], values: Values) -> Node:
    """The fixed end further left; or the fixed end a spring keeps its block to the right of."""
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
    canvas = figure.canvas
    x = 0.0
    faces: list[tuple[float, float]] = []  # each node's left and right face
    for index, node in enumerate(line.nodes):
        if isinstance(node, str):
            body = model.body(node)
            fill = FILLS[sum(isinstance(n, str) for n in line.nodes[:index]) % len(FILLS)]
            _block(figure, (x + BLOCK / 2, 0.0), (1.0, 0.0), body_label(body, model), fill)
            coordinate = dict(body.position)["x"]
            if isinstance(coordinate, sympy.Symbol):
                canvas.arrow((x + BLOCK / 2 - 0.5, -0.6), (x + BLOCK / 2 + 0.9, -0.6), width=0.04)
                canvas.text((x + BLOCK / 2 + 1.2, -0.6), symbol_label(coordinate.name), anchor="start")
            faces.append((x, x + BLOCK))
            x += BLOCK + SPRING
        else:
            hatch_left = index == 0
            canvas.ground((x, 0.0), (x, WALL), below=not hatch_left)
            faces.append((x, x))
            x += SPRING
    left, right = faces[0][0], faces[-1][1]
    canvas.ground((left - (0.0 if not isinstance(line.nodes[0], str) else 1.0), 0.0),
                  (right + (0.0 if not isinstance(line.nodes[-1], str) else 1.0), 0.0))  # fmt: skip
    names = []
    for index, spring in enumerate(line.springs):
        start, end = faces[index][1], faces[index + 1][0]
        canvas.spring((start, BLOCK / 2), (end, BLOCK / 2))
        stiffness = stiffness_symbols(spring, model)
        name = symbol_label(stiffness[0].name) if stiffness else ""
        if name:
            canvas.text(((start + end) / 2, BLOCK / 2 + 0.55), name)
        names.append(name)
    walls = [node for node in line.nodes if not isinstance(node, str)]
    if len(walls) == 2 and walls[1].free_symbols:
        _dimension(figure, left, right, _length_label(walls[1] - walls[0]))
    figure.say(_description(model, line, names))


def _dimension(figure: Figure, left: float, right: float, label: str) -> None:
    """The walls' distance apart, as a dimension line below the floor."""
    canvas = figure.canvas
    y = -1.4
    middle = (left + right) / 2
    canvas.arrow((middle, y), (left, y), width=0.03)
    canvas.arrow((middle, y), (right, y), width=0.03)
    canvas.text((middle, y - 0.4), label)


def _length_label(length: sympy.Expr) -> str:
    return symbol_label(length.name) if isinstance(length, sympy.Symbol) else str(length)


def _description(model: Model, line: SpringLine, names: list[str]) -> str:
    parts = []
    for index, node in enumerate(line.nodes):
        if isinstance(node, str):
            parts.append(body_label(model.body(node), model))
        else:
            parts.append("a wall" if node == 0 or index == 0 else f"a wall at {_length_label(node)}")
        if index < len(names):
            parts.append(f"a spring {names[index]}".rstrip())
    return "On a horizontal frictionless floor, from left to right: " + ", ".join(parts) + "."
