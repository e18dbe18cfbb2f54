"""The service's log: JSON lines, written a loop iteration's lines at a time, in the order they were made."""

from __future__ import annotations

import asyncio
import json
import logging
from collections.abc import Iterator

import pytest

from app.logs import JsonLogFormatter, LoopBatchingHandler


class Writes:
    """A stream that keeps each write apart."""

    def __init__(self) -> None:
        self.writes: list[str] = []

    def write(self, text: str) -> None:
        self.writes.append(text)

    def flush(self) -> None:
        pass


Logged = tuple[logging.Logger, Writes]


@pytest.fixture
def logged() -> Iterator[Logged]:
    writes = Writes()
    handler = LoopBatchingHandler()
    handler.setStream(writes)  # type: ignore[arg-type]
    handler.setFormatter(JsonLogFormatter())
    logger = logging.getLogger("physcheck.test-log-lines")
    logger.handlers[:] = [handler]
    logger.setLevel(logging.INFO)
    logger.propagate = False
    yield logger, writes
    logger.handlers[:] = []


def messages(text: str) -> list[str]:
    return [json.loads(line)["message"] for line in text.splitlines()]


def test_the_lines_of_one_loop_iteration_are_written_together_when_it_ends(logged: Logged) -> None:
    logger, writes = logged

    async def serve() -> list[str]:
        for n in range(3):
            logger.info("request %d", n, extra={"status": 200})
        before = list(writes.writes)
        await asyncio.sleep(0)  # the iteration ends
        return before

    assert asyncio.run(serve()) == []
    assert len(writes.writes) == 1
    assert messages(writes.writes[0]) == ["request 0", "request 1", "request 2"]
    assert json.loads(writes.writes[0].splitlines()[0])["status"] == 200


def test_a_warning_is_written_at_once_after_the_lines_pending_before_it(logged: Logged) -> None:
    logger, writes = logged

    async def serve() -> list[str]:
        logger.info("request")
        logger.warning("worker died")
        return list(writes.writes)

    assert [messages(text) for text in asyncio.run(serve())] == [["request", "worker died"]]


def test_a_line_logged_off_any_event_loop_is_written_at_once(logged: Logged) -> None:
    logger, writes = logged
    logger.info("starting")
    assert [messages(text) for text in writes.writes] == [["starting"]]


def test_pending_lines_are_written_when_the_handler_is_flushed(logged: Logged) -> None:
    logger, writes = logged

    async def serve() -> None:
        logger.info("last request")
        logger.handlers[0].flush()  # as logging.shutdown() does at exit, if the loop stopped first

    asyncio.run(serve())
    assert [messages(text) for text in writes.writes] == [["last request"]]
