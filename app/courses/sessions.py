"""Students without an LMS: a personal sign-in link (a single-use token) opens a session for the
course, held in an HttpOnly, SameSite=Lax cookie, so every tab of the browser is signed in and no
page asks for an API key. The cookie holds one session per course (a student in a physics course
and its lab is in both in one browser): a request acts as the session of its course or problem
(`choose`), else the latest; an instructor's "view as a student" beside them acts for the problem it
was opened for. The session reads as a launched student's (`SessionRecord`), so the API and the
student pages accept it exactly as they accept an LMS launch, CSRF token included.

A student's link to come back (shown when they join, or made again while signed in) is the same
kind of token, not spent by signing in: it is what a password is elsewhere, so only its hash is
kept, and any new link of theirs (the instructor's included) replaces it."""

from __future__ import annotations

import secrets
from collections.abc import Sequence
from dataclasses import dataclass
from datetime import datetime, timedelta

from app.auth import Role
from app.courses import access
from app.courses.records import AssignmentNotFound, CourseSession, roster_identity
from app.lti.sessions import SessionRecord, token_hash
from app.storage import Stores
from app.storage.protocols import CourseStore

COOKIE = "physcheck_course"
SESSION_LIFETIME = timedelta(days=14)
LINK_LIFETIME = timedelta(days=30)
RETURN_LINK_LIFETIME = timedelta(days=365)  # a course's year at most; a new one replaces it sooner
PREVIEW_LIFETIME = timedelta(hours=8)
SIGN_IN_PATH = "/s/"  # followed by the token
COURSE_PLATFORM = 0  # no LMS: what a course session's SessionRecord names as its platform
MAX_COURSES = 8  # sessions one browser's cookie holds, the latest first
_SEPARATOR = "."  # not in token_urlsafe's alphabet


def issue_link(courses: CourseStore, course_id: int, student: str, now: datetime) -> str:
    """A new personal link's token (shown once; only its hash is kept); older unused links die."""
    token = secrets.token_urlsafe(24)
    courses.issue_sign_in(course_id, student, token_hash(token), now + LINK_LIFETIME)
    return token


def issue_return_link(courses: CourseStore, course_id: int, student: str, now: datetime) -> str:
    """The student's new link to come back (shown once): it signs them in on any device, each time,
    until they or their instructor make a new link."""
    token = secrets.token_urlsafe(24)
    courses.issue_sign_in(course_id, student, token_hash(token), now + RETURN_LINK_LIFETIME, reusable=True)
    return token


def sign_in(courses: CourseStore, token: str, now: datetime) -> tuple[str, CourseSession] | None:
    """Spend the link's token and open a session: (cookie value, session), or None if the link is
    unknown, spent, replaced or expired."""
    if not token or len(token) > 100:
        return None
    redeemed = courses.redeem_sign_in(token_hash(token), now)
    if redeemed is None:
        return None
    course_id, student = redeemed
    enrolment = courses.enrolment(course_id, student)
    session = CourseSession(
        course_id=course_id,
        student=student,
        name=enrolment.name if enrolment is not None else "",
        csrf_token=secrets.token_urlsafe(32),
        expires_at=now + SESSION_LIFETIME,
    )
    cookie = secrets.token_urlsafe(32)
    courses.save_session(token_hash(cookie), session, now)
    return cookie, session


def open_preview(
    courses: CourseStore, key_id: str, name: str, problem_id: str, now: datetime
) -> tuple[str, CourseSession]:
    """ "View as a student" of one problem for an instructor key: a student's session under the
    instructor's preview identity (`preview:<key id>`, filed apart from the class as the instructor's
    previews always are), added to the browser's cookie as a course's is; it acts in place of a
    course's session for that problem's pages only: (cookie value, session)."""
    cookie = secrets.token_urlsafe(32)
    session = CourseSession(
        None, f"preview:{key_id}", name, secrets.token_urlsafe(32), now + PREVIEW_LIFETIME, problem_id
    )
    courses.save_session(token_hash(cookie), session, now)
    return cookie, session


def _cookie_ids(cookie: str | None) -> list[str]:
    return [part for part in (cookie or "").split(_SEPARATOR) if 0 < len(part) <= 100][:MAX_COURSES]


def live(courses: CourseStore, cookie: str | None, now: datetime) -> list[tuple[str, CourseSession]]:
    """(id hash, session) of each live session the browser's cookie holds, the latest first."""
    found = []
    for cookie_id in _cookie_ids(cookie):
        id_hash = token_hash(cookie_id)
        session = courses.get_session(id_hash)
        if session is not None and session.expires_at > now:
            found.append((id_hash, session))
    return found


def added(courses: CourseStore, cookie: str | None, new: str, session: CourseSession, now: datetime) -> str:
    """The browser's cookie with a new session first, in place of any it held for the same course or
    student (signing in to one course no longer signs the browser out of the others)."""
    kept = [new]
    for cookie_id in _cookie_ids(cookie):
        other = courses.get_session(token_hash(cookie_id))
        if other is None or other.expires_at <= now:
            continue
        if (
            other.course_id is None
            or other.course_id == session.course_id
            or other.student == session.student
        ):
            continue
        kept.append(cookie_id)
    return _SEPARATOR.join(kept[:MAX_COURSES])


