"""An impact's figure: the two bodies with their velocities before, or the fragments of an explosion."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import sympy

from physics.engine import load_model
from physics.figures import model_figure

SVG = "{http://www.w3.org/2000/svg}"
SYMBOLS = {n: sympy.Symbol(n, positive=True) for n in ("m1", "m2", "Q", "u1")}


def _figure(impact: dict[str, object], state: dict[str, str]) -> ET.Element:
    model = load_model(
        {
            "coordinates": ["x1", "x2"],
            "bodies": {
                "a": {"mass": "m1", "position": {"x": "x1"}},
                "b": {"mass": "m2", "position": {"x": "x2"}},
            },
            "state": state,
            "impact": {"bodies": ["a", "b"], **impact},
            "quantities": {"v": {"final_velocity": "b"}},
        },
        SYMBOLS,
    )
    return ET.fromstring(model_figure(model, {}, title="impact"))


def _texts(root: ET.Element) -> set[str | None]:
    return {e.text for e in root.iter(f"{SVG}text")}


def test_a_collision_figure_labels_the_moving_body_and_its_velocity() -> None:
    root = _figure({"restitution": 1}, {"x1_dot": "u1"})
    assert {"m₁", "m₂", "u₁"} <= _texts(root)
    assert "elastic collision" in root.findtext(f"{SVG}desc", "")


def test_an_explosion_figure_says_the_fragments_are_pushed_apart() -> None:
    root = _figure({"release": "Q"}, {})
    assert {"m₁", "m₂"} <= _texts(root)
    assert "explosion" in root.findtext(f"{SVG}desc", "")
