"""Sessions of our own, opened by a launch: a random id in a cookie, its hash and the identity in an
`LtiSessionStore`. The API accepts the cookie as well as a bearer key (`principal_from_session`)."""

from __future__ import annotations

import hashlib
import hmac
import secrets
from collections.abc import Sequence
from dataclasses import dataclass
from datetime import datetime, timedelta
from typing import TYPE_CHECKING

from fastapi import Request

from app.auth import Principal, Role

if TYPE_CHECKING:  # the stores name this module's record
    from app.courses.records import CourseSession
    from app.storage import Stores
    from app.storage.protocols import LtiSessionStore

SESSION_COOKIE = "physcheck_session"
CSRF_HEADER = "X-CSRF-Token"
SESSION_LIFETIME = timedelta(hours=8)
SAFE_METHODS = frozenset({"GET", "HEAD", "OPTIONS"})
_STUDENT_ID_LIMIT = 200

# LIS roles that may see solutions and deep-link (context roles, and the system/institution admins).
INSTRUCTOR_ROLES = frozenset(
    {
        "http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor",
        "http://purl.imsglobal.org/vocab/lis/v2/membership#Administrator",
        "http://purl.imsglobal.org/vocab/lis/v2/membership#ContentDeveloper",
        "http://purl.imsglobal.org/vocab/lis/v2/membership/Instructor#TeachingAssistant",
        "http://purl.imsglobal.org/vocab/lis/v2/institution/person#Administrator",
        "http://purl.imsglobal.org/vocab/lis/v2/system/person#Administrator",
    }
)


def token_hash(token: str) -> str:
    return hashlib.sha256(token.encode("utf-8")).hexdigest()


def role_from_claims(roles: tuple[str, ...] | list[str]) -> Role:
    """Instructor when any signed role is a teaching or administrative one; otherwise student."""
    return Role.INSTRUCTOR if any(role in INSTRUCTOR_ROLES for role in roles) else Role.STUDENT


def student_id(platform_id: int, sub: str) -> str:
    """The identity an LTI user's submissions are filed under: `lti:<platform id>:<sub>` (hashed
    when the platform's sub is too long for the column)."""
    plain = f"lti:{platform_id}:{sub}"
    if len(plain) <= _STUDENT_ID_LIMIT:
        return plain
    return f"lti:{platform_id}:sha256:{hashlib.sha256(sub.encode('utf-8')).hexdigest()}"


@dataclass(frozen=True)
class SessionRecord:
    platform_id: int
    sub: str
    student: str
    role: Role
    name: str
    csrf_token: str
    expires_at: datetime

    def principal(self, id_hash: str) -> Principal:
        return Principal(
            key_id=f"lti-session:{id_hash[:16]}",
            role=self.role,
            name=self.name or self.student,
            student=self.student if self.role is Role.STUDENT else None,
            api_key=False,
            account=self.student,
        )


def open_session(
    sessions: LtiSessionStore, *, platform_id: int, sub: str, role: Role, name: str, now: datetime
) -> tuple[str, SessionRecord]:
    """A new session; returns the cookie value (shown once) and the record."""
    session_id = secrets.token_urlsafe(32)
    record = SessionRecord(
        platform_id=platform_id,
        sub=sub,
        student=student_id(platform_id, sub),
        role=role,
        name=name[:200],
        csrf_token=secrets.token_urlsafe(32),
        expires_at=now + SESSION_LIFETIME,
    )
    sessions.save(token_hash(session_id), record, now)
    return session_id, record


def find_session(sessions: LtiSessionStore, session_id: str, *, now: datetime) -> SessionRecord | None:
    """The live session the cookie value names, or None."""
    if not session_id or len(session_id) > 100:
        return None
    record = sessions.get(token_hash(session_id))
    return None if record is None or record.expires_at <= now else record


