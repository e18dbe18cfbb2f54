"""A projectile's figure: the launch velocity drawn at the student's launch angle, and the dashed path
from the launch point down to the ground line, as long and as high as the numbers make it."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest
import sympy

from physics.engine import load_model
from physics.figures import model_figure
from problems.symbols import symbol_table
from problems.variants import draw_variant, si_values
from tests.figures.test_figures import BANK, SVG, figure_of


def _values(student: str) -> dict[str, float]:
    doc = BANK["projectile"]
    drawn = si_values(doc, draw_variant(doc, 1, student, "secret"), symbol_table(doc))
    return {s.name: float(v) for s, v in drawn.items()}


def _points(element: ET.Element) -> list[tuple[float, float]]:
    pairs = (p.split(",") for p in element.get("points", "").split())
    return [(float(x), -float(y)) for x, y in pairs]  # back to y up


@pytest.mark.parametrize("student", ["ada", "bob", "cy"])
def test_the_path_runs_from_the_launch_point_to_the_ground_with_the_numbers_shape(student: str) -> None:
    values = _values(student)
    root = figure_of("projectile", student)
    [path] = [e for e in root.iter(f"{SVG}polyline") if e.get("stroke-dasharray")]
    points = _points(path)
    (x0, y0), (x1, y1) = points[0], points[-1]
    assert y1 == pytest.approx(y0, abs=1e-3)  # launched from level ground, it lands on it
    ground = [e for e in root.iter(f"{SVG}line") if float(e.get("stroke-width", 0)) == 0.07]
    assert ground and all(-float(e.get("y1", 0)) == pytest.approx(y1, abs=1e-3) for e in ground)
    height = max(y for _, y in points) - y0
    assert height / (x1 - x0) == pytest.approx(math.tan(values["alpha"]) / 4, rel=0.02)


def test_the_launch_velocity_is_drawn_at_the_launch_angle() -> None:
    values = _values("ada")
    root = figure_of("projectile")
    [path] = [e for e in root.iter(f"{SVG}polyline") if e.get("stroke-dasharray")]
    x0, y0 = _points(path)[0]
    [arrow] = [
        e
        for e in root.iter(f"{SVG}line")
        if float(e.get("x1", 0)) == pytest.approx(x0)
        and -float(e.get("y1", 0)) == pytest.approx(y0)
        and float(e.get("stroke-width", 0)) == 0.06
    ]
    dx = float(arrow.get("x2", 0)) - x0
    dy = -float(arrow.get("y2", 0)) - y0
    assert math.atan2(dy, dx) == pytest.approx(values["alpha"], abs=1e-3)
    assert root.find(f"{SVG}path") is not None  # the angle's arc


def test_a_launch_from_a_height_stands_on_a_cliff_labelled_with_it() -> None:
    symbols = {n: sympy.Symbol(n, positive=True) for n in ("m", "v0", "alpha", "g", "h")}
    model = load_model(
        {
            "coordinates": ["x", "y"],
            "bodies": {"ball": {"mass": "m", "position": {"x": "x", "y": "y"}}},
            "gravity": "g",
            "state": {"x": 0, "y": "h", "x_dot": "v0*cos(alpha)", "y_dot": "v0*sin(alpha)"},
            "domain": {"ranges": {"alpha": ["0", "pi/2"]}},
            "quantities": {"range": {"range": "ball", "level": 0}},
        },
        symbols,
    )
    root = ET.fromstring(model_figure(model, {"v0": 10.0, "alpha": 0.5, "g": 9.81, "h": 20.0}, title="cliff"))
    [path] = [e for e in root.iter(f"{SVG}polyline") if e.get("stroke-dasharray")]
    points = _points(path)
    assert points[0][1] - points[-1][1] > 1.0  # it lands well below where it was launched
    assert {"m", "v₀", "α", "h"} <= {e.text for e in root.iter(f"{SVG}text")}
    assert "from a height h" in root.findtext(f"{SVG}desc", "")


@pytest.mark.parametrize("slope", ["theta", "-theta"], ids=["up-an-incline", "down-an-incline"])
def test_a_landing_on_a_slope_draws_the_slope_through_the_launch_point_and_ends_the_path_on_it(
    slope: str,
) -> None:
    symbols = {n: sympy.Symbol(n, positive=True) for n in ("m", "v0", "alpha", "theta", "g")}
    model = load_model(
        {
            "coordinates": ["x", "y"],
            "bodies": {"ball": {"mass": "m", "position": {"x": "x", "y": "y"}}},
            "gravity": "g",
            "state": {"x": 0, "y": 0, "x_dot": "v0*cos(alpha)", "y_dot": "v0*sin(alpha)"},
            "quantities": {"range": {"range": "ball", "slope": slope}},
        },
        symbols,
    )
    angle = 0.3 if slope == "theta" else -0.3
    values = {"v0": 10.0, "alpha": 0.8, "theta": 0.3, "g": 9.81}
    root = ET.fromstring(model_figure(model, values, title="incline"))
    [path] = [e for e in root.iter(f"{SVG}polyline") if e.get("stroke-dasharray")]
    (x0, y0), (x1, y1) = _points(path)[0], _points(path)[-1]
    assert (y1 - y0) / (x1 - x0) == pytest.approx(math.tan(angle), rel=1e-3)
    [ground] = [e for e in root.iter(f"{SVG}line") if float(e.get("stroke-width", 0)) == 0.07]
    ends = [(float(ground.get(f"x{i}", 0)), -float(ground.get(f"y{i}", 0))) for i in (1, 2)]
    assert all(y - y0 == pytest.approx((x - x0) * math.tan(angle), abs=1e-2) for x, y in ends)
    assert "lands on the slope" in root.findtext(f"{SVG}desc", "")
