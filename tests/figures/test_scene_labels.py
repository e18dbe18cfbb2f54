"""Scene figures: a given push is drawn as an arrow onto the body it pushes, and no label lies across a
body's box (a coefficient of friction written on a block, a name too long for its box)."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest

from physics.figures import body_forces
from physics.figures.svg import FILLS, INK
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table
from tests.figures.test_figures import BANK, figure_of

SVG = "{http://www.w3.org/2000/svg}"
Point = tuple[float, float]
Box = tuple[float, float, float, float]  # left, top, right, bottom on the page (y down)


def text_boxes(root: ET.Element) -> list[tuple[str, Box]]:
    """Each label with the box it covers, estimated as the canvas estimates it."""
    found = []
    for text in root.iter(f"{SVG}text"):
        size = float(text.get("font-size", 0))
        x, y = float(text.get("x", 0)), float(text.get("y", 0)) - size * 0.35
        width = size * 0.6 * len(text.text or "")
        left = x + {"start": 0.0, "middle": -width / 2, "end": -width}[text.get("text-anchor", "middle")]
        found.append((text.text or "", (left, y - size / 2, left + width, y + size / 2)))
    return found


def body_boxes(root: ET.Element) -> list[list[Point]]:
    """The blocks, as their corners on the page: four-cornered polygons filled as bodies are (a wedge,
    a triangle, may carry its angle's mark)."""
    polygons = [
        [(float(a), float(b)) for a, b in (pair.split(",") for pair in polygon.get("points", "").split())]
        for polygon in root.iter(f"{SVG}polygon")
        if polygon.get("fill") in FILLS
    ]
    return [corners for corners in polygons if len(corners) == 4]


def inside(polygon: list[Point], point: Point) -> bool:
    """Is the point strictly inside the convex polygon?"""
    signs = set()
    for (ax, ay), (bx, by) in zip(polygon, polygon[1:] + polygon[:1], strict=True):
        cross = (bx - ax) * (point[1] - ay) - (by - ay) * (point[0] - ax)
        if abs(cross) > 1e-9:
            signs.add(cross > 0)
    return len(signs) == 1


def covered(polygon: list[Point], box: Box) -> list[bool]:
    left, top, right, bottom = box
    grid = [(left + (right - left) * i / 6, top + (bottom - top) * j / 2) for i in range(7) for j in range(3)]
    return [inside(polygon, point) for point in grid]


@pytest.mark.parametrize("problem_id", sorted(BANK))
def test_no_label_lies_across_a_body_box_and_a_box_holds_only_its_own_name(problem_id: str) -> None:
    root = figure_of(problem_id)
    labels = text_boxes(root)
    for polygon in body_boxes(root):
        within = []
        for text, box in labels:
            parts = covered(polygon, box)
            assert all(parts) or not any(parts), f"{text!r} lies across a box's edge"
            if all(parts):
                within.append(text)
        assert len(within) <= 1, f"{within} all written on one box"


def centre(polygon: list[Point]) -> Point:
    return (sum(x for x, _ in polygon) / len(polygon), sum(y for _, y in polygon) / len(polygon))


def box_named(root: ET.Element, label: str) -> list[Point]:
    """The body box with `label` written inside it."""
    (name_box,) = [box for text, box in text_boxes(root) if text == label]
    return next(polygon for polygon in body_boxes(root) if all(covered(polygon, name_box)))


def arrows(root: ET.Element) -> list[tuple[Point, Point]]:
    """(tail, tip) of each black arrow: a line ending where a black arrowhead's point is."""
    tips = [
        tuple(float(v) for v in polygon.get("points", "").split()[0].split(","))
        for polygon in root.iter(f"{SVG}polygon")
        if polygon.get("fill") == INK
    ]
    found = []
    for line in root.iter(f"{SVG}line"):
        tail = (float(line.get("x1", 0)), float(line.get("y1", 0)))
        tip = (float(line.get("x2", 0)), float(line.get("y2", 0)))
        if any(math.dist(tip, other) < 1e-6 for other in tips):
            found.append((tail, tip))
    return found


@pytest.mark.parametrize(
    ("problem_id", "body", "label"),
    [("incline-push-friction", "crate", "m"), ("pushed-blocks", "block1", "m₁")],
)
def test_a_given_push_is_an_arrow_onto_the_body_it_pushes_pointing_as_the_model_says(
    problem_id: str, body: str, label: str
) -> None:
    root = figure_of(problem_id)
    polygon = box_named(root, label)
    middle = centre(polygon)
    reach = max(math.dist(middle, corner) for corner in polygon)
    onto = [
        (tail, tip)
        for tail, tip in arrows(root)
        if math.dist(tip, middle) <= reach + 0.15 and math.dist(tail, middle) > math.dist(tip, middle) + 1.0
    ]
    assert len(onto) == 1, onto
    (tail, tip) = onto[0]
    doc = BANK[problem_id]
    push = next(f for f in body_forces(load_doc_model(doc, symbol_table(doc)), body, {}) if f.label == "F")
    drawn = ((tip[0] - tail[0]), -(tip[1] - tail[1]))  # the page's y runs down
    assert drawn[0] * push.direction[0] + drawn[1] * push.direction[1] > 0.9 * math.hypot(*drawn)
    named = [box for text, box in text_boxes(root) if text == "F"]
    assert named and min(math.dist(tail, ((b[0] + b[2]) / 2, (b[1] + b[3]) / 2)) for b in named) < 0.6


def test_a_rough_floor_under_blocks_side_by_side_is_labelled_once_beside_them() -> None:
    root = figure_of("pushed-blocks")
    assert [text for text, _ in text_boxes(root)].count("μ") == 1


def test_falling_bodies_show_the_drag_each_free_body_diagram_names() -> None:
    root = figure_of("falling-drag")
    doc = BANK["falling-drag"]
    model = load_doc_model(doc, symbol_table(doc))
    texts = {text for text, _ in text_boxes(root)}
    for body in model.bodies:
        drags = {f.label for f in body_forces(model, body.name, {}) if not f.label.endswith("g")}
        assert drags and drags <= texts, (drags, texts)


def _crosses(segment: tuple[Point, Point], box: Box) -> bool:
    """Does the straight segment pass through the box (sampled finely along it)?"""
    (x1, y1), (x2, y2) = segment
    left, top, right, bottom = box
    return any(
        left < x1 + (x2 - x1) * t / 200 < right and top < y1 + (y2 - y1) * t / 200 < bottom
        for t in range(201)
    )


@pytest.mark.parametrize("problem_id", ["orbit-effective-potential", "satellite-orbit"])
def test_an_orbits_names_are_struck_by_neither_the_distance_nor_the_orbit(problem_id: str) -> None:
    # the dashed distance from the centre ran through the centre's mass M, and the arc through m
    root = figure_of(problem_id)
    labels = text_boxes(root)
    lines = [
        (
            (float(line.get("x1", 0)), float(line.get("y1", 0))),
            (float(line.get("x2", 0)), float(line.get("y2", 0))),
        )
        for line in root.iter(f"{SVG}line")
    ]
    assert [(text, line) for text, box in labels for line in lines if _crosses(line, box)] == []
    arc = next(root.iter(f"{SVG}path"))
    radius = float(arc.get("d", "").split()[4])  # "M x y A r r …", about the centre at the origin
    for text, (left, top, right, bottom) in labels:
        near = math.hypot(max(left, min(0.0, right)), max(top, min(0.0, bottom)))
        far = max(math.hypot(x, y) for x in (left, right) for y in (top, bottom))
        assert not near < radius < far, f"{text!r} lies on the orbit"
