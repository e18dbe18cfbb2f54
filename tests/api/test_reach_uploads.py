"""Speed at a position and trajectories through `POST /v1/problems`: derived and graded, or refused with
the reason at the model's path."""

from __future__ import annotations

from typing import Any

import yaml

from tests.api.test_authoring import BANK
from tests.api.test_engine_uploads import _details, upload


def bank_upload(problem: str, new_id: str) -> dict[str, Any]:
    doc = yaml.safe_load((BANK / problem / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK / problem / "model.yaml").read_text())
    doc["id"] = new_id
    assert isinstance(doc, dict)
    return doc


def test_an_uploaded_slide_derives_the_speed_and_the_normal_force_at_the_bottom(
    client, instructor_headers, student_headers
):
    response = upload(client, instructor_headers, bank_upload("quarter-circle-slide", "my-slide"))
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/my-slide/solution", headers=instructor_headers).json()
    assert {r["part"]: r["source"] for r in solution["references"]}["normal_force_at_bottom"] == "derived"
    assert solution["methods_agree"] is True
    graded = {
        answer: client.post(
            "/v1/problems/my-slide/parts/normal_force_at_bottom/submissions",
            json={"answer": answer},
            headers=student_headers,
        ).json()
        for answer in ("3*m*g", "m*g")
    }
    assert graded["3*m*g"]["verdict"] == "correct"
    assert graded["m*g"]["verdict"] == "incorrect"
    assert "at rest" in graded["m*g"]["feedback"]


def test_an_uploaded_projectile_with_a_wrong_typed_range_is_refused(client, instructor_headers):
    doc = bank_upload("projectile", "my-projectile")
    doc["parts"][1]["answer"] = "v0^2*sin(alpha)*cos(alpha)/g"  # the distance to the apex, typed as the range
    details = _details(upload(client, instructor_headers, doc))
    assert "disagrees with the model" in details["parts[1].answer"]


def test_a_speed_whose_start_is_not_in_the_state_is_refused_at_the_state(client, instructor_headers):
    doc = bank_upload("quarter-circle-slide", "my-slide")
    del doc["model"]["state"]
    details = _details(upload(client, instructor_headers, doc))
    assert "give where theta start" in details["model.state"]


def test_a_speed_where_the_block_never_arrives_is_refused_with_the_reason(client, instructor_headers):
    doc = bank_upload("quarter-circle-slide", "my-slide")
    doc["model"]["state"] = {"theta": "-pi/4"}
    doc["model"]["quantities"]["speed_at_bottom"]["at"] = {"theta": "pi/2"}
    details = _details(upload(client, instructor_headers, doc))
    assert any("does not reach theta = pi/2" in message for message in details.values()), details
