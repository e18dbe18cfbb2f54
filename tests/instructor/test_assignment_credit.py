"""What a course's student earns on an assignment's problem, as their problem page shows it and the
gradebook counts it: late penalties, and no credit after reading the worked solution."""

from __future__ import annotations

import re
from datetime import UTC, datetime, timedelta

import pytest
from fastapi.testclient import TestClient

from app.courses.policy import granted, shown
from app.courses.records import (
    AssignmentRecord,
    AssignmentSpec,
    ExtensionRecord,
    LateKind,
    LatePolicy,
    SolutionRelease,
)
from app.courses.service import student_cell
from app.storage import Stores
from tests.db.helpers import CORRECT
from tests.instructor.conftest import csrf_of

PENALTY = LatePolicy(LateKind.PENALTY, per_day=0.1, limit=0.5)


def _joined_student(
    signed_in: TestClient, stores: Stores, spec: AssignmentSpec, timezone: str = "UTC"
) -> tuple[TestClient, str, AssignmentRecord]:
    """A course with one assignment, and a student who joined it by its code: their browser, the
    identity their work is filed under, and the assignment."""
    form = signed_in.get("/instructor/courses")
    made = signed_in.post(
        "/instructor/courses", data={"csrf": csrf_of(form.text), "title": "Mechanics", "timezone": timezone}
    )
    course = int(made.headers["location"].rsplit("/", 1)[1])
    assignment = stores.courses.create_assignment(course, spec)
    page = signed_in.get(f"/instructor/courses/{course}")
    signed_in.post(
        f"/instructor/courses/{course}/join-code", data={"csrf": csrf_of(page.text), "enabled": "1"}
    )
    student = TestClient(signed_in.app, follow_redirects=False)
    student.post(f"/join/{stores.courses.get_course(course).join_code}", data={"name": "Ada"})
    (enrolment,) = stores.courses.roster(course)
    return student, enrolment.student, assignment


def _file_right_answer(stores: Stores, student: str) -> None:
    stores.submissions.file(
        problem_id="yo-yo",
        problem_version=stores.problems.get("yo-yo").version,
        part_id="acceleration",
        student=student,
        answer="g",
        verdict=CORRECT,
        max_attempts=None,
    )


def _file_right_answers(stores: Stores, student: str) -> None:
    """A right answer to each of the yo-yo's parts, filed now."""
    for part in stores.problems.get("yo-yo").document["parts"]:
        stores.submissions.file(
            problem_id="yo-yo",
            problem_version=stores.problems.get("yo-yo").version,
            part_id=part["id"],
            student=student,
            answer="g",
            verdict=CORRECT,
            max_attempts=None,
        )


def _gradebook_score(client: TestClient, assignment: AssignmentRecord, student: str) -> float:
    services = client.app.state.services  # type: ignore[attr-defined]
    return student_cell(services.stores, services.catalog, assignment, student, datetime.now(UTC)).score


def test_the_problem_page_shows_a_late_answers_score_with_its_penalty_as_the_gradebook_counts_it(
    signed_in: TestClient, stores: Stores
):
    # the page had said "1 of 4" where the gradebook counted 0.9 of the late part
    now = datetime.now(UTC)
    spec = AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), now - timedelta(hours=1), PENALTY)
    student, identity, assignment = _joined_student(signed_in, stores, spec)
    _file_right_answer(stores, identity)
    counted = _gradebook_score(signed_in, assignment, identity)
    assert counted == 0.9  # one day (or part of one) late, 10 % a day
    page = student.get("/p/yo-yo").text
    assert f"Your score: <strong>{counted:g} of " in page
    assert "late penalties applied" in page
    assert (
        f"Solved late: best score {counted:g} of 1 (answered after the due date: a 10 % late penalty)."
        in page
    )
    assert "Late: it counts for 90 % of its score." in page  # in the part's history, beside the answer


def test_the_problem_page_shows_an_answer_on_time_in_full(signed_in: TestClient, stores: Stores):
    now = datetime.now(UTC)
    spec = AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), now + timedelta(days=1), PENALTY)
    student, identity, _ = _joined_student(signed_in, stores, spec)
    _file_right_answer(stores, identity)
    page = student.get("/p/yo-yo").text
    assert "Solved: best score 1 of 1." in page
    assert "late penalt" not in page and "Solved late" not in page and "Late: it counts" not in page


