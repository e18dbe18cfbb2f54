"""A string from a body on a slope or a table over a pulley at its edge: to a hanging body, or down
under a light movable pulley that carries it and up to a support."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest
import sympy

from physics.engine import load_model
from physics.figures import model_figure

SVG = "{http://www.w3.org/2000/svg}"
SYMBOLS = {n: sympy.Symbol(n, positive=True) for n in ("m1", "m2", "g", "theta", "mu")}
SLOPES = {
    "incline": {
        "kind": "incline",
        "body": "block",
        "mass": "m1",
        "angle": "theta",
        "coordinate": "s",
        "direction": "up",
    },
    "table": {"kind": "surface", "body": "block", "mass": "m1", "coordinate": "s", "friction": "mu"},
}
ALONG = {"incline": {"x": "cos(theta)", "y": "sin(theta)"}, "table": "right"}


def _figure(slope: str, hanging_end: dict[str, str], position: str) -> ET.Element:
    model = load_model(
        {
            "coordinates": ["s"],
            "bodies": {"carrier": {"mass": "m2", "position": {"y": position}}},
            "elements": {
                "ramp": SLOPES[slope],
                "string": {"kind": "pulley", "ends": [{"body": "block", "pulls": ALONG[slope]}, hanging_end]},
            },
            "gravity": "g",
            "quantities": {"a": {"acceleration": "s"}},
        },
        SYMBOLS,
    )
    return ET.fromstring(model_figure(model, {"theta": 0.5, "mu": 0.2}, title="pulley"))


def _wheels(root: ET.Element) -> int:
    return sum(float(e.get("r", "0")) >= 0.3 for e in root.iter(f"{SVG}circle"))


@pytest.mark.parametrize("slope", sorted(SLOPES))
def test_a_string_under_a_movable_pulley_is_drawn_under_it(slope: str) -> None:
    root = _figure(slope, {"under": "carrier", "pulls": "up"}, "-s/2")
    assert _wheels(root) == 2
    said = root.findtext(f"{SVG}desc", "")
    assert "down under a light movable pulley carrying m₂, and up to a fixed support" in said


@pytest.mark.parametrize("slope", sorted(SLOPES))
def test_a_string_to_a_hanging_body_has_one_pulley(slope: str) -> None:
    root = _figure(slope, {"body": "carrier", "pulls": "up"}, "-s")
    assert _wheels(root) == 1
    assert "m₂, which hangs" in root.findtext(f"{SVG}desc", "")


WHEEL = {"mass": "M", "radius": "R", "inertia": "M*R^2/2"}
WHEEL_SYMBOLS = {**SYMBOLS, "M": sympy.Symbol("M", positive=True), "R": sympy.Symbol("R", positive=True)}


def _table_figure(bodies: dict, table: dict | None, pulls: str, wheel: dict) -> ET.Element:
    elements = {} if table is None else {"table": table}
    ends = [{"body": "m1", "pulls": pulls}, {"body": "m2", "pulls": "up"}]
    document = {
        "coordinates": ["s"],
        "bodies": bodies,
        "elements": {**elements, "string": {"kind": "pulley", "ends": ends, **wheel}},
        "gravity": "g",
        "quantities": {"a": {"acceleration": "s"}},
    }
    return ET.fromstring(model_figure(load_model(document, WHEEL_SYMBOLS), {"mu": 0.2}, title="table"))


HANGING = {"mass": "m2", "position": {"y": "-s"}}
SURFACE = {"kind": "surface", "body": "m1", "mass": "m1", "coordinate": "s", "friction": "mu"}


@pytest.mark.parametrize(
    ("bodies", "table", "pulls", "wheel", "said"),
    [
        # A block written by hand to slide at one height is on a table, not hanging beside m2.
        ({"m1": {"mass": "m1", "position": {"x": "s"}}, "m2": HANGING}, None, "right", {}, "A table with m₁"),
        ({"m1": {"mass": "m1", "position": {"x": "-s"}}, "m2": HANGING}, None, "left", {}, "A table with m₁"),
        (
            {"m1": {"mass": "m1", "position": {"x": "s"}}, "m2": HANGING},
            None,
            "right",
            WHEEL,
            "over a pulley, M,",
        ),
        # A massive pulley at a surface's edge: m2 hangs from it (the wheel was drawn as the hanging body).
        ({"m2": HANGING}, SURFACE, "right", WHEEL, "over a pulley, M, at the edge to m₂, which hangs"),
    ],
)
def test_a_body_on_a_table_is_drawn_on_it_with_its_string_over_the_edge(bodies, table, pulls, wheel, said):
    root = _table_figure(bodies, table, pulls, wheel)
    description = root.findtext(f"{SVG}desc", "")
    assert said in description and "m₂, which hangs" in description
    assert "either side" not in description
    assert _wheels(root) == 1


def test_the_pulley_is_on_the_side_the_table_body_moves_to_as_the_other_descends():
    def pulley_x(x: str, pulls: str) -> float:
        root = _table_figure({"m1": {"mass": "m1", "position": {"x": x}}, "m2": HANGING}, None, pulls, {})
        wheel = next(e for e in root.iter(f"{SVG}circle") if float(e.get("r", "0")) >= 0.3)
        block = next(e for e in root.iter(f"{SVG}polygon"))
        left_edge = min(float(point.split(",")[0]) for point in block.get("points", "").split())
        return float(wheel.get("cx", "0")) - left_edge

    assert pulley_x("s", "right") > 0
    assert pulley_x("-s", "left") < 0
