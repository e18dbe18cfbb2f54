"""The students' side of courses: the personal sign-in link, my courses and assignments.

    GET  /s/{token}       "Sign in to <course>" (a button: mail scanners that fetch links spend nothing)
    POST /s/{token}       spends the link, sets the course session cookie, goes to /courses
    GET|POST /join/{code} a course's join code: name and email, then signed in as its new student,
                          shown their link to come back
    POST /courses/return-link   a signed-in student's new link to come back (the old one stops working)
    POST /courses/sign-out      ends the browser's session
    GET  /courses         my courses, each with its assignments: due date, status and score
    GET  /courses/{c}/assignments/{a}   the assignment: its problems, due date, late policy, score

The session cookie (HttpOnly, SameSite=Lax, Secure on https) is sent by every tab; the pages and the
API read it as they read an LMS launch's, so no student page asks for a key.
"""

from __future__ import annotations

import hmac
from dataclasses import dataclass
from datetime import datetime
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, RedirectResponse, Response
from starlette.concurrency import run_in_threadpool

from app.courses import access, service
from app.courses import sessions as course_sessions
from app.courses.gradebook import AssignmentCell
from app.courses.policy import Status, late_policy_text, shown
from app.courses.records import AssignmentNotFound, AssignmentRecord, CourseRecord, CourseSession
from app.db.errors import ProblemNotFound
from app.deps import RecordId
from app.lti.context import LtiContext, LtiContextDep
from app.lti.platforms import platform_origins
from app.lti.sessions import current_session
from app.services import Services
from app.web.layout import page

router = APIRouter(tags=["course pages"], include_in_schema=False)


async def _frames(context: LtiContext) -> list[str]:
    """Framable by the registered LMSs: a launched student meets these pages in the LMS's frame."""
    return await run_in_threadpool(platform_origins, context.stores.platforms)


def _services(request: Request) -> Services:
    services: Services = request.app.state.services
    return services


@router.get("/s/{token}")
async def sign_in_page(token: str, request: Request) -> HTMLResponse:
    return page(request, "courses/sign_in.html", {"title": "Sign in", "token": token})


def _cross_site(request: Request) -> bool:
    """A form posted from another site (login CSRF: signing a victim in as someone else's student).
    Browsers say where a request comes from in Sec-Fetch-Site; without it, a real Origin is compared
    (our pages send no Referer, so a same-site form may carry `Origin: null`)."""
    fetch_site = request.headers.get("sec-fetch-site")
    if fetch_site is not None:
        return fetch_site not in ("same-origin", "none")
    origin = request.headers.get("origin")
    if origin is None or origin == "null":
        return False
    ours = {str(request.base_url).rstrip("/")}
    context = getattr(request.app.state, "lti", None)
    if context is not None:
        ours.add(context.origin)  # the configured public address (behind a proxy that rewrites Host)
    return origin.rstrip("/") not in ours


def _refused_cross_site(request: Request) -> HTMLResponse:
    return page(request, "courses/signed_out.html", {"title": "Sign in", "cross_site": True}, status=403)


@router.post("/s/{token}")
async def sign_in(token: str, request: Request, context: LtiContextDep) -> Response:
    if _cross_site(request):
        return _refused_cross_site(request)
    now = context.clock()
    opened = await run_in_threadpool(course_sessions.sign_in, context.stores.courses, token, now)
    if opened is None:
        return page(
            request,
            "courses/sign_in.html",
            {"title": "Sign in", "token": token, "spent": True},
            status=400,
        )
    response = RedirectResponse("/courses", status_code=303)
    await course_cookie(response, request, context, opened[0], opened[1])
    return response


async def course_cookie(
    response: Response, request: Request, context: LtiContext, new: str, session: CourseSession
) -> None:
    """The browser's cookie with the new session beside those of its other courses (an instructor's
    "View as a student" too: it signs nobody out)."""
    cookie = await run_in_threadpool(
        course_sessions.added,
        context.stores.courses,
        request.cookies.get(course_sessions.COOKIE),
        new,
        session,
        context.clock(),
    )
    response.set_cookie(
        course_sessions.COOKIE,
        cookie,
        max_age=int(course_sessions.SESSION_LIFETIME.total_seconds()),
        path="/",
        httponly=True,
        samesite="lax",
        secure=request.url.scheme == "https",
    )


