"""Figures true to the student's values: an angle is drawn at its value where that reads clearly, and a
figure that cannot draw it so says it is not to scale; the axis and coordinates the statement defines
are drawn."""

from __future__ import annotations

import math
import re
from decimal import Decimal

import pytest

from app.web.layout import scale_note
from physics.figures import model_figure
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table
from problems.variants import Variant, si_values
from tests.bank import bank_documents

_POLYGON = re.compile(r'<polygon points="([^"]+)"')


def _figure(problem: str, **given: float) -> str:
    doc = bank_documents()[problem]
    table = symbol_table(doc)
    values = {name: (float(g.min) + float(g.max)) / 2 for name, g in doc.given.items()}
    values.update(given)
    variant = Variant(problem, 0, "s", {name: Decimal(str(v)) for name, v in values.items()})
    si = {str(symbol): float(value) for symbol, value in si_values(doc, variant, table).items()}
    return model_figure(load_doc_model(doc, table), si, title=doc.title)


def _slopes(svg: str) -> list[float]:
    """The angles (degrees, 0-90) of the sides of the first polygon drawn: the incline or the wedge."""
    points = [tuple(map(float, p.split(","))) for p in _POLYGON.search(svg).group(1).split()]  # type: ignore[union-attr]
    angles = []
    for (x1, y1), (x2, y2) in zip(points, points[1:] + points[:1], strict=True):
        if math.hypot(x2 - x1, y2 - y1) > 1e-6:
            angle = abs(math.degrees(math.atan2(y2 - y1, x2 - x1))) % 180
            angles.append(min(angle, 180 - angle))
    return angles


@pytest.mark.parametrize(
    ("problem", "symbol", "degrees"),
    [
        ("skier-friction", "alpha", 7.5),  # was drawn at 20° under "with your values"
        ("skier-friction", "alpha", 12.0),
        ("incline-friction", "theta", 35.0),
        ("moving-wedge", "theta", 20.0),
        ("moving-wedge", "theta", 50.0),
        ("rough-incline-speed", "theta", 60.0),
    ],
)
def test_an_angle_is_drawn_at_the_students_value(problem: str, symbol: str, degrees: float) -> None:
    svg = _figure(problem, **{symbol: degrees})
    slopes = _slopes(svg)
    assert any(abs(s - degrees) < 0.05 for s in slopes), (degrees, slopes)
    assert scale_note(svg) == ""


def test_an_angle_too_small_to_read_is_drawn_larger_and_the_figure_says_so() -> None:
    svg = _figure("skier-friction", alpha=2.0)
    assert any(abs(s - 5.0) < 0.05 for s in _slopes(svg))
    assert not any(abs(s - 2.0) < 0.5 for s in _slopes(svg))
    assert scale_note(svg) == "Not to scale: α = 2° is drawn as 5°."
    assert 'data-to-scale="no"' in svg and "Not to scale" in svg  # said in the description too


def test_the_wedge_figure_draws_the_x_axis_and_both_coordinates() -> None:
    svg = _figure("moving-wedge")
    texts = re.findall(r"<text[^>]*>([^<]*)</text>", svg)
    assert {"x", "X", "s"} <= set(texts), texts
    assert "The +x axis points to the right." in svg


def test_the_yoyo_figure_marks_the_distance_fallen_by_the_solutions_name() -> None:
    svg = _figure("yo-yo")
    assert "The coordinate s grows along the blue arrow marked s." in svg  # the model's notation renames d


def _gap(a: tuple[float, float, float, float], b: tuple[float, float, float, float]) -> float:
    """How far apart two label boxes are (0 when they touch or overlap)."""
    return max(b[0] - a[2], a[0] - b[2], b[1] - a[3], a[1] - b[3], 0.0)


@pytest.mark.parametrize("degrees", [20.0, 35.0, 50.0, 65.0])
def test_the_wedges_labels_stand_apart_at_every_angle(degrees: float) -> None:
    # "M", "X" and "θ" crowded the wedge's corner, one over another at the steep end of the range
    import xml.etree.ElementTree as ET

    from tests.figures.test_scene_labels import text_boxes

    labels = text_boxes(ET.fromstring(_figure("moving-wedge", theta=degrees)))
    assert {"M", "X", "θ", "m", "s", "x"} <= {text for text, _ in labels}
    crowded = [
        (first, second)
        for i, (first, a) in enumerate(labels)
        for second, b in labels[i + 1 :]
        if _gap(a, b) < 0.3
    ]
    assert crowded == []
