"""Instructors upload problems (JSON or YAML), version and retire them, and read worked solutions."""

from __future__ import annotations

import copy
import json
from pathlib import Path

import pytest
import yaml

BANK = Path(__file__).resolve().parents[2] / "problems" / "bank"


def atwood_upload(problem_id: str = "my-atwood") -> dict:
    doc = yaml.safe_load((BANK / "atwood" / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK / "atwood" / "model.yaml").read_text())
    doc["id"] = problem_id
    return doc


def upload(client, headers, doc, fmt="json"):
    if fmt == "json":
        return client.post(
            "/v1/problems", content=json.dumps(doc), headers={**headers, "content-type": "application/json"}
        )
    return client.post(
        "/v1/problems", content=yaml.safe_dump(doc), headers={**headers, "content-type": "application/yaml"}
    )


@pytest.mark.parametrize("fmt", ["json", "yaml"])
def test_instructor_uploads_a_problem_students_can_answer(client, instructor_headers, student_headers, fmt):
    response = upload(client, instructor_headers, atwood_upload(), fmt)
    assert response.status_code == 201, response.text
    assert response.json() == {"id": "my-atwood", "version": 1}
    assert "my-atwood" in {p["id"] for p in client.get("/v1/problems", headers=student_headers).json()}
    result = client.post(
        "/v1/problems/my-atwood/parts/acceleration/submissions",
        json={"answer": "g (m2 - m1)/(m1 + m2)"},
        headers=student_headers,
    ).json()
    assert result["verdict"] == "correct"


def test_broken_upload_lists_every_error_with_its_path(client, instructor_headers):
    doc = atwood_upload()
    del doc["title"]
    doc["parts"][0]["kind"] = "essay"
    doc["parts"][2]["tolerance"] = {"rel": -0.5}
    doc["given"]["nobody"] = {"min": 1, "max": 2, "unit": "kg"}
    response = upload(client, instructor_headers, doc)
    assert response.status_code == 422
    error = response.json()["error"]
    assert error["code"] == "invalid_problem"
    paths = {detail["path"] for detail in error["details"]}
    assert {"title", "parts[0].kind", "parts[2].tolerance.rel"} <= paths, paths
    assert error["message"] == f"The problem has {len(error['details'])} errors: see details."


def test_upload_with_one_error_says_error_in_the_singular(client, instructor_headers):
    doc = atwood_upload()
    doc["parts"][0]["answer"] = "(m2 - m1)*g/m2"
    error = upload(client, instructor_headers, doc).json()["error"]
    assert len(error["details"]) == 1, error["details"]
    assert error["message"] == "The problem has 1 error: see details."


def test_hand_typed_reference_contradicting_the_derivation_is_refused(client, instructor_headers):
    doc = atwood_upload()
    doc["parts"][0]["answer"] = "(m2 - m1)*g/m2"
    response = upload(client, instructor_headers, doc)
    assert response.status_code == 422
    details = response.json()["error"]["details"]
    assert any("parts" in d["path"] and "answer" in d["path"] for d in details), details


def test_unsafe_yaml_is_refused(client, instructor_headers):
    body = "!!python/object/apply:os.system ['true']\n"
    response = client.post(
        "/v1/problems", content=body, headers={**instructor_headers, "content-type": "application/yaml"}
    )
    assert response.status_code == 422


def test_students_cannot_upload(client, student_headers):
    assert upload(client, student_headers, atwood_upload()).status_code == 403


def test_only_the_owner_versions_and_retires_a_problem(client, instructor_headers, student_headers):
    from tests.api.conftest import key_headers

    other = key_headers(client, "instructor", "other")
    upload(client, instructor_headers, atwood_upload())
    changed = copy.deepcopy(atwood_upload())
    changed["title"] = "Atwood machine, revised"
    body = json.dumps(changed)
    json_type = {"content-type": "application/json"}
    assert (
        client.put("/v1/problems/my-atwood", content=body, headers={**other, **json_type}).status_code == 403
    )
    assert (
        client.put(
            "/v1/problems/atwood", content=body, headers={**instructor_headers, **json_type}
        ).status_code
        == 403
    )
    response = client.put("/v1/problems/my-atwood", content=body, headers={**instructor_headers, **json_type})
    assert response.json() == {"id": "my-atwood", "version": 2}
    assert (
        client.get("/v1/problems/my-atwood", headers=student_headers).json()["title"]
        == "Atwood machine, revised"
    )
    assert client.delete("/v1/problems/my-atwood", headers=other).status_code == 403
    assert client.delete("/v1/problems/my-atwood", headers=instructor_headers).status_code == 204
    assert client.get("/v1/problems/my-atwood", headers=student_headers).status_code == 404


