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


def _dropped(state_speed: str) -> ET.Element:
    symbols = {n: sympy.Symbol(n, positive=True) for n in ("m", "g", "h", "e")}
    model = load_model(
        {
            "coordinates": ["y"],
            "bodies": {"ball": {"mass": "m", "position": {"y": "y"}}},
            "gravity": "g",
            "state": {"y": 0, "y_dot": state_speed},
            "impact": {"bodies": ["ball", {"fixed": "floor"}], "normal": {"y": -1}, "restitution": "e"},
            "quantities": {"v": {"final_speed": "ball"}},
        },
        symbols,
    )
    return ET.fromstring(model_figure(model, {}, title="bounce"))


def _arrow_heights(root: ET.Element) -> list[tuple[float, float]]:
    """(start, end) heights of each arrow's shaft (a line ending at a head's tip), in SVG coordinates,
    which grow downwards."""
    tips = {e.get("points", "").split()[0] for e in root.iter(f"{SVG}polygon")}
    return [
        (float(e.get("y1", "0")), float(e.get("y2", "0")))
        for e in root.iter(f"{SVG}line")
        if f"{e.get('x2')},{e.get('y2')}" in tips
    ]


def _squares(root: ET.Element) -> int:
    return sum(len(e.get("points", "").split()) == 4 for e in root.iter(f"{SVG}polygon"))


def test_a_ball_dropped_on_the_floor_is_drawn_round_with_its_fall_pointing_down() -> None:
    root = _dropped("-sqrt(2*g*h)")
    assert len(list(root.iter(f"{SVG}circle"))) == 1 and not _squares(root)
    heights = _arrow_heights(root)
    assert len(heights) == 1 and heights[0][1] > heights[0][0]  # towards the floor
    assert "moving down" in root.findtext(f"{SVG}desc", "")


def test_a_ball_thrown_up_into_a_ceiling_points_up() -> None:
    root = _dropped("sqrt(2*g*h)")
    heights = _arrow_heights(root)
    assert len(heights) == 1 and heights[0][1] < heights[0][0]
    assert "moving up" in root.findtext(f"{SVG}desc", "")


def test_a_rigid_body_in_an_impact_is_drawn_as_a_rod_met_at_its_struck_point() -> None:
    symbols = {n: sympy.Symbol(n, positive=True) for n in ("m", "M", "L", "u")}
    model = load_model(
        {
            "coordinates": ["s"],
            "bodies": {"ball": {"mass": "m", "position": {"x": "s"}}},
            "elements": {
                "axle": {
                    "kind": "pendulum",
                    "body": "rod",
                    "mass": "M",
                    "inertia": "M*L^2/12",
                    "distance": "L/2",
                    "coordinate": "phi",
                }
            },
            "state": {"s": "0", "phi": "0", "s_dot": "u"},
            "impact": {
                "bodies": ["ball", "rod"],
                "restitution": 1,
                "points": {"rod": {"x": "L*sin(phi)", "y": "-L*cos(phi)"}},
            },
            "quantities": {"spin": {"velocity_after": "phi"}},
        },
        symbols,
    )
    figure = ET.fromstring(model_figure(model, {}, title="impact"))
    assert "M is a rigid body turning about a fixed pivot, drawn as a rod" in figure.findtext(
        f"{SVG}desc", ""
    )
    circles = figure.findall(f".//{SVG}circle")
    assert len([c for c in circles if float(c.get("r", "0")) > 0.2]) == 1  # the ball only: the rod is no ball


def test_a_free_rod_in_an_impact_has_no_pivot() -> None:
    symbols = {n: sympy.Symbol(n, positive=True) for n in ("m", "M", "L", "u")}
    model = load_model(
        {
            "coordinates": ["s", "X", "Y", "theta"],
            "bodies": {
                "puck": {"mass": "m", "position": {"x": "s"}},
                "rod": {
                    "mass": "M",
                    "inertia": "M*L^2/12",
                    "position": {"x": "X", "y": "Y"},
                    "angle": "theta",
                },
            },
            "state": {"s": "0", "X": "0", "Y": "0", "theta": "0", "s_dot": "u"},
            "impact": {
                "bodies": ["puck", "rod"],
                "restitution": 1,
                "points": {"rod": {"x": "X - L*sin(theta)/2", "y": "Y + L*cos(theta)/2"}},
            },
            "quantities": {"spin": {"velocity_after": "theta"}},
        },
        symbols,
    )
    said = ET.fromstring(model_figure(model, {}, title="impact")).findtext(f"{SVG}desc", "")
    assert "M is a rigid body, drawn as a rod" in said and "pivot" not in said
