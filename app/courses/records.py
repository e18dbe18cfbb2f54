"""What the course store returns: plain frozen dataclasses, and the errors it raises."""

from __future__ import annotations

from dataclasses import dataclass
from datetime import datetime
from enum import StrEnum

from app.db.errors import NotFound, StorageError


class StaffRole(StrEnum):
    INSTRUCTOR = "instructor"
    TA = "ta"


class LateKind(StrEnum):
    CLOSED = "closed"  # nothing accepted after the due date (or the student's extension)
    PENALTY = "penalty"  # accepted, each late day costing `per_day` of the score, up to `limit`


class SolutionRelease(StrEnum):
    NEVER = "never"
    AFTER_DUE = "after_due"
    AFTER_LAST_ATTEMPT = "after_last_attempt"
    RELEASED = "released"  # by the instructor, now ("release solutions now")


@dataclass(frozen=True)
class LatePolicy:
    kind: LateKind = LateKind.CLOSED
    per_day: float = 0.0  # a fraction of the score, 0.1 = 10 % a day
    limit: float = 1.0  # the most taken off, as a fraction

    def __post_init__(self) -> None:
        if not (0.0 <= self.per_day <= 1.0 and 0.0 <= self.limit <= 1.0):
            raise ValueError("a late penalty is a fraction between 0 and 1")


@dataclass(frozen=True)
class CourseRecord:
    id: int
    title: str
    timezone: str  # IANA name: how dates are shown to the course; stored in UTC
    join_code: str | None
    lti_platform_id: int | None
    lti_context_id: str | None
    created_at: datetime


@dataclass(frozen=True)
class StaffRecord:
    course_id: int
    member: str  # "key:<api key id>" or an LMS identity "lti:<platform>:<sub>"
    role: StaffRole
    name: str


@dataclass(frozen=True)
class RosterRow:
    """One line of a roster CSV: the institution's id, the name and the email."""

    roster_id: str
    name: str
    email: str


@dataclass(frozen=True)
class EnrolmentRecord:
    course_id: int
    student: str  # the identity the student's submissions are filed under
    roster_id: str | None
    name: str
    email: str
    created_at: datetime

    @property
    def shown_id(self) -> str:
        """The id instructors and LMS gradebook imports read: the institution's, else the course's own
        (`join-3f2a…` for a student who joined by code: stable, unlike a name), else the LMS identity."""
        return self.roster_id or self.student.removeprefix(roster_identity(self.course_id, ""))

    @property
    def detail(self) -> str:
        """What tells two students of the same name apart: the email, else the id."""
        return self.email or self.shown_id


@dataclass(frozen=True)
class RosterImport:
    added: int
    updated: int
    unchanged: int


@dataclass(frozen=True)
class CourseSession:
    """A student's session, opened by their personal sign-in link (or an instructor's "view as a
    student", in no course); the cookie holds its id."""

    course_id: int | None
    student: str
    name: str
    csrf_token: str
    expires_at: datetime
    problem_id: str | None = None  # a preview's: the problem it was opened for (see sessions.choose)


@dataclass(frozen=True)
class AssignmentSpec:
    """What an instructor sets; the store adds the id and course."""

    title: str
    problems: tuple[str, ...]  # in the order students see them
    opens_at: datetime
    due_at: datetime
    late: LatePolicy = LatePolicy()
    max_attempts: int | None = None  # per part; None keeps each problem's own
    solutions: SolutionRelease = SolutionRelease.AFTER_DUE

    def __post_init__(self) -> None:
        if self.opens_at.tzinfo is None or self.due_at.tzinfo is None:
            raise ValueError("assignment dates must carry a time zone")
        if self.due_at < self.opens_at:
            raise ValueError("an assignment is due after it opens")
        if len(set(self.problems)) != len(self.problems):
            raise ValueError("a problem appears once in an assignment")
        if self.max_attempts is not None and self.max_attempts < 1:
            raise ValueError("attempts per part are at least 1")


@dataclass(frozen=True)
class AssignmentRecord:
    id: int
    course_id: int
    spec: AssignmentSpec
    created_at: datetime

    @property
    def title(self) -> str:
        return self.spec.title

    @property
    def problems(self) -> tuple[str, ...]:
        return self.spec.problems


@dataclass(frozen=True)
class ExtensionRecord:
    """A student's own due date for an assignment. It counts for the answers they give from
    `granted_at` on: one given before keeps the grade it had (an extension reopens the assignment, it
    does not regrade late work), unless the teacher asked it to cover earlier answers too (None).
    `earlier` holds the due dates it replaced when it was moved, oldest first, each with its own grant
    time: an answer keeps the due date in force when it was given, as with a new extension."""

    due_at: datetime
    granted_at: datetime | None
    earlier: tuple[ExtensionRecord, ...] = ()

    def covers(self, submitted_at: datetime) -> bool:
        return self.granted_at is None or submitted_at >= self.granted_at

    def in_force(self, submitted_at: datetime) -> ExtensionRecord | None:
        """The grant that set this student's due date for an answer given then; None before any."""
        for grant in (self, *reversed(self.earlier)):
            if grant.covers(submitted_at):
                return grant
        return None


class CourseNotFound(NotFound):
    def __init__(self, course_id: int) -> None:
        super().__init__(f"no course {course_id}")
        self.course_id = course_id


class AssignmentNotFound(NotFound):
    def __init__(self, assignment_id: int) -> None:
        super().__init__(f"no assignment {assignment_id}")
        self.assignment_id = assignment_id


class JoinCodeTaken(StorageError):
    def __init__(self, code: str) -> None:
        super().__init__(f"join code {code!r} is in use")
        self.code = code


def roster_identity(course_id: int, roster_id: str) -> str:
    """The identity a rostered student's work is filed under: per course, from the institution's id."""
    return f"course:{course_id}:{roster_id}"
