"""A damped oscillator's figure: a spring and a dashpot side by side, each from the wall to the block."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from physics.figures.svg import FILLS
from tests.figures.test_figures import SVG, figure_of

Point = tuple[float, float]


def _points(element: ET.Element) -> list[Point]:
    pairs = (p.split(",") for p in element.get("points", "").split())
    return [(float(x), -float(y)) for x, y in pairs]  # back to y up


def _ends(line: ET.Element) -> tuple[Point, Point]:
    return (float(line.get("x1", 0)), -float(line.get("y1", 0))), (
        float(line.get("x2", 0)),
        -float(line.get("y2", 0)),
    )


def _block_and_wall(root: ET.Element) -> tuple[list[Point], float]:
    [block] = [_points(e) for e in root.iter(f"{SVG}polygon") if e.get("fill") == FILLS[0]]
    [wall] = [
        a[0]
        for a, b in (_ends(e) for e in root.iter(f"{SVG}line") if e.get("stroke-width") == "0.07")
        if a[0] == b[0] and abs(a[1] - b[1]) > 1  # the wall, not the piston
    ]
    return block, wall


def test_a_spring_and_a_dashpot_each_join_the_wall_to_the_block_at_different_heights() -> None:
    root = figure_of("damped-oscillator")
    block, wall = _block_and_wall(root)
    face = min(x for x, _ in block)
    low, high = min(y for _, y in block), max(y for _, y in block)
    drawn = [_points(e) for e in root.iter(f"{SVG}polyline") if e.get("stroke-width") == "0.045"]
    [spring] = [p for p in drawn if len(p) > 10]
    [cylinder] = [p for p in drawn if len(p) == 4]
    rods = [_ends(e) for e in root.iter(f"{SVG}line") if e.get("stroke-width") == "0.045"]
    height = rods[0][0][1]
    assert all(a[1] == b[1] == height for a, b in rods)  # the dashpot lies along one horizontal line
    assert min(x for (x, _), _ in rods) == wall and max(x for _, (x, _) in rods) == face
    assert all(wall < x < face and abs(y - height) < 0.5 for x, y in cylinder)
    assert spring[0][0] == wall and spring[-1][0] == face
    assert low < spring[0][1] < high and low < height < high and abs(spring[0][1] - height) > 0.6


def test_an_undamped_spring_has_no_dashpot() -> None:
    root = figure_of("mass-spring")
    drawn = [_points(e) for e in root.iter(f"{SVG}polyline")]
    assert not [p for p in drawn if len(p) == 4]
