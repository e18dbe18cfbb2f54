"""`GET /v1/submissions`: an instructor key sees its courses' students (and students in no course), a
student only its own."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Query
from starlette.concurrency import run_in_threadpool

from app.auth import Principal
from app.courses import access
from app.db.records import SubmissionRecord
from app.deps import CurrentPrincipal, ServicesDep, Submissions
from app.errors import Forbidden, NotFound
from app.openapi import AUTHENTICATED, errors
from app.schemas.problems import StudentId, SubmissionPage, SubmissionPublic
from app.services import Services

router = APIRouter(tags=["submissions"], responses=AUTHENTICATED)

MAX_PAGE = 1000


@router.get("/v1/submissions", response_model=SubmissionPage, responses=errors(403, 404, 422))
async def list_submissions(
    submissions: Submissions,
    services: ServicesDep,
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
    elif student is not None and not await run_in_threadpool(
        access.may_reach_student, services.stores, principal, student
    ):
        raise NotFound(f"There is no student {student!r} in your courses.")

    page = await run_in_threadpool(
        submissions.page, problem_id=problem, student=student, limit=limit, cursor=cursor
    )
    items = list(page.items)
    if principal.acts_for_students and student is None:
        # Students of courses the caller does not teach are left out (a page may come back shorter).
        reachable = await run_in_threadpool(_reachable, services, principal, {i.student for i in items})
        items = [item for item in items if item.student in reachable]
    return SubmissionPage(items=[public(item) for item in items], next=page.next)


def _reachable(services: Services, principal: Principal, students: set[str]) -> set[str]:
    return {s for s in students if access.may_reach_student(services.stores, principal, s)}


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
