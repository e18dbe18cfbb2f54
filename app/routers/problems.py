"""Problems: the list, one student's variant, previews and submissions of answers to a part."""

from __future__ import annotations

from datetime import datetime
from typing import Annotated

from fastapi import APIRouter, Body, Path, Query, Request
from starlette.concurrency import run_in_threadpool

from app.auth import Principal
from app.courses import access
from app.db.errors import ProblemNotFound
from app.db.records import ProblemRecord
from app.deps import CurrentPrincipal, PreviewPrincipal, ServicesDep
from app.errors import AppError, Conflict, Forbidden, NotFound
from app.grading.submit import stored_problem_fault, submit_answer
from app.openapi import AUTHENTICATED, errors
from app.schemas import examples
from app.schemas.problems import (
    PartSummary,
    PreviewIn,
    PreviewPublic,
    ProblemPublic,
    ProblemSummary,
    StudentId,
    SubmissionIn,
    SubmissionResult,
)
from app.services import Services
from app.web.rendering import tex_to_mathml
from physics.errors import SpecError

router = APIRouter(tags=["problems"], responses=AUTHENTICATED)
# The course the answer is made in, for a student in more than one whose assignments have the problem
# (a course's page sends it; without it, the first open assignment by due date takes the answer).
CourseQuery = Annotated[
    int | None,
    Query(ge=1, description="the course the answer is made in (a student in several courses)"),
]
# Examples for /docs "Try it out": a problem and part of the built-in bank.
ProblemIdPath = Annotated[str, Path(openapi_examples=examples.PROBLEM_ID)]
PartIdPath = Annotated[str, Path(openapi_examples=examples.PART_ID)]


class StudentNotAllowed(AppError):
    status, code = 422, "malformed_request"


def student_of(principal: Principal, named: str | None) -> str:
    """Whose work this is: the caller's own, or the student an instructor's API key names."""
    if named is None or named == principal.own_identity:
        return principal.own_identity
    if principal.student is not None:
        raise StudentNotAllowed(
            "A student key cannot name a student.", [{"path": "student", "message": "not allowed"}]
        )
    if not principal.acts_for_students:
        raise Forbidden("A session opened from an LMS acts only for itself; use an instructor API key.")
    return named


@router.get("/v1/problems", response_model=list[ProblemSummary])
async def list_problems(
    request: Request, services: ServicesDep, principal: CurrentPrincipal
) -> list[ProblemSummary]:
    """Instructors: the bank, their courses' uploads and those shared to the bank. Students: the
    problems of their courses' open assignments (a student in no course: every problem)."""
    records = await run_in_threadpool(visible_problems, services, principal, now_of(request))
    summaries = []
    for record in records:
        doc = services.catalog.document(record)
        summaries.append(
            ProblemSummary(
                id=doc.id,
                title=doc.title,
                topics=list(doc.topics),
                parts=[PartSummary(id=p.id, kind=p.kind, prompt=p.prompt) for p in doc.parts],
                version=record.version,
                builtin=record.builtin,
            )
        )
    return summaries


@router.get("/v1/problems/{problem_id}", response_model=ProblemPublic, responses=errors(403, 404, 422))
async def get_problem(
    problem_id: str,
    request: Request,
    services: ServicesDep,
    principal: CurrentPrincipal,
    student: Annotated[StudentId | None, Query()] = None,
    course: CourseQuery = None,
) -> ProblemPublic:
    who = student_of(principal, student)
    opened = await run_in_threadpool(
        require_open, services, principal, problem_id, who, now_of(request), course
    )
    try:
        view = await run_in_threadpool(services.catalog.student_view, problem_id, who)
    except LookupError:
        raise NotFound(f"There is no problem {problem_id!r}.") from None
    return ProblemPublic.model_validate(opened.attempts_in(view))


