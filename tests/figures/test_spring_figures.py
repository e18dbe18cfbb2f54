"""Springs in figures: the scene draws every spring of the model to its two ends, with a wall where an
end is fixed, and each body's free-body diagram shows each spring's force, named as the scene names
the spring and pointing the way the spring pulls or pushes where the body rests."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest

from physics.engine.model import Model
from physics.figures import body_forces, free_body_figure, model_figure
from physics.figures.figure import Values
from physics.figures.geometry import spring_sign
from problems.loader import parse_problem
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table
from tests.bank import bank_documents

SVG = "{http://www.w3.org/2000/svg}"
BANK = bank_documents()
# An instructor's upload whose scene once showed only the left spring and wall, and whose free-body
# diagram was empty.
TWO_WALLS = """
id: block-between-walls
title: A block held between two springs
statement: |
  A block of mass $m$ slides on a frictionless floor between two walls a distance $D$ apart, held by
  a spring $k_1$ (natural length $L_1$) to the left wall and a spring $k_2$ (natural length $L_2$) to
  the right wall. Measure $x$ from the left wall.
symbols:
  m: {meaning: mass of the block, dimension: kg}
  k1: {meaning: constant of the left spring, dimension: N/m}
  k2: {meaning: constant of the right spring, dimension: N/m}
  L1: {meaning: natural length of the left spring, dimension: m}
  L2: {meaning: natural length of the right spring, dimension: m}
  D: {meaning: distance between the walls, dimension: m}
parts:
  - id: rest_position
    kind: symbolic
    prompt: Find the block's distance from the left wall when it rests.
    symbols: [m, k1, k2, L1, L2, D]
model:
  coordinates: [x]
  bodies:
    block: {mass: m, position: {x: x}}
  elements:
    left: {kind: spring, between: [{x: 0}, block], stiffness: k1, length: L1}
    right: {kind: spring, between: [block, {x: D}], stiffness: k2, length: L2}
  domain:
    ranges: {x: ["0", "D"]}
  quantities:
    rest_position: {equilibrium: x}
