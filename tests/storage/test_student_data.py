"""One student's data, exported and erased across the stores (SQLite, PostgreSQL, the fake): every
submission, attempt counter, grade target with its queued scores, and LMS session of that student,
and nothing of anyone else's; submissions stay append-only for everyone not being erased."""

from __future__ import annotations

from datetime import timedelta

import pytest
from sqlalchemy import delete, update
from sqlalchemy.exc import DatabaseError

from app.auth import Role
from app.courses import sessions as course_sessions
from app.courses.records import AssignmentSpec, ExtensionRecord
from app.db.database import Database
from app.db.models import Submission
from app.db.types import utc_now
from app.lti.platforms import add_platform
from app.lti.sessions import SessionRecord
from app.storage import Stores
from app.storage.student_data import Erased
from tests.db.helpers import CORRECT, PART, PROBLEM
from tests.storage.helpers import store_problem, submit

ISSUER = "https://lms.example"
URLS = (f"{ISSUER}/auth", f"{ISSUER}/token", f"{ISSUER}/jwks")
ERASED, KEPT = "lti:1:erased", "lti:1:kept"


def _two_students(stores: Stores) -> None:
    """Each: two submissions (one graded, which queues a score to the LMS), a grade target, a session."""
    version = store_problem(stores)
    platform = add_platform(stores.platforms, ISSUER, "client", ["d"], *URLS)
    now = utc_now()
    for student in (ERASED, KEPT):
        sub = student.rsplit(":", 1)[1]
        stores.outbox.add_target(
            platform, student=student, problem_id=PROBLEM, lineitem_url=f"{ISSUER}/li/1", sub=sub
        )
        submit(stores, version, student=student, answer=f"m g ({sub})")
        submit(stores, version, CORRECT, student=student, answer=f"m*g ({sub})")
        record = SessionRecord(
            platform.id, sub, student, Role.STUDENT, f"Name of {sub}", "csrf", now + timedelta(hours=8)
        )
        stores.lti_sessions.save(f"session-{sub}", record, now)
        stores.keys.create(Role.STUDENT, name=f"Key of {sub}", student=student)
    # both on a course's roster, each with a personal sign-in link, a session and an extension
    course = stores.courses.create_course("Mechanics", owner="key:1", owner_name="Prof", timezone="UTC")
    assignment = stores.courses.create_assignment(
        course.id, AssignmentSpec("Homework 1", (PROBLEM,), now, now + timedelta(days=7))
    )
    for student in (ERASED, KEPT):
        sub = student.rsplit(":", 1)[1]
        stores.courses.enrol(course.id, student, f"Name of {sub}", f"{sub}@uni.example")
        course_sessions.sign_in(
            stores.courses, course_sessions.issue_link(stores.courses, course.id, student, now), now
        )
        course_sessions.issue_link(stores.courses, course.id, student, now)
        stores.courses.set_extension(assignment.id, student, ExtensionRecord(now + timedelta(days=9), now))
        stores.courses.open_solution(student, PROBLEM, now)


def test_export_holds_everything_of_one_student_and_nothing_of_others(stores: Stores):
    _two_students(stores)
    data = stores.student_data.export(ERASED)
    assert data.student == ERASED
    assert [s.answer for s in data.submissions] == ["m g (erased)", "m*g (erased)"]
    assert {s.student for s in data.submissions} == {ERASED}
    assert [(a.problem_id, a.part_id, a.used) for a in data.attempts] == [(PROBLEM, PART, 2)]
    [target] = data.grade_targets
    assert (target.issuer, target.problem_id, target.sub) == (ISSUER, PROBLEM, "erased")
    assert len(target.scores) >= 1
    [session] = data.lti_sessions
    assert (session.issuer, session.sub, session.name) == (ISSUER, "erased", "Name of erased")
    [key] = data.keys
    assert (key.name, key.revoked_at) == ("Key of erased", None)
    [enrolment] = data.enrolments
    assert (enrolment.name, enrolment.email) == ("Name of erased", "erased@uni.example")
    assert len(data.extensions) == 1
    assert [(o.problem_id, o.opened_at) for o in data.solutions_opened] == [
        (PROBLEM, data.extensions[0].due_at - timedelta(days=9))
    ]


def test_an_unknown_student_exports_empty(stores: Stores):
    _two_students(stores)
    data = stores.student_data.export("nobody")
    assert (data.submissions, data.attempts, data.grade_targets, data.lti_sessions, data.keys) == (
        [],
        [],
        [],
        [],
        [],
    )


def test_erase_removes_one_students_data_and_keeps_the_others(stores: Stores):
    _two_students(stores)
    kept_before = stores.student_data.export(KEPT)
    scores_before = len(stores.outbox.scores())
    erased = stores.student_data.erase(ERASED)
    assert erased == Erased(
        submissions=2,
        attempt_counters=1,
        grade_targets=1,
        scores=erased.scores,
        lti_sessions=1,
        keys=1,
        enrolments=1,
        course_sessions=3,  # the session a link opened, that spent link, and a newer one not yet used
        extensions=1,
        solution_views=1,
    )
    assert erased.scores >= 1 and len(stores.outbox.scores()) == scores_before - erased.scores
    after = stores.student_data.export(ERASED)
    assert (after.submissions, after.attempts, after.grade_targets, after.lti_sessions) == ([], [], [], [])
    assert stores.submissions.page(student=ERASED).items == []
    assert stores.submissions.attempts_used(PROBLEM, PART, ERASED) == 0
    assert stores.lti_sessions.get("session-erased") is None
    assert (after.enrolments, after.extensions, after.solutions_opened) == ([], [], [])
    assert stores.courses.solutions_opened(KEPT) != {}
    assert stores.courses.courses_enrolled(ERASED) == []
    [key] = after.keys  # kept as a row, revoked and nameless
    assert key.name is None and key.revoked_at is not None
    assert [k.revoked for k in stores.keys.list() if k.student == ERASED] == [True]
    assert stores.student_data.export(KEPT) == kept_before
    assert stores.student_data.erase(ERASED) == Erased(0, 0, 0, 0, 0, keys=1)  # again: the key row stays


def test_an_erased_student_starts_afresh(stores: Stores):
    _two_students(stores)
    stores.student_data.erase(ERASED)
    filed = submit(stores, 1, CORRECT, student=ERASED)
    assert filed.attempts_used == 1


@pytest.mark.parametrize("backend", ["sqlite", pytest.param("postgres", marks=pytest.mark.postgres)])
def test_submissions_stay_append_only_outside_an_erasure(stores: Stores, db: Database):
    _two_students(stores)
    for statement in (
        delete(Submission).where(Submission.student == KEPT),
        update(Submission).where(Submission.student == KEPT).values(answer="changed"),
    ):
        with pytest.raises(DatabaseError, match="append-only"), db.session() as session:
            session.execute(statement)
    stores.student_data.erase(ERASED)
    with pytest.raises(DatabaseError, match="append-only"), db.session() as session:
        session.execute(delete(Submission).where(Submission.student == KEPT))
    assert len(stores.submissions.page(student=KEPT).items) == 2
