"""The student page `/p/{problem_id}`: statement (MathML made here), one answer box per part with a
live preview, verdicts and attempts. After a launch the session cookie identifies the student; outside
an LMS the page asks for a student key, kept in the tab's sessionStorage and sent as a bearer token.
On load the script restores each part's last answer, its verdict and the attempts used, from
`GET /v1/submissions` (the student view has no attempt limits, so "N of M" only once a submission says M).

What it needs from the app, through `LtiContext`: `student_view(problem_id, student)` (the API's
student view: title, statement, parts) and, for the key mode, `authenticate_key(key)`.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Mapping, Sequence
from html import escape
from pathlib import Path
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response
from starlette.concurrency import run_in_threadpool

from app.auth import bearer_token
from app.lti.context import LtiContext, LtiContextDep
from app.lti.mathml import inline_html, text_to_html
from app.lti.pages import html_page
from app.lti.platforms import platform_origins
from app.lti.sessions import current_session

router = APIRouter(tags=["student page"])
STATIC = Path(__file__).resolve().parent / "static"
SCRIPT_PATH = "/lti/static/student.js"
_PROBLEM_ID = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]{0,99}$")


def _hidden(text: str) -> str:
    """Words for screen readers only: three parts' boxes and buttons must not all sound alike."""
    return f'<span class="visually-hidden">{escape(text)}</span>'


def _limit_attribute(part: Mapping[str, Any]) -> str:
    """`data-max-attempts` when the view states the part's limit (today's student view does not)."""
    limit = part.get("max_attempts")
    if isinstance(limit, int) and not isinstance(limit, bool) and limit > 0:
        return f' data-max-attempts="{limit}"'
    return ""


def render_content(view: Mapping[str, Any], *, student: str | None = None) -> str:
    """The problem as HTML: every value from the view is escaped, math becomes MathML.

    `student` (whose work the page submits) goes on each answer form so that the script asks the API
    for that student's earlier submissions only: an instructor's key sees everyone's otherwise."""
    owner = f' data-student="{escape(student)}"' if student else ""
    parts_html = []
    for index, part in enumerate(view.get("parts", [])):
        part_id = str(part.get("id", ""))
        units = part.get("units")
        symbols: Sequence[str] = part.get("symbols") or []
        if units:
            hint = f"Give a number with units, e.g. in {units}."
        elif symbols:
            hint = "Answer in terms of: " + ", ".join(symbols) + "."
        else:
            hint = ""
        parts_html.append(
            f'<section class="part" aria-labelledby="part-{index}-heading">'
            f'<h2 id="part-{index}-heading">Part {index + 1}</h2>'
            f"<p>{inline_html(str(part.get('prompt', '')))}</p>"
            f'<form class="answer" data-part="{escape(part_id)}"{owner}{_limit_attribute(part)} novalidate>'
            f'<label for="answer-{index}">Your answer{_hidden(f" to part {index + 1}")}</label>'
            f'<input id="answer-{index}" name="answer" type="text" autocomplete="off" autocapitalize="off" '
            f'spellcheck="false" maxlength="2000" aria-describedby="hint-{index} preview-{index}">'
            f'<p id="hint-{index}" class="hint">{escape(hint)}</p>'
            f'<p id="preview-{index}" class="preview" aria-live="polite"></p>'
            f'<button type="submit">Check answer{_hidden(f" to part {index + 1}")}</button>'
            '<p class="verdict" role="status" aria-live="polite"></p>'
            # Not a live region: the earlier work the script restores on load is there to be read, not
            # announced; the live verdict above speaks only for submissions made on this page.
            '<p class="earlier" hidden></p>'
            "</form></section>"
        )
    return (
        f"<h1>{escape(str(view.get('title', '')))}</h1>"
        f'<section aria-label="Statement">{text_to_html(str(view.get("statement", "")))}</section>'
        + "".join(parts_html)
    )


