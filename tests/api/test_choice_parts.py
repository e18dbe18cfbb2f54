"""A multiple-choice part end to end: uploaded with a problem, shown to students, graded and filed."""

from __future__ import annotations

import json

from tests.problems.documents import spring_with_choice

PART = "/v1/problems/tiny-spring/parts/friction_direction"


def _upload(client, instructor_headers) -> None:
    response = client.post(
        "/v1/problems",
        content=json.dumps(spring_with_choice()),
        headers={**instructor_headers, "content-type": "application/json"},
    )
    assert response.status_code == 201, response.text


def test_an_uploaded_choice_part_is_shown_graded_and_filed(client, instructor_headers, student_headers):
    _upload(client, instructor_headers)
    view = client.get("/v1/problems/tiny-spring", headers=student_headers).json()
    part = next(p for p in view["parts"] if p["id"] == "friction_direction")
    assert part["kind"] == "choice"
    assert [c["label"] for c in part["choices"]] == ["A", "B", "C"]
    assert "correct" not in json.dumps(part)

    unreadable = client.post(f"{PART}/submissions", json={"answer": "E"}, headers=student_headers)
    assert unreadable.status_code == 201
    assert (unreadable.json()["verdict"], unreadable.json()["attempts_used"]) == ("invalid", 0)

    preview = client.post(f"{PART}/preview", json={"answer": "b"}, headers=student_headers).json()
    assert preview["read_as"]["text"] == "B" and preview["error"] is None

    wrong = client.post(f"{PART}/submissions", json={"answer": "b"}, headers=student_headers).json()
    assert (wrong["verdict"], wrong["reason"], wrong["attempts_used"]) == ("incorrect", "known_mistake", 1)
    assert wrong["feedback"] == "Friction opposes the sliding, which is down the slope."
    # max_attempts: 1, so the right answer comes too late
    late = client.post(f"{PART}/submissions", json={"answer": "A"}, headers=student_headers)
    assert late.status_code == 409


def test_the_solution_names_the_right_choice(client, instructor_headers):
    _upload(client, instructor_headers)
    solution = client.get("/v1/problems/tiny-spring/solution", headers=instructor_headers).json()
    reference = next(r for r in solution["references"] if r["part"] == "friction_direction")
    assert (reference["kind"], reference["text"]) == ("choice", "A: Up the slope")


def test_the_student_page_offers_the_choices_as_radio_buttons(client, instructor_headers, student_headers):
    _upload(client, instructor_headers)
    html = client.get("/p/tiny-spring/content", headers=student_headers).text
    assert 'type="radio"' in html and 'value="B"' in html
    assert "Perpendicular to the slope" in html
