"""From a graded submission to the score the LMS shows: the sum over the problem's parts of the best
score on each (so a later wrong attempt never lowers a grade), out of the number of parts, which is the
line item's `scoreMaximum` that deep linking sets."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from sqlalchemy import exists, func, select
from sqlalchemy.orm import Session

from app.db.models import ProblemVersion, Submission
from app.db.records import SubmissionRecord
from app.lti.models import LtiGradeTarget
from app.lti.outbox import enqueue_scores
from physics.verdict import Outcome


def problem_score(
    session: Session, problem_id: str, problem_version: int, student: str
) -> tuple[float, float]:
    """(score given, score maximum) for one student on one problem version's parts."""
    version = session.get(ProblemVersion, (problem_id, problem_version))
    rows = session.execute(
        select(Submission.part_id, func.max(Submission.score))
        .where(
            Submission.problem_id == problem_id,
            Submission.student == student,
            Submission.verdict != Outcome.INVALID.value,
        )
        .group_by(Submission.part_id)
    ).all()
    best: dict[str, float] = {part_id: float(score or 0.0) for part_id, score in rows}
    return score_of({} if version is None else version.document, best)


def score_of(document: Mapping[str, Any], best: Mapping[str, float]) -> tuple[float, float]:
    """(score given, score maximum) from the best score on each part: one point per part."""
    parts = document.get("parts")
    part_ids = [p.get("id") for p in parts if isinstance(p, dict)] if isinstance(parts, list) else []
    given = sum(best.get(str(part_id), 0.0) for part_id in part_ids)
    return given, float(max(len(part_ids), 1))


def queue_grade(session: Session, stored: SubmissionRecord) -> int:
    """The SQL submission store's filing hook: inside the submission's transaction, queue the
    student's new problem score for every LMS line item it was launched from. Returns how many."""
    if stored.verdict == Outcome.INVALID:
        return 0
    launched = session.scalar(
        select(
            exists().where(
                LtiGradeTarget.student == stored.student, LtiGradeTarget.problem_id == stored.problem_id
            )
        )
    )
    if not launched:
        return 0
    given, maximum = problem_score(session, stored.problem_id, stored.problem_version, stored.student)
    return enqueue_scores(session, stored.problem_id, stored.student, given, maximum, stored.created_at)
