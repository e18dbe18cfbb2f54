"""Uploads through `POST /v1/problems` meet the engine's trust rules: a wrong model is never verified."""

from __future__ import annotations

import json
from typing import Any

import pytest
import yaml

from tests.api.test_authoring import BANK, atwood_upload


def upload(client: Any, headers: dict[str, str], doc: dict[str, Any]) -> Any:
    return client.post(
        "/v1/problems", content=json.dumps(doc), headers={**headers, "content-type": "application/json"}
    )


def hanging_spring(ranges: dict[str, list[str]] | None) -> dict[str, Any]:
    """A mass on a vertical spring of natural length L0, hung from a ceiling: how far below it does it rest?"""
    model: dict[str, Any] = {
        "coordinates": ["s"],
        "bodies": {"bob": {"mass": "m", "position": {"y": "-s"}}},
        "gravity": "g",
        "potentials": [{"bodies": ["bob"], "anchor": {"y": 0}, "distance": "d", "energy": "k*(d - L0)^2/2"}],
        "quantities": {"rest_length": {"equilibrium": "s"}},
    }
    if ranges is not None:
        model["domain"] = {"ranges": ranges}
    return {
        "id": "my-hanging-spring",
        "title": "Mass hanging on a spring",
        "topics": ["springs"],
        "statement": "A mass $m$ hangs on a spring $k$ of natural length $L_0$ from the ceiling.",
        "symbols": {
            "m": {"meaning": "mass", "dimension": "kg"},
            "k": {"meaning": "spring constant", "dimension": "N/m"},
            "g": {"meaning": "gravity", "dimension": "m/s^2"},
            "L0": {"meaning": "natural length", "dimension": "m"},
        },
        "given": {
            "m": {"min": 0.5, "max": 2, "unit": "kg"},
            "k": {"min": 50, "max": 100, "unit": "N/m"},
            "g": {"min": 9.81, "max": 9.81, "unit": "m/s^2"},
            "L0": {"min": 0.1, "max": 0.3, "unit": "m"},
        },
        "parts": [
            {
                "id": "rest_length",
                "kind": "symbolic",
                "prompt": "How far below the ceiling does the mass rest?",
                "answer": "L0 + m*g/k",
            }
        ],
        "model": model,
    }


def _details(response: Any) -> dict[str, str]:
    assert response.status_code == 422, response.text
    return {d["path"]: d["message"] for d in response.json()["error"]["details"]}


def test_a_spring_whose_side_is_not_declared_is_refused_with_the_reason(client, instructor_headers):
    details = _details(upload(client, instructor_headers, hanging_spring(None)))
    assert "not even in d" in details["model.potentials[0].distance"]


def test_a_spring_whose_side_is_declared_derives_l0_plus_m_g_over_k(client, instructor_headers):
    response = upload(client, instructor_headers, hanging_spring({"s": ["0", "oo"]}))
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/my-hanging-spring/solution", headers=instructor_headers).json()
    (reference,) = solution["references"]
    assert reference["source"] == "derived"
    assert solution["methods_agree"] is True


def test_a_misspelled_quantity_is_refused_even_beside_a_typed_answer(client, instructor_headers):
    doc = atwood_upload()
    doc["parts"][1]["quantity"] = "tensoin"
    doc["parts"][1]["answer"] = "m1*g"
    details = _details(upload(client, instructor_headers, doc))
    assert "'tensoin'" in details["parts[1].quantity"]


def test_a_part_with_only_a_typed_answer_is_labelled_not_derived(client, instructor_headers):
    doc = atwood_upload()
    doc["parts"][1]["id"] = "string_tension"
    doc["model"]["unused"] = ["tension"]  # derived, but no part asks for it: said on purpose
    response = upload(client, instructor_headers, doc)
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/my-atwood/solution", headers=instructor_headers).json()
    sources = {r["part"]: r["source"] for r in solution["references"]}
    assert sources["string_tension"] == "not derived"
    assert sources["acceleration"] == sources["acceleration_numeric"] == "derived"


