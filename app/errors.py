"""Every error the service reports, and the one place they become HTTP responses.

    AppError                       carries status, code, message, details
     ├── Unauthenticated   401    no key, unknown or revoked key
     ├── Forbidden         403    the key's role may not do this
     │    └── InstructorsOnly     a course's TA asking what only its instructors may do (courses/access.py)
     ├── NotFound          404    unknown problem, part or submission (or not yours)
     ├── Conflict          409    e.g. no attempts left
     ├── PayloadTooLarge   413
     ├── CourseRequired    422    a browser in several courses calls the API naming none (`?course=`)
     ├── RateLimited       429    with Retry-After
     ├── GraderFault       500    grading itself failed (a crash, a stored problem that will not grade)
     └── Busy              503    the grading queue is full, with Retry-After
          └── Unavailable  503    grading or the database is down for now; retry after Retry-After

Domain errors from the core (`physics.errors.SpecError`) and from storage are mapped here too; an
answer that cannot be read is never an error: it is an `invalid` verdict with status 200.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping, Sequence
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from sqlalchemy.exc import DataError, InterfaceError, OperationalError
from sqlalchemy.exc import TimeoutError as PoolTimeout
from starlette.exceptions import HTTPException as StarletteHTTPException

from app.allowed_methods import allowed_methods
from app.db import errors as storage
from physics.errors import DerivationError, SpecError
from physics.wording import counted
from problems.errors import ProblemInvalid
from problems.schema import KIND_MESSAGES, format_path

log = logging.getLogger("physcheck.errors")
DATABASE_RETRY_AFTER = 5


class AppError(Exception):
    status = 500
    code = "internal"

    def __init__(
        self, message: str, details: Sequence[dict[str, Any]] = (), headers: dict[str, str] | None = None
    ):
        super().__init__(message)
        self.message = message
        self.details = list(details)
        self.headers = headers or {}


class Unauthenticated(AppError):
    status, code = 401, "unauthenticated"


class Forbidden(AppError):
    status, code = 403, "forbidden"


class NotFound(AppError):
    status, code = 404, "not_found"


class Conflict(AppError):
    status, code = 409, "conflict"


class CourseRequired(AppError):
    status, code = 422, "course_required"


class PayloadTooLarge(AppError):
    status, code = 413, "payload_too_large"


class RateLimited(AppError):
    status, code = 429, "rate_limited"

    def __init__(self, message: str, retry_after: int):
        super().__init__(message, headers={"Retry-After": str(retry_after)})


class Busy(AppError):
    status, code = 503, "busy"

    def __init__(self, message: str, retry_after: int = 1):
        super().__init__(message, headers={"Retry-After": str(retry_after)})


class Unavailable(Busy):
    code = "unavailable"


class GraderFault(AppError):
    """Grading failed for a reason that is not the answer's: logged where it happened; nothing stored."""

    code = "grader_fault"


def error_body(code: str, message: str, details: Sequence[dict[str, Any]] = ()) -> dict[str, Any]:
    return {"error": {"code": code, "message": message, "details": list(details)}}


def _json(
    status: int,
    code: str,
    message: str,
    details: Sequence[dict[str, Any]] = (),
    headers: dict[str, str] | None = None,
) -> JSONResponse:
    return JSONResponse(error_body(code, message, details), status_code=status, headers=headers)


_HTTP_CODES = {
    400: "bad_request",
    401: "unauthenticated",
    403: "forbidden",
    404: "not_found",
    405: "method_not_allowed",
    413: "payload_too_large",
    415: "unsupported_media_type",
    422: "malformed_request",
    429: "rate_limited",
}


_STORAGE_ERRORS: dict[type[storage.StorageError], tuple[int, str]] = {
    storage.AttemptsExhausted: (409, "attempts_exhausted"),
    storage.ProblemExists: (409, "problem_exists"),
    storage.NotFound: (404, "not_found"),
    storage.InvalidPage: (422, "malformed_request"),
}


def unreadable_body_message(cause: BaseException) -> str:
    if isinstance(cause, UnicodeDecodeError):
        return f"The body is not UTF-8 text (byte {cause.start})."
    if isinstance(cause, RecursionError):
        return "The JSON body is nested too deeply."
    if isinstance(cause, ValueError) and "digits" in str(cause):
        return "A number in the JSON body has too many digits."
    return "The body is not readable JSON."


def _message(msg: str) -> str:
    # A field's own validator says what it must be ("must be a finite number"), as in problem uploads.
    return msg.removeprefix("Value error, ")


def _detail(error: Mapping[str, Any]) -> dict[str, str]:
    """A validation error as the API says it; a check's `kind` missing or unknown as an upload's part's
    is (pydantic's "Unable to extract tag using discriminator" names no field a caller wrote)."""
    loc = tuple(error.get("loc", ()))
    kind = KIND_MESSAGES.get(str(error.get("type")))
    if kind is not None:
        return {"path": _path((*loc, "kind")), "message": kind}
    return {"path": _path(loc), "message": _message(error.get("msg", "invalid"))}