def _enrolled_in(request: Request, context: LtiContext, course: CourseRecord) -> str | None:
    """The name of the student this browser is signed in as, when they are in `course` already."""
    for who in _students(request, context):
        enrolment = context.stores.courses.enrolment(course.id, who.student)
        if enrolment is not None:
            return enrolment.name or "you"
    return None


@router.get("/join/{code}")
async def join_page(code: str, request: Request, context: LtiContextDep) -> HTMLResponse:
    def load() -> tuple[CourseRecord | None, str | None]:
        course = context.stores.courses.course_by_join_code(code[:32])
        return course, None if course is None else _enrolled_in(request, context, course)

    course, member = await run_in_threadpool(load)
    if course is None:
        return page(request, "courses/join.html", {"title": "Join a course", "unknown": True}, status=404)
    return page(
        request,
        "courses/join.html",
        {"title": f"Join {course.title}", "course": course, "code": code, "member": member},
    )


@router.post("/join/{code}")
async def join(code: str, request: Request, context: LtiContextDep) -> Response:
    if _cross_site(request):
        return _refused_cross_site(request)
    form = await request.form(max_files=0, max_fields=10)
    name = str(form.get("name") or "").strip()[:200]
    email = str(form.get("email") or "").strip()[:254]
    course = await run_in_threadpool(context.stores.courses.course_by_join_code, code[:32])
    if course is None:
        return page(request, "courses/join.html", {"title": "Join a course", "unknown": True}, status=404)
    if await run_in_threadpool(_enrolled_in, request, context, course) is not None:
        return RedirectResponse("/courses", status_code=303)  # a second join would split their work
    values: dict[str, Any] = {
        "title": f"Join {course.title}",
        "course": course,
        "code": code,
        "name": name,
        "email": email,
    }
    if not name:
        return page(request, "courses/join.html", {**values, "error": "Give your name."}, status=422)
    joined = await run_in_threadpool(
        course_sessions.join, context.stores.courses, code, name, email, context.clock()
    )
    if joined is None:
        return page(request, "courses/join.html", {"title": "Join a course", "unknown": True}, status=404)
    if isinstance(joined, course_sessions.AlreadyJoined):
        return page(
            request,
            "courses/join.html",
            {**values, "taken": joined.matched, "rostered": joined.rostered},
            status=409,
        )
    response = _return_link_page(request, course, joined.session.name, joined.return_token, joined=True)
    await course_cookie(response, request, context, joined.cookie, joined.session)
    return response


def _return_link_page(
    request: Request, course: CourseRecord, name: str, token: str, *, joined: bool
) -> HTMLResponse:
    """The link to come back, shown once (only its hash is kept)."""
    url = str(request.base_url).rstrip("/") + course_sessions.SIGN_IN_PATH + token
    title = f"Welcome to {course.title}" if joined else "Your link to come back"
    return page(
        request,
        "courses/return_link.html",
        {"title": title, "course": course, "name": name, "url": url, "joined": joined},
    )


@router.post("/courses/return-link")
async def new_return_link(request: Request, context: LtiContextDep) -> Response:
    """A signed-in student's new link to come back; their earlier links stop working."""
    if _cross_site(request):
        return _refused_cross_site(request)
    form = await request.form(max_files=0, max_fields=10)
    sent = str(form.get("csrf") or "")
    asked = str(form.get("course") or "")
    now = context.clock()

    def issue() -> tuple[CourseRecord, str, str] | int:
        signed_in = _students(request, context)
        if not signed_in:
            return 401
        # the session of the course asked for (a browser may be signed in to several), else the latest
        mine = [(each, context.stores.courses.courses_enrolled(each.student)) for each in signed_in]
        who, courses = next(((w, c) for w, c in mine if any(str(x.id) == asked for x in c)), mine[0])
        student = who.student
        if (
            not who.by_link  # an LMS signs them in
            or not courses  # an instructor's "view as a student"
            or not hmac.compare_digest(sent.encode(), who.csrf_token.encode())
        ):
            return 403
        course = courses[0]  # a joined or rostered student's identity belongs to one course
        enrolment = context.stores.courses.enrolment(course.id, student)
        name = enrolment.name if enrolment is not None else ""
        return (
            course,
            name,
            course_sessions.issue_return_link(context.stores.courses, course.id, student, now),
        )

    issued = await run_in_threadpool(issue)
    if isinstance(issued, int):
        values = {"title": "Your courses", "stale": issued == 403}
        return page(request, "courses/signed_out.html", values, status=issued)
    return _return_link_page(request, issued[0], issued[1], issued[2], joined=False)


