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