def test_a_solution_read_with_nothing_at_stake_still_freezes_the_grade_when_an_extension_reopens_answers(
    signed_in: TestClient, stores: Stores
):
    # read after the due date, it had not been recorded: an extension then let its answers earn credit
    now = datetime.now(UTC)
    spec = AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), now - timedelta(hours=1))
    student, identity, assignment = _joined_student(signed_in, stores, spec)
    shown = student.get("/p/yo-yo/solution")
    assert (
        shown.status_code == 200 and "confirm-solution" not in shown.text
    )  # shown at once: nothing at stake
    assert "yo-yo" in stores.courses.solutions_opened(identity)
    stores.courses.set_extension(assignment.id, identity, ExtensionRecord(now + timedelta(days=1), now))
    _file_right_answer(stores, identity)
    assert _gradebook_score(signed_in, assignment, identity) == 0
    assert "Your grade on this part is frozen" in student.get("/p/yo-yo").text


def test_a_solution_not_yet_released_is_not_recorded_as_read(signed_in: TestClient, stores: Stores):
    now = datetime.now(UTC)
    spec = AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), now + timedelta(days=1))
    student, identity, _ = _joined_student(signed_in, stores, spec)
    assert "Not released yet" in student.get("/p/yo-yo/solution").text
    assert stores.courses.solutions_opened(identity) == {}


def _answer_boxes(page: str) -> list[str]:
    return re.findall(r'<input id="answer-\d+"[^>]*>', page)


def test_a_closed_assignments_problem_page_disables_its_answer_boxes_until_an_extension_reopens_them(
    signed_in: TestClient, stores: Stores
):
    # past its due date the boxes had stayed open, and a typed answer was refused (409) only when sent
    now = datetime.now(UTC)
    spec = AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), now - timedelta(hours=1))
    student, identity, assignment = _joined_student(signed_in, stores, spec)
    page = student.get("/p/yo-yo").text
    assert "answers are no longer accepted" in page
    assert _answer_boxes(page) and all("disabled" in box for box in _answer_boxes(page))
    stores.courses.set_extension(assignment.id, identity, ExtensionRecord(now + timedelta(days=1), now))
    reopened = student.get("/p/yo-yo").text
    assert _answer_boxes(reopened) and not any("disabled" in box for box in _answer_boxes(reopened))


def test_the_frozen_grade_notice_gives_the_moment_in_the_courses_zone_as_the_solution_page_does(
    signed_in: TestClient, stores: Stores
):
    # the problem page had given it in UTC, the solution page and the due date in the course's zone
    now = datetime.now(UTC)
    spec = AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), now - timedelta(hours=1))
    student, identity, assignment = _joined_student(signed_in, stores, spec, timezone="Asia/Tokyo")
    student.get("/p/yo-yo/solution")
    opened = stores.courses.solutions_opened(identity)["yo-yo"]
    stores.courses.set_extension(assignment.id, identity, ExtensionRecord(now + timedelta(days=1), now))
    page = student.get("/p/yo-yo").text
    assert (
        f'you opened the worked solution on <time datetime="{opened.isoformat()}">{shown(opened, "Asia/Tokyo")}</time>'
        in page
    )


def test_a_closed_assignments_parts_say_since_when_they_are_closed_in_the_courses_zone(
    signed_in: TestClient, stores: Stores
):
    # each part had said "Attempts: 0 used (no limit)" beside its disabled box, as if it were open
    now = datetime.now(UTC)
    due = now - timedelta(hours=1)
    spec = AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), due)
    student, identity, _ = _joined_student(signed_in, stores, spec, timezone="Asia/Tokyo")
    _file_right_answer(stores, identity)  # on the acceleration: its attempt is still said
    page = student.get("/p/yo-yo").text
    standings = dict(re.findall(r'id="standing-(\d+)">\s*<span class="attempts[^"]*">([^<]*)</span>', page))
    closed = f"Closed since {shown(due, 'Asia/Tokyo')}"
    assert standings == {"0": f"{closed}; 1 attempt used.", "1": f"{closed}.", "2": f"{closed}."}
    assert "(no limit)" not in page