def test_an_upload_whose_model_derives_a_quantity_no_part_asks_for_is_refused(client, instructor_headers):
    doc = atwood_upload()
    doc["parts"][1]["id"] = "tensoin"  # a typo: the typed answer would be graded, the derivation ignored
    details = _details(upload(client, instructor_headers, doc))
    assert "'tensoin'" in details["parts[1].id"] and "'tension'" in details["parts[1].id"]
    assert "no part asks for the quantity 'tension'" in details["model.quantities.tension"]


@pytest.mark.parametrize("problem", ["atwood"])
def test_bank_verify_names_the_parts_that_are_not_derived(problem: str) -> None:
    from problems.loader import parse_problem
    from problems.selftest import verify_problem

    doc = yaml.safe_load((BANK / problem / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK / problem / "model.yaml").read_text())
    doc["parts"][1]["id"] = "string_tension"
    doc["model"]["unused"] = ["tension"]
    summary = verify_problem(parse_problem(doc), variants=1).summary()
    assert "not derived (typed answer only): string_tension" in summary


def test_a_derivation_fault_is_reported_at_its_place_in_the_model(client, instructor_headers):
    doc = atwood_upload()
    doc["model"].pop("elements")
    doc["model"]["constraints"] = {
        "string": {"kind": "string", "gap": "y_m1 - y_m2"}
    }  # the positions break it
    details = _details(upload(client, instructor_headers, doc))
    assert "violate" in details["model.constraints.string"]


def test_a_model_term_with_the_wrong_dimension_is_refused_at_its_path(client, instructor_headers):
    doc = hanging_spring({"s": ["0", "oo"]})
    doc["model"]["potentials"][0]["energy"] = "k*(d - L0)"  # a force where the energy belongs
    details = _details(upload(client, instructor_headers, doc))
    assert "expected an energy" in details["model.potentials[0].energy"]


def pulled_block() -> dict[str, Any]:
    """A block on a rough floor pulled by a rope at an angle: an applied force beside friction."""
    return {
        "id": "my-pulled-block",
        "title": "Block pulled along a rough floor",
        "topics": ["friction", "forces"],
        "statement": "A block $m$ is pulled by a force $F$ at $\\alpha$ above the horizontal; friction $\\mu$.",
        "symbols": {
            "m": {"meaning": "mass", "dimension": "kg"},
            "F": {"meaning": "pull", "dimension": "N"},
            "alpha": {"meaning": "angle of the rope", "dimension": "1", "range": [0, "pi/2"]},
            "mu": {"meaning": "kinetic friction coefficient", "dimension": "1"},
            "g": {"meaning": "gravity", "dimension": "m/s^2"},
        },
        "constraints": ["F*sin(alpha) < m*g", "mu*(m*g - F*sin(alpha)) < F*cos(alpha)"],
        "given": {
            "m": {"min": 2, "max": 3, "unit": "kg"},
            "F": {"min": 20, "max": 25, "unit": "N"},
            "alpha": {"min": 10, "max": 30, "unit": "deg"},
            "mu": {"min": 0.1, "max": 0.3, "unit": "1"},
            "g": {"min": 9.81, "max": 9.81, "unit": "m/s^2"},
        },
        "parts": [
            {"id": "acceleration", "kind": "symbolic", "prompt": "Find the acceleration."},
            {"id": "normal_force", "kind": "symbolic", "prompt": "Find the normal force."},
        ],
        "model": {
            "coordinates": ["x"],
            "bodies": {"block": {"mass": "m", "position": {"x": "x", "y": 0}}},
            "gravity": "g",
            "constraints": {"floor": {"kind": "surface", "gap": "y_block"}},
            "friction": [{"constraint": "floor", "body": "block", "coefficient": "mu", "sliding": "x"}],
            "forces": [{"body": "block", "force": {"x": "F*cos(alpha)", "y": "F*sin(alpha)"}}],
            "domain": {
                "ranges": {"alpha": ["0", "pi/2"]},
                "positive": ["m*g - F*sin(alpha)", "F*cos(alpha) - mu*(m*g - F*sin(alpha))"],
            },
            "quantities": {"acceleration": {"acceleration": "x"}, "normal_force": {"force": "floor"}},
        },
    }