@router.post("/courses/sign-out")
async def sign_out(request: Request, context: LtiContextDep) -> Response:
    """Ends this browser's session (a shared computer's next user is not signed in as the student)."""
    if _cross_site(request):
        return _refused_cross_site(request)
    form = await request.form(max_files=0, max_fields=10)
    sent = str(form.get("csrf") or "")

    def end() -> int:
        who = _student(request)
        if who is None:
            return 401
        if not who.by_link or not hmac.compare_digest(sent.encode(), who.csrf_token.encode()):
            return 403
        for each in _students(request, context):  # every course this browser is signed in to
            context.stores.courses.end_session(each.session_hash)
        return 200

    status = await run_in_threadpool(end)
    values = {"title": "Signed out" if status == 200 else "Your courses", "stale": status == 403}
    response = page(
        request, "courses/signed_out.html", {**values, "signed_out": status == 200}, status=status
    )
    if status == 200:
        response.delete_cookie(course_sessions.COOKIE, path="/")
    return response


@dataclass(frozen=True)
class Row:
    assignment: AssignmentRecord
    cell: AssignmentCell
    due: str
    late_policy: str
    opens: str = ""  # shown while it is not open yet

    @property
    def status(self) -> str:
        return self.cell.status.value

    @property
    def open(self) -> bool:
        return self.cell.status is not Status.NOT_OPEN


def _rows(services: Services, course: CourseRecord, student: str, now: datetime) -> list[Row]:
    rows = []
    for assignment in services.stores.courses.assignments(course.id):
        cell = service.student_cell(services.stores, services.catalog, assignment, student, now)
        rows.append(
            Row(
                assignment,
                cell,
                shown(cell.due, course.timezone),
                late_policy_text(assignment.spec.late),
                shown(assignment.spec.opens_at, course.timezone),
            )
        )
    return rows


@dataclass(frozen=True)
class SignedIn:
    student: str  # the identity their work is filed under
    name: str
    csrf_token: str
    session_hash: str
    by_link: bool  # by a link or a join code (not by an LMS): they make links to come back, sign out


def _students(request: Request, context: LtiContext) -> list[SignedIn]:
    """Everyone this browser is signed in as: an LMS launch's student, else each course's session."""
    latest = _student(request)
    if latest is None or not latest.by_link:
        return [] if latest is None else [latest]
    cookie = request.cookies.get(course_sessions.COOKIE)
    found = course_sessions.live(context.stores.courses, cookie, context.clock())
    each = [SignedIn(s.student, s.name, s.csrf_token, h, True) for h, s in found if s.course_id is not None]
    return each or [latest]


def _student(request: Request) -> SignedIn | None:
    """The signed-in student, or None."""
    found = current_session(request)
    if found is None:
        return None
    _, record = found
    principal = record.principal(found[0])
    if principal.student is None:
        return None
    return SignedIn(
        principal.student,
        record.name,
        record.csrf_token,
        found[0],
        record.platform_id == course_sessions.COURSE_PLATFORM,
    )


def _signed_in_elsewhere(request: Request, context: LtiContext) -> bool:
    """Whether this browser holds a session of some course: a page of a course it has none for then
    asks to sign in to that one (no other course's session acts for it: `course_sessions.choose`)."""
    cookie = request.cookies.get(course_sessions.COOKIE)
    found = course_sessions.live(context.stores.courses, cookie, context.clock())
    return any(session.course_id is not None for _, session in found)


