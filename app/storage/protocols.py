"""What the service asks of storage, one small protocol per store.

Each has a SQL implementation (`sql.py`: SQLite or PostgreSQL, one transaction per call) and an
in-memory fake (`memory.py`) that the contract tests (`tests/storage/`) hold to the same behaviour.
Every call is atomic on its own: callers never open sessions or hold a transaction across calls.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass
from datetime import datetime
from typing import Any, Protocol

from app.courses.records import (
    AssignmentRecord,
    AssignmentSpec,
    CourseRecord,
    CourseSession,
    EnrolmentRecord,
    ExtensionRecord,
    RosterImport,
    RosterRow,
    StaffRecord,
    StaffRole,
)
from app.db.class_results import PartResults
from app.db.records import ApiKeyRecord, CreatedKey, Page, ProblemRecord, Role, SubmissionRecord
from app.lti.outbox import ClaimedScore, DeliveryProblem, Outcome
from app.lti.platforms import PlatformRecord
from app.lti.sessions import SessionRecord
from physics.verdict import Verdict

DEFAULT_PAGE_LIMIT = 100
MAX_PAGE_LIMIT = 1000


class ApiKeyStore(Protocol):
    """API keys, kept only as hashes (`app.db.keys` holds the format)."""

    def create(self, role: Role, *, name: str | None = None, student: str | None = None) -> CreatedKey:
        """A new key; a student key files under `student` (a fresh id when not given)."""
        ...

    def authenticate(self, plaintext: str) -> ApiKeyRecord | None:
        """The active key `plaintext` names, or None (unknown, malformed or revoked)."""
        ...

    def get(self, key_id: int) -> ApiKeyRecord:
        """Raises KeyNotFound."""
        ...

    def revoke(self, key_id: int) -> ApiKeyRecord:
        """Revoke for good; again keeps the first time. Raises KeyNotFound."""
        ...

    def list(self, *, include_revoked: bool = True) -> list[ApiKeyRecord]:
        """Oldest first."""
        ...


@dataclass(frozen=True)
class CompiledEntry:
    """A compilation sealed by the catalog, stored with the version it compiles (`CompiledCache`'s row)."""

    key: str
    payload: bytes
    mac: str


class ProblemStore(Protocol):
    """Problems and their versions: every version kept forever, ids never reused. A version may be
    stored with its compilation (an upload's, from its vetting), in the same transaction."""

    def get(
        self, problem_id: str, version: int | None = None, *, include_retired: bool = False
    ) -> ProblemRecord:
        """The latest version or the one asked for; ProblemNotFound / ProblemVersionNotFound."""
        ...

    def list(self, *, include_retired: bool = False, owner_key_id: int | None = None) -> list[ProblemRecord]:
        """The latest version of each problem, by id."""
        ...

    def save_builtin(
        self, problem_id: str, document: Mapping[str, Any], *, compiled: CompiledEntry | None = None
    ) -> ProblemRecord:
        """Idempotent: an unchanged document keeps its version. ProblemExists if an instructor owns the id."""
        ...

    def create(
        self,
        problem_id: str,
        document: Mapping[str, Any],
        *,
        owner_key_id: int,
        compiled: CompiledEntry | None = None,
    ) -> ProblemRecord:
        """Version 1 of a new problem; ProblemExists if the id was ever used (and nothing stored)."""
        ...

    def add_version(
        self, problem_id: str, document: Mapping[str, Any], *, compiled: CompiledEntry | None = None
    ) -> ProblemRecord:
        """The next version (the latest document again changes nothing); ProblemNotFound if retired."""
        ...

    def retire(self, problem_id: str) -> ProblemRecord:
        """Hide from listings and new work; ProblemNotFound if unknown or already retired."""
        ...


@dataclass(frozen=True)
class Filed:
    """A stored submission and the graded attempts its student has now used on the part."""

    record: SubmissionRecord
    attempts_used: int


class SubmissionStore(Protocol):
    """The append-only submissions log and its attempt counters."""

    def file(
        self,
        *,
        problem_id: str,
        problem_version: int,
        part_id: str,
        student: str,
        answer: str,
        verdict: Verdict,
        max_attempts: int | None,
    ) -> Filed:
        """Store one submission, atomically with its attempt (a graded verdict uses one; past
        `max_attempts` AttemptsExhausted and nothing stored) and with the LMS scores it queues. Once
        this returns, the submission is durable."""
        ...

    def attempts_used(self, problem_id: str, part_id: str, student: str) -> int: ...

    def page(
        self,
        *,
        problem_id: str | None = None,
        student: str | None = None,
        limit: int = DEFAULT_PAGE_LIMIT,
        cursor: str | None = None,
    ) -> Page[SubmissionRecord]:
        """Oldest first by (created_at, id), keyset-paged: InvalidLimit, InvalidCursor."""
        ...

    def class_results(self, problem_id: str, part_ids: Sequence[str]) -> list[PartResults]:
        """How the class did on each of `part_ids` (instructors' previews counted apart)."""
        ...


class CompiledCache(Protocol):
    """Compiled problems across restarts: opaque sealed bytes by key (the catalog seals them)."""

    def get(self, key: str) -> tuple[bytes, str] | None: ...

    def get_many(self, keys: Collection[str]) -> dict[str, tuple[bytes, str]]:
        """(payload, mac) of each of `keys` that is stored, at once."""
        ...

    def put(self, key: str, payload: bytes, mac: str) -> None:
        """Store or replace."""
        ...


@dataclass(frozen=True)
class QueuedScore:
    """One row of the grade passback outbox, as operators (and tests) see it."""

    id: int
    student: str
    problem_id: str
    score_given: float
    score_maximum: float
    timestamp: datetime
    status: str
    attempts: int
    claimed_by: str | None
    next_attempt_at: datetime


class ScoreOutbox(Protocol):
    """LMS grade passback: grade targets recorded at launch, scores queued with each graded
    submission (inside `SubmissionStore.file`), claimed by delivery workers and delivered once."""

    def add_target(
        self, platform: PlatformRecord, *, student: str, problem_id: str, lineitem_url: str, sub: str
    ) -> None:
        """Where a student's score on a problem goes (a line item); recording it again changes nothing."""
        ...

    def enqueue(
        self, problem_id: str, student: str, score_given: float, score_maximum: float, timestamp: datetime
    ) -> int:
        """Queue a score for every target of (student, problem), superseding any not yet sent;
        returns how many. Timestamps of a target only grow (by a millisecond when equal)."""
        ...

    def claim(self, claim: str, now: datetime, limit: int) -> list[ClaimedScore]:
        """Up to `limit` due scores, oldest timestamp first, for this worker alone until its lease
        ends. A due score with a newer one for its target is superseded instead; one whose target has
        an older score in flight waits."""
        ...

    def finish(self, score: ClaimedScore, outcome: Outcome, now: datetime) -> None:
        """File the outcome, unless the claim was lost; a platform that answered ends the backoff of
        every score waiting for it."""
        ...

    def launched(self, student: str, problem_id: str) -> bool:
        """Whether the student was launched into the problem from an LMS link with a grade target."""
        ...

    def delivery_problems(self, *, limit: int = 200) -> list[DeliveryProblem]:
        """Scores failed, still being retried, or superseded after failed tries, newest first."""
        ...

    def scores(self) -> list[QueuedScore]:
        """Every queued score, oldest first."""
        ...


class ToolKeys(Protocol):
    """Our LTI signing keys (RSA), made on first use and rotated with overlap."""

    def sign(self, claims: dict[str, Any]) -> str:
        """A compact RS256 JWT over `claims` with the current key."""
        ...

    def public_jwks(self) -> dict[str, list[dict[str, Any]]]:
        """The public halves of every live key (never empty)."""
        ...

    def rotate(self) -> str:
        """A new signing key; the previous one stays published, older ones are retired. Its kid."""
        ...


class PlatformStore(Protocol):
    """Registered LMSs (LTI 1.3 platforms) and their deployments."""

    def register(
        self,
        issuer: str,
        client_id: str,
        deployment_ids: Sequence[str],
        auth_url: str,
        token_url: str,
        jwks_url: str,
    ) -> PlatformRecord:
        """A new platform, or the known (issuer, client_id) with these URLs and its deployments
        joined by `deployment_ids` (none is ever removed)."""
        ...

    def find(self, issuer: str, client_id: str | None) -> PlatformRecord:
        """The platform for (issuer, client_id); without a client_id, the issuer's only registration.
        Raises PlatformNotFound."""
        ...

    def get(self, platform_id: int) -> PlatformRecord:
        """Raises PlatformNotFound."""
        ...

    def deployments(self, platform_id: int) -> list[str]: ...

    def is_deployed(self, platform_id: int, deployment_id: str) -> bool: ...

    def list(self) -> list[PlatformRecord]:
        """Every platform, by id."""
        ...


@dataclass(frozen=True)
class LoginState:
    """A login in progress, kept under its state's hash: what the launch answering it must match."""

    nonce: str
    browser_hash: str
    platform_id: int
    expires_at: datetime


@dataclass(frozen=True)
class PendingDeepLink:
    """A deep-linking request waiting for the instructor's choice; `data` is the platform's JSON text."""

    id: str
    session_hash: str
    platform_id: int
    deployment_id: str
    return_url: str
    data: str | None
    accept_multiple: bool
    expires_at: datetime


class LaunchStore(Protocol):
    """The launch flow's short-lived state: logins in progress, spent nonces, deep-link requests.
    Saving drops what expired before `now`."""

    def save_login(self, state_hash: str, login: LoginState, now: datetime) -> None: ...

    def take_login(self, state_hash: str) -> LoginState | None:
        """The login, removed: of concurrent takers exactly one gets it."""
        ...

    def spend_nonce(self, platform_id: int, nonce: str, expires_at: datetime, now: datetime) -> bool:
        """Remember the nonce until `expires_at`; False if it was already spent (a replay)."""
        ...

    def save_deep_link(self, request: PendingDeepLink, now: datetime) -> None: ...

    def get_deep_link(self, request_id: str) -> PendingDeepLink | None:
        """As saved, expired or not (the caller judges)."""
        ...

    def drop_deep_link(self, request_id: str) -> None: ...


class LtiSessionStore(Protocol):
    """Our sessions opened by launches, kept under the hash of the cookie's id."""

    def save(self, id_hash: str, record: SessionRecord, now: datetime) -> None:
        """Store a new session (dropping those expired before `now`)."""
        ...

    def get(self, id_hash: str) -> SessionRecord | None:
        """As saved, expired or not (the caller judges)."""
        ...


class CourseStore(Protocol):
    """Courses, their staff and rosters, students' sign-in links and sessions, assignments and
    extensions, and the uploads shared to the bank (records in `app.courses.records`)."""

    def create_course(
        self,
        title: str,
        *,
        owner: str,
        owner_name: str = "",
        timezone: str = "UTC",
        lti_context: tuple[int, str] | None = None,
    ) -> CourseRecord:
        """A new course taught by `owner` (its first instructor); with `lti_context` (platform id,
        context id) the LMS context's course: the known one when it exists."""
        ...

    def get_course(self, course_id: int) -> CourseRecord:
        """Raises CourseNotFound."""
        ...

    def course_for_context(self, platform_id: int, context_id: str) -> CourseRecord | None: ...

    def course_by_join_code(self, code: str) -> CourseRecord | None: ...

    def set_join_code(self, course_id: int, code: str | None) -> CourseRecord:
        """Raises JoinCodeTaken when another course uses it."""
        ...

    def courses_taught(self, member: str) -> list[tuple[CourseRecord, StaffRole]]:
        """By course id."""
        ...

    def courses_enrolled(self, student: str) -> list[CourseRecord]:
        """By course id."""
        ...

    def add_staff(self, course_id: int, member: str, role: StaffRole, name: str = "") -> StaffRecord:
        """Adds, or changes the role of, a member of staff."""
        ...

    def remove_staff(self, course_id: int, member: str) -> None: ...

    def staff(self, course_id: int) -> list[StaffRecord]:
        """By member."""
        ...

    def import_roster(self, course_id: int, rows: Sequence[RosterRow]) -> RosterImport:
        """Each row by its roster id: a new student, or the known one with this name and email (never
        a second enrolment). Atomic: all rows or none."""
        ...

    def enrol(self, course_id: int, student: str, name: str = "", email: str = "") -> EnrolmentRecord:
        """Enrol an identity (a join code, an LMS launch); again keeps the first enrolment."""
        ...

    def roster(self, course_id: int) -> list[EnrolmentRecord]:
        """By name, then identity."""
        ...

    def enrolment(self, course_id: int, student: str) -> EnrolmentRecord | None: ...

    def issue_sign_in(
        self, course_id: int, student: str, token_hash: str, expires_at: datetime, *, reusable: bool = False
    ) -> None:
        """A new personal link for an enrolled student (`reusable`: their link to come back, never
        spent); their older links that still work stop working. Raises NotFound when the student is
        not enrolled."""
        ...

    def redeem_sign_in(self, token_hash: str, now: datetime) -> tuple[int, str] | None:
        """(course id, student) of a live link: a single-use one is spent now (of concurrent redeemers
        one wins), a reusable one stays live."""
        ...

    def save_session(self, id_hash: str, session: CourseSession, now: datetime) -> None:
        """Store a new session (dropping those expired before `now`)."""
        ...

    def get_session(self, id_hash: str) -> CourseSession | None:
        """As saved, expired or not (the caller judges)."""
        ...

    def end_session(self, id_hash: str) -> None:
        """Signing out: the session is gone (a copy of its cookie no longer signs in)."""
        ...

    def create_assignment(self, course_id: int, spec: AssignmentSpec) -> AssignmentRecord: ...

    def update_assignment(self, assignment_id: int, spec: AssignmentSpec) -> AssignmentRecord: ...

    def delete_assignment(self, assignment_id: int) -> None:
        """With its extensions. Raises AssignmentNotFound."""
        ...

    def get_assignment(self, assignment_id: int) -> AssignmentRecord:
        """Raises AssignmentNotFound."""
        ...

    def assignments(self, course_id: int) -> list[AssignmentRecord]:
        """By due date, then id."""
        ...

    def set_extension(self, assignment_id: int, student: str, extension: ExtensionRecord | None) -> None:
        """A student's own due date for an assignment; None removes it."""
        ...

    def extensions(self, assignment_id: int) -> dict[str, ExtensionRecord]: ...

    def open_solution(self, student: str, problem_id: str, now: datetime) -> datetime:
        """Record that the student opened the problem's worked solution; when they first did."""
        ...

    def solutions_opened(self, student: str) -> dict[str, datetime]:
        """When the student first opened each problem's worked solution, by problem id."""
        ...

    def share_problem(self, problem_id: str, shared: bool) -> None:
        """Share an upload to the bank (every instructor may use it), or take it back."""
        ...

    def shared_problems(self) -> set[str]: ...
