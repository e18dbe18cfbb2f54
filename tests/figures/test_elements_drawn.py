"""Figures are drawn from the elements the author wrote: every bank problem's figure is drawn at several
parameter values without falling back to its bodies side by side (from its elements, when it has any),
each element kind's figure shows that element, and only a parameter without a number falls back."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Callable

import pytest
import sympy
import yaml

from physics.engine import load_model
from physics.figures import model_figure
from physics.figures.scene import DRAWERS, compose
from physics.figures.svg import Point
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table
from problems.variants import draw_variant, si_values
from tests.bank import bank_documents
from tests.engine.conftest import BANK as BANK_DIR
from tests.engine.conftest import LOWLEVEL

SVG = "{http://www.w3.org/2000/svg}"
BANK = bank_documents()
STUDENTS = ("ada", "grace", "linus")


def positive(*names: str) -> dict[str, sympy.Symbol]:
    return {n: sympy.Symbol(n, positive=True) for n in names}


@pytest.mark.parametrize("problem_id", sorted(BANK))
def test_every_bank_figure_is_drawn_without_falling_back_at_several_values(problem_id: str) -> None:
    doc = BANK[problem_id]
    table = symbol_table(doc)
    model = load_doc_model(doc, table)
    variants = [si_values(doc, draw_variant(doc, 1, student, "secret"), table) for student in STUDENTS]
    for given in [{}, *({s.name: float(v) for s, v in values.items()} for values in variants)]:
        figure = compose(model, given)
        assert figure.fallback is None, (given, figure.fallback)
        if model.elements and model.impact is None:
            assert figure.drawn_from == "elements", given


def _points(text: str) -> list[Point]:
    """An SVG points list, back in the drawing's axes (y up)."""
    return [(float(x), -float(y)) for x, y in (pair.split(",") for pair in text.split())]


def _polygons(root: ET.Element, corners: int) -> list[list[Point]]:
    found = [_points(e.get("points", "")) for e in root.iter(f"{SVG}polygon")]
    return [p for p in found if len(p) == corners]


def _circles(root: ET.Element) -> list[tuple[Point, float]]:
    return [
        ((float(e.get("cx", 0)), -float(e.get("cy", 0))), float(e.get("r", 0)))
        for e in root.iter(f"{SVG}circle")
    ]


def _lines(root: ET.Element, *, dashed: bool = False) -> list[tuple[Point, Point]]:
    return [
        ((float(e.get("x1", 0)), -float(e.get("y1", 0))), (float(e.get("x2", 0)), -float(e.get("y2", 0))))
        for e in root.iter(f"{SVG}line")
        if (e.get("stroke-dasharray") is not None) == dashed
    ]


def _edges(polygon: list[Point]) -> list[tuple[Point, Point]]:
    return list(zip(polygon, polygon[1:] + polygon[:1], strict=True))


def _slope(edge: tuple[Point, Point]) -> float:
    """The edge's angle to the horizontal, in [0, pi/2]."""
    (ax, ay), (bx, by) = edge
    return math.atan2(abs(by - ay), abs(bx - ax))


def _near(a: float, b: float) -> bool:
    return abs(a - b) < 1e-2


def _slope_with_block_on_it(root: ET.Element, angle: float) -> bool:
    """A right triangle with a face at `angle` (an incline, a wedge) and a block whose base lies along it."""
    for triangle in _polygons(root, 3):
        slopes = sorted(_slope(edge) for edge in _edges(triangle))
        if _near(slopes[0], 0.0) and _near(slopes[2], math.pi / 2) and _near(slopes[1], angle):
            return any(_near(_slope(_edges(block)[0]), angle) for block in _polygons(root, 4))
    return False


def _round_body_on_slope(root: ET.Element, angle: float) -> bool:
    """A round body touching the face at `angle` of a right triangle."""
    for triangle in _polygons(root, 3):
        for (ax, ay), (bx, by) in _edges(triangle):
            if not _near(_slope(((ax, ay), (bx, by))), angle):
                continue
            length = math.hypot(bx - ax, by - ay)
            for (cx, cy), radius in _circles(root):
                distance = abs((bx - ax) * (ay - cy) - (ax - cx) * (by - ay)) / length
                if _near(distance, radius):
                    return True
    return False


def _blocks_on_a_floor(root: ET.Element) -> bool:
    """Two blocks standing on one horizontal line drawn as the floor."""
    floors = [y for (_, y), (_, y2) in _lines(root) if _near(y, y2)]
    bases = [min(y for _, y in block) for block in _polygons(root, 4)]
    return any(sum(_near(base, floor) for base in bases) >= 2 for floor in floors)


def _atwood(root: ET.Element) -> bool:
    """A pulley with a string hanging straight down from each side."""
    for (cx, cy), radius in _circles(root):
        sides = {
            round(x1 - cx, 2)
            for (x1, y1), (x2, y2) in _lines(root)
            if _near(x1, x2) and _near(y1, cy) and y2 < y1 and _near(abs(x1 - cx), radius)
        }
        if len(sides) == 2:
            return True
    return False


def _pendulum(root: ET.Element) -> bool:
    """A string from the pivot at the origin down to the bob at its end."""
    return any(
        _near(a[0], 0.0) and _near(a[1], 0.0) and b[1] < 0 and _near(centre[0], b[0])
        for a, b in _lines(root)
        for centre, _ in _circles(root)
        if _near(centre[1], b[1])
    )


