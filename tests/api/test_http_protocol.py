"""`physcheck serve`'s HTTP protocol sends what one turn of the event loop writes as one write: a
response's head and body leave together, and nothing is held past the turn or lost at a close."""

from __future__ import annotations

import asyncio
import socket
import threading
from collections.abc import Iterator

import httpx
import pytest
import uvicorn
from starlette.types import Receive, Scope, Send

from app.http_protocol import HttpProtocol, _OneWritePerTurn


class FakeTransport:
    def __init__(self) -> None:
        self.writes: list[bytes] = []
        self.closed = False

    def write(self, data: bytes) -> None:
        assert not self.closed, "written after close"
        self.writes.append(data)

    def is_closing(self) -> bool:
        return self.closed

    def close(self) -> None:
        self.closed = True

    def get_extra_info(self, name: str) -> str:
        return f"info:{name}"


def test_writes_in_one_turn_leave_as_one_write_at_its_end() -> None:
    async def scenario() -> list[list[bytes]]:
        transport = FakeTransport()
        wrapped = _OneWritePerTurn(transport, asyncio.get_running_loop())  # type: ignore[arg-type]
        wrapped.write(b"HTTP/1.1 200 OK\r\n\r\n")
        wrapped.write(b"body")
        seen = [list(transport.writes)]  # nothing yet: the turn has not ended
        await asyncio.sleep(0)
        seen.append(list(transport.writes))
        wrapped.write(b"next")
        await asyncio.sleep(0)
        seen.append(list(transport.writes))
        return seen

    during, after, later = asyncio.run(scenario())
    assert during == []
    assert after == [b"HTTP/1.1 200 OK\r\n\r\nbody"]
    assert later == [b"HTTP/1.1 200 OK\r\n\r\nbody", b"next"]


def test_a_close_sends_what_is_held_first_and_nothing_is_written_after() -> None:
    async def scenario() -> FakeTransport:
        transport = FakeTransport()
        wrapped = _OneWritePerTurn(transport, asyncio.get_running_loop())  # type: ignore[arg-type]
        wrapped.write(b"head")
        wrapped.write(b"tail")
        wrapped.close()
        await asyncio.sleep(0)  # the turn's scheduled flush finds nothing held
        wrapped.write(b"late")
        await asyncio.sleep(0)  # ... and a write after the close is dropped, as a closing transport's
        return transport

    transport = asyncio.run(scenario())
    assert transport.writes == [b"headtail"]
    assert transport.closed


def test_everything_else_is_the_transports() -> None:
    loop = asyncio.new_event_loop()
    try:
        wrapped = _OneWritePerTurn(FakeTransport(), loop)  # type: ignore[arg-type]
        assert wrapped.get_extra_info("peername") == "info:peername"
    finally:
        loop.close()


async def _app(scope: Scope, receive: Receive, send: Send) -> None:
    if scope["type"] != "http":
        return
    size = int(scope["path"].strip("/") or 0)
    await send({"type": "http.response.start", "status": 200, "headers": [(b"content-type", b"text/plain")]})
    for _ in range(3):  # a streamed body: three chunks, chunked encoding
        await send({"type": "http.response.body", "body": b"x" * size, "more_body": True})
    await send({"type": "http.response.body", "body": b""})


@pytest.fixture
def served() -> Iterator[str]:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    server = uvicorn.Server(
        uvicorn.Config(_app, host="127.0.0.1", port=port, http=HttpProtocol, log_level="warning")
    )
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    while not server.started:
        assert thread.is_alive()
        threading.Event().wait(0.02)
    yield f"http://127.0.0.1:{port}"
    server.should_exit = True
    thread.join(10)


@pytest.mark.parametrize("size", [0, 10, 200_000])
def test_responses_arrive_whole_on_kept_alive_and_closed_connections(served: str, size: int) -> None:
    with httpx.Client(trust_env=False) as client:  # one connection, kept alive across requests
        for _ in range(3):
            response = client.get(f"{served}/{size}")
            assert response.status_code == 200
            assert response.content == b"x" * (3 * size)
    closed = httpx.get(f"{served}/{size}", headers={"connection": "close"}, trust_env=False)
    assert closed.content == b"x" * (3 * size)
