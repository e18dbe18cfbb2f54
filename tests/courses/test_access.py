"""Which assignment takes a student's answer to a problem (`access.opening`)."""

from __future__ import annotations

from datetime import UTC, datetime, timedelta

import pytest

from app.courses import access
from app.courses.records import AssignmentSpec
from app.storage import memory_stores

NOW = datetime(2026, 3, 10, 12, tzinfo=UTC)
STUDENT = "lti:1:ada"  # an LMS identity, enrolled in each course it is launched from


@pytest.mark.parametrize(
    ("named", "taken_by"),
    [
        (None, "Lecture"),  # no course named: the first open assignment by due date
        ("Lecture", "Lecture"),
        ("Lab", "Lab"),  # it had gone to the lecture's, whose attempts and due date held it
        ("Elsewhere", None),  # a course the student is not in: the problem is not theirs there
    ],
)
def test_an_answer_is_taken_by_the_assignment_of_the_course_it_is_made_in(
    named: str | None, taken_by: str | None
):
    stores = memory_stores(clock=lambda: NOW)
    courses = {}
    for title, due in (
        ("Lecture", NOW + timedelta(days=1)),
        ("Lab", NOW + timedelta(days=2)),
        ("Elsewhere", NOW),
    ):
        course = stores.courses.create_course(title, owner="key:1")
        courses[title] = course.id
        spec = AssignmentSpec(f"{title} HW", ("yo-yo",), NOW - timedelta(days=1), due, max_attempts=3)
        stores.courses.create_assignment(course.id, spec)
        if title != "Elsewhere":
            stores.courses.enrol(course.id, STUDENT)
    opened = access.opening(stores, STUDENT, "yo-yo", NOW, None if named is None else courses[named])
    assert (opened and opened.assignment and opened.assignment.title) == (taken_by and f"{taken_by} HW")
