"""The service's log: one JSON object per line on stderr, written a loop iteration's lines at a time."""

from __future__ import annotations

import asyncio
import functools
import json
import logging
import time
from typing import Any

# One encoder for every line: json.dumps with an argument builds a new one per call.
_ENCODE = json.JSONEncoder(default=str).encode


class JsonLogFormatter(logging.Formatter):
    """One JSON object per line; fields passed with `extra=` become keys."""

    _RESERVED = frozenset(logging.LogRecord("", 0, "", 0, "", None, None).__dict__) | {"message", "asctime"}

    @staticmethod
    @functools.lru_cache(maxsize=4)
    def _time(second: int) -> str:
        # Formatted once a second rather than once a line: a busy server logs thousands of lines a second.
        return time.strftime("%Y-%m-%dT%H:%M:%S", time.localtime(second))

    def format(self, record: logging.LogRecord) -> str:
        entry: dict[str, Any] = {
            "time": self._time(int(record.created)),
            "level": record.levelname,
            "logger": record.name,
            "message": record.getMessage(),
        }
        entry.update({k: v for k, v in record.__dict__.items() if k not in self._RESERVED})
        if record.exc_info:
            entry["exception"] = self.formatException(record.exc_info)
        return _ENCODE(entry)


class LoopBatchingHandler(logging.StreamHandler):  # type: ignore[type-arg]
    """A stream handler that writes the lines logged on an event loop's thread once per loop iteration,
    in one write: a server under load logs a line per request, and a system call per line cost its
    event loop more than making the line. Warnings, errors and lines from other threads are written at
    once, after whatever is pending, so the order of lines is kept; `flush` (logging does it at exit)
    writes what is pending. A process killed outright loses at most its last iteration's lines."""

    def __init__(self) -> None:
        super().__init__()
        self._pending: list[str] = []

    def emit(self, record: logging.LogRecord) -> None:  # called with the handler's lock held
        try:
            self._pending.append(self.format(record) + self.terminator)
            loop = _running_loop()
            if loop is None or record.levelno >= logging.WARNING:
                self._write_pending()
            elif len(self._pending) == 1:
                loop.call_soon(self.flush)
        except Exception:
            self.handleError(record)

    def flush(self) -> None:
        with self.lock:  # type: ignore[union-attr]  # made by Handler.__init__
            self._write_pending()
            super().flush()

    def _write_pending(self) -> None:
        if self._pending:
            lines, self._pending = "".join(self._pending), []
            self.stream.write(lines)


def _running_loop() -> asyncio.AbstractEventLoop | None:
    try:
        return asyncio.get_running_loop()
    except RuntimeError:  # none in this thread
        return None


def configure_logging(level: str) -> None:
    handler = LoopBatchingHandler()
    handler.setFormatter(JsonLogFormatter())
    root = logging.getLogger("physcheck")
    root.handlers[:] = [handler]
    root.setLevel(level)
    root.propagate = False