def test_an_applied_force_is_derived_and_its_checks_are_listed(client, instructor_headers, student_headers):
    response = upload(client, instructor_headers, pulled_block())
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/my-pulled-block/solution", headers=instructor_headers).json()
    assert {"dimensions", "energy balance", "limit acceleration (no friction)"} <= set(solution["checks"])
    verdict = client.post(
        "/v1/problems/my-pulled-block/parts/normal_force/submissions",
        json={"answer": "m*g - F*sin(alpha)"},
        headers=student_headers,
    ).json()
    assert verdict["verdict"] == "correct"


def test_a_force_with_the_wrong_dimension_is_refused(client, instructor_headers):
    doc = pulled_block()
    doc["model"]["forces"][0]["force"]["x"] = "F*cos(alpha)/m"
    details = _details(upload(client, instructor_headers, doc))
    assert "expected a force" in details["model.forces[0].force.x"]


def three_springs() -> dict[str, Any]:
    """Two masses between two walls joined by three springs: both normal-mode frequencies."""
    springs = [
        {"bodies": ["a"], "anchor": {"x": 0}, "distance": "d", "energy": "k*d^2/2"},
        {"bodies": ["a", "b"], "distance": "d", "energy": "k*d^2/2"},
        {"bodies": ["b"], "anchor": {"x": 0}, "distance": "d", "energy": "k*d^2/2"},
    ]
    return {
        "id": "my-three-springs",
        "title": "Two masses and three springs",
        "topics": ["oscillations", "normal modes"],
        "statement": "Two masses $m$ between two walls are joined by three springs $k$.",
        "symbols": {
            "m": {"meaning": "mass", "dimension": "kg"},
            "k": {"meaning": "spring constant", "dimension": "N/m"},
        },
        "given": {"m": {"min": 1, "max": 2, "unit": "kg"}, "k": {"min": 10, "max": 20, "unit": "N/m"}},
        "parts": [
            {"id": "slow_mode", "kind": "symbolic", "prompt": "The lower normal-mode angular frequency."},
            {"id": "fast_mode", "kind": "symbolic", "prompt": "The higher one.", "answer": "sqrt(3*k/m)"},
        ],
        "model": {
            "coordinates": ["x1", "x2"],
            "bodies": {
                "a": {"mass": "m", "position": {"x": "x1"}},
                "b": {"mass": "m", "position": {"x": "x2"}},
            },
            "potentials": springs,
            "quantities": {"slow_mode": {"normal_frequency": 1}, "fast_mode": {"normal_frequency": 2}},
        },
    }


def test_both_normal_modes_are_derived_from_an_upload(client, instructor_headers, student_headers):
    response = upload(client, instructor_headers, three_springs())
    assert response.status_code == 201, response.text
    verdict = client.post(
        "/v1/problems/my-three-springs/parts/slow_mode/submissions",
        json={"answer": "sqrt(k/m)"},
        headers=student_headers,
    ).json()
    assert verdict["verdict"] == "correct"


def test_modes_typed_in_the_wrong_order_are_refused(client, instructor_headers):
    doc = three_springs()
    doc["parts"][1]["answer"] = "sqrt(k/m)"  # the lower mode typed for the higher one
    details = _details(upload(client, instructor_headers, doc))
    assert "sqrt(3*k/m)" in details["parts[1].answer"]  # the higher mode, as the model derives it


def test_a_part_defined_as_a_formula_of_quantities_is_derived(client, instructor_headers):
    doc = atwood_upload()
    doc["model"]["quantities"]["net_force"] = {"expression": "tension - m1*g"}
    doc["parts"].append(
        {"id": "net_force", "kind": "symbolic", "prompt": "Net force on m1?", "answer": "m1*g"}
    )
    details = _details(upload(client, instructor_headers, doc))  # a wrong typed answer is caught
    assert "disagrees with the model" in details["parts[3].answer"]
    doc["parts"][3]["answer"] = "m1*(m2 - m1)*g/(m1 + m2)"
    response = upload(client, instructor_headers, doc)
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/my-atwood/solution", headers=instructor_headers).json()
    assert {r["part"]: r["source"] for r in solution["references"]}["net_force"] == "derived"
