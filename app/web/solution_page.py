"""A problem's worked solution for a student, at a stable link an instructor can post: `/p/{id}/solution`.

Shown only when `solution_release` (app/web/solution_access.py, the one gate) says so; otherwise the
page says when it opens. Like the problem page, an LTI session sees it at once and a student key
fetches it as a fragment (`/p/{id}/solution/content`, bearer key). The content is the instructor's
(app/instructor/described.py and worked.py) for the student's own variant: the answers, the figure and
free-body diagrams, the methods compared and each method's solution, laid out to print on A4 or Letter.

A course's student's every opening is recorded, and freezes their grade on the problem's parts
(app/courses/gradebook.py): within an assignment whose answers still count (late work accepted), the
page first says so and asks, and `POST /p/{id}/solution` records the opening; when nothing is left to
earn now, it is shown at once and recorded then (an extension may reopen the answers later).
"""

from __future__ import annotations

import hmac
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, RedirectResponse, Response
from starlette.concurrency import run_in_threadpool

from app.courses.policy import shown
from app.instructor.described import describe
from app.lti.context import LtiContextDep
from app.lti.sessions import requested_course
from app.web.course_pages import _cross_site, _refused_cross_site
from app.web.layout import page, templates
from app.web.solution_access import solution_release
from app.web.student_page import (
    _FRAGMENT_HEADERS,
    _PROBLEM_ID,
    SCRIPT,
    Loaded,
    _ancestors,
    _caller,
    _fragment_caller,
    _load,
    _not_found,
    _refused,
    solution_within,
)
from problems.variants import fill_statement

router = APIRouter(tags=["student page"])


def solution_context(request: Request, problem_id: str, student: str) -> dict[str, Any] | None:
    """Everything the solution shows for `student`, or None for no such problem. `released` says
    whether it may be shown (the rest is then left out)."""
    services = getattr(request.app.state, "services", None)
    loaded = _load(request.app.state.lti, problem_id, student, requested_course(request))
    if services is None or loaded is None:
        return None
    catalog = services.catalog
    record = catalog.get(problem_id)
    doc = catalog.document(record)
    release = solution_release(doc, loaded.work, solution_within(loaded))
    values: dict[str, Any] = {
        "problem_id": problem_id,
        "doc": doc,
        "release": release,
        "student": student,
        "assignment": loaded.assignment,  # a course's student: the page leads back to their courses
    }
    if not release.released:
        return values
    frozen_at = next((w.frozen_at for w in loaded.work.parts.values() if w.frozen_at), None)
    if frozen_at is None and (still_open := _still_to_earn(loaded)):
        return {**values, "confirm": still_open}
    if frozen_at is None and loaded.opened.course is not None:
        # Read with nothing at stake (past the due date, out of attempts) it is still read: an
        # extension later must not let its answers earn credit, so every opening is recorded.
        frozen_at = request.app.state.lti.stores.courses.open_solution(student, problem_id, loaded.now)
    if frozen_at is not None and loaded.opened.course is not None:
        values["opened_at"] = shown(frozen_at, loaded.opened.course.timezone)
    variant = catalog.variant(record, student)
    try:
        forces = catalog.free_body_figures(problem_id, student)
    except Exception:  # an illustration: the solution is complete without it
        forces = ()
    return {
        **values,
        "statement": fill_statement(doc.statement, doc, variant),
        "described": describe(catalog.compiled(record), variant),
        "figure": loaded.figure,
        "forces": forces,
    }


def _still_to_earn(loaded: Loaded) -> list[int]:
    """The numbers of the parts opening the solution would freeze: within an assignment that still
    takes answers, those neither earned in full nor out of attempts (nothing is lost on the others; a
    part solved late had been taken as earned, and was frozen without a word)."""
    if solution_within(loaded) is None or not loaded.opened.accepting:
        return []
    return [
        index + 1
        for index, work in enumerate(loaded.work.parts.values())
        if not (work.earned_in_full or work.locked)
    ]


@router.post("/p/{problem_id}/solution", include_in_schema=False)
async def open_solution(problem_id: str, request: Request, context: LtiContextDep) -> Response:
    """The student chose to read the worked solution: their grade on its parts is frozen from now."""
    if _cross_site(request):
        return _refused_cross_site(request)
    caller = await _caller(request, context, allow_key=False)
    form = await request.form(max_files=0, max_fields=10)
    sent = str(form.get("csrf") or "")
    if caller is None or not caller.csrf_token:
        return _refused(401, "Sign in again to open the worked solution.")
    if not hmac.compare_digest(sent.encode(), caller.csrf_token.encode()):
        return _refused(403, "This page is out of date: reload it and try again.")

    def record() -> bool:
        values = solution_context(request, problem_id, caller.student)
        if values is None:
            return False
        if values.get("confirm"):  # else recorded as it was shown, or not released: nothing to keep
            context.stores.courses.open_solution(caller.student, problem_id, context.clock())
        return True

    if not _PROBLEM_ID.match(problem_id) or not await run_in_threadpool(record):
        return _not_found(request, await _ancestors(context))
    course = requested_course(request)
    query = "" if course is None else f"?course={course}"
    return RedirectResponse(f"/p/{problem_id}/solution{query}", status_code=303)


@router.get("/p/{problem_id}/solution", include_in_schema=False)
async def solution_page(problem_id: str, request: Request, context: LtiContextDep) -> Response:
    ancestors = await _ancestors(context)
    if not _PROBLEM_ID.match(problem_id):
        return _not_found(request, ancestors)
    caller = await _caller(request, context, allow_key=False)
    shell = {
        "problem_id": problem_id,
        "scripts": [SCRIPT],
        "title": "Worked solution",
        "content_url": f"/p/{problem_id}/solution/content",
    }
    if caller is None:
        return page(request, "solution/student.html", {**shell, "mode": "key"}, frame_ancestors=ancestors)
    values = await run_in_threadpool(solution_context, request, problem_id, caller.student)
    if values is None:
        return _not_found(request, ancestors)
    return page(
        request,
        "solution/student.html",
        {
            **shell,
            **values,
            "mode": "session",
            "title": f"Worked solution: {values['doc'].title}",
            "csrf": caller.csrf_token,
        },
        frame_ancestors=ancestors,
    )


@router.get("/p/{problem_id}/solution/content", include_in_schema=False)
async def solution_content(problem_id: str, request: Request, context: LtiContextDep) -> Response:
    caller = await _fragment_caller(request, context)
    if isinstance(caller, Response):
        return caller
    if not _PROBLEM_ID.match(problem_id):
        return _refused(404, "not found")
    values = await run_in_threadpool(solution_context, request, problem_id, caller.student)
    if values is None:
        return _refused(404, "not found")
    response: HTMLResponse = templates.TemplateResponse(
        request, "solution/content.html", values, headers=_FRAGMENT_HEADERS
    )
    return response