def choose(
    stores: Stores,
    found: Sequence[tuple[str, CourseSession]],
    now: datetime,
    *,
    course_id: int | None = None,
    problem_id: str | None = None,
) -> tuple[str, CourseSession] | None:
    """Which of the browser's sessions a request acts as: the one of its course, and none when it
    names a course the browser is not signed in to (another course's student had acted on its pages);
    for a problem, the instructor's preview opened for it, else the course session whose open
    assignment takes answers to it (else one that has it at all); else the latest of a course. A
    preview acts for its own problem only: for 8 hours it had been chosen for every problem page, the
    browser's own student's too."""
    courses = [item for item in found if item[1].course_id is not None]
    if course_id is not None:
        return next((item for item in courses if item[1].course_id == course_id), None)
    if problem_id is not None:
        for item in found:
            if item[1].course_id is None and item[1].problem_id == problem_id:
                return item
    if problem_id is not None and len(courses) > 1:
        openings = [(item, access.opening(stores, item[1].student, problem_id, now)) for item in courses]
        for item, opened in openings:
            if opened is not None and opened.accepting:
                return item
        for item, opened in openings:
            if opened is not None:
                return item
    return courses[0] if courses else found[0]


def implied_course(
    stores: Stores,
    found: Sequence[tuple[str, CourseSession]],
    *,
    assignment_id: str | None,
    student: str | None,
) -> int | None:
    """The course an API call names without `?course=`: an assignment's (`/v1/assignments/{id}…`: the
    id names it), else that of the one session among the browser's whose course has the student the
    call names (`?student=`); None when the call implies none, or more than one."""
    if assignment_id is not None and assignment_id.isdigit() and len(assignment_id) < 10:
        try:
            return stores.courses.get_assignment(int(assignment_id)).course_id
        except AssignmentNotFound:
            return None
    courses = {s.course_id for s in _with_student(stores, found, student)} if student else set()
    return courses.pop() if len(courses) == 1 else None


def _with_student(
    stores: Stores, found: Sequence[tuple[str, CourseSession]], student: str
) -> list[CourseSession]:
    """The browser's course sessions whose course has this student."""
    return [
        s
        for _, s in found
        if s.course_id is not None
        and (s.student == student or stores.courses.enrolment(s.course_id, student) is not None)
    ]


def rivals(
    stores: Stores,
    found: Sequence[tuple[str, CourseSession]],
    now: datetime,
    *,
    problem_id: str | None,
    student: str | None = None,
) -> list[CourseSession]:
    """The course sessions an API call naming no course could act as, when more than one could (else
    none): for a problem, those of the courses whose open assignments have it (a preview opened for it
    is chosen before them); for a student (`?student=`), those of the courses that have them, where the
    call's answer depends on the course (a student in none of them is no one's to choose by);
    else every one. `choose` would take one of them: the call must say which (`?course=`), so that no
    answer is filed in a course the student did not mean."""
    if problem_id is not None and any(s.course_id is None and s.problem_id == problem_id for _, s in found):
        return []
    courses = [s for _, s in found if s.course_id is not None]
    if problem_id is not None:
        courses = [s for s in courses if access.opening(stores, s.student, problem_id, now) is not None]
    if student:
        having = _with_student(stores, found, student)
        courses = [s for s in courses if s in having]
    return courses if len(courses) > 1 else []


def as_record(session: CourseSession) -> SessionRecord:
    """A course session as a launched student's, which the API and the pages accept."""
    return SessionRecord(
        platform_id=COURSE_PLATFORM,
        sub=session.student,
        student=session.student,
        role=Role.STUDENT,
        name=session.name,
        csrf_token=session.csrf_token,
        expires_at=session.expires_at,
    )


JOIN_PATH = "/join/"
_JOIN_ALPHABET = "ABCDEFGHJKLMNPQRSTUVWXYZ23456789"  # no 0/O or 1/I to misread


def new_join_code() -> str:
    return "".join(secrets.choice(_JOIN_ALPHABET) for _ in range(8))


@dataclass(frozen=True)
class Joined:
    """A new student of the course, signed in: the session's cookie, and their link to come back."""

    cookie: str
    session: CourseSession
    return_token: str


@dataclass(frozen=True)
class AlreadyJoined:
    """Someone of the course has this name or email already: no second student is made (they would
    lose their work), and nobody signs in as that student by typing their name."""

    matched: str  # "name" or "email"
    rostered: bool = False  # on the roster the instructor imported: they sign in by the link sent them


def _same_name(a: str, b: str) -> bool:
    return " ".join(a.split()).casefold() == " ".join(b.split()).casefold()


def join(
    courses: CourseStore, code: str, name: str, email: str, now: datetime
) -> Joined | AlreadyJoined | None:
    """Enrol a new student by the course's join code and sign them in, or say who is there already;
    None for an unknown code. Each join is a new student of the course (their own identity)."""
    if not code or len(code) > 32:
        return None
    course = courses.course_by_join_code(code)
    if course is None:
        return None
    for enrolment in courses.roster(course.id):
        rostered = enrolment.roster_id is not None
        if email and enrolment.email.casefold() == email.casefold():
            return AlreadyJoined("email", rostered)
        if _same_name(enrolment.name, name):
            return AlreadyJoined("name", rostered)
    student = roster_identity(course.id, "join-" + secrets.token_hex(6))
    courses.enrol(course.id, student, name, email)
    session = CourseSession(course.id, student, name, secrets.token_urlsafe(32), now + SESSION_LIFETIME)
    cookie = secrets.token_urlsafe(32)
    courses.save_session(token_hash(cookie), session, now)
    return Joined(cookie, session, issue_return_link(courses, course.id, student, now))