@router.post(
    "/v1/problems/{problem_id}/parts/{part_id}/submissions",
    status_code=201,
    response_model=SubmissionResult,
    responses=errors(403, 404, 409, 413, 422),
)
async def submit(
    problem_id: ProblemIdPath,
    part_id: PartIdPath,
    body: Annotated[SubmissionIn, Body(openapi_examples=examples.SUBMISSION)],
    request: Request,
    services: ServicesDep,
    principal: CurrentPrincipal,
    course: CourseQuery = None,
) -> SubmissionResult:
    """Graded and filed; for a student of a course, only within an assignment that accepts answers
    now (409 after a closed assignment's due date), with the assignment's attempts per part; with
    `course`, an assignment of that course."""
    who = student_of(principal, body.student)
    opened = await run_in_threadpool(
        require_open, services, principal, problem_id, who, now_of(request), course
    )
    if not opened.accepting:
        raise Conflict(opened.why)
    record = await run_in_threadpool(services.catalog.get, problem_id)
    _require_part(services, record, part_id)
    limit = None if opened.assignment is None else opened.assignment.spec.max_attempts
    return await submit_answer(
        services, record, part_id, who, body.answer, principal.grading_share, max_attempts=limit
    )


@router.post(
    "/v1/problems/{problem_id}/parts/{part_id}/preview",
    response_model=PreviewPublic,
    responses=errors(404, 413, 422),
)
async def preview(
    problem_id: ProblemIdPath,
    part_id: PartIdPath,
    body: Annotated[PreviewIn, Body(openapi_examples=examples.PREVIEW)],
    services: ServicesDep,
    request: Request,
    principal: PreviewPrincipal,
    course: CourseQuery = None,
) -> PreviewPublic:
    """How the answer would be read (for a live preview while typing); nothing is graded or stored."""
    who = student_of(principal, None)
    await run_in_threadpool(require_open, services, principal, problem_id, who, now_of(request), course)
    record = await run_in_threadpool(services.catalog.get, problem_id)
    _require_part(services, record, part_id)
    job = await run_in_threadpool(services.catalog.job, record, part_id, who, body.answer)
    try:
        result = await services.pool.preview(job, principal.grading_share)
    except SpecError as error:
        raise stored_problem_fault(error, {"problem": record.id, "part": part_id, "student": who}) from error
    mathml = str(tex_to_mathml(result.read_as.latex, display=True)) if result.read_as else None
    return PreviewPublic(read_as=result.read_as, error=result.error, mathml=mathml)


def visible_problems(services: Services, principal: Principal, now: datetime) -> list[ProblemRecord]:
    records = services.catalog.list()
    if principal.student is not None:
        allowed = access.assigned_problems(services.stores, principal.student, now)
        return records if allowed is None else [r for r in records if r.id in allowed]
    colleagues = access.colleagues(services.stores, principal)
    shared = services.stores.courses.shared_problems()
    return [r for r in records if access.may_use_problem(r, principal, colleagues, shared)]


def require_open(
    services: Services,
    principal: Principal,
    problem_id: str,
    who: str,
    now: datetime,
    course: int | None = None,
) -> access.Opening:
    """The problem as `who` may reach it: NotFound when it is outside their assignments, when an
    instructor names a student of a course they do not teach, or an upload not theirs to use."""
    missing = NotFound(f"There is no problem {problem_id!r}.")
    if principal.student is None:
        if who != principal.own_identity and not access.may_reach_student(services.stores, principal, who):
            raise NotFound(f"There is no student {who!r} in your courses.")
        if who == principal.own_identity:
            try:
                record = services.catalog.get(problem_id)
            except ProblemNotFound:
                raise missing from None
            colleagues = access.colleagues(services.stores, principal)
            if not access.may_use_problem(
                record, principal, colleagues, services.stores.courses.shared_problems()
            ):
                raise missing
            return access.Opening(None, None, True, None)
    found = access.opening(services.stores, who, problem_id, now, course)
    if found is None:
        raise missing
    return found


def now_of(request: Request) -> datetime:
    clock: datetime = request.app.state.lti.clock()
    return clock


def _require_part(services: Services, record: ProblemRecord, part_id: str) -> None:
    if part_id not in {p.id for p in services.catalog.document(record).parts}:
        raise NotFound(f"Problem {record.id!r} has no part {part_id!r}.")
