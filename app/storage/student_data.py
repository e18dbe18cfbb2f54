"""One student's personal data, as a school's export or erasure request needs it: every submission,
the attempts counted, where their scores go in an LMS (grade targets) and the scores queued there,
the sessions LMS launches opened for them, their API keys, and their courses' records (enrolments with
the roster's name and email, personal sign-in links, sessions those opened, extensions, when they opened worked solutions). A protocol with its SQL and in-memory
implementations.

Erasure is the one exception to "submissions are append-only": the database lets a DELETE through only
for a student named in `student_erasures`, a row that exists only inside the erasing transaction.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from datetime import datetime
from typing import Protocol

from sqlalchemy import delete, func, select, update

from app.courses.models import CourseSessionRow, Enrolment, Extension, SignInToken, SolutionView
from app.db import keys as key_repository
from app.db.database import Database
from app.db.models import ApiKey, AttemptCounter, StudentErasure, Submission
from app.db.records import SubmissionRecord
from app.db.submissions import _record as submission_record
from app.db.types import utc_now
from app.lti.models import LtiGradeTarget, LtiPlatform, LtiScoreOutbox, LtiSession
from app.storage.memory import MemoryApiKeyStore, MemoryScoreOutbox, MemorySubmissionStore
from app.storage.memory_courses import MemoryCourseStore
from app.storage.memory_lti import MemoryLtiSessionStore, MemoryPlatformStore


@dataclass(frozen=True)
class AttemptsUsed:
    problem_id: str
    part_id: str
    used: int


@dataclass(frozen=True)
class GradeTarget:
    """Where an LMS takes this student's score on a problem, and the scores queued for it."""

    issuer: str
    problem_id: str
    lineitem_url: str
    sub: str  # the LMS's own id of the student
    scores: list[QueuedScoreData]


@dataclass(frozen=True)
class QueuedScoreData:
    score_given: float
    score_maximum: float
    timestamp: datetime
    status: str


@dataclass(frozen=True)
class LaunchSession:
    issuer: str
    sub: str
    role: str
    name: str
    expires_at: datetime


@dataclass(frozen=True)
class StudentKey:
    """A student API key (never its secret, which is stored only as a hash)."""

    id: int
    name: str | None
    created_at: datetime
    revoked_at: datetime | None


@dataclass(frozen=True)
class CourseEnrolment:
    course_id: int
    roster_id: str | None
    name: str
    email: str
    enrolled_at: datetime


@dataclass(frozen=True)
class StudentExtension:
    assignment_id: int
    due_at: datetime


@dataclass(frozen=True)
class SolutionOpened:
    problem_id: str
    opened_at: datetime


@dataclass(frozen=True)
class StudentData:
    student: str
    submissions: list[SubmissionRecord]
    attempts: list[AttemptsUsed]
    grade_targets: list[GradeTarget]
    lti_sessions: list[LaunchSession]
    keys: list[StudentKey]
    enrolments: list[CourseEnrolment] = field(default_factory=list)
    extensions: list[StudentExtension] = field(default_factory=list)
    solutions_opened: list[SolutionOpened] = field(default_factory=list)


@dataclass(frozen=True)
class Erased:
    """How many of each were deleted."""

    submissions: int
    attempt_counters: int
    grade_targets: int
    scores: int
    lti_sessions: int
    keys: int  # revoked and their names removed (kept as rows: key ids are never reused)
    enrolments: int = 0
    course_sessions: int = 0  # sessions opened by sign-in links, and the links themselves
    extensions: int = 0
    solution_views: int = 0


class StudentDataStore(Protocol):
    def export(self, student: str) -> StudentData:
        """Everything stored about `student` (empty lists for an unknown one)."""
        ...

    def erase(self, student: str) -> Erased:
        """Delete everything stored about `student`, at once (one transaction); revoke their API keys
        and remove the keys' names."""
        ...


