"""The SQL submission store's second filing hook: a graded submission to a problem of an assignment
launched from an LMS queues the student's new assignment total, in the submission's transaction."""

from __future__ import annotations

from typing import Any

from sqlalchemy import select
from sqlalchemy.orm import Session

from app.courses import passback
from app.courses.models import Assignment, Extension, SolutionView
from app.db.models import Problem, ProblemVersion, Submission
from app.db.records import SubmissionRecord
from app.db.submissions import _record as submission_record
from app.lti.models import LtiGradeTarget
from app.storage.sql_courses import assignment_record, extension_record
from app.storage.sql_outbox import enqueue_scores
from physics.verdict import Outcome as Verdicts


def queue_assignment_grades(session: Session, stored: SubmissionRecord) -> int:
    """Queue the total of every launched assignment holding this submission's problem; how many."""
    if stored.verdict == Verdicts.INVALID:
        return 0
    keys = session.scalars(
        select(LtiGradeTarget.problem_id)
        .where(
            LtiGradeTarget.student == stored.student, LtiGradeTarget.problem_id.like(f"{passback.PREFIX}%")
        )
        .distinct()
    ).all()
    queued = 0
    for key in keys:
        assignment_id = passback.assignment_of(key)
        row = None if assignment_id is None else session.get(Assignment, assignment_id)
        if row is None or stored.problem_id not in row.problems:
            continue
        assignment = assignment_record(row)
        extension = session.get(Extension, (row.id, stored.student))
        submissions = [
            submission_record(item)
            for item in session.scalars(
                select(Submission).where(
                    Submission.student == stored.student, Submission.problem_id.in_(assignment.problems)
                )
            )
        ]
        given, maximum = passback.assignment_score(
            assignment,
            _documents(session, assignment.problems),
            submissions,
            stored.student,
            None if extension is None else extension_record(extension),
            stored.created_at,
            {
                row.problem_id: row.opened_at
                for row in session.scalars(select(SolutionView).where(SolutionView.student == stored.student))
            },
        )
        queued += enqueue_scores(session, key, stored.student, given, maximum, stored.created_at)
    return queued


def _documents(session: Session, problem_ids: tuple[str, ...]) -> dict[str, dict[str, Any]]:
    found = {}
    for problem_id in problem_ids:
        problem = session.get(Problem, problem_id)
        if problem is not None:
            version = session.get(ProblemVersion, (problem_id, problem.latest_version))
            if version is not None:
                found[problem_id] = version.document
    return found
