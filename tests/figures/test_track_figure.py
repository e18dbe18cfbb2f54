"""A block on a curved track: the quarter circle from where it starts to where the problem asks about
it, drawn about its centre, with the block at the top."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest

from physics.figures.svg import FILLS
from tests.figures.test_figures import SVG, figure_of

Point = tuple[float, float]


def _points(element: ET.Element) -> list[Point]:
    pairs = (p.split(",") for p in element.get("points", "").split())
    return [(float(x), -float(y)) for x, y in pairs]  # back to y up


def test_the_track_is_a_quarter_circle_about_its_centre_from_level_with_it_down_to_the_bottom() -> None:
    root = figure_of("quarter-circle-slide")
    [track] = [e for e in root.iter(f"{SVG}polyline") if e.get("stroke-width") == "0.07"]
    [centre] = [(float(e.get("cx", 0)), -float(e.get("cy", 0))) for e in root.iter(f"{SVG}circle")]
    points = _points(track)
    radii = [math.hypot(x - centre[0], y - centre[1]) for x, y in points]
    assert max(radii) - min(radii) == pytest.approx(0, abs=1e-2)
    (_, y0), (x1, y1) = points[0], points[-1]
    assert y0 == pytest.approx(centre[1], abs=1e-3)  # starts level with the centre
    assert x1 == pytest.approx(centre[0], abs=1e-3) and y1 < centre[1]  # ends right below it
    dashed = [e for e in root.iter(f"{SVG}line") if e.get("stroke-dasharray")]
    assert len(dashed) == 2  # the radius to either end


def test_the_block_sits_at_the_top_of_the_track_on_its_inside() -> None:
    root = figure_of("quarter-circle-slide")
    [track] = [e for e in root.iter(f"{SVG}polyline") if e.get("stroke-width") == "0.07"]
    [block] = [e for e in root.iter(f"{SVG}polygon") if e.get("fill") == FILLS[0]]
    [centre] = [(float(e.get("cx", 0)), -float(e.get("cy", 0))) for e in root.iter(f"{SVG}circle")]
    top = _points(track)[0]
    corners = _points(block)
    assert min(math.dist(c, top) for c in corners) < 0.05  # touching the track's start
    radius = math.dist(top, centre)
    assert all(math.dist(c, centre) <= radius + 1e-3 for c in corners)  # inside the curve, not in the track
