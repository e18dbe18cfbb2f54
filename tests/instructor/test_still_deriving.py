"""While a first start still derives the bank, the pages students land on say so (`/ready` did alone)."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from fastapi.testclient import TestClient

from app.storage import Stores
from tests.instructor.conftest import csrf_of, new_key

SAID = "still preparing its problems"


@pytest.fixture
def deriving(client: TestClient) -> Iterator[TestClient]:
    """The app as at a first start, its warm-up not done."""
    warm = client.app.state.services.catalog.warm  # type: ignore[attr-defined]
    warm.clear()
    yield client
    warm.set()


def test_a_key_students_problem_list_says_the_problems_are_still_being_prepared(
    deriving: TestClient, stores: Stores
):
    key = new_key(stores, "student", "Ada", student="ada")
    listed = deriving.get("/problems/content", headers={"Authorization": f"Bearer {key}"})
    assert listed.status_code == 200 and SAID in listed.text and "/p/yo-yo" in listed.text
    deriving.app.state.services.catalog.warm.set()  # type: ignore[attr-defined]
    assert SAID not in deriving.get("/problems/content", headers={"Authorization": f"Bearer {key}"}).text


def test_a_course_students_courses_say_the_problems_are_still_being_prepared(
    deriving: TestClient, stores: Stores, instructor_key: str
):
    from tests.instructor.conftest import sign_in

    sign_in(deriving, instructor_key)
    form = deriving.get("/instructor/courses")
    made = deriving.post("/instructor/courses", data={"csrf": csrf_of(form.text), "title": "Mechanics"})
    course = int(made.headers["location"].rsplit("/", 1)[1])
    page = deriving.get(f"/instructor/courses/{course}")
    deriving.post(
        f"/instructor/courses/{course}/join-code", data={"csrf": csrf_of(page.text), "enabled": "1"}
    )
    student = TestClient(deriving.app, follow_redirects=False)
    student.post(f"/join/{stores.courses.get_course(course).join_code}", data={"name": "Ada"})
    assert SAID in student.get("/courses").text