def _shell(problem_id: str, mode: str, content: str) -> str:
    key_form = ""
    if mode == "key":
        key_form = (
            '<form id="key-form"><h1>Open this problem</h1>'
            '<label for="key">Your student key</label>'
            '<input id="key" type="password" autocomplete="off" required autofocus aria-describedby="key-hint">'
            '<p id="key-hint" class="hint">The key your instructor gave you; it is kept in this tab only.</p>'
            '<p><button type="submit">Open</button></p><p id="key-error" role="alert"></p></form>'
        )
    return (
        f'<div id="problem" data-problem="{escape(problem_id)}" data-mode="{mode}">'
        f'{key_form}<div id="content">{content}</div></div>'
    )


async def _ancestors(context: LtiContext) -> list[str]:
    def load() -> list[str]:
        with context.database.session(read_only=True) as session:
            return platform_origins(session)

    return await run_in_threadpool(load)


def _not_found(frame_ancestors: Sequence[str]) -> HTMLResponse:
    body = '<h1>No such problem</h1><p role="alert">Check the link, or ask your instructor.</p>'
    return html_page("No such problem", body, status=404, frame_ancestors=frame_ancestors)


def _view(context: LtiContext, problem_id: str, student: str) -> Mapping[str, Any] | None:
    if context.student_view is None:
        return None
    try:
        return context.student_view(problem_id, student)
    except LookupError:
        return None


@router.get("/p/{problem_id}", include_in_schema=False)
async def student_page(problem_id: str, request: Request, context: LtiContextDep) -> Response:
    ancestors = await _ancestors(context)
    if not _PROBLEM_ID.match(problem_id):
        return _not_found(ancestors)
    found = await run_in_threadpool(current_session, request)
    if found is None:
        return html_page(
            "physcheck", _shell(problem_id, "key", ""), frame_ancestors=ancestors, script_src=SCRIPT_PATH
        )
    id_hash, record = found
    principal = record.principal(id_hash)
    who = principal.student or f"preview:{principal.key_id}"
    view = await run_in_threadpool(_view, context, problem_id, who)
    if view is None:
        return _not_found(ancestors)
    return html_page(
        str(view.get("title", "physcheck")),
        _shell(problem_id, "session", render_content(view, student=who)),
        frame_ancestors=ancestors,
        script_src=SCRIPT_PATH,
        meta={"csrf-token": record.csrf_token},
    )


@router.get("/p/{problem_id}/content", include_in_schema=False)
async def student_content(problem_id: str, request: Request, context: LtiContextDep) -> Response:
    """The problem's HTML for a student key (the page's key mode fetches it)."""
    token = bearer_token(request.headers.get("authorization"))
    principal = None
    if token is not None and context.authenticate_key is not None:
        principal = await run_in_threadpool(context.authenticate_key, token)
    headers = {"Cache-Control": "no-store", "X-Content-Type-Options": "nosniff"}
    if principal is None:
        return Response("unauthenticated", status_code=401, media_type="text/plain", headers=headers)
    wait = None if context.rate_limit is None else await run_in_threadpool(context.rate_limit, principal)
    if wait is not None:
        headers["Retry-After"] = str(wait)
        return Response(
            f"Too many requests; try again in {wait} s.",
            status_code=429,
            media_type="text/plain",
            headers=headers,
        )
    view = None
    if _PROBLEM_ID.match(problem_id):
        who = principal.student or f"preview:{principal.key_id}"
        view = await run_in_threadpool(_view, context, problem_id, who)
    if view is None:
        return Response("not found", status_code=404, media_type="text/plain", headers=headers)
    return HTMLResponse(render_content(view, student=who), headers=headers)


@functools.cache
def _script() -> bytes:
    return (STATIC / "student.js").read_bytes()


@router.get(SCRIPT_PATH, include_in_schema=False)
async def student_script() -> Response:
    return Response(
        _script(),
        media_type="text/javascript",
        headers={"Cache-Control": "public, max-age=300", "X-Content-Type-Options": "nosniff"},
    )
