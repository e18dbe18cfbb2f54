"""The on_graded hook: a graded submission of a launched student queues the best-per-part score."""

from __future__ import annotations

import pytest

from app.db.database import Database
from app.db.submissions import record_submission
from app.lti.grades import queue_grade
from app.lti.models import LtiGradeTarget, LtiScoreOutbox
from physics.verdict import Outcome, Reason, Verdict

STUDENT = "lti:1:student-1"
CORRECT = Verdict(Outcome.CORRECT, 1.0, Reason.EQUIVALENT, "")
WRONG = Verdict(Outcome.INCORRECT, 0.0, Reason.WRONG_VALUE, "")
INVALID = Verdict(Outcome.INVALID, 0.0, Reason.PARSE_ERROR, "")


def submit(database: Database, part: str, verdict: Verdict, student: str = STUDENT) -> int:
    with database.session() as session:
        stored = record_submission(
            session, problem_id="moving-wedge", problem_version=1, part_id=part, student=student,
            answer="x", verdict=verdict, max_attempts=None,
        )  # fmt: skip
        return queue_grade(session, stored)


def queued(database: Database) -> list[tuple[float, float]]:
    with database.session() as session:
        rows = session.query(LtiScoreOutbox).order_by(LtiScoreOutbox.id)
        return [(row.score_given, row.score_maximum) for row in rows]


@pytest.fixture
def launched(database: Database) -> Database:
    with database.session() as session:
        session.add(
            LtiGradeTarget(
                platform_id=1, student=STUDENT, problem_id="moving-wedge",
                lineitem_url="https://lms.test/lineitems/1", sub="student-1",
            )
        )  # fmt: skip
    return database


def test_best_score_per_part_out_of_number_of_parts(launched: Database):
    submit(launched, "a", CORRECT)
    submit(launched, "a", WRONG)  # a later wrong attempt does not lower the grade
    submit(launched, "b", CORRECT)
    assert queued(launched) == [(1.0, 2.0), (1.0, 2.0), (2.0, 2.0)]


def test_invalid_answer_queues_nothing(launched: Database):
    assert submit(launched, "a", INVALID) == 0
    assert queued(launched) == []


def test_student_never_launched_from_lms_queues_nothing(launched: Database):
    assert submit(launched, "a", CORRECT, student="api-student") == 0
    assert queued(launched) == []
