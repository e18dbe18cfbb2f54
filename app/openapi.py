"""What the OpenAPI document says beyond the routes: the error body every failure shares, the bearer
scheme (so /docs "Try it out" sends the key), the error statuses each endpoint can answer, and /docs
itself, served from Swagger UI files packaged with fastapi-offline (no CDN: it works offline).

`tests/api/test_openapi_responses.py` provokes every status documented here and validates the body
against the published schema, so a status documented but never answered (or answered in another
shape) fails there.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import fastapi_offline
from fastapi import FastAPI
from fastapi.openapi.docs import get_swagger_ui_html
from fastapi.responses import HTMLResponse
from fastapi.security import HTTPBearer
from fastapi.staticfiles import StaticFiles
from pydantic import BaseModel, Field

SWAGGER_UI_FILES = Path(fastapi_offline.__file__).resolve().parent / "static"
DOCS_ASSETS = "/docs/assets"

# Documentation only: `app.deps.current_principal` reads the header itself, so that a malformed one is
# a 401 rather than a silent fall-back to the LMS session cookie.
bearer_scheme = HTTPBearer(
    scheme_name="bearer",
    description="An API key from `physcheck keys create`, sent as `Authorization: Bearer <key>`.",
    auto_error=False,
)


class ErrorInfo(BaseModel):
    code: str = Field(description="Stable and machine-readable, e.g. `not_found`, `rate_limited`.")
    message: str = Field(description="For people.")
    details: list[dict[str, Any]] = Field(description="E.g. `{path, message}` for each malformed field.")


class ErrorBody(BaseModel):
    """The shape of every answer that is not a success or a grading verdict."""

    error: ErrorInfo


class Ready(BaseModel):
    status: str = Field(examples=["ready"])


_WHY = {
    401: "No API key (or LMS session), or an unknown or revoked key.",
    403: "The key's role (or an LMS session's scope) does not allow this.",
    404: "Unknown (or retired) problem or part, or not one of yours.",
    409: "Conflict: no attempts left on this part, or a problem with this id exists.",
    413: "The request body is over the size limit.",
    415: "The body is neither JSON nor YAML.",
    422: "The request is malformed (unreadable JSON, a missing or invalid field or parameter).",
    429: "Rate limited: over the key's or the student's budget; wait `Retry-After` seconds.",
    503: "Temporarily unavailable (grading queue full, grader restarting, database unreachable); "
    "retry after `Retry-After` seconds.",
}
_RETRY_AFTER = {"Retry-After": {"description": "Seconds to wait.", "schema": {"type": "integer"}}}


def errors(*statuses: int) -> dict[int | str, dict[str, Any]]:
    """`responses=` entries for these statuses, in the error shape."""
    return {
        status: {"model": ErrorBody, "description": _WHY[status]}
        | ({"headers": _RETRY_AFTER} if status in (429, 503) else {})
        for status in statuses
    }


# What every route that takes a key can answer.
AUTHENTICATED = errors(401, 429, 503)


def install_docs(app: FastAPI) -> None:
    """/docs from the packaged Swagger UI (FastAPI's self-hosting recipe); the app is built with
    `docs_url=None, redoc_url=None` (ReDoc would load fonts from elsewhere)."""
    app.mount(DOCS_ASSETS, StaticFiles(directory=SWAGGER_UI_FILES), name="docs-assets")
    openapi_url = app.openapi_url or "/openapi.json"

    @app.get("/docs", include_in_schema=False)
    async def docs() -> HTMLResponse:
        return get_swagger_ui_html(
            openapi_url=openapi_url,
            title=f"{app.title}: API",
            swagger_js_url=f"{DOCS_ASSETS}/swagger-ui-bundle.js",
            swagger_css_url=f"{DOCS_ASSETS}/swagger-ui.css",
            swagger_favicon_url=f"{DOCS_ASSETS}/favicon.png",
            oauth2_redirect_url=None,
            # No online validator badge; keep the key across reloads of the page.
            swagger_ui_parameters={"validatorUrl": None, "persistAuthorization": True},
        )
