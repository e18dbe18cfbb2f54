"""An instructor API key exports and erases one student's data through the API; nobody else may
(no key 401; a student key, even for its own id, or an LMS instructor session 403)."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from app.auth import Role
from app.db.types import utc_now
from app.lti.sessions import CSRF_HEADER, SESSION_COOKIE, open_session
from tests.api.conftest import key_headers

SUBMIT = "/v1/problems/atwood/parts/acceleration/submissions"
DATA = "/v1/student-data"


def _file(client: TestClient, headers: dict[str, str], student: str, answer: str) -> None:
    response = client.post(SUBMIT, json={"answer": answer, "student": student}, headers=headers)
    assert response.status_code == 201, response.text


def test_an_instructor_exports_one_students_data(client: TestClient, instructor_headers: dict[str, str]):
    _file(client, instructor_headers, "eve", "g (m2 - m1)/(m1 + m2)")
    _file(client, instructor_headers, "eve", "g")
    _file(client, instructor_headers, "bob", "2 g")
    response = client.get(DATA, params={"student": "eve"}, headers=instructor_headers)
    assert response.status_code == 200, response.text
    data = response.json()
    assert data["student"] == "eve"
    assert [s["answer"] for s in data["submissions"]] == ["g (m2 - m1)/(m1 + m2)", "g"]
    assert data["attempts"] == [{"problem": "atwood", "part": "acceleration", "used": 2}]
    assert data["grade_targets"] == [] and data["lti_sessions"] == [] and data["keys"] == []


def test_an_instructor_erases_one_students_data_and_no_one_elses(
    client: TestClient, instructor_headers: dict[str, str]
):
    _file(client, instructor_headers, "eve", "g (m2 - m1)/(m1 + m2)")
    _file(client, instructor_headers, "bob", "2 g")
    eves_key = key_headers(client, "student", "Eve Example", student="eve")
    assert client.get("/v1/problems", headers=eves_key).status_code == 200
    response = client.delete(DATA, params={"student": "eve"}, headers=instructor_headers)
    assert response.status_code == 200, response.text
    assert response.json() == {
        "student": "eve",
        "erased": {
            "submissions": 1,
            "attempt_counters": 1,
            "grade_targets": 0,
            "scores": 0,
            "lti_sessions": 0,
            "keys": 1,
            "enrolments": 0,
            "course_sessions": 0,
            "extensions": 0,
            "solution_views": 0,
        },
    }
    listed = client.get("/v1/submissions", params={"student": "eve"}, headers=instructor_headers).json()
    assert listed["items"] == []
    exported = client.get(DATA, params={"student": "eve"}, headers=instructor_headers).json()
    assert exported["submissions"] == [] and exported["attempts"] == []
    [key] = exported["keys"]
    assert key["name"] is None and key["revoked_at"] is not None
    assert client.get("/v1/problems", headers=eves_key).status_code == 401  # her key is revoked at once
    bob = client.get("/v1/submissions", params={"student": "bob"}, headers=instructor_headers).json()
    assert [item["answer"] for item in bob["items"]] == ["2 g"]


def _lms_instructor(client: TestClient) -> dict[str, str]:
    stores = client.app.state.services.stores  # type: ignore[attr-defined]
    session_id, record = open_session(
        stores.lti_sessions, platform_id=1, sub="prof", role=Role.INSTRUCTOR, name="Prof", now=utc_now()
    )
    return {"Cookie": f"{SESSION_COOKIE}={session_id}", CSRF_HEADER: record.csrf_token}


@pytest.mark.parametrize("method", ["GET", "DELETE"])
@pytest.mark.parametrize("caller", ["no key", "student key", "own student key", "LMS instructor session"])
def test_only_an_instructor_api_key_reaches_a_students_data(
    client: TestClient, instructor_headers: dict[str, str], method: str, caller: str
):
    _file(client, instructor_headers, "eve", "g")
    headers = {
        "no key": lambda: {},
        "student key": lambda: key_headers(client, "student", "bob", student="bob"),
        "own student key": lambda: key_headers(client, "student", "eve", student="eve"),
        "LMS instructor session": lambda: _lms_instructor(client),
    }[caller]()
    response = client.request(method, DATA, params={"student": "eve"}, headers=headers)
    assert response.status_code == (401 if caller == "no key" else 403), response.text
    still = client.get("/v1/submissions", params={"student": "eve"}, headers=instructor_headers).json()
    assert len(still["items"]) == 1
