"""ASGI middleware: request ids with one structured log line per request, and the body size cap."""

from __future__ import annotations

import itertools
import json
import logging
import os
import re
import time

from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.errors import error_body

log = logging.getLogger("physcheck.http")
_SAFE_REQUEST_ID = re.compile(r"^[A-Za-z0-9._-]{1,64}$")


class BodyTooLarge(Exception):
    pass


class RequestContext:
    """One pass over each request: tags it with an id (the client's X-Request-ID when sane), refuses a
    body over `max_bytes` with 413 (by declared length or by counting a streamed body), and logs its
    outcome in one line. One layer rather than two: every layer wraps `send` and `receive` again.

    A chunked body (no Content-Length) is read whole here before the app sees it: FastAPI turns any
    error raised while it reads the body into 400, so the cap must be enforced before that."""

    def __init__(self, app: ASGIApp, max_bytes: int):
        self.app = app
        self.max_bytes = max_bytes
        # Ids need only be unique, not secret: a random per-process prefix and a counter, rather than
        # a system call for fresh randomness on every request.
        self._id_prefix = os.urandom(8).hex()
        self._ids = itertools.count()

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        if "\x00" in scope["path"] or b"%00" in scope["query_string"].lower():
            # No id, problem or student contains NUL, and databases refuse it: answer 422, not 500.
            await _send_error(send, 422, "malformed_request", "The address contains a NUL character.")
            return
        headers = dict(scope["headers"])
        given = headers.get(b"x-request-id", b"").decode("latin-1")
        request_id = given if _SAFE_REQUEST_ID.match(given) else f"{self._id_prefix}{next(self._ids):016x}"
        scope.setdefault("state", {})["request_id"] = request_id
        id_header = (b"x-request-id", request_id.encode())
        started_at = time.perf_counter()
        status = 500
        started = False
        seen = 0

        async def send_with_id(message: Message) -> None:
            nonlocal status, started
            if message["type"] == "http.response.start":
                status = message["status"]
                started = True
                message.setdefault("headers", []).append(id_header)
            await send(message)

        async def counting_receive() -> Message:
            nonlocal seen
            message = await receive()
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > self.max_bytes:
                    raise BodyTooLarge
            return message

        try:
            declared = headers.get(b"content-length")
            if declared is not None and (not declared.isdigit() or int(declared) > self.max_bytes):
                await self._refuse(send_with_id)
                return
            if declared is None and b"transfer-encoding" in headers:
                buffered = await self._read_whole(receive)
                if buffered is None:
                    await self._refuse(send_with_id)
                    return
                receive = replay(buffered, receive)
            try:
                await self.app(scope, counting_receive, send_with_id)
            except BodyTooLarge:
                if not started:
                    await self._refuse(send_with_id)
        finally:
            if log.isEnabledFor(logging.INFO):
                # Straight to the handlers: Logger.info would also walk the stack for the caller's line.
                fields = {
                    "request_id": request_id,
                    "method": scope["method"],
                    "path": scope["path"],
                    "status": status,
                    "ms": round((time.perf_counter() - started_at) * 1000, 2),
                }
                log.handle(
                    log.makeRecord(log.name, logging.INFO, __file__, 0, "request", (), None, extra=fields)
                )

    async def _read_whole(self, receive: Receive) -> Message | None:
        """The body as one message, or None once it passes the cap (the rest is never read)."""
        parts: list[bytes] = []
        seen = 0
        while True:
            message = await receive()
            if message["type"] != "http.request":
                return message  # the client went away: the app sees the disconnect
            body = message.get("body", b"")
            seen += len(body)
            if seen > self.max_bytes:
                return None
            parts.append(body)
            if not message.get("more_body", False):
                return {"type": "http.request", "body": b"".join(parts), "more_body": False}

    async def _refuse(self, send: Send) -> None:
        await _send_error(send, 413, "payload_too_large", f"The request body is over {self.max_bytes} bytes.")


def replay(first: Message, receive: Receive) -> Receive:
    pending = [first]

    async def replaying_receive() -> Message:
        return pending.pop() if pending else await receive()

    return replaying_receive


async def _send_error(send: Send, status: int, code: str, message: str) -> None:
    body = json.dumps(error_body(code, message)).encode()
    headers = [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode())]
    await send({"type": "http.response.start", "status": status, "headers": headers})
    await send({"type": "http.response.body", "body": body})
