"""Grading a submission to a stored problem and filing it: acknowledged only once it is committed."""

from __future__ import annotations

import logging

from starlette.concurrency import run_in_threadpool

from app.db.records import ProblemRecord
from app.errors import GraderFault, Unavailable
from app.schemas.check import VerdictPublic
from app.schemas.problems import SubmissionResult
from app.services import Services
from physics.errors import SpecError

log = logging.getLogger("physcheck.submissions")
LOGGED_ANSWER_CHARS = 120


async def submit_answer(
    services: Services,
    record: ProblemRecord,
    part_id: str,
    student: str,
    answer: str,
    share: str | None = None,
    *,
    max_attempts: int | None = None,
) -> SubmissionResult:
    """`max_attempts`: an assignment's attempts per part, over the problem's own (None: the problem's)."""
    catalog = services.catalog
    # No early refusal when attempts are used up: an unreadable answer uses none and is still filed,
    # and only grading tells which it is. The insert refuses a graded one over the limit.
    if max_attempts is None:
        max_attempts = catalog.max_attempts(record, part_id)
    job = await run_in_threadpool(catalog.job, record, part_id, student, answer)
    context: dict[str, object] = {
        "problem": record.id,
        "version": record.version,
        "part": part_id,
        "student": student,
    }
    if services.settings.log_answers:
        # Bounded and escaped by the JSON formatter: an answer cannot forge or flood log lines.
        context["answer"] = (
            answer if len(answer) <= LOGGED_ANSWER_CHARS else answer[:LOGGED_ANSWER_CHARS] + "…"
        )
    # A fault of the grader is never filed as the student's verdict and uses no attempt.
    try:
        verdict = await services.pool.check(job, share)
    except SpecError as error:
        raise stored_problem_fault(error, context) from error
    except (Unavailable, GraderFault) as error:
        log.error("not graded (%s): %s; not filed", error.code, error.message, extra=context)
        raise
    log.info(
        "graded",
        extra={**context, "verdict": verdict.outcome.value, "reason": verdict.reason.value},
    )
    filed = await run_in_threadpool(
        services.stores.submissions.file,
        problem_id=record.id,
        problem_version=record.version,
        part_id=part_id,
        student=student,
        answer=answer,
        verdict=verdict,
        max_attempts=max_attempts,
    )
    return SubmissionResult(
        **VerdictPublic.of(verdict).model_dump(),
        submission_id=filed.record.id,
        attempts_used=filed.attempts_used,
        max_attempts=max_attempts,
    )


def stored_problem_fault(error: SpecError, context: dict[str, object]) -> GraderFault:
    """A stored problem was vetted at upload: its reference failing now is our fault, not the answer's."""
    log.error("stored problem failed to grade: %s at %s", error.message, error.path, extra=context)
    return GraderFault(
        "This problem could not be graded on our side; it has been logged. Nothing was recorded."
    )
