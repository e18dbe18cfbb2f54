"""A student's personal data, for the requests schools receive: export it all, or erase it all.

    GET    /v1/student-data?student=S   every submission, attempt count, LMS grade target (with the
                                        scores queued for it), LMS session, API key, enrolment and
                                        extension of S, as JSON
    DELETE /v1/student-data?student=S   erase all of it at once (keys are revoked and their names
                                        removed); the counts of what was deleted

Instructor API keys only (they act for students); an LMS session acts only for itself, so it may not.
A student enrolled in courses is reached only by an instructor of one of them (404 for the others).
"""

from __future__ import annotations

from datetime import datetime
from typing import Annotated

from fastapi import APIRouter, Query
from pydantic import BaseModel
from starlette.concurrency import run_in_threadpool

from app.auth import Principal
from app.courses import access
from app.deps import Instructor, ServicesDep
from app.errors import Forbidden, NotFound
from app.openapi import AUTHENTICATED, errors
from app.routers.submissions import public
from app.schemas.problems import StudentId, SubmissionPublic
from app.services import Services
from app.storage.student_data import StudentData

router = APIRouter(tags=["students"], responses=AUTHENTICATED | errors(403, 404, 422))

StudentQuery = Annotated[
    StudentId,
    Query(
        description="The id the student's work is filed under (as in `GET /v1/submissions`).",
        examples=["s-1024"],
    ),
]


class AttemptsPublic(BaseModel):
    problem: str
    part: str
    used: int


class QueuedScorePublic(BaseModel):
    score_given: float
    score_maximum: float
    timestamp: datetime
    status: str


class GradeTargetPublic(BaseModel):
    issuer: str
    problem: str
    lineitem_url: str
    sub: str
    scores: list[QueuedScorePublic]


class LtiSessionPublic(BaseModel):
    issuer: str
    sub: str
    role: str
    name: str
    expires_at: datetime


class StudentKeyPublic(BaseModel):
    id: int
    name: str | None
    created_at: datetime
    revoked_at: datetime | None


class EnrolmentPublic(BaseModel):
    course_id: int
    roster_id: str | None
    name: str
    email: str
    enrolled_at: datetime


class ExtensionPublic(BaseModel):
    assignment_id: int
    due_at: datetime


class SolutionOpenedPublic(BaseModel):
    problem_id: str
    opened_at: datetime


class StudentDataPublic(BaseModel):
    student: str
    submissions: list[SubmissionPublic]
    attempts: list[AttemptsPublic]
    grade_targets: list[GradeTargetPublic]
    lti_sessions: list[LtiSessionPublic]
    keys: list[StudentKeyPublic]
    enrolments: list[EnrolmentPublic] = []
    extensions: list[ExtensionPublic] = []
    solutions_opened: list[SolutionOpenedPublic] = []


class ErasedCounts(BaseModel):
    submissions: int
    attempt_counters: int
    grade_targets: int
    scores: int
    lti_sessions: int
    keys: int
    enrolments: int = 0
    course_sessions: int = 0
    extensions: int = 0
    solution_views: int = 0


class StudentErased(BaseModel):
    student: str
    erased: ErasedCounts


def _for_students(services: Services, principal: Principal, student: str) -> None:
    if not principal.acts_for_students:
        raise Forbidden("A session opened from an LMS acts only for itself; use an instructor API key.")
    if not access.may_reach_student(services.stores, principal, student):
        raise NotFound(f"There is no student {student!r} in your courses.")


@router.get("/v1/student-data", response_model=StudentDataPublic)
async def export_student(
    student: StudentQuery, services: ServicesDep, principal: Instructor
) -> StudentDataPublic:
    """Everything stored about one student (empty lists for a student with nothing stored)."""
    await run_in_threadpool(_for_students, services, principal, student)
    data = await run_in_threadpool(services.stores.student_data.export, student)
    return _public(data)


@router.delete("/v1/student-data", response_model=StudentErased)
async def erase_student(student: StudentQuery, services: ServicesDep, principal: Instructor) -> StudentErased:
    """Erase everything stored about one student, at once; the counts of what was deleted. Scores not
    yet sent to an LMS are not sent. The student may start afresh (no attempts used)."""
    await run_in_threadpool(_for_students, services, principal, student)
    erased = await run_in_threadpool(services.stores.student_data.erase, student)
    return StudentErased(
        student=student,
        erased=ErasedCounts(
            submissions=erased.submissions,
            attempt_counters=erased.attempt_counters,
            grade_targets=erased.grade_targets,
            scores=erased.scores,
            lti_sessions=erased.lti_sessions,
            keys=erased.keys,
            enrolments=erased.enrolments,
            course_sessions=erased.course_sessions,
            extensions=erased.extensions,
            solution_views=erased.solution_views,
        ),
    )


def _public(data: StudentData) -> StudentDataPublic:
    return StudentDataPublic(
        student=data.student,
        submissions=[public(item) for item in data.submissions],
        attempts=[AttemptsPublic(problem=a.problem_id, part=a.part_id, used=a.used) for a in data.attempts],
        grade_targets=[
            GradeTargetPublic(
                issuer=t.issuer,
                problem=t.problem_id,
                lineitem_url=t.lineitem_url,
                sub=t.sub,
                scores=[
                    QueuedScorePublic(
                        score_given=s.score_given,
                        score_maximum=s.score_maximum,
                        timestamp=s.timestamp,
                        status=s.status,
                    )
                    for s in t.scores
                ],
            )
            for t in data.grade_targets
        ],
        lti_sessions=[
            LtiSessionPublic(issuer=s.issuer, sub=s.sub, role=s.role, name=s.name, expires_at=s.expires_at)
            for s in data.lti_sessions
        ],
        keys=[
            StudentKeyPublic(id=k.id, name=k.name, created_at=k.created_at, revoked_at=k.revoked_at)
            for k in data.keys
        ],
        enrolments=[
            EnrolmentPublic(
                course_id=e.course_id,
                roster_id=e.roster_id,
                name=e.name,
                email=e.email,
                enrolled_at=e.enrolled_at,
            )
            for e in data.enrolments
        ],
        extensions=[ExtensionPublic(assignment_id=x.assignment_id, due_at=x.due_at) for x in data.extensions],
        solutions_opened=[
            SolutionOpenedPublic(problem_id=x.problem_id, opened_at=x.opened_at)
            for x in data.solutions_opened
        ],
    )
