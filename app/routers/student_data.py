"""A student's personal data, for the requests schools receive: export it all, or erase it all.

    GET    /v1/student-data?student=S   every submission, attempt count, LMS grade target (with the
                                        scores queued for it), LMS session and API key of S, as JSON
    DELETE /v1/student-data?student=S   erase all of it at once (keys are revoked and their names
                                        removed); the counts of what was deleted

Instructor API keys only (they act for students); an LMS session acts only for itself, so it may not.
"""

from __future__ import annotations

from datetime import datetime
from typing import Annotated

from fastapi import APIRouter, Query
from pydantic import BaseModel
from starlette.concurrency import run_in_threadpool

from app.auth import Principal
from app.deps import Instructor, ServicesDep
from app.errors import Forbidden
from app.openapi import AUTHENTICATED, errors
from app.routers.submissions import public
from app.schemas.problems import StudentId, SubmissionPublic
from app.storage.student_data import StudentData

router = APIRouter(tags=["students"], responses=AUTHENTICATED | errors(403, 422))

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


class StudentDataPublic(BaseModel):
    student: str
    submissions: list[SubmissionPublic]
    attempts: list[AttemptsPublic]
    grade_targets: list[GradeTargetPublic]
    lti_sessions: list[LtiSessionPublic]
    keys: list[StudentKeyPublic]


class ErasedCounts(BaseModel):
    submissions: int
    attempt_counters: int
    grade_targets: int
    scores: int
    lti_sessions: int
    keys: int


class StudentErased(BaseModel):
    student: str
    erased: ErasedCounts


def _for_students(principal: Principal) -> None:
    if not principal.acts_for_students:
        raise Forbidden("A session opened from an LMS acts only for itself; use an instructor API key.")


@router.get("/v1/student-data", response_model=StudentDataPublic)
async def export_student(
    student: StudentQuery, services: ServicesDep, principal: Instructor
) -> StudentDataPublic:
    """Everything stored about one student (empty lists for a student with nothing stored)."""
    _for_students(principal)
    data = await run_in_threadpool(services.stores.student_data.export, student)
    return _public(data)


@router.delete("/v1/student-data", response_model=StudentErased)
async def erase_student(student: StudentQuery, services: ServicesDep, principal: Instructor) -> StudentErased:
    """Erase everything stored about one student, at once; the counts of what was deleted. Scores not
    yet sent to an LMS are not sent. The student may start afresh (no attempts used)."""
    _for_students(principal)
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
    )