async def sign_in_prompt(request: Request, context: LtiContext, frames: list[str]) -> Response:
    """A page of a course this browser is not signed in to (401): sign in to that course, or, signed
    in to none, how to sign in."""
    if await run_in_threadpool(_signed_in_elsewhere, request, context):
        values: dict[str, Any] = {"title": "Sign in to this course", "other_course": True}
    else:
        values = {"title": "Your courses"}
    return page(request, "courses/signed_out.html", values, status=401, frame_ancestors=frames)


@router.get("/courses")
async def my_courses(request: Request, context: LtiContextDep) -> HTMLResponse:
    services = _services(request)
    now = context.clock()

    def load() -> dict[str, Any] | None:
        who = _student(request)
        if who is None:
            return None
        courses = [
            (c, _rows(services, c, each.student, now), each)
            for each in _students(request, context)
            for c in services.stores.courses.courses_enrolled(each.student)
        ]
        return {"courses": sorted(courses, key=lambda item: item[0].id), "who": who}

    values = await run_in_threadpool(load)
    frames = await _frames(context)
    if values is None:
        return page(
            request, "courses/signed_out.html", {"title": "Your courses"}, status=401, frame_ancestors=frames
        )
    return page(request, "courses/home.html", {"title": "Your courses", **values}, frame_ancestors=frames)


@router.get("/courses/{course_id}/assignments/{assignment_id}")
async def assignment_page(
    course_id: RecordId, assignment_id: RecordId, request: Request, context: LtiContextDep
) -> Response:
    services = _services(request)
    now = context.clock()

    def load() -> dict[str, Any] | str | None:
        who = _student(request)
        if who is None:
            return "signed out"
        student = who.student
        if services.stores.courses.enrolment(course_id, student) is None:
            return None
        try:
            assignment = services.stores.courses.get_assignment(assignment_id)
        except AssignmentNotFound:
            return None
        if assignment.course_id != course_id or assignment.spec.opens_at > now:
            return None
        course = services.stores.courses.get_course(course_id)
        cell = service.student_cell(services.stores, services.catalog, assignment, student, now)
        by_problem: dict[str, list[Any]] = {}
        for part in cell.parts:
            by_problem.setdefault(part.problem_id, []).append(part)
        problems = []
        for problem_id in assignment.problems:
            try:
                title = services.catalog.document(services.catalog.get(problem_id)).title
            except ProblemNotFound:  # retired by its author: the assignment's other problems stay open
                continue
            parts = by_problem.get(problem_id, [])
            problems.append(
                {
                    "id": problem_id,
                    "title": title,
                    "score": sum(p.score for p in parts),
                    "points": len(parts),
                    "late": any(p.late for p in parts),
                    "started": any(p.attempts for p in parts),
                }
            )
        return {
            "course": course,
            "assignment": assignment,
            "row": Row(
                assignment, cell, shown(cell.due, course.timezone), late_policy_text(assignment.spec.late)
            ),
            "problems": problems,
        }

    values = await run_in_threadpool(load)
    frames = await _frames(context)
    if values == "signed out":
        return await sign_in_prompt(request, context, frames)
    if not isinstance(values, dict):
        return page(
            request,
            "student/not_found.html",
            {"title": "No such assignment"},
            status=404,
            frame_ancestors=frames,
        )
    return page(
        request,
        "courses/assignment.html",
        {"title": values["assignment"].title, **values},
        frame_ancestors=frames,
    )


def assignment_banner(opened: access.Opening) -> dict[str, Any] | None:
    """What a problem page says about the assignment it is answered in: title, due date (the
    student's, in the course's zone), late policy, and whether answers are still accepted. From the
    page's own `access.opening` (one look at the student's courses per page)."""
    if opened.assignment is None or opened.course is None or opened.due is None:
        return None
    return {
        "course": opened.course,
        "assignment": opened.assignment,
        "due": shown(opened.due, opened.course.timezone),
        "extended": opened.extension is not None,
        "late_policy": late_policy_text(opened.assignment.spec.late),
        "accepting": opened.accepting,
        "why": opened.why,
        # carried by the page's links and answers, so that they stay in this course (see `choose`)
        "query": f"?course={opened.course.id}",
    }
