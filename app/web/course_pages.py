"""The students' side of courses: the personal sign-in link, my courses and assignments.

    GET  /s/{token}       "Sign in to <course>" (a button: mail scanners that fetch links spend nothing)
    POST /s/{token}       spends the link, sets the course session cookie, goes to /courses
    GET|POST /join/{code} a course's join code: name and email, then signed in as its new student
    GET  /courses         my courses, each with its assignments: due date, status and score
    GET  /courses/{c}/assignments/{a}   the assignment: its problems, due date, late policy, score

The session cookie (HttpOnly, SameSite=Lax, Secure on https) is sent by every tab; the pages and the
API read it as they read an LMS launch's, so no student page asks for a key.
"""

from __future__ import annotations

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
from app.courses.records import AssignmentNotFound, AssignmentRecord, CourseRecord
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
    opened = await run_in_threadpool(course_sessions.sign_in, context.stores.courses, token, context.clock())
    if opened is None:
        return page(
            request,
            "courses/sign_in.html",
            {"title": "Sign in", "token": token, "spent": True},
            status=400,
        )
    response = RedirectResponse("/courses", status_code=303)
    _course_cookie(response, request, opened[0])
    return response


def _course_cookie(response: Response, request: Request, cookie: str) -> None:
    response.set_cookie(
        course_sessions.COOKIE,
        cookie,
        max_age=int(course_sessions.SESSION_LIFETIME.total_seconds()),
        path="/",
        httponly=True,
        samesite="lax",
        secure=request.url.scheme == "https",
    )


@router.get("/join/{code}")
async def join_page(code: str, request: Request, context: LtiContextDep) -> HTMLResponse:
    course = await run_in_threadpool(context.stores.courses.course_by_join_code, code[:32])
    if course is None:
        return page(request, "courses/join.html", {"title": "Join a course", "unknown": True}, status=404)
    return page(
        request, "courses/join.html", {"title": f"Join {course.title}", "course": course, "code": code}
    )


@router.post("/join/{code}")
async def join(code: str, request: Request, context: LtiContextDep) -> Response:
    if _cross_site(request):
        return _refused_cross_site(request)
    form = await request.form(max_files=0, max_fields=10)
    name = str(form.get("name") or "").strip()[:200]
    email = str(form.get("email") or "").strip()[:254]
    if not name:
        course = await run_in_threadpool(context.stores.courses.course_by_join_code, code[:32])
        values = {"title": "Join a course", "course": course, "code": code, "error": "Give your name."}
        return page(request, "courses/join.html", values, status=422)
    opened = await run_in_threadpool(
        course_sessions.join, context.stores.courses, code, name, email, context.clock()
    )
    if opened is None:
        return page(request, "courses/join.html", {"title": "Join a course", "unknown": True}, status=404)
    response = RedirectResponse("/courses", status_code=303)
    _course_cookie(response, request, opened[0])
    return response


@dataclass(frozen=True)
class Row:
    assignment: AssignmentRecord
    cell: AssignmentCell
    due: str
    late_policy: str

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
            Row(assignment, cell, shown(cell.due, course.timezone), late_policy_text(assignment.spec.late))
        )
    return rows


def _student(request: Request) -> tuple[str, str] | None:
    """(student identity, csrf token) of the signed-in student, or None."""
    found = current_session(request)
    if found is None:
        return None
    _, record = found
    principal = record.principal(found[0])
    return (principal.student, record.csrf_token) if principal.student is not None else None


@router.get("/courses")
async def my_courses(request: Request, context: LtiContextDep) -> HTMLResponse:
    services = _services(request)
    now = context.clock()

    def load() -> dict[str, Any] | None:
        who = _student(request)
        if who is None:
            return None
        courses = services.stores.courses.courses_enrolled(who[0])
        return {"courses": [(c, _rows(services, c, who[0], now)) for c in courses], "student": who[0]}

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
        student = who[0]
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
            except LookupError:
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
        return page(
            request, "courses/signed_out.html", {"title": "Your courses"}, status=401, frame_ancestors=frames
        )
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
        "late_policy": late_policy_text(opened.assignment.spec.late),
        "accepting": opened.accepting,
        "why": opened.why,
    }
