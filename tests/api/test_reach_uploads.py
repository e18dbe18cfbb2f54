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
    assert "give where theta starts under" in details["model.state"]


def test_a_speed_where_the_block_never_arrives_is_refused_with_the_reason(client, instructor_headers):
    doc = bank_upload("quarter-circle-slide", "my-slide")
    doc["model"]["state"] = {"theta": "-pi/4"}
    doc["model"]["quantities"]["speed_at_bottom"]["at"] = {"theta": "pi/2"}
    details = _details(upload(client, instructor_headers, doc))
    assert any("does not reach theta = pi/2" in message for message in details.values()), details


def moving_wedge_with_a_drop(new_id: str) -> dict[str, Any]:
    """The bank's moving wedge, asked for the wedge's speed once the block has descended h from rest."""
    doc = bank_upload("moving-wedge", new_id)
    doc["symbols"]["h"] = {"meaning": "height the block descends", "dimension": "m"}
    doc["given"]["h"] = {"min": 0.2, "max": 1.0, "unit": "m", "sigfigs": 2}
    doc["model"]["state"] = {"s": 0, "X": 0}
    doc["model"]["quantities"]["wedge_speed"] = {"speed": "wedge", "at": {"s": "h/sin(theta)"}}
    doc["parts"].append(
        {
            "id": "wedge_speed",
            "kind": "symbolic",
            "prompt": "Find the wedge's speed when the block has descended a height $h$.",
            "answer": "m*cos(theta)*sqrt(2*g*h/((M + m)*(M + m*sin(theta)^2)))",
        }
    )
    return doc


def test_an_uploaded_moving_wedge_derives_its_speed_after_the_drop_by_momentum_and_energy(
    client, instructor_headers, student_headers
):
    response = upload(client, instructor_headers, moving_wedge_with_a_drop("my-wedge"))
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/my-wedge/solution", headers=instructor_headers).json()
    assert {r["part"]: r["source"] for r in solution["references"]}["wedge_speed"] == "derived"
    graded = {
        answer: client.post(
            "/v1/problems/my-wedge/parts/wedge_speed/submissions",
            json={"answer": answer},
            headers=student_headers,
        ).json()["verdict"]
        for answer in (
            "m*cos(theta)*sqrt(2*g*h)/sqrt((M + m)*(M + m*sin(theta)^2))",
            "m*cos(theta)*sqrt(2*g*h)/(M + m)",  # the block's speed as if the wedge were fixed
        )
    }
    assert list(graded.values()) == ["correct", "incorrect"]


def test_an_uploaded_wedge_tied_to_a_wall_is_refused_at_the_speed_s_at_saying_what_to_declare(
    client, instructor_headers
):
    doc = moving_wedge_with_a_drop("my-wedge")
    doc["symbols"]["k"] = {"meaning": "stiffness of the spring holding the wedge", "dimension": "N/m"}
    doc["given"]["k"] = {"min": 10, "max": 20, "unit": "N/m", "sigfigs": 2}
    doc["model"]["potentials"] = [
        {"bodies": ["wedge"], "anchor": {"x": 0}, "distance": "d", "energy": "k*d^2/2"}
    ]
    details = _details(upload(client, instructor_headers, doc))
    message = details["model.quantities.wedge_speed.at"]
    assert "X is not determined" in message and "Declare X fixed" in message
