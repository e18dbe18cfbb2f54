"""One `Database` per process: the engine and a session factory, configured per backend from a URL."""

from __future__ import annotations

import math
import sqlite3
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from sqlalchemy import Engine, create_engine, event, text
from sqlalchemy.engine import Connection, make_url
from sqlalchemy.orm import Session, sessionmaker

from app.db.deadline import ConnectionDeadlines

# How long a SQLite connection waits for another writer before failing with "database is locked".
DEFAULT_SQLITE_BUSY_TIMEOUT_MS = 10_000
# Seconds to wait for a PostgreSQL connection (libpq's connect_timeout; a URL may set its own).
POSTGRES_CONNECT_TIMEOUT = 5
# The execution option that tells the SQLite `begin` hook which BEGIN to emit.
_SQLITE_BEGIN_OPTION = "physcheck_sqlite_begin"


def create_database_engine(
    url: str,
    *,
    sqlite_busy_timeout_ms: int = DEFAULT_SQLITE_BUSY_TIMEOUT_MS,
    timeout_seconds: float | None = None,
) -> Engine:
    """An engine for `sqlite:///path` or `postgresql+psycopg://...`, with the settings each needs.

    `timeout_seconds` (the server's; migrations run without one) bounds every wait on the database:
    for a free connection from the pool, a lock (SQLite's busy timeout, PostgreSQL's statement_timeout)
    and, on PostgreSQL, a server that never answers (app/db/deadline.py). Past it, the call fails with
    a database error, which the service answers 503 + Retry-After.
    """
    parsed = make_url(url)
    pool = {} if timeout_seconds is None else {"pool_timeout": timeout_seconds}
    if parsed.get_backend_name() == "sqlite":
        if parsed.database in (None, "", ":memory:") or parsed.query.get("mode") == "memory":
            # Each connection would get its own empty database, and migrations would vanish with theirs.
            raise ValueError("in-memory SQLite is not supported; give a file path (sqlite:///path.db)")
        engine = create_engine(url, connect_args={"check_same_thread": False}, **pool)
        busy_ms = sqlite_busy_timeout_ms if timeout_seconds is None else int(timeout_seconds * 1000)
        _configure_sqlite(engine, busy_ms)
        return engine
    if parsed.get_backend_name() == "postgresql":
        # A database host that does not answer fails a connection in seconds (then 503), not minutes.
        connect_timeout = (
            POSTGRES_CONNECT_TIMEOUT if timeout_seconds is None else max(2, math.ceil(timeout_seconds))
        )
        connect_args: dict[str, Any] = (
            {} if "connect_timeout" in parsed.query else {"connect_timeout": connect_timeout}
        )
        if timeout_seconds is not None:
            # A statement waiting on a lock, or slow, is ended by the server itself.
            connect_args["options"] = f"-c statement_timeout={int(timeout_seconds * 1000)}"
        engine = create_engine(url, pool_pre_ping=True, connect_args=connect_args, **pool)
        if timeout_seconds is not None:
            # The server's own timeout does nothing when the server never answers: cut from here.
            ConnectionDeadlines(timeout_seconds).install(engine)
        return engine
    raise ValueError(f"unsupported database backend {parsed.get_backend_name()!r}; use sqlite or postgresql")


def _configure_sqlite(engine: Engine, busy_timeout_ms: int) -> None:
    """WAL, a busy timeout, foreign keys, and transactions that we begin ourselves.

    The sqlite3 module would otherwise open transactions lazily with a plain deferred BEGIN, and a
    deferred transaction that reads and then writes can fail at once with SQLITE_BUSY instead of waiting
    (busy_timeout does not apply to its lock upgrade). So the driver's own handling is switched off and
    every transaction starts with BEGIN IMMEDIATE, unless the session was opened read-only.
    """

    @event.listens_for(engine, "connect")
    def _on_connect(dbapi_connection: Any, _record: Any) -> None:
        dbapi_connection.isolation_level = None
        cursor = dbapi_connection.cursor()
        try:
            cursor.execute(f"PRAGMA busy_timeout = {int(busy_timeout_ms)}")
            _use_wal(cursor, busy_timeout_ms)
            cursor.execute("PRAGMA synchronous = NORMAL")
            cursor.execute("PRAGMA foreign_keys = ON")
        finally:
            cursor.close()

    @event.listens_for(engine, "begin")
    def _on_begin(connection: Connection) -> None:
        mode = connection.get_execution_options().get(_SQLITE_BEGIN_OPTION, "IMMEDIATE")
        connection.exec_driver_sql("BEGIN IMMEDIATE" if mode == "IMMEDIATE" else "BEGIN")


def _use_wal(cursor: Any, busy_timeout_ms: int) -> None:
    """Switch the file to WAL (it stays so); wait out another connection doing the same.

    Changing the journal mode needs the file to itself and reports SQLITE_BUSY at once, without the
    busy handler, when two processes open a new database together.
    """
    deadline = time.monotonic() + busy_timeout_ms / 1000
    while True:
        try:
            if cursor.execute("PRAGMA journal_mode").fetchone()[0].lower() != "wal":
                cursor.execute("PRAGMA journal_mode = WAL")
            return
        except sqlite3.OperationalError:
            if time.monotonic() > deadline:
                raise
            time.sleep(0.05)


class Database:
    """The engine and session factory for one database URL."""

    def __init__(
        self,
        url: str,
        *,
        sqlite_busy_timeout_ms: int = DEFAULT_SQLITE_BUSY_TIMEOUT_MS,
        timeout_seconds: float | None = None,
    ) -> None:
        self.url = url
        self.engine = create_database_engine(
            url, sqlite_busy_timeout_ms=sqlite_busy_timeout_ms, timeout_seconds=timeout_seconds
        )
        self._sessions = sessionmaker(self.engine, expire_on_commit=False)
        # The same pool, with connections that begin deferred (no write lock) on SQLite.
        self._read_engine = self.engine.execution_options(**{_SQLITE_BEGIN_OPTION: "DEFERRED"})
        self._read_sessions = sessionmaker(self._read_engine, expire_on_commit=False)

    @property
    def backend(self) -> str:
        """`sqlite` or `postgresql`."""
        return self.engine.dialect.name

    @contextmanager
    def session(self, *, read_only: bool = False) -> Iterator[Session]:
        """A session in one transaction: committed if the block ends normally, rolled back if it raises.

        On SQLite a read-write session holds the database's single write lock from its first statement
        to the end, so keep it short (never across a check). `read_only=True` takes no write lock there
        (WAL readers never block); on PostgreSQL both are the same.
        """
        factory = self._read_sessions if read_only else self._sessions
        with factory() as session, session.begin():
            yield session

    def ping(self) -> bool:
        """True when the database answers a trivial query; for the readiness probe."""
        try:
            with self._read_engine.connect() as connection:
                connection.execute(text("SELECT 1"))
        except Exception:
            return False
        return True

    def dispose(self) -> None:
        """Close every pooled connection (at shutdown, and in tests before dropping a database)."""
        self.engine.dispose()