def _spring_to_block(root: ET.Element) -> bool:
    """A zigzag whose end meets a block's face."""
    for spring in (_points(e.get("points", "")) for e in root.iter(f"{SVG}polyline")):
        if len(spring) < 10:
            continue
        end = spring[-1]
        for block in _polygons(root, 4):
            xs = sorted(x for x, _ in block)
            ys = sorted(y for _, y in block)
            if _near(end[0], xs[0]) and ys[0] <= end[1] <= ys[-1]:
                return True
    return False


def _turning_axis(root: ET.Element) -> bool:
    """The vertical axis the frame turns about, dashed, with the arc of the turning drawn across it."""
    arcs = [path.get("d", "").split() for path in root.iter(f"{SVG}path")]
    middles = [(float(d[1]) + float(d[-2])) / 2 for d in arcs if len(d) == 11 and d[0] == "M" and d[3] == "A"]
    return any(
        _near(a[0], b[0]) and not _near(a[1], b[1]) and any(_near(middle, a[0]) for middle in middles)
        for a, b in _lines(root, dashed=True)
    )


# element kind: (a bank problem led by it, the values it is drawn at, what its figure must show)
SHOWN: dict[str, tuple[str, dict[str, float], Callable[[ET.Element], bool]]] = {
    "incline": ("incline-friction", {"theta": 0.5}, lambda root: _slope_with_block_on_it(root, 0.5)),
    "surface": ("pushed-blocks", {}, _blocks_on_a_floor),
    "rolling": ("sphere-rolling-up", {"theta": 0.4}, lambda root: _round_body_on_slope(root, 0.4)),
    "pulley": ("atwood", {}, _atwood),
    "pendulum": ("simple-pendulum", {}, _pendulum),
    "spring": ("mass-spring", {}, _spring_to_block),
    "rotating": ("bead-rotating-hoop", {}, _turning_axis),
}


def test_every_element_kind_has_a_drawer_and_a_figure_that_shows_it() -> None:
    assert set(SHOWN) == set(DRAWERS)


@pytest.mark.parametrize("kind", sorted(SHOWN))
def test_an_element_kinds_figure_shows_the_element(kind: str) -> None:
    problem_id, given, shows = SHOWN[kind]
    doc = BANK[problem_id]
    model = load_doc_model(doc, symbol_table(doc))
    assert kind in {element.kind for element in model.elements}
    assert shows(ET.fromstring(model_figure(model, given, title=doc.title)))


def test_a_wedge_is_drawn_as_a_slope_carrying_the_block() -> None:
    doc = BANK["moving-wedge"]
    root = ET.fromstring(model_figure(load_doc_model(doc, symbol_table(doc)), {"theta": 0.6}, title="w"))
    assert _slope_with_block_on_it(root, 0.6)


def test_a_collision_with_a_block_on_an_incline_draws_the_incline_that_pushes_on_it() -> None:
    doc = BANK["cart-hits-block-on-incline"]
    root = ET.fromstring(model_figure(load_doc_model(doc, symbol_table(doc)), {"theta": 0.5}, title="c"))
    assert _slope_with_block_on_it(root, 0.5)
    assert "resting at the foot of a fixed incline at angle θ" in root.findtext(f"{SVG}desc", "")


def _incline_model(angle: str) -> dict[str, object]:
    return {
        "gravity": "g",
        "elements": {"ramp": {"kind": "incline", "mass": "m", "angle": angle, "coordinate": "s"}},
        "quantities": {"acceleration": {"acceleration": "s"}},
    }


def test_a_parameter_without_a_number_falls_back_to_the_bodies_and_says_why() -> None:
    # theta = asin(k) has no real value at the typical k = 2 the figure draws at
    model = load_model(_incline_model("asin(k)"), positive("m", "g", "k"))
    figure = compose(model, {"k": 2.0})
    assert figure.fallback is not None and "at the figure's values" in figure.fallback
    assert "The bodies of the problem" in " ".join(figure.said)


def test_a_bug_in_a_drawer_surfaces_instead_of_falling_back(monkeypatch: pytest.MonkeyPatch) -> None:
    def broken(*_: object) -> bool:
        raise KeyError("a drawer's bug")

    monkeypatch.setitem(DRAWERS, "incline", broken)
    model = load_model(_incline_model("theta"), positive("m", "g", "theta"))
    with pytest.raises(KeyError):
        compose(model, {})


@pytest.mark.parametrize("problem", sorted(p.stem for p in LOWLEVEL.glob("*.yaml")))
def test_a_hand_written_model_is_recognised_as_the_picture_its_elements_draw(problem: str) -> None:
    table = positive(*yaml.safe_load((BANK_DIR / problem / "problem.yaml").read_text())["symbols"])
    by_hand = load_model(yaml.safe_load((LOWLEVEL / f"{problem}.yaml").read_text()), table)
    written = load_model(yaml.safe_load((BANK_DIR / problem / "model.yaml").read_text()), table)
    recognised, drawn = compose(by_hand, {}), compose(written, {})
    assert (recognised.drawn_from, drawn.drawn_from) == ("low-level model", "elements")
    assert recognised.canvas.elements == drawn.canvas.elements
    assert recognised.said == drawn.said
