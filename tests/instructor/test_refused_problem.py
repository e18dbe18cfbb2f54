"""A stored problem that the running engine refuses (vetted by older code, which verified what this code
refuses): its author is shown why on its pages and can edit it; a student's check of it is a server
fault that says so, and nothing is recorded."""

from __future__ import annotations

import dataclasses
import html

import yaml
from fastapi.testclient import TestClient

from app.db.records import Role
from app.storage import Stores
from problems.loader import BANK_DIR
from tests.instructor.conftest import csrf_of, sign_in


def refused_document() -> dict:
    """The atwood problem with a reference the engine refuses (a symbol declared nowhere), standing for
    a model an engine change now refuses."""
    doc = yaml.safe_load((BANK_DIR / "atwood" / "problem.yaml").read_text())
    doc["id"], doc["title"] = "old-atwood", "An Atwood machine of last term"
    doc["parts"][0]["answer"] = "(m2 - m1)*g/(m1 + m2) + zeta"
    return doc


def test_a_stored_problem_the_engine_now_refuses_shows_its_author_why_and_no_student_is_graded(
    client: TestClient, stores: Stores
):
    author = stores.keys.create(Role.INSTRUCTOR, name="Prof Ada")
    student = stores.keys.create(Role.STUDENT, name="Ada", student="ada")
    stores.problems.create("old-atwood", refused_document(), owner_key_id=author.record.id)
    assert sign_in(client, author.plaintext).status_code == 303  # type: ignore[attr-defined]

    page = client.get("/instructor/problems/old-atwood")
    assert page.status_code == 200, page.text
    assert "This version no longer verifies" in page.text
    assert "zeta" in page.text  # the refusal, at its path
    assert 'href="/instructor/problems/old-atwood/edit">Edit it</a>' in page.text
    assert "Worked solution to print" not in page.text  # it has none under this code
    assert client.get("/instructor/problems/old-atwood/results").status_code == 200  # answers stay readable
    listing = client.get("/instructor/problems")
    assert "No longer verifies under this version of physcheck" in listing.text

    content = client.get("/p/old-atwood/content", headers={"Authorization": f"Bearer {student.plaintext}"})
    assert "This problem cannot be answered for now" in content.text
    assert content.text.count("disabled>") >= 3  # every part's answer box and button
    check = client.post(
        "/v1/problems/old-atwood/parts/acceleration/submissions",
        headers={"Authorization": f"Bearer {student.plaintext}"},
        json={"answer": "(m2 - m1) g/(m1 + m2)"},
    )
    assert check.status_code == 500
    assert "cannot be graded by this version of physcheck" in check.json()["error"]["message"]
    assert stores.submissions.page(problem_id="old-atwood").items == []


def test_a_problem_the_engine_now_refuses_cannot_be_newly_assigned_but_stays_where_it_was(
    client: TestClient, stores: Stores
):
    author = stores.keys.create(Role.INSTRUCTOR, name="Prof Ada")
    stores.problems.create("old-atwood", refused_document(), owner_key_id=author.record.id)
    client.app.state.services.catalog.warm_up()  # type: ignore[attr-defined]  # as at start: derives it
    api = {"Authorization": f"Bearer {author.plaintext}"}
    course = client.post("/v1/courses", headers=api, json={"title": "Mechanics", "timezone": "UTC"})
    assignment = {
        "title": "Homework 1",
        "problems": ["yo-yo", "old-atwood"],
        "opens_at": "2026-03-02T08:00:00+00:00",
        "due_at": "2026-03-09T23:59:00+00:00",
    }
    refused = client.post(f"/v1/courses/{course.json()['id']}/assignments", headers=api, json=assignment)
    assert refused.status_code == 422
    [detail] = refused.json()["error"]["details"]
    assert detail["path"] == "problems.1" and "no longer verifies" in detail["message"]

    made = client.post(
        f"/v1/courses/{course.json()['id']}/assignments",
        headers=api,
        json={**assignment, "problems": ["yo-yo"]},
    )
    assert made.status_code == 201, made.text
    # Assigned before the code changed (stored as it was then): the assignment can still be edited.
    stored = stores.courses.update_assignment(
        made.json()["id"],
        dataclasses.replace(
            stores.courses.get_assignment(made.json()["id"]).spec, problems=("yo-yo", "old-atwood")
        ),
    )
    edited = client.put(
        f"/v1/assignments/{stored.id}", headers=api, json={**assignment, "title": "Homework 1 (due later)"}
    )
    assert edited.status_code == 200, edited.text


def test_the_assignment_builder_says_a_problem_the_engine_now_refuses_must_be_edited_first(
    client: TestClient, stores: Stores
):
    author = stores.keys.create(Role.INSTRUCTOR, name="Prof Ada")
    stores.problems.create("old-atwood", refused_document(), owner_key_id=author.record.id)
    client.app.state.services.catalog.warm_up()  # type: ignore[attr-defined]
    assert sign_in(client, author.plaintext).status_code == 303  # type: ignore[attr-defined]
    course = client.post(
        "/v1/courses",
        headers={"Authorization": f"Bearer {author.plaintext}"},
        json={"title": "Mechanics", "timezone": "UTC"},
    ).json()["id"]
    form = client.get(f"/instructor/courses/{course}/assignments/new")
    refused = client.post(
        f"/instructor/courses/{course}/assignments/new",
        data={
            "csrf": csrf_of(form.text),
            "problem": ["old-atwood"],
            "order-old-atwood": "1",
            "title": "Homework 1",
            "opens_at": "2026-03-01T09:00",
            "due_at": "2026-03-08T23:59",
            "solutions": "after_due",
        },
    )
    assert refused.status_code == 422
    assert "no longer verifies under this version of physcheck" in html.unescape(refused.text)
    assert stores.courses.assignments(course) == []


def test_the_worked_solution_of_a_problem_the_engine_now_refuses_shows_its_faults_and_edit_link_not_a_500(
    client: TestClient, stores: Stores
):
    # it had been a 500 (a server fault) where the problem's page says why and how to edit it
    author = stores.keys.create(Role.INSTRUCTOR, name="Prof Ada")
    stores.problems.create("old-atwood", refused_document(), owner_key_id=author.record.id)
    assert sign_in(client, author.plaintext).status_code == 303  # type: ignore[attr-defined]
    page = client.get("/instructor/problems/old-atwood/solution")
    assert page.status_code == 409, page.text
    assert "This version no longer verifies" in page.text and "zeta" in page.text
    assert 'href="/instructor/problems/old-atwood/edit">Edit it</a>' in page.text
