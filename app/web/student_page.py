"""The student page `/p/{problem_id}` and the student's problem list `/problems`.

After an LTI launch the session cookie identifies the student; outside an LMS the page asks for a
student key, kept in the tab's sessionStorage and sent as a bearer token when the script fetches the
server-rendered fragments (`/p/{id}/content`, `/p/{id}/parts/{part}/work`, `/problems/content`).
Everything is rendered here, from the student view and the stored submissions: statement, prompts and
feedback as MathML, each part's symbols, units, tolerance, attempts, best score and history. The script
(static/student.js) only previews, submits through the JSON API and swaps in fresh fragments.

What it needs from the app, through `LtiContext`: `student_view(problem_id, student)`, the database,
`authenticate_key(key)` for the key mode, and optionally `figure(problem_id, student)` (SVG text).
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from datetime import datetime
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, RedirectResponse, Response
from starlette.concurrency import run_in_threadpool

from app.auth import bearer_token
from app.courses import access
from app.courses.policy import Counting
from app.lti.context import LtiContext, LtiContextDep
from app.lti.platforms import platform_origins
from app.lti.sessions import current_session, requested_course
from app.web.course_pages import assignment_banner, sign_in_prompt
from app.web.layout import page, templates
from app.web.solution_access import Within, solution_release
from app.web.student_work import ProblemWork, load_work
from physics.mathinput.render import latex_name

router = APIRouter(tags=["student page"])
SCRIPT = "/static/student.js"
_PROBLEM_ID = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]{0,99}$")
_FRAGMENT_HEADERS = {"Cache-Control": "no-store", "X-Content-Type-Options": "nosniff"}


class Throttled(Exception):
    def __init__(self, wait: int) -> None:
        super().__init__(wait)
        self.wait = wait


@dataclass(frozen=True)
class Caller:
    student: str  # whose work the page shows and submits (an instructor key previews as "preview:…")
    csrf_token: str | None  # a session's; None for a key
    course: int | None = None  # the course the page is opened in (`?course=`), if it names one


def _who(student: str | None, key_id: str) -> str:
    return student or f"preview:{key_id}"


async def _caller(request: Request, context: LtiContext, *, allow_key: bool) -> Caller | None:
    """The student named by a bearer key (fragments only) or else by the LTI session cookie."""
    token = bearer_token(request.headers.get("authorization"))
    if allow_key and token is not None and context.authenticate_key is not None:
        principal = await run_in_threadpool(context.authenticate_key, token)
        if principal is None:
            return None
        # A key's page requests spend the API's budgets (per key and per student), as its API calls do.
        wait = None if context.rate_limit is None else await run_in_threadpool(context.rate_limit, principal)
        if wait is not None:
            raise Throttled(wait)
        return Caller(_who(principal.student, principal.key_id), None, requested_course(request))
    found = await run_in_threadpool(current_session, request)
    if found is None:
        return None
    id_hash, record = found
    principal = record.principal(id_hash)
    return Caller(_who(principal.student, principal.key_id), record.csrf_token, requested_course(request))


async def _ancestors(context: LtiContext) -> list[str]:
    return await run_in_threadpool(platform_origins, context.stores.platforms)


def tolerance_text(tolerance: Mapping[str, Any] | None, units: str | None) -> str:
    """`{"rel": 0.01}` -> "within 1 % of the expected value", and so on for abs and sigfigs."""
    if not tolerance:
        return ""
    said = []
    if "rel" in tolerance:
        said.append(f"within {float(tolerance['rel']) * 100:g} % of the expected value")
    if "abs" in tolerance:
        unit = f" {units}" if units and units != "1" else ""
        said.append(f"within ±{float(tolerance['abs']):g}{unit}")
    if "sigfigs" in tolerance:
        said.append(f"given to exactly {int(tolerance['sigfigs'])} significant figures")
    return "Counted right " + " and ".join(said) + "."


def _symbol_rows(view: Mapping[str, Any], names: Sequence[str]) -> list[dict[str, str]]:
    meta = view.get("symbols") or {}
    rows = []
    for name in names:
        info = meta.get(name) or {}
        rows.append(
            {
                "name": name,
                "latex": latex_name(name),
                "meaning": str(info.get("meaning", "")),
                "dimension": str(info.get("dimension", "")),
            }
        )
    return rows


def _parts(view: Mapping[str, Any]) -> list[dict[str, Any]]:
    parts = []
    for index, part in enumerate(view.get("parts", [])):
        units = part.get("units")
        parts.append(
            {
                **part,  # the kind's own fields, as its template (`<kind>/student.html`) reads them
                "index": index,
                "id": str(part.get("id", "")),
                "kind": part.get("kind"),
                "prompt": str(part.get("prompt", "")),
                "units": units,
                "dimensionless": units in ("1", ""),
                "symbols": _symbol_rows(view, part.get("symbols") or []),
                "tolerance": tolerance_text(part.get("tolerance"), units),
                "max_attempts": part.get("max_attempts"),
                "choices": part.get("choices") or [],
            }
        )
    return parts


def _figure(context: LtiContext, problem_id: str, student: str) -> str | None:
    if context.figure is None:
        return None
    try:
        return context.figure(problem_id, student)
    except Exception:  # a figure is an illustration: the page works without it
        return None


@dataclass(frozen=True)
class Loaded:
    view: Mapping[str, Any]
    work: ProblemWork
    figure: str | None
    opened: access.Opening  # whether and under which assignment the student's answers count now
    now: datetime  # the time `opened` was decided at
    assignment: Mapping[str, Any] | None = None  # the assignment it is answered in (a course's student)


def _load(context: LtiContext, problem_id: str, student: str, course: int | None = None) -> Loaded | None:
    if context.student_view is None or not _PROBLEM_ID.match(problem_id):
        return None
    # A course's student sees only the problems of their open assignments (app.courses.access).
    now = context.clock()
    opened = access.opening(context.stores, student, problem_id, now, course)
    if opened is None:
        return None
    try:
        view = opened.attempts_in(context.student_view(problem_id, student))
    except LookupError:
        return None
    work = load_work(
        context.stores.submissions,
        problem_id,
        student,
        view.get("parts", []),
        counting(context, opened, student, problem_id),
    )
    figure = _figure(context, problem_id, student)
    return Loaded(view, work, figure, opened, now, assignment_banner(opened))


def counting(context: LtiContext, opened: access.Opening, student: str, problem_id: str) -> Counting | None:
    """How the assignment the problem is answered in counts the student's answers, as its gradebook
    does: late penalties from the due date in force when each was given, and no credit after they
    opened the worked solution."""
    if opened.assignment is None:
        return None
    frozen = context.stores.courses.solutions_opened(student).get(problem_id)
    return Counting(opened.assignment, opened.extension, frozen)


def solution_within(loaded: Loaded) -> Within | None:
    """The assignment whose policy releases the worked solution (None: the problem's own rule)."""
    opened = loaded.opened
    if opened.assignment is None or opened.due is None:
        return None
    return Within(opened.assignment, opened.due, loaded.now)


def _solution_released(request: Request, problem_id: str, loaded: Loaded) -> bool:
    """Whether the worked solution is open to the student now, so the page can say so (the link had
    said "shown once it is released" after it was)."""
    services = getattr(request.app.state, "services", None)
    if services is None:
        return False
    try:
        doc = services.catalog.document(services.catalog.get(problem_id))
    except LookupError:
        return False
    return solution_release(doc, loaded.work, solution_within(loaded)).released


def _engine_refuses(request: Request, problem_id: str) -> bool:
    """Whether the running engine refuses the problem's stored version (vetted by older code): its
    checks would fail, so the page says so before anyone types an answer."""
    services = getattr(request.app.state, "services", None)
    if services is None:
        return False
    try:
        return services.catalog.refusal(services.catalog.get(problem_id)) is not None
    except LookupError:
        return False


def _content_context(request: Request, loaded: Loaded, problem_id: str, student: str) -> dict[str, Any]:
    return {
        "refused": _engine_refuses(request, problem_id),
        "solution_released": _solution_released(request, problem_id, loaded),
        "problem_id": problem_id,
        "view": loaded.view,
        "parts": _parts(loaded.view),
        "work": loaded.work,
        "figure": loaded.figure,
        "student": student,
        "assignment": loaded.assignment,
    }


def _not_found(request: Request, ancestors: Sequence[str]) -> HTMLResponse:
    return page(
        request,
        "student/not_found.html",
        {"title": "No such problem"},
        status=404,
        frame_ancestors=ancestors,
    )


@router.get("/p/{problem_id}", include_in_schema=False)
async def student_page(problem_id: str, request: Request, context: LtiContextDep) -> Response:
    ancestors = await _ancestors(context)
    if not _PROBLEM_ID.match(problem_id):
        return _not_found(request, ancestors)
    caller = await _caller(request, context, allow_key=False)
    shell = {"problem_id": problem_id, "scripts": [SCRIPT], "title": "Problem"}
    if caller is None and requested_course(request) is not None:
        # Opened from a course's assignment page: a course's student signs in by link, not by key.
        return await sign_in_prompt(request, context, ancestors)
    if caller is None:
        return page(request, "student/problem.html", {**shell, "mode": "key"}, frame_ancestors=ancestors)
    loaded = await run_in_threadpool(_load, context, problem_id, caller.student, caller.course)
    if loaded is None:
        return _not_found(request, ancestors)
    return page(
        request,
        "student/problem.html",
        {
            **shell,
            **_content_context(request, loaded, problem_id, caller.student),
            "mode": "session",
            "title": str(loaded.view.get("title", "Problem")),
            "meta": {"csrf-token": caller.csrf_token or ""},
        },
        frame_ancestors=ancestors,
    )


def _fragment(request: Request, template: str, values: Mapping[str, Any]) -> HTMLResponse:
    return templates.TemplateResponse(request, template, dict(values), headers=_FRAGMENT_HEADERS)


def _refused(status: int, text: str, headers: Mapping[str, str] | None = None) -> Response:
    return Response(
        text, status_code=status, media_type="text/plain", headers={**_FRAGMENT_HEADERS, **(headers or {})}
    )


async def _fragment_caller(request: Request, context: LtiContext) -> Caller | Response:
    """The caller of a fragment, or the response refusing it (401, or 429 with Retry-After)."""
    try:
        caller = await _caller(request, context, allow_key=True)
    except Throttled as throttled:
        return _refused(
            429, f"Too many requests; try again in {throttled.wait} s.", {"Retry-After": str(throttled.wait)}
        )
    return caller if caller is not None else _refused(401, "unauthenticated")


@router.get("/p/{problem_id}/content", include_in_schema=False)
async def student_content(problem_id: str, request: Request, context: LtiContextDep) -> Response:
    """The problem's HTML for the page's key mode (bearer key) or a session."""
    caller = await _fragment_caller(request, context)
    if isinstance(caller, Response):
        return caller
    loaded = await run_in_threadpool(_load, context, problem_id, caller.student, caller.course)
    if loaded is None:
        return _refused(404, "not found")
    return _fragment(
        request, "student/content.html", _content_context(request, loaded, problem_id, caller.student)
    )


@router.get("/p/{problem_id}/parts/{part_id}/work", include_in_schema=False)
async def part_work(problem_id: str, part_id: str, request: Request, context: LtiContextDep) -> Response:
    """One part's standing and history, and the problem's score, fresh after a submission."""
    caller = await _fragment_caller(request, context)
    if isinstance(caller, Response):
        return caller
    loaded = await run_in_threadpool(_load, context, problem_id, caller.student, caller.course)
    parts = {part["id"]: part for part in _parts(loaded.view)} if loaded else {}
    if loaded is None or part_id not in parts:
        return _refused(404, "not found")
    values = {**_content_context(request, loaded, problem_id, caller.student), "part": parts[part_id]}
    return _fragment(request, "student/work.html", values)


def _problem_list(request: Request, student: str) -> list[dict[str, Any]]:
    """Every live problem with this student's score on it (needs the full app's catalog)."""
    services = getattr(request.app.state, "services", None)
    if services is None:
        return []
    context: LtiContext = request.app.state.lti
    allowed = access.assigned_problems(context.stores, student, context.clock())
    rows = []
    for record in services.catalog.list():
        if allowed is not None and record.id not in allowed:
            continue
        document = services.catalog.document(record)
        parts = [
            {"id": part.id, "max_attempts": part.max_attempts or document.max_attempts}
            for part in document.parts
        ]
        work = load_work(context.stores.submissions, record.id, student, parts)
        rows.append({"id": record.id, "title": document.title, "topics": document.topics, "work": work})
    return sorted(rows, key=lambda row: (str(row["title"]).casefold(), row["id"]))


@router.get("/problems", include_in_schema=False)
async def problems_page(request: Request, context: LtiContextDep) -> Response:
    ancestors = await _ancestors(context)
    caller = await _caller(request, context, allow_key=False)
    values: dict[str, Any] = {"title": "Your problems", "scripts": [SCRIPT], "mode": "key"}
    if caller is not None:
        enrolled = await run_in_threadpool(context.stores.courses.courses_enrolled, caller.student)
        if enrolled:
            return RedirectResponse("/courses", status_code=303)  # a course's student: their assignments
    if caller is not None:
        rows = await run_in_threadpool(_problem_list, request, caller.student)
        values.update(mode="session", problems=rows, student=caller.student)
    return page(request, "student/problems.html", values, frame_ancestors=ancestors)


@router.get("/problems/content", include_in_schema=False)
async def problems_content(request: Request, context: LtiContextDep) -> Response:
    caller = await _fragment_caller(request, context)
    if isinstance(caller, Response):
        return caller
    rows = await run_in_threadpool(_problem_list, request, caller.student)
    return _fragment(request, "student/problem_list.html", {"problems": rows, "student": caller.student})
