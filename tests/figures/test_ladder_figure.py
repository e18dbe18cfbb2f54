"""A leaning ladder's figure: a rod from the floor to the wall at the student's angle with the floor,
the floor and the wall hatched on their solid sides."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest

from physics.figures.svg import FILLS
from problems.symbols import symbol_table
from problems.variants import draw_variant, si_values
from tests.figures.test_figures import BANK, SVG, figure_of


def _theta(student: str) -> float:
    doc = BANK["ladder-slipping"]
    drawn = si_values(doc, draw_variant(doc, 1, student, "secret"), symbol_table(doc))
    return next(float(v) for s, v in drawn.items() if s.name == "theta")


def _ends(line: ET.Element) -> tuple[tuple[float, float], tuple[float, float]]:
    a = (float(line.get("x1", 0)), -float(line.get("y1", 0)))
    b = (float(line.get("x2", 0)), -float(line.get("y2", 0)))
    return a, b


@pytest.mark.parametrize("student", ["ada", "bob", "cy"])
def test_the_ladder_runs_from_the_floor_to_the_wall_at_the_students_angle(student: str) -> None:
    root = figure_of("ladder-slipping", student)
    surfaces = [_ends(e) for e in root.iter(f"{SVG}line") if e.get("stroke-width") == "0.07"]
    [floor] = [s for s in surfaces if s[0][1] == s[1][1]]
    [wall] = [s for s in surfaces if s[0][0] == s[1][0]]
    [rod] = [e for e in root.iter(f"{SVG}polygon") if e.get("fill") == FILLS[1]]
    corners = [(float(x), -float(y)) for x, y in (p.split(",") for p in rod.get("points", "").split())]
    foot = ((corners[0][0] + corners[1][0]) / 2, (corners[0][1] + corners[1][1]) / 2)
    top = ((corners[2][0] + corners[3][0]) / 2, (corners[2][1] + corners[3][1]) / 2)
    assert foot[1] == pytest.approx(floor[0][1], abs=1e-3)
    assert top[0] == pytest.approx(wall[0][0], abs=1e-3)
    assert math.atan2(top[1] - foot[1], abs(foot[0] - top[0])) == pytest.approx(_theta(student), abs=1e-3)
    hatches = [_ends(e) for e in root.iter(f"{SVG}line") if e.get("stroke-width") == "0.03"]
    under_floor = [
        h
        for h in hatches
        if max(h[0][1], h[1][1]) <= floor[0][1] + 1e-6 and min(h[0][1], h[1][1]) < floor[0][1]
    ]
    behind_wall = [
        h
        for h in hatches
        if max(h[0][0], h[1][0]) <= wall[0][0] + 1e-6 and min(h[0][0], h[1][0]) < wall[0][0]
    ]
    assert len(under_floor) >= 5 and len(behind_wall) >= 5
    assert root.find(f"{SVG}path") is not None  # the angle's arc