def test_solution_shows_each_method_and_their_agreement(client, instructor_headers, student_headers):
    solution = client.get("/v1/problems/moving-wedge/solution", headers=instructor_headers).json()
    assert solution["methods_agree"] is True
    assert len(solution["methods"]) >= 2
    assert all(len(methods) >= 2 for methods in solution["agreement"].values())
    references = {r["part"]: r for r in solution["references"]}
    assert "sin" in references["wedge_acceleration"]["text"]
    assert all(step["latex"] for method in solution["methods"] for step in method["steps"])
    assert client.get("/v1/problems/moving-wedge/solution", headers=student_headers).status_code == 403


def test_attempt_limit_refuses_graded_answers_but_files_unreadable_ones(
    client, instructor_headers, student_headers
):
    doc = atwood_upload()
    doc["max_attempts"] = 2
    assert upload(client, instructor_headers, doc).status_code == 201
    view = client.get("/v1/problems/my-atwood", headers=student_headers).json()
    assert {part["max_attempts"] for part in view["parts"]} == {2}
    url = "/v1/problems/my-atwood/parts/acceleration/submissions"
    statuses = [
        client.post(url, json={"answer": f"{i + 1} g"}, headers=student_headers).status_code for i in range(3)
    ]
    assert statuses == [201, 201, 409]
    refused = client.post(url, json={"answer": "5 g"}, headers=student_headers).json()
    assert refused["error"]["code"] == "attempts_exhausted"
    unreadable = client.post(url, json={"answer": "g +"}, headers=student_headers)
    assert (unreadable.status_code, unreadable.json()["verdict"], unreadable.json()["attempts_used"]) == (
        201,
        "invalid",
        2,
    )
    assert (
        client.post(
            url.replace("acceleration", "tension"), json={"answer": "g"}, headers=student_headers
        ).status_code
        == 201
    )


def test_grade_passback_problems_are_for_instructors(client, instructor_headers, student_headers):
    assert client.get("/v1/lti/delivery-problems", headers=instructor_headers).json() == []
    assert client.get("/v1/lti/delivery-problems", headers=student_headers).status_code == 403


def test_upload_using_abs_is_accepted_and_graded_through_the_worker(
    client, instructor_headers, student_headers
):
    # The reference crosses into the grading worker compiled, never printed by sympy (`Abs(...)`) and
    # read again by the parser, which knows only `abs`.
    doc = yaml.safe_load((BANK / "atwood" / "problem.yaml").read_text())
    doc["id"] = "abs-atwood"
    acceleration = doc["parts"][0]
    acceleration["prompt"] = "Find the magnitude of the acceleration."
    acceleration["answer"] = "abs(m2 - m1)*g/(m1 + m2)"
    acceleration["mistakes"] = [{"answer": "abs(m2 - m1)*g/m2", "feedback": "Accelerate both masses."}]
    acceleration["limits"] = []
    response = upload(client, instructor_headers, doc, "yaml")
    assert response.status_code == 201, response.text

    def submit(answer: str) -> dict:
        response = client.post(
            "/v1/problems/abs-atwood/parts/acceleration/submissions",
            json={"answer": answer},
            headers=student_headers,
        )
        assert response.status_code == 201, response.text
        return response.json()

    assert submit("|m1 - m2| g/(m1 + m2)")["verdict"] == "correct"
    wrong = submit("(m2 - m1) g/(m1 + m2)")  # differs where m1 > m2
    assert (wrong["verdict"], wrong["reason"]) == ("incorrect", "wrong_value")
    mistake = submit("abs(m1 - m2) g/m2")
    assert (mistake["reason"], mistake["feedback"]) == ("known_mistake", "Accelerate both masses.")


def test_solution_names_bodies_that_share_a_mass_by_their_own_names(client, instructor_headers):
    # rolling-incline: a cylinder, a hoop, a sphere and a point, each of mass m ("mass of each object")
    solution = client.get("/v1/problems/rolling-incline/solution", headers=instructor_headers).json()
    titles = [step["title"] for method in solution["methods"] for step in method["steps"]]
    assert not any("the each object" in title for title in titles), titles
    assert any("for the hoop" in title for title in titles), titles
