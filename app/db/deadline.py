"""A PostgreSQL connection that waits past its deadline for the server is cut, so the call fails (503).

A database that accepts connections but never answers (a host gone behind a proxy or load balancer
that still accepts, a network path that drops every reply) is not caught by the server's own
`statement_timeout`, which it never reads, nor by TCP timeouts, since whatever accepted the connection
acknowledges every byte; the driver then waits for a reply forever, holding a server thread. So every
wait for the server (a statement, a commit or rollback, the pool's ping and reset) is watched from one
thread, and a connection still waiting at its deadline has its socket shut down: the driver's wait ends
with a disconnect error, the pool drops the connection, and the request is answered 503 + Retry-After.
New connections are bounded by libpq's `connect_timeout`, and a free connection from the pool by
`pool_timeout`.
"""

from __future__ import annotations

import contextlib
import logging
import socket
import threading
import time
from collections.abc import Callable
from typing import Any

from sqlalchemy import Engine, event

log = logging.getLogger("physcheck.database")
_POLL_SECONDS = 0.1


class ConnectionDeadlines:
    def __init__(self, seconds: float, clock: Callable[[], float] = time.monotonic):
        self.seconds = seconds
        self._clock = clock
        self._waiting: dict[int, tuple[Any, float]] = {}  # id(DBAPI connection) -> (it, deadline)
        self._lock = threading.Lock()
        self._watcher: threading.Thread | None = None
        self.cut = 0  # connections cut so far

    def install(self, engine: Engine) -> None:
        def watch_connection(conn: Any, *_: Any) -> None:
            self.watch(_dbapi_connection(conn))

        def release_connection(conn: Any, *_: Any) -> None:
            self.release(_dbapi_connection(conn))

        event.listen(engine, "before_cursor_execute", watch_connection)
        event.listen(engine, "after_cursor_execute", release_connection)
        event.listen(engine, "commit", watch_connection)  # released at check-in, right after
        event.listen(engine, "rollback", watch_connection)
        # A statement that failed stays watched until the next one, the rollback or the check-in,
        # which come at once: nothing that runs while SQLAlchemy handles an error may raise here.
        event.listen(engine.pool, "reset", lambda dbapi_connection, *_: self.watch(dbapi_connection))
        for ending in ("checkin", "close", "invalidate", "detach"):
            event.listen(engine.pool, ending, lambda dbapi_connection, *_: self.release(dbapi_connection))
        dialect = engine.dialect
        ping = dialect.do_ping

        def watched_ping(dbapi_connection: Any) -> bool:
            self.watch(dbapi_connection)
            try:
                return ping(dbapi_connection)
            finally:
                self.release(dbapi_connection)

        dialect.do_ping = watched_ping  # type: ignore[method-assign]

    def watch(self, dbapi_connection: Any) -> None:
        """Cut `dbapi_connection` if it is still watched `seconds` from now."""
        if dbapi_connection is None:
            return
        with self._lock:
            self._waiting[id(dbapi_connection)] = (dbapi_connection, self._clock() + self.seconds)
            if self._watcher is None:
                self._watcher = threading.Thread(target=self._watch, name="database-deadlines", daemon=True)
                self._watcher.start()

    def release(self, dbapi_connection: Any) -> None:
        if dbapi_connection is None:
            return
        with self._lock:
            self._waiting.pop(id(dbapi_connection), None)

    def _watch(self) -> None:
        while True:
            time.sleep(_POLL_SECONDS)
            now = self._clock()
            with self._lock:
                late = [conn for key, (conn, deadline) in self._waiting.items() if deadline <= now]
                for conn in late:
                    del self._waiting[id(conn)]
            for conn in late:
                self._cut(conn)

    def _cut(self, dbapi_connection: Any) -> None:
        try:
            fd = dbapi_connection.pgconn.socket
        except Exception:  # closed meanwhile: nothing is waiting on it
            return
        # A duplicate of the descriptor: shutting it down ends the socket for the driver's too (close
        # would not), and closing the duplicate leaves the driver's own descriptor for it to close.
        with contextlib.suppress(OSError), socket.fromfd(fd, socket.AF_INET, socket.SOCK_STREAM) as dup:
            dup.shutdown(socket.SHUT_RDWR)
        self.cut += 1
        log.warning("the database did not answer within %g s; its connection was cut", self.seconds)


def _dbapi_connection(conn: Any) -> Any:
    """The driver's connection under a SQLAlchemy Connection, or None once it was invalidated or
    closed (a rollback after a disconnect fires its event first: asking then would raise)."""
    if conn.closed or conn.invalidated:
        return None
    try:
        return conn.connection.dbapi_connection
    except Exception:
        return None