def current_session(request: Request) -> tuple[str, SessionRecord] | None:
    """(id hash, record) of the session named by the cookie, if live. The student page takes the
    CSRF token from here to put in its page for its scripts to send back."""
    session_id = request.cookies.get(SESSION_COOKIE)
    context = getattr(request.app.state, "lti", None)
    if context is None:
        return None
    if session_id:
        record = find_session(context.stores.lti_sessions, session_id, now=context.clock())
        if record is not None:
            return token_hash(session_id), record
    # Else a student signed in by a course's personal link (the same shape; see app.courses.sessions).
    from app.courses import sessions as course_sessions

    course_cookie = request.cookies.get(course_sessions.COOKIE)
    if not course_cookie:
        return None
    now = context.clock()
    found = course_sessions.live(context.stores.courses, course_cookie, now)
    if not found:
        return None
    chosen = course_sessions.choose(
        context.stores,
        found,
        now,
        course_id=requested_course(request) or implied_course(context.stores, found, request),
        problem_id=request.path_params.get("problem_id"),
    )
    if chosen is None:
        return None
    id_hash, session = chosen
    return id_hash, course_sessions.as_record(session)


@dataclass(frozen=True)
class Unsettled:
    """Why an API call through a course cookie cannot say which of the browser's sessions it is:
    `?course=` names a course the browser is not signed in to, or it names none where more than one
    could take the call (`app.courses.sessions.rivals`). Either had acted as the latest course's."""

    unknown: int | None = None
    rivals: tuple[int, ...] = ()


def unsettled_course(request: Request) -> Unsettled | None:
    """None when the call's session is settled (an LMS session's, one course's, or the named course's)."""
    context = getattr(request.app.state, "lti", None)
    if context is None:
        return None
    session_id = request.cookies.get(SESSION_COOKIE)
    now = context.clock()
    if session_id and find_session(context.stores.lti_sessions, session_id, now=now) is not None:
        return None
    from app.courses import sessions as course_sessions

    found = course_sessions.live(context.stores.courses, request.cookies.get(course_sessions.COOKIE), now)
    named = requested_course(request)
    if named is not None:
        in_query = request.query_params.get("course") is not None and "course_id" not in request.path_params
        mine = any(session.course_id == named for _, session in found)
        return Unsettled(unknown=named) if in_query and found and not mine else None
    implied = implied_course(context.stores, found, request)
    if implied is not None:
        mine = any(session.course_id == implied for _, session in found)
        return Unsettled(unknown=implied) if found and not mine else None
    problem_id = request.path_params.get("problem_id")
    student = request.query_params.get("student")
    rivals = course_sessions.rivals(context.stores, found, now, problem_id=problem_id, student=student)
    ids = tuple(session.course_id for session in rivals if session.course_id is not None)
    return Unsettled(rivals=ids) if ids else None


def implied_course(
    stores: Stores, found: Sequence[tuple[str, CourseSession]], request: Request
) -> int | None:
    """The course the call implies by the assignment or the student it names (see `course_sessions`)."""
    from app.courses import sessions as course_sessions

    assignment_id = request.path_params.get("assignment_id")
    return course_sessions.implied_course(
        stores,
        found,
        assignment_id=None if assignment_id is None else str(assignment_id),
        student=request.query_params.get("student"),
    )


def requested_course(request: Request) -> int | None:
    """The course a request is made in: its path's (`/courses/{course_id}/…`), else `?course=`, as a
    problem's page and its answers carry it from the assignment they were opened in."""
    named = request.path_params.get("course_id") or request.query_params.get("course")
    text = str(named) if isinstance(named, (int, str)) else ""
    return int(text) if text.isdigit() and len(text) < 10 else None


def principal_from_session(request: Request) -> Principal | None:
    """The caller named by the session cookie, or None. A request that changes state must also send
    the session's CSRF token in `X-CSRF-Token` (the cookie is SameSite=None, so it rides along on
    cross-site requests too). Uses `request.app.state.lti` (an `LtiContext`)."""
    found = current_session(request)
    if found is None:
        return None
    id_hash, record = found
    if request.method not in SAFE_METHODS:
        sent = request.headers.get(CSRF_HEADER, "")
        if not hmac.compare_digest(sent.encode("utf-8"), record.csrf_token.encode("utf-8")):
            return None
    return record.principal(id_hash)
