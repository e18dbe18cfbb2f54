"""Free-body diagrams from models: the forces on a body point the way the physics says."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest

from physics.figures import body_forces, free_body_figure
from problems.loader import load_bank
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table

BANK = {doc.id: doc for doc in load_bank()}
THIRTY = math.radians(30)


def forces(
    problem_id: str, body: str, values: dict[str, float] | None = None
) -> dict[str, tuple[float, float]]:
    doc = BANK[problem_id]
    model = load_doc_model(doc, symbol_table(doc))
    return {f.label: f.direction for f in body_forces(model, body, values or {})}


def close(a: tuple[float, float], b: tuple[float, float]) -> bool:
    return math.isclose(a[0], b[0], abs_tol=1e-9) and math.isclose(a[1], b[1], abs_tol=1e-9)


def test_cart_on_an_incline_feels_its_weight_the_normal_force_and_the_tension_up_the_slope() -> None:
    found = forces("incline-pulley", "m1", {"theta": THIRTY})
    assert set(found) == {"m₁g", "N", "T"}
    assert close(found["m₁g"], (0.0, -1.0))
    assert close(found["N"], (-math.sin(THIRTY), math.cos(THIRTY)))  # out of the slope
    assert close(found["T"], (math.cos(THIRTY), math.sin(THIRTY)))  # up the slope, along the string


def test_friction_opposes_the_sliding_down_the_slope() -> None:
    found = forces("skier-friction", "skier", {"alpha": THIRTY})
    assert close(found["f"], (-math.cos(THIRTY), math.sin(THIRTY)))


def test_the_wedge_feels_the_block_pushing_into_it_and_the_floor_pushing_up() -> None:
    found = forces("moving-wedge", "wedge", {"theta": THIRTY})
    normals = [direction for label, direction in found.items() if label.startswith("N")]
    assert any(close(d, (0.0, 1.0)) for d in normals)
    assert any(close(d, (-math.sin(THIRTY), -math.cos(THIRTY))) for d in normals)


@pytest.mark.parametrize("problem_id", sorted(BANK))
def test_every_body_of_every_bank_problem_gets_a_free_body_diagram(problem_id: str) -> None:
    doc = BANK[problem_id]
    model = load_doc_model(doc, symbol_table(doc))
    for body in model.bodies:
        root = ET.fromstring(free_body_figure(model, body.name, {}, title=doc.title))
        assert root.get("role") == "img"
        assert "Forces on" in root.findtext("{http://www.w3.org/2000/svg}desc", "")
