"""`POST /v1/check` answered without FastAPI's per-request machinery when nothing about it is unusual.

The route (app/routers/check.py) defines the endpoint: it is documented, and it answers every request
this layer passes on. This layer answers only the common case, with the same parts the route uses: a
JSON body that validates as a CheckIn, an active bearer key (found in memory, or else looked up in the
thread pool as the route would), and rate limits counted in memory. Anything else (no key, an unknown
or revoked key, a session, a malformed body, a shared rate limit) goes on to the app with the body
replayed, untouched by this layer, so every refusal is made in one place; a fault while grading is
answered by the app's own exception handlers.

Why it exists: routing, dependency solving and the exception layers cost the server more CPU per check
than the check costs its worker, and the server's one event loop serves every request (bench/targets.py).
"""

from __future__ import annotations

import hashlib
import inspect
import json
from collections import OrderedDict
from typing import Any

from fastapi import FastAPI
from pydantic import TypeAdapter, ValidationError
from starlette.requests import Request
from starlette.responses import Response
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.auth import Principal, bearer_token
from app.deps import counted_in_memory, key_principal, spend_budget
from app.middleware import replay
from app.schemas.check import CheckIn
from app.services import Services
from physics.checking import CheckJob

CHECK_PATH = "/v1/check"
_CHECK_IN: TypeAdapter[Any] = TypeAdapter(CheckIn)
_JSON_HEADERS = [(b"content-type", b"application/json")]
# A body sent again (a script re-checking, a class typing the same answer) skips reading, validating and
# building its job: the job is a function of the body alone. Small bodies only, so the memory is bounded.
REMEMBERED_BODIES = 1024
REMEMBERED_BODY_BYTES = 4096


class CheckFastPath:
    def __init__(self, app: ASGIApp, application: FastAPI):
        self.app = app  # everything else: FastAPI's own stack
        self.application = application  # its state (the services) and exception handlers
        self._jobs: OrderedDict[bytes, tuple[CheckJob, str]] = OrderedDict()  # body -> job, its cache key

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or scope["path"] != CHECK_PATH or scope["method"] != "POST":
            await self.app(scope, receive, send)
            return
        services: Services | None = getattr(self.application.state, "services", None)
        principal = None if services is None else await _known_caller(services, scope)
        if principal is None:
            await self.app(scope, receive, send)
            return
        assert services is not None
        message = await _whole_body(receive)
        content: bytes = message.get("body", b"")
        known = self._jobs.get(content) if message["type"] == "http.request" else None
        check_in = None if known is not None else _valid_body(message)
        if known is None and check_in is None:
            await self.app(scope, replay(message, receive), send)
            return
        try:
            spend_budget(services, principal)
            if known is None:
                assert check_in is not None
                known = self._remember(content, check_in.job())
            else:
                self._jobs.move_to_end(content)
            job, key = known
            verdict = await services.pool.check(job, principal.grading_share, key=key)
        except Exception as error:
            await self._handled(error, scope, receive, send)
            return
        body = services.verdict_json(verdict)
        headers = [*_JSON_HEADERS, (b"content-length", str(len(body)).encode())]
        await send({"type": "http.response.start", "status": 200, "headers": headers})
        await send({"type": "http.response.body", "body": body})

    def _remember(self, content: bytes, job: CheckJob) -> tuple[CheckJob, str]:
        # The body's digest names its verdict (the job is a function of the body), at a twentieth of
        # the CPU of the job's repr; "body:" keeps it apart from every repr key of the verdict cache.
        known = (job, "body:" + hashlib.blake2b(content, digest_size=16).hexdigest())
        if len(content) <= REMEMBERED_BODY_BYTES:
            self._jobs[content] = known
            if len(self._jobs) > REMEMBERED_BODIES:
                self._jobs.popitem(last=False)
        return known

    async def _handled(self, error: Exception, scope: Scope, receive: Receive, send: Send) -> None:
        """The response the app's exception handler for `error` gives (the route's would be the same)."""
        handlers = self.application.exception_handlers
        handler = next(handlers[kind] for kind in type(error).__mro__ if kind in handlers)
        response = handler(Request(scope, receive), error)
        if inspect.isawaitable(response):
            response = await response
        assert isinstance(response, Response)
        await response(scope, receive, send)


async def _known_caller(services: Services, scope: Scope) -> Principal | None:
    """The caller when its key is active and it is counted in memory; else None (the app decides).

    A key is remembered for only a few seconds, so every connection of a busy client misses at once
    when it expires: looked up here, those requests stay on this path instead of costing FastAPI's
    whole stack each (about nine times this path's CPU). A lookup that fails for any reason (a
    revoked key, the database down) leaves the request to the app, which looks again and refuses."""
    if not counted_in_memory(services):
        return None
    authorization = content_type = None
    for name, value in scope["headers"]:
        if name == b"authorization":
            authorization = value
        elif name == b"content-type":
            content_type = value
    if authorization is None or content_type is None:
        return None
    if content_type.split(b";", 1)[0].strip().lower() != b"application/json":
        return None
    token = bearer_token(authorization.decode("latin-1"))
    if token is None:
        return None
    try:
        return await key_principal(services, token)
    except Exception:
        return None


async def _whole_body(receive: Receive) -> Message:
    """The request body as one message (the body cap is counted by RequestContext's receive), or the
    first message that is not body, such as a disconnect."""
    message = await receive()
    if message["type"] != "http.request" or not message.get("more_body", False):
        return message
    parts = [message.get("body", b"")]
    while message.get("more_body", False):
        message = await receive()
        if message["type"] != "http.request":
            return message
        parts.append(message.get("body", b""))
    return {"type": "http.request", "body": b"".join(parts), "more_body": False}


def _valid_body(message: Message) -> Any:
    """The CheckIn the body validates as, read as FastAPI reads it; None for anything else."""
    if message["type"] != "http.request":
        return None
    try:
        return _CHECK_IN.validate_python(json.loads(message.get("body", b"")))
    except (ValueError, ValidationError, RecursionError):  # JSONDecodeError and UnicodeDecodeError too
        return None