class SqlStudentData:
    def __init__(self, database: Database) -> None:
        self._database = database

    def export(self, student: str) -> StudentData:
        with self._database.session(read_only=True) as session:
            submissions = [
                submission_record(row)
                for row in session.scalars(
                    select(Submission)
                    .where(Submission.student == student)
                    .order_by(Submission.created_at, Submission.id)
                )
            ]
            attempts = [
                AttemptsUsed(row.problem_id, row.part_id, row.used)
                for row in session.scalars(
                    select(AttemptCounter)
                    .where(AttemptCounter.student == student)
                    .order_by(AttemptCounter.problem_id, AttemptCounter.part_id)
                )
            ]
            targets = []
            for target, issuer in session.execute(
                select(LtiGradeTarget, LtiPlatform.issuer)
                .join(LtiPlatform, LtiPlatform.id == LtiGradeTarget.platform_id)
                .where(LtiGradeTarget.student == student)
                .order_by(LtiGradeTarget.id)
            ):
                scores = [
                    QueuedScoreData(row.score_given, row.score_maximum, row.timestamp, row.status)
                    for row in session.scalars(
                        select(LtiScoreOutbox)
                        .where(LtiScoreOutbox.target_id == target.id)
                        .order_by(LtiScoreOutbox.id)
                    )
                ]
                targets.append(
                    GradeTarget(issuer, target.problem_id, target.lineitem_url, target.sub, scores)
                )
            sessions = [
                LaunchSession(issuer, row.sub, row.role, row.name, row.expires_at)
                for row, issuer in session.execute(
                    select(LtiSession, LtiPlatform.issuer)
                    .join(LtiPlatform, LtiPlatform.id == LtiSession.platform_id)
                    .where(LtiSession.student == student)
                    .order_by(LtiSession.created_at)
                )
            ]
            keys = [
                StudentKey(row.id, row.name, row.created_at, row.revoked_at)
                for row in session.scalars(
                    select(ApiKey).where(ApiKey.student == student).order_by(ApiKey.id)
                )
            ]
            enrolments = [
                CourseEnrolment(row.course_id, row.roster_id, row.name, row.email, row.created_at)
                for row in session.scalars(
                    select(Enrolment).where(Enrolment.student == student).order_by(Enrolment.course_id)
                )
            ]
            extensions = [
                StudentExtension(row.assignment_id, row.due_at)
                for row in session.scalars(
                    select(Extension).where(Extension.student == student).order_by(Extension.assignment_id)
                )
            ]
            opened = [
                SolutionOpened(row.problem_id, row.opened_at)
                for row in session.scalars(
                    select(SolutionView)
                    .where(SolutionView.student == student)
                    .order_by(SolutionView.problem_id)
                )
            ]
        return StudentData(
            student, submissions, attempts, targets, sessions, keys, enrolments, extensions, opened
        )

    def erase(self, student: str) -> Erased:
        with self._database.session() as session:
            session.add(StudentErasure(student=student))
            session.flush()
            targets = select(LtiGradeTarget.id).where(LtiGradeTarget.student == student)
            counts = Erased(
                submissions=_deleted(
                    session.execute(delete(Submission).where(Submission.student == student))
                ),
                attempt_counters=_deleted(
                    session.execute(delete(AttemptCounter).where(AttemptCounter.student == student))
                ),
                scores=_deleted(
                    session.execute(delete(LtiScoreOutbox).where(LtiScoreOutbox.target_id.in_(targets)))
                ),
                grade_targets=_deleted(
                    session.execute(delete(LtiGradeTarget).where(LtiGradeTarget.student == student))
                ),
                lti_sessions=_deleted(
                    session.execute(delete(LtiSession).where(LtiSession.student == student))
                ),
                keys=_deleted(
                    session.execute(
                        update(ApiKey)
                        .where(ApiKey.student == student)
                        .values(name=None, revoked_at=func.coalesce(ApiKey.revoked_at, utc_now()))
                    )
                ),
                extensions=_deleted(session.execute(delete(Extension).where(Extension.student == student))),
                solution_views=_deleted(
                    session.execute(delete(SolutionView).where(SolutionView.student == student))
                ),
                course_sessions=_deleted(
                    session.execute(delete(CourseSessionRow).where(CourseSessionRow.student == student))
                )
                + _deleted(session.execute(delete(SignInToken).where(SignInToken.student == student))),
                enrolments=_deleted(session.execute(delete(Enrolment).where(Enrolment.student == student))),
            )
            session.execute(delete(StudentErasure).where(StudentErasure.student == student))
        key_repository.revocations += 1  # caches of authenticated keys drop at once
        return counts


def _deleted(result: object) -> int:
    return int(getattr(result, "rowcount", 0) or 0)


