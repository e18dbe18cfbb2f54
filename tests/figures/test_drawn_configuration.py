"""Free-body diagrams are drawn in the configuration the scene shows: each force points as it does
there, and a body the model moves along one axis only still feels what holds it."""

from __future__ import annotations

import math
import re

import pytest

from physics.figures import body_forces, model_figure
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table
from tests.bank import bank_documents

BANK = bank_documents()
PENDULUMS = {  # problem: the body on the string
    "vertical-circle": "ball",
    "conical-pendulum": "bob",
    "pendulum-on-cart": "bob",
    "simple-pendulum": "bob",
    "ballistic-pendulum": "block",
}
_STRING = re.compile(
    r'<line x1="(-?0\.000)" y1="(-?0\.000)" x2="(-?[\d.]+)" y2="(-?[\d.]+)" stroke="[^"]+" stroke-width="0.04" '
    r"stroke-linecap"
)


def _model(problem_id: str):  # type: ignore[no-untyped-def]
    doc = BANK[problem_id]
    return load_doc_model(doc, symbol_table(doc))


def _forces(problem_id: str, body: str) -> dict[str, tuple[float, float]]:
    return {f.label: f.direction for f in body_forces(_model(problem_id), body, {})}


def _drawn_string_angle(problem_id: str) -> float:
    """The angle from the downward vertical at which the scene draws the string from its pivot (at the
    figure's origin), read from the SVG (whose y grows downwards)."""
    svg = model_figure(_model(problem_id), {}, title=problem_id)
    match = _STRING.search(svg)
    assert match is not None, "the scene draws no string from the pivot"
    x, down = float(match.group(3)), float(match.group(4))
    return math.atan2(x, down)


def _close(a: tuple[float, float], b: tuple[float, float]) -> bool:
    return math.isclose(a[0], b[0], abs_tol=1e-3) and math.isclose(a[1], b[1], abs_tol=1e-3)


def test_a_ball_at_the_top_of_a_vertical_circle_is_pulled_down_by_its_string() -> None:
    assert _close(_forces("vertical-circle", "ball")["T"], (0.0, -1.0))


@pytest.mark.parametrize(("problem_id", "body"), sorted(PENDULUMS.items()))
def test_a_pendulum_string_pulls_along_the_string_the_scene_draws(problem_id: str, body: str) -> None:
    angle = _drawn_string_angle(problem_id)
    assert _close(_forces(problem_id, body)["T"], (-math.sin(angle), math.cos(angle)))


def test_a_conical_pendulum_string_is_drawn_and_pulls_off_the_vertical() -> None:
    angle = _drawn_string_angle("conical-pendulum")
    assert math.radians(5) < abs(angle) < math.radians(85)
    tension = _forces("conical-pendulum", "bob")["T"]
    assert abs(tension[0]) > 0.1 and tension[1] > 0  # up and towards the axis, not straight up


def test_a_cart_stands_on_its_floor_and_feels_its_pendulum_pull_at_the_pivot() -> None:
    on_cart = _forces("pendulum-on-cart", "cart")
    on_bob = _forces("pendulum-on-cart", "bob")
    assert _close(on_cart["N"], (0.0, 1.0))
    assert _close(on_cart["T"], (-on_bob["T"][0], -on_bob["T"][1]))  # one label, opposite ways


def test_a_hanging_weight_over_a_pulley_is_still_pulled_straight_up() -> None:
    assert _close(_forces("incline-pulley", "m2")["T"], (0.0, 1.0))


def test_rolling_friction_on_a_ball_drawn_off_the_bowls_bottom_lies_along_the_bowl() -> None:
    found = _forces("bowl-rolling", "ball")
    (fx, fy), (nx, ny) = found["f"], found["N"]
    assert abs(nx) > 0.1  # drawn off the bottom, where a level friction would cross the surface
    assert math.isclose(fx * nx + fy * ny, 0.0, abs_tol=1e-9)


def test_a_double_pendulums_lower_rod_pulls_both_bobs_along_it_as_drawn_swung_aside() -> None:
    lower = _forces("double-pendulum", "bob2")["T₂"]
    assert abs(lower[0]) > 0.1  # the scene swings the rods aside from the vertical
    assert _close(_forces("double-pendulum", "bob1")["T₂"], (-lower[0], -lower[1]))
