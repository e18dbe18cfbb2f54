"""The LTI routes. State lives in one `LtiContext` reached through `get_lti_context` (reads
`request.app.state.lti`; override the dependency to supply it another way).

    GET|POST /lti/login            OIDC login initiation (third-party initiated login)
    POST     /lti/launch           the platform's form post with id_token and state
    POST     /lti/deep-link/{id}   the instructor's choice -> signed response, auto-posted back
    GET      /lti/jwks             our public keys (also /.well-known/jwks.json)
    GET      /p/{problem_id}       the student page and /problems (app.web.student_page), with fragments
"""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from typing import Any
from urllib.parse import quote

from fastapi import APIRouter, Request
from fastapi.responses import JSONResponse, RedirectResponse, Response
from starlette.concurrency import run_in_threadpool

from app.auth import Role
from app.lti.context import LtiContext, LtiContextDep
from app.lti.errors import LaunchRefused, MalformedRequest, PlatformKeysUnavailable
from app.lti.flow import (
    BROWSER_COOKIE,
    LOGIN_LIFETIME,
    assignment_choices,
    begin_login,
    complete_launch,
    finish_deep_link,
    problem_choices,
)
from app.lti.pages import ProblemChoice, auto_post_page, picker_page, refusal_page, unavailable_page
from app.lti.platforms import platform_origins
from app.lti.sessions import SESSION_COOKIE, SESSION_LIFETIME
from app.web import student_page

router = APIRouter(tags=["lti"])
router.include_router(student_page.router)
Context = LtiContextDep
_MAX_FORM_FIELDS = 50


def set_cross_site_cookie(response: Response, name: str, value: str, max_age: int) -> None:
    """A cookie that reaches us inside an LMS iframe: cross-site (None), HTTPS only, partitioned per
    top-level site (CHIPS), hidden from scripts. Written by hand: the standard library only learns the
    Partitioned attribute in Python 3.14. Values are ours (URL-safe base64), so nothing needs quoting."""
    response.headers.append(
        "set-cookie",
        f"{name}={value}; Max-Age={max_age}; Path=/; Secure; HttpOnly; SameSite=None; Partitioned",
    )


async def _frame_ancestors(context: LtiContext) -> list[str]:
    return await run_in_threadpool(platform_origins, context.stores.platforms)


async def _refusing(context: LtiContext, action: Callable[[], Awaitable[Response]]) -> Response:
    """Run the action; a refusal becomes a plain page with its status, never a stack trace."""
    try:
        return await action()
    except LaunchRefused as error:
        return refusal_page(error, frame_ancestors=await _frame_ancestors(context))
    except PlatformKeysUnavailable:
        return unavailable_page("The LMS's signing keys could not be fetched; try again in a moment.")


async def _params(request: Request, *, query: bool = True) -> dict[str, str]:
    """Query (unless `query` is false) and, for POST, form fields as plain strings; file fields are
    refused, and of a repeated field the last counts."""
    items: list[tuple[str, Any]] = list(request.query_params.multi_items()) if query else []
    if request.method == "POST":
        form = await request.form(max_files=0, max_fields=_MAX_FORM_FIELDS)
        items += list(form.multi_items())
    params: dict[str, str] = {}
    for name, value in items:
        if not isinstance(value, str):
            raise MalformedRequest("bad_field", f"The field '{name[:40]}' is not text.")
        params[name] = value
    return params


@router.api_route("/lti/login", methods=["GET", "POST"], include_in_schema=False)
async def login(request: Request, context: Context) -> Response:
    async def action() -> Response:
        params = await _params(request)
        redirect = await begin_login(context, params, request.cookies.get(BROWSER_COOKIE))
        response = RedirectResponse(redirect.url, status_code=302)
        set_cross_site_cookie(
            response, BROWSER_COOKIE, redirect.browser_token, int(LOGIN_LIFETIME.total_seconds())
        )
        response.headers["Cache-Control"] = "no-store"
        return response

    return await _refusing(context, action)


@router.post("/lti/launch", include_in_schema=False)
async def launch(request: Request, context: Context) -> Response:
    async def action() -> Response:
        # Only the form post: an id_token or state in the URL would end up in logs and Referer headers.
        form = await _params(request, query=False)
        outcome = await complete_launch(context, form, request.cookies.get(BROWSER_COOKIE))
        response: Response
        if outcome.deep_link_id is not None:
            response = picker_page(
                outcome.deep_link_id,
                outcome.session.csrf_token,
                await run_in_threadpool(choices, context, outcome.session.student),
                frame_ancestors=await _frame_ancestors(context),
                multiple=outcome.claims.deep_link_accept_multiple,
            )
        elif outcome.assignment is not None:
            course_id, assignment_id = outcome.assignment
            target = (
                f"/instructor/courses/{course_id}/gradebook"
                if outcome.session.role is Role.INSTRUCTOR
                else f"/courses/{course_id}/assignments/{assignment_id}"
            )
            response = RedirectResponse(target, status_code=303)
        else:
            assert outcome.problem_id is not None
            response = RedirectResponse(f"/p/{quote(outcome.problem_id, safe='')}", status_code=303)
        set_cross_site_cookie(
            response, SESSION_COOKIE, outcome.session_id, int(SESSION_LIFETIME.total_seconds())
        )
        return response

    return await _refusing(context, action)


def choices(context: LtiContext, member: str) -> list[ProblemChoice]:
    """The course's assignments first (one link and one grade each), then every problem."""
    return [*assignment_choices(context.stores, member), *problem_choices(context.stores.problems)]


@router.post("/lti/deep-link/{request_id}", include_in_schema=False)
async def deep_link_return(request_id: str, request: Request, context: Context) -> Response:
    async def action() -> Response:
        form = await request.form(max_files=0, max_fields=_MAX_FORM_FIELDS)
        csrf = form.get("csrf_token")
        chosen = [value for value in form.getlist("problem") if isinstance(value, str)]
        if not isinstance(csrf, str):
            raise MalformedRequest("missing_csrf_token", "The form lacks its CSRF token.")
        return_url, token = await run_in_threadpool(finish_deep_link, context, request_id, csrf, chosen)
        return auto_post_page(return_url, {"JWT": token}, frame_ancestors=await _frame_ancestors(context))

    return await _refusing(context, action)


@router.get("/lti/jwks", include_in_schema=False)
@router.get("/.well-known/jwks.json", include_in_schema=False)
async def jwks(context: Context) -> JSONResponse:
    document = await run_in_threadpool(context.stores.tool_keys.public_jwks)
    return JSONResponse(document, headers={"Cache-Control": "public, max-age=300"})
