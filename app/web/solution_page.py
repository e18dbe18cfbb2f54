"""A problem's worked solution for a student, at a stable link an instructor can post: `/p/{id}/solution`.

Shown only when `solution_release` (app/web/solution_access.py, the one gate) says so; otherwise the
page says when it opens. Like the problem page, an LTI session sees it at once and a student key
fetches it as a fragment (`/p/{id}/solution/content`, bearer key). The content is the instructor's
(app/instructor/described.py and worked.py) for the student's own variant: the answers, the figure and
free-body diagrams, the methods compared and each method's solution, laid out to print on A4 or Letter.
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response
from starlette.concurrency import run_in_threadpool

from app.instructor.described import describe
from app.lti.context import LtiContextDep
from app.web.layout import page, templates
from app.web.solution_access import solution_release
from app.web.student_page import (
    _FRAGMENT_HEADERS,
    _PROBLEM_ID,
    SCRIPT,
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
    loaded = _load(request.app.state.lti, problem_id, student)
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
        {**shell, **values, "mode": "session", "title": f"Worked solution: {values['doc'].title}"},
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