def _path(loc: Sequence[Any]) -> str:
    parts = [str(p) for p in loc if p not in ("body",)]
    return ".".join(parts)


def install_error_handlers(app: FastAPI) -> None:
    @app.exception_handler(AppError)
    async def app_error(request: Request, error: AppError) -> JSONResponse:
        return _json(error.status, error.code, error.message, error.details, error.headers)

    @app.exception_handler(ProblemInvalid)
    async def problem_invalid(request: Request, error: ProblemInvalid) -> JSONResponse:
        details = [{"path": path, "message": message} for path, message in error.errors]
        count = len(details)
        return _json(
            422, "invalid_problem", f"The problem has {counted(count, 'error')}: see details.", details
        )

    @app.exception_handler(SpecError)
    async def spec_error(request: Request, error: SpecError) -> JSONResponse:
        details = [{"path": ".".join(str(p) for p in error.path), "message": error.message}]
        return _json(422, "invalid_reference", error.message, details)

    @app.exception_handler(DerivationError)
    async def derivation_error(request: Request, error: DerivationError) -> JSONResponse:
        details = [
            {"path": format_path(("model", *path)), "message": message} for path, message in error.items()
        ]
        return _json(422, "derivation_failed", error.message, details)

    @app.exception_handler(storage.StorageError)
    async def storage_error(request: Request, error: storage.StorageError) -> JSONResponse:
        status, code = next(
            (_STORAGE_ERRORS[k] for k in type(error).__mro__ if k in _STORAGE_ERRORS), (500, "internal")
        )
        if status == 500:
            log.error("unmapped storage error: %r", error)
        return _json(status, code, str(error))

    async def refused_caller(request: Request) -> JSONResponse | None:
        # Imported here: the check needs the dependencies, which raise the errors defined above.
        from app.auth_first import caller_refusal

        refusal = await caller_refusal(request)
        return None if refusal is None else await app_error(request, refusal)

    @app.exception_handler(RequestValidationError)
    async def malformed(request: Request, error: RequestValidationError) -> JSONResponse:
        if any(e.get("type") == "json_invalid" for e in error.errors()):
            # The body was read before the caller was known: the caller first (app/auth_first.py).
            refused = await refused_caller(request)
            if refused is not None:
                return refused
        details = [_detail(e) for e in error.errors()]
        return _json(422, "malformed_request", "The request is malformed: see details.", details)

    @app.exception_handler(StarletteHTTPException)
    async def http_error(request: Request, error: StarletteHTTPException) -> JSONResponse:
        if error.status_code == 400 and error.__cause__ is not None:
            # FastAPI answers 400 when decoding the JSON body raised anything but JSONDecodeError;
            # the contract calls every unreadable body a malformed request, once the caller may call.
            refused = await refused_caller(request)
            if refused is not None:
                return refused
            return _json(422, "malformed_request", unreadable_body_message(error.__cause__))
        code = _HTTP_CODES.get(error.status_code, "error")
        headers = getattr(error, "headers", None)
        if error.status_code == 405:
            allowed = allowed_methods(request.app, request.url.path)
            headers = headers if allowed is None else {**(headers or {}), "Allow": allowed}
        return _json(error.status_code, code, str(error.detail), headers=headers)

    @app.exception_handler(DataError)
    async def unstorable(request: Request, error: DataError) -> JSONResponse:
        # The last line of defence; the schemas refuse NUL and lone surrogates before this.
        log.warning("database refused a value: %s", type(error.orig).__name__)
        return _json(422, "malformed_request", "A value in the request cannot be stored.")

    async def database_unavailable(request: Request, error: Exception) -> JSONResponse:
        # Unreachable, restarting, or (SQLite) locked past the busy timeout: a retry will do, so this is
        # a 503 with Retry-After, answered on the same keep-alive connection; the pool reconnects by itself.
        first_line = str(getattr(error, "orig", None) or error).splitlines()[0] if str(error) else ""
        log.warning("database unavailable: %s: %s", type(error).__name__, first_line)
        return _json(
            503,
            "unavailable",
            "The database is not reachable just now; try again shortly.",
            headers={"Retry-After": str(DATABASE_RETRY_AFTER)},
        )

    for unavailable in (OperationalError, InterfaceError, PoolTimeout):
        app.add_exception_handler(unavailable, database_unavailable)

    @app.exception_handler(Exception)
    async def fault(request: Request, error: Exception) -> JSONResponse:
        request_id = getattr(request.state, "request_id", None)
        log.exception("unhandled error", extra={"request_id": request_id})
        return _json(500, "internal", f"Internal error (request {request_id}); it has been logged.")