"""
# The same block hanging between a floor and a ceiling.
FLOOR_CEILING = (
    TWO_WALLS.replace("position: {x: x}", "position: {y: x}")
    .replace("[{x: 0}, block]", "[{y: 0}, block]")
    .replace("[block, {x: D}]", "[block, {y: D}]")
)
STRETCHED = {"m": 0.5, "k1": 40.0, "k2": 60.0, "L1": 0.25, "L2": 0.2, "D": 0.7}  # 0.25 + 0.2 < 0.7
SQUEEZED = {**STRETCHED, "L1": 0.5, "L2": 0.45}  # 0.5 + 0.45 > 0.7: both springs push


def two_walls() -> Model:
    doc = parse_problem(TWO_WALLS)
    return load_doc_model(doc, symbol_table(doc))


def floor_ceiling() -> Model:
    doc = parse_problem(FLOOR_CEILING)
    return load_doc_model(doc, symbol_table(doc))


def bank_model(problem_id: str) -> Model:
    doc = BANK[problem_id]
    return load_doc_model(doc, symbol_table(doc))


def model_of(problem_id: str) -> Model:
    uploads = {"two-walls": two_walls, "floor-ceiling": floor_ceiling}
    return uploads[problem_id]() if problem_id in uploads else bank_model(problem_id)


def springs_of(model: Model) -> list[str]:
    values = Values(model, {})
    return [p.name for p in model.potentials if spring_sign(p, values) > 0]


SPRING_PROBLEMS = ["two-walls", "floor-ceiling", *sorted(i for i in BANK if springs_of(bank_model(i)))]


def zigzags(root: ET.Element) -> list[list[tuple[float, float]]]:
    """The springs drawn: polylines of many points (a dashpot's outline has four)."""
    found = []
    for line in root.iter(f"{SVG}polyline"):
        points = [tuple(float(v) for v in p.split(",")) for p in line.get("points", "").split()]
        if len(points) >= 8:
            found.append([(x, y) for x, y in points])
    return found


def walls(root: ET.Element) -> list[float]:
    """The x of each wall drawn: a thick vertical line (hatched)."""
    return sorted(
        float(line.get("x1", "nan"))
        for line in root.iter(f"{SVG}line")
        if line.get("stroke-width") == "0.07"
        and line.get("x1") == line.get("x2")
        and line.get("y1") != line.get("y2")
    )


def texts(root: ET.Element) -> set[str]:
    return {element.text or "" for element in root.iter(f"{SVG}text")}


@pytest.mark.parametrize("problem_id", SPRING_PROBLEMS)
def test_the_scene_draws_every_spring_of_the_model(problem_id: str) -> None:
    model = model_of(problem_id)
    root = ET.fromstring(model_figure(model, {}, title=problem_id))
    assert len(zigzags(root)) == len(springs_of(model))


def test_a_block_between_two_walls_has_a_spring_from_each_wall_labelled_with_its_constant() -> None:
    root = ET.fromstring(model_figure(two_walls(), STRETCHED, title="walls"))
    left_wall, right_wall = walls(root)
    ends = sorted((spring[0][0], spring[-1][0]) for spring in zigzags(root))
    assert len(ends) == 2
    assert math.isclose(ends[0][0], left_wall) and math.isclose(ends[1][1], right_wall)
    assert ends[0][1] < ends[1][0], "the block lies between the springs"
    assert {"k₁", "k₂", "m", "D"} <= texts(root)
    assert "k₁" in root.findtext(f"{SVG}desc", "") and "k₂" in root.findtext(f"{SVG}desc", "")


def test_a_block_between_a_floor_and_a_ceiling_has_a_spring_to_each() -> None:
    root = ET.fromstring(model_figure(floor_ceiling(), STRETCHED, title="floor and ceiling"))
    surfaces = sorted(
        float(line.get("y1", "nan"))
        for line in root.iter(f"{SVG}line")
        if line.get("stroke-width") == "0.07" and line.get("y1") == line.get("y2")
    )
    spans = sorted(sorted((spring[0][1], spring[-1][1])) for spring in zigzags(root))
    assert len(surfaces) == 2 and len(spans) == 2
    assert math.isclose(spans[0][0], surfaces[0]) and math.isclose(spans[1][1], surfaces[1])  # SVG y is down
    assert {"k₁", "k₂", "m", "D"} <= texts(root)


def test_three_springs_end_at_the_two_walls_with_both_blocks_between() -> None:
    root = ET.fromstring(model_figure(bank_model("three-springs"), {}, title="three springs"))
    left_wall, right_wall = walls(root)
    spans = sorted((spring[0][0], spring[-1][0]) for spring in zigzags(root))
    assert math.isclose(spans[0][0], left_wall) and math.isclose(spans[-1][1], right_wall)
    assert {"k", "k₂", "block1", "block2"} <= texts(root)


def directions(model: Model, body: str, values: dict[str, float]) -> dict[str, tuple[float, float]]:
    return {f.label: f.direction for f in body_forces(model, body, values)}


def close(a: tuple[float, float], b: tuple[float, float]) -> bool:
    return math.isclose(a[0], b[0], abs_tol=1e-9) and math.isclose(a[1], b[1], abs_tol=1e-9)


LEFT, RIGHT, UP = (-1.0, 0.0), (1.0, 0.0), (0.0, 1.0)
THIRTY = math.radians(30)


@pytest.mark.parametrize(
    ("problem_id", "body", "values", "expected"),
    [
        ("two-walls", "block", STRETCHED, {"Fₖ₁": LEFT, "Fₖ₂": RIGHT}),  # each pulls towards its wall
        ("two-walls", "block", SQUEEZED, {"Fₖ₁": RIGHT, "Fₖ₂": LEFT}),  # each pushes away from it
        ("three-springs", "block1", {}, {"Fₖ": LEFT, "Fₖ₂": RIGHT}),
        ("three-springs", "block2", {}, {"Fₖ₂": LEFT, "Fₖ": RIGHT}),
        (
            "vertical-spring",
            "block",
            {"m": 1.0, "g": 9.81, "k": 100.0, "L0": 0.3},
            {"Fₖ": UP, "mg": (0.0, -1.0)},
        ),
        ("spring-incline", "block", {"theta": THIRTY}, {"Fₖ": (-math.cos(THIRTY), math.sin(THIRTY))}),
        ("spring-two-masses", "block1", {}, {"Fₖ": RIGHT}),  # relaxed: drawn pulling towards m₂
        ("spring-two-masses", "block2", {}, {"Fₖ": LEFT}),
    ],
)
def test_a_springs_force_points_the_way_it_pulls_or_pushes_where_the_body_rests(
    problem_id: str, body: str, values: dict[str, float], expected: dict[str, tuple[float, float]]
) -> None:
    found = directions(model_of(problem_id), body, values)
    for label, direction in expected.items():
        assert label in found, found
        assert close(found[label], direction), (label, found[label])


@pytest.mark.parametrize("problem_id", SPRING_PROBLEMS)
def test_each_spring_shows_its_force_named_as_the_scene_names_the_spring(problem_id: str) -> None:
    model = model_of(problem_id)
    scene = texts(ET.fromstring(model_figure(model, {}, title=problem_id)))
    plain = str.maketrans("ₖ", "k")
    values = Values(model, {})
    for body in model.bodies:
        held = [p for p in model.potentials if body.name in p.bodies and spring_sign(p, values) > 0]
        diagram = ET.fromstring(free_body_figure(model, body.name, {}, title=problem_id))
        labels = [t for t in texts(diagram) if t.startswith("Fₖ")]
        assert len(labels) == len(held), (body.name, texts(diagram))
        for label in labels:
            assert label[1:].translate(plain) in scene, (label, scene)
        for label in labels:
            assert label in diagram.findtext(f"{SVG}desc", "")


@pytest.mark.parametrize(
    ("problem_id", "body", "label", "direction"),
    [
        ("falling-drag", "pebble", "bv", UP),  # falling: the drag holds it back
        ("falling-drag", "ball", "cv²", UP),
        ("incline-push-friction", "crate", "F", RIGHT),  # the given push
        ("damped-oscillator", "block", "bv", LEFT),  # at rest: against motion towards +x
    ],
)
def test_given_forces_and_drag_are_drawn(
    problem_id: str, body: str, label: str, direction: tuple[float, float]
) -> None:
    found = directions(bank_model(problem_id), body, {})
    assert label in found and close(found[label], direction), found


@pytest.mark.parametrize("problem_id", sorted(BANK))
def test_arrows_along_one_line_are_drawn_side_by_side_not_on_top_of_each_other(problem_id: str) -> None:
    model = bank_model(problem_id)
    for body in model.bodies:
        root = ET.fromstring(free_body_figure(model, body.name, {}, title=problem_id))
        arrows = [
            tuple(line.get(k) for k in ("x1", "y1", "x2", "y2"))
            for line in root.iter(f"{SVG}line")
            if line.get("stroke") == "#a11111"
        ]
        assert len(arrows) == len(set(arrows)), (body.name, arrows)


def test_a_body_name_too_long_for_its_block_is_written_beside_it() -> None:
    root = ET.fromstring(free_body_figure(bank_model("three-springs"), "block1", {}, title="three springs"))
    [name] = [t for t in root.iter(f"{SVG}text") if t.text == "block1"]
    assert float(name.get("x", "0")) >= 0.5  # the block's right edge: the name starts past it


def test_two_springs_of_one_constant_are_both_named_by_it_not_numbered() -> None:
    doc = parse_problem(TWO_WALLS.replace("stiffness: k2", "stiffness: k1"))
    model = load_doc_model(doc, symbol_table(doc))
    labels = [f.label for f in body_forces(model, "block", STRETCHED)]
    assert labels == ["Fₖ₁", "Fₖ₁"]  # as the scene labels both springs k₁; Fₖ₂ would name a spring k₂