class MemoryStudentData:
    """The same over the in-memory fakes (their internals, under their locks, as one transaction)."""

    def __init__(
        self,
        submissions: MemorySubmissionStore,
        outbox: MemoryScoreOutbox,
        sessions: MemoryLtiSessionStore,
        platforms: MemoryPlatformStore,
        keys: MemoryApiKeyStore,
        courses: MemoryCourseStore,
    ) -> None:
        self._submissions, self._outbox, self._sessions = submissions, outbox, sessions
        self._platforms, self._keys, self._courses = platforms, keys, courses

    def export(self, student: str) -> StudentData:
        with self._submissions._lock, self._outbox._lock, self._sessions._lock:
            submissions = sorted(
                (row for row in self._submissions._rows if row.student == student),
                key=lambda r: (r.created_at, r.id),
            )
            attempts = [
                AttemptsUsed(problem, part, used)
                for (problem, part, who), used in sorted(self._submissions._used.items())
                if who == student
            ]
            targets = [
                GradeTarget(
                    t.platform.issuer,
                    t.problem_id,
                    t.lineitem_url,
                    t.sub,
                    [
                        QueuedScoreData(s.score_given, s.score_maximum, s.timestamp, s.status)
                        for s in self._outbox._rows
                        if s.target is t
                    ],
                )
                for t in self._outbox._targets
                if t.student == student
            ]
            sessions = [
                LaunchSession(
                    self._platforms.get(r.platform_id).issuer, r.sub, r.role.value, r.name, r.expires_at
                )
                for r in self._sessions._sessions.values()
                if r.student == student
            ]
        keys = [
            StudentKey(r.id, r.name, r.created_at, r.revoked_at)
            for r in self._keys.list()
            if r.student == student
        ]
        courses = self._courses
        with courses._lock:
            enrolments = [
                CourseEnrolment(e.course_id, e.roster_id, e.name, e.email, e.created_at)
                for (_, who), e in sorted(courses._enrolments.items())
                if who == student
            ]
            extensions = [
                StudentExtension(assignment, extension.due_at)
                for (assignment, who), extension in sorted(courses._extensions.items())
                if who == student
            ]
            opened = [
                SolutionOpened(problem, at)
                for (who, problem), at in sorted(courses._solution_views.items())
                if who == student
            ]
        return StudentData(
            student, list(submissions), attempts, targets, sessions, keys, enrolments, extensions, opened
        )

    def erase(self, student: str) -> Erased:
        with self._submissions._lock, self._outbox._lock, self._sessions._lock:
            subs = self._submissions
            kept_rows = [row for row in subs._rows if row.student != student]
            used = {key: n for key, n in subs._used.items() if key[2] != student}
            targets = [t for t in self._outbox._targets if t.student != student]
            scores = [s for s in self._outbox._rows if s.target.student != student]
            sessions = {k: r for k, r in self._sessions._sessions.items() if r.student != student}
            erased = Erased(
                submissions=len(subs._rows) - len(kept_rows),
                attempt_counters=len(subs._used) - len(used),
                grade_targets=len(self._outbox._targets) - len(targets),
                scores=len(self._outbox._rows) - len(scores),
                lti_sessions=len(self._sessions._sessions) - len(sessions),
                keys=self._forget_keys(student),
            )
            subs._rows, subs._used = kept_rows, used
            self._outbox._targets, self._outbox._rows = targets, scores
            self._sessions._sessions = sessions
        return replace(erased, **self._forget_courses(student))

    def _forget_courses(self, student: str) -> dict[str, int]:
        courses = self._courses
        with courses._lock:
            enrolments = {k: e for k, e in courses._enrolments.items() if k[1] != student}
            extensions = {k: d for k, d in courses._extensions.items() if k[1] != student}
            tokens = {k: t for k, t in courses._tokens.items() if t[1] != student}
            sessions = {k: c for k, c in courses._sessions.items() if c.student != student}
            views = {k: at for k, at in courses._solution_views.items() if k[0] != student}
            counts = {
                "solution_views": len(courses._solution_views) - len(views),
                "enrolments": len(courses._enrolments) - len(enrolments),
                "extensions": len(courses._extensions) - len(extensions),
                "course_sessions": len(courses._sessions)
                - len(sessions)
                + len(courses._tokens)
                - len(tokens),
            }
            courses._enrolments, courses._extensions = enrolments, extensions
            courses._tokens, courses._sessions = tokens, sessions
            courses._solution_views = views
        return counts

    def _forget_keys(self, student: str) -> int:
        """Revoke the student's keys and remove their names; how many."""
        with self._keys._lock:
            rows = self._keys._rows
            mine = [key_id for key_id, (_, record) in rows.items() if record.student == student]
            for key_id in mine:
                stored_hash, record = rows[key_id]
                rows[key_id] = (
                    stored_hash,
                    replace(record, name=None, revoked_at=record.revoked_at or utc_now()),
                )
        key_repository.revocations += 1
        return len(mine)
