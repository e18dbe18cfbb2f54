"""Free-body diagrams show the forces of constraints the engine knows only by their gaps (kind "other"):
a wire or a hoop holding a bead, a pivot or an axle holding a rigid body, a floor's grip on a ladder's
foot; and a ball rolling in a bowl keeps its normal force and friction with typical values too."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest
import sympy

from physics.engine import Model
from physics.figures import body_forces, free_body_figure
from physics.figures.configuration import drawn_configuration
from physics.figures.figure import Values
from problems.symbols import symbol_table
from problems.variants import draw_variant, si_values
from tests.figures.test_free_body import BANK, bank_model

SVG = "{http://www.w3.org/2000/svg}"
UP, TOWARDS_WALL = (0.0, 1.0), (-1.0, 0.0)
ACROSS_PATH = None  # across the body's path, upwards, where the scene draws it on that path
# (problem, body, label of the held force, its direction where the diagram is drawn)
HELD = [
    pytest.param("bead-parabola", "bead", "N", ACROSS_PATH, id="wire-holds-the-bead-up-across-it"),
    pytest.param("bead-rotating-hoop", "bead", "N", ACROSS_PATH, id="hoop-pulls-the-bead-to-its-centre"),
    pytest.param("bowl-rolling", "ball", "N", ACROSS_PATH, id="bowl-pushes-the-ball-up-across-it"),
    # an axle's one arrow is the resultant of the solutions' R_x and R_y (P where the radius is R)
    pytest.param("physical-pendulum", "rod", "R", UP, id="axle-holds-the-rod"),
    pytest.param("atwood-massive-pulley", "stringWheel", "P", UP, id="axle-holds-the-pulley"),
    pytest.param("flywheel", "wheel", "P", UP, id="axle-holds-the-flywheel"),
    pytest.param("ladder-slipping", "ladder", "f", TOWARDS_WALL, id="floor-grips-the-ladder-foot"),
]


def student_values(problem_id: str) -> dict[str, float]:
    doc = BANK[problem_id]
    values = si_values(doc, draw_variant(doc, 1, "ada", "secret"), symbol_table(doc))
    return {s.name: float(v) for s, v in values.items()}


def across_path(model: Model, body: str, given: dict[str, float]) -> tuple[float, float]:
    """The upward unit normal to the body's path (its one coordinate's), where the scene draws it."""
    (coordinate,) = model.coordinates
    drawn = drawn_configuration(model, given)
    values = Values(model, given)
    position = dict(model.body(body).position)
    vx, vy = (values.number(sympy.diff(position[axis], coordinate.symbol), drawn) for axis in "xy")
    norm = math.hypot(vx, vy)
    return (-vy / norm, vx / norm) if vx > 0 else (vy / norm, -vx / norm)


@pytest.mark.parametrize("typical", [False, True], ids=["student-values", "typical-values"])
@pytest.mark.parametrize(("problem_id", "body", "label", "direction"), HELD)
def test_a_body_held_by_a_constraint_shows_its_force_pointing_the_way_it_holds(
    problem_id: str, body: str, label: str, direction: tuple[float, float] | None, typical: bool
) -> None:
    model = bank_model(problem_id)
    values = {} if typical else student_values(problem_id)
    direction = direction or across_path(model, body, values)
    found = {f.label: f.direction for f in body_forces(model, body, values)}
    assert label in found, found
    assert math.isclose(found[label][0], direction[0], abs_tol=1e-9)
    assert math.isclose(found[label][1], direction[1], abs_tol=1e-9)
    root = ET.fromstring(free_body_figure(model, body, values, title="t"))
    assert label in {text.text for text in root.iter(f"{SVG}text")}
    assert label in root.findtext(f"{SVG}desc", "")


@pytest.mark.parametrize("problem_id", ["physical-pendulum", "atwood-massive-pulley", "flywheel"])
def test_a_pivot_is_one_force_against_the_others_not_one_per_axis(problem_id: str) -> None:
    model = bank_model(problem_id)
    (turning,) = [b for b in model.bodies if b.angle is not None]
    forces = body_forces(model, turning.name, student_values(problem_id))
    pivots = [f for f in forces if f.label in ("R", "P")]  # the axle's letter, as the solutions name it
    assert len(pivots) == 1, forces
    others = [f.direction for f in forces if f not in pivots]
    pull = (sum(d[0] for d in others), sum(d[1] for d in others))
    assert pivots[0].direction[0] * pull[0] + pivots[0].direction[1] * pull[1] < 0  # it holds the body