@pytest.mark.parametrize(
    ("due_in", "asked_for"),
    [
        (timedelta(days=1), None),  # solved on time: nothing left to earn, shown at once
        (timedelta(hours=-1), "parts 1, 2, 3"),  # solved late, a penalty taken: asked first
    ],
)
def test_opening_a_released_solution_asks_first_for_parts_solved_only_late(
    signed_in: TestClient, stores: Stores, due_in: timedelta, asked_for: str | None
):
    # a part solved late had counted as earned: the solution opened without a word, its grade frozen
    now = datetime.now(UTC)
    spec = AssignmentSpec(
        "HW 1", ("yo-yo",), now - timedelta(days=2), now + due_in, PENALTY, None, SolutionRelease.RELEASED
    )
    student, identity, _ = _joined_student(signed_in, stores, spec)
    _file_right_answers(stores, identity)
    shown = student.get("/p/yo-yo/solution").text
    asked = re.search(r"your grade on (parts? [\d, ]+) of this problem stays as it is now", shown)
    assert (asked and asked.group(1)) == asked_for
    assert ("yo-yo" in stores.courses.solutions_opened(identity)) is (asked_for is None)
    warned = "Opening it freezes your grade" in student.get("/p/yo-yo").text
    assert warned is (asked_for is not None)


def test_a_part_solved_only_late_says_its_grade_is_frozen_once_the_solution_is_opened(
    signed_in: TestClient, stores: Stores
):
    # its answers earn no more than the late score now, yet the page had said nothing of it
    now = datetime.now(UTC)
    spec = AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), now - timedelta(hours=1), PENALTY)
    student, identity, _ = _joined_student(signed_in, stores, spec)
    _file_right_answer(stores, identity)
    stores.courses.open_solution(identity, "yo-yo", datetime.now(UTC))  # after the answer: it counts
    page = student.get("/p/yo-yo").text
    assert "Solved late: best score 0.9 of 1" in page
    assert "Your grade on this part is frozen at 0.9 of 1" in page


@pytest.mark.parametrize(("ticked", "score"), [(False, 0.9), (True, 1.0)])
def test_an_extension_set_on_the_gradebook_page_regrades_an_earlier_late_answer_only_when_ticked(
    signed_in: TestClient, stores: Stores, ticked: bool, score: float
):
    # an extension had lifted the penalty of answers graded before it was granted, unasked
    now = datetime.now(UTC)
    spec = AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), now - timedelta(hours=1), PENALTY)
    student, identity, assignment = _joined_student(signed_in, stores, spec)
    _file_right_answer(stores, identity)
    gradebook = f"/instructor/courses/{assignment.course_id}/gradebook"
    form = {
        "csrf": csrf_of(signed_in.get(gradebook).text),
        "student": identity,
        "assignment": str(assignment.id),
        "due_at": f"{now + timedelta(days=2):%Y-%m-%dT%H:%M}",
    }
    sent = signed_in.post(
        f"/instructor/courses/{assignment.course_id}/extensions",
        data={**form, "regrade_earlier": "on"} if ticked else form,
    )
    assert sent.status_code == 303
    assert _gradebook_score(signed_in, assignment, identity) == score
    assert f"best score {score:g} of 1" in student.get("/p/yo-yo").text  # the page counts as the gradebook
    _file_right_answer(stores, identity)  # within the extension: in full either way
    assert _gradebook_score(signed_in, assignment, identity) == 1.0


def test_the_problem_pages_banner_says_a_due_date_is_the_students_extension(
    signed_in: TestClient, stores: Stores
):
    # the banner gave the extended date bare, beside "answered after the due date" on the answers before it,
    # where the course's and the assignment's pages say "(your extension)"
    now = datetime.now(UTC).replace(second=0, microsecond=0)
    spec = AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), now - timedelta(hours=1), PENALTY)
    student, identity, assignment = _joined_student(signed_in, stores, spec)
    banner = re.compile(r'<aside class="notice assignment-banner".*?</aside>', re.S)
    before = banner.search(student.get("/p/yo-yo").text)
    assert before and "your extension" not in before.group(0)
    due = now + timedelta(days=2)
    stores.courses.set_extension(assignment.id, identity, granted(None, due, now, regrade_earlier=False))
    after = banner.search(student.get("/p/yo-yo").text)
    assert after and f"due <strong>{shown(due, 'UTC')}</strong> (your extension)." in after.group(0)
