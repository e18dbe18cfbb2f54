"""`GET /v1/submissions`: instructors see every submission, a student only its own."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Query
from starlette.concurrency import run_in_threadpool

from app.db.records import SubmissionRecord
from app.deps import CurrentPrincipal, Submissions
from app.errors import Forbidden
from app.openapi import AUTHENTICATED, errors
from app.schemas.problems import StudentId, SubmissionPage, SubmissionPublic

router = APIRouter(tags=["submissions"], responses=AUTHENTICATED)

MAX_PAGE = 1000


@router.get("/v1/submissions", response_model=SubmissionPage, responses=errors(403, 422))
async def list_submissions(
    submissions: Submissions,
    principal: CurrentPrincipal,
    problem: Annotated[str | None, Query(max_length=100)] = None,
    student: Annotated[StudentId | None, Query()] = None,
    limit: Annotated[int, Query(ge=1, le=MAX_PAGE)] = 100,
    cursor: Annotated[str | None, Query(max_length=200)] = None,
) -> SubmissionPage:
    if not principal.acts_for_students:
        if student is not None and student != principal.own_identity:
            raise Forbidden("This key or session sees only its own submissions.")
        student = principal.own_identity

    page = await run_in_threadpool(
        submissions.page, problem_id=problem, student=student, limit=limit, cursor=cursor
    )
    return SubmissionPage(items=[public(item) for item in page.items], next=page.next)


def public(item: SubmissionRecord) -> SubmissionPublic:
    return SubmissionPublic(
        submission_id=item.id,
        problem=item.problem_id,
        part=item.part_id,
        student=item.student,
        answer=item.answer,
        verdict=item.verdict.value,
        score=item.score,
        reason=item.reason.value,
        feedback=item.feedback,
        created_at=item.created_at,
        problem_version=item.problem_version,
    )
