"""The Database object: sessions commit or roll back, ping answers, SQLite is configured for a server."""

from __future__ import annotations

import pytest
from sqlalchemy import text

from app.db.database import Database, create_database_engine
from app.db.errors import KeyNotFound
from app.db.keys import create_key, list_keys
from app.db.records import Role


def test_session_commits_when_the_block_ends(db: Database) -> None:
    with db.session() as session:
        create_key(session, Role.INSTRUCTOR, name="kept")
    with db.session(read_only=True) as session:
        assert [key.name for key in list_keys(session)] == ["kept"]


def test_session_rolls_back_when_the_block_raises(db: Database) -> None:
    with pytest.raises(KeyNotFound), db.session() as session:
        create_key(session, Role.INSTRUCTOR, name="lost")
        raise KeyNotFound(1)
    with db.session(read_only=True) as session:
        assert list_keys(session) == []


def test_ping_answers_when_the_database_is_up(db: Database) -> None:
    assert db.ping() is True


def test_ping_is_false_when_the_database_cannot_be_opened(tmp_path) -> None:
    database = Database(f"sqlite:///{tmp_path / 'missing-dir' / 'x.db'}")
    try:
        assert database.ping() is False
    finally:
        database.dispose()


@pytest.mark.parametrize(
    ("pragma", "expected"),
    [("foreign_keys", 1), ("journal_mode", "wal"), ("busy_timeout", 10_000)],
    ids=["foreign-keys-on", "wal", "busy-timeout"],
)
def test_sqlite_connections_are_configured(tmp_path, pragma: str, expected: object) -> None:
    database = Database(f"sqlite:///{tmp_path / 'x.db'}")
    try:
        with database.session(read_only=True) as session:
            assert session.execute(text(f"PRAGMA {pragma}")).scalar() == expected
    finally:
        database.dispose()


@pytest.mark.parametrize(
    ("url", "message"),
    [
        ("mysql://localhost/x", "unsupported database backend"),
        ("sqlite://", "in-memory SQLite"),
        ("sqlite:///:memory:", "in-memory SQLite"),
        ("sqlite:///file:x?mode=memory&uri=true", "in-memory SQLite"),
    ],
    ids=["mysql", "sqlite-default-memory", "sqlite-memory", "sqlite-uri-memory"],
)
def test_an_unusable_url_is_refused(url: str, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        create_database_engine(url)


def test_the_servers_timeout_bounds_lock_waits_and_statements(db: Database) -> None:
    """A server's Database (with `timeout_seconds`) waits at most that long for a lock (SQLite) or a
    statement (PostgreSQL's own statement_timeout); migrations' engines (none given) are not bounded."""
    bounded = Database(db.url, timeout_seconds=1.5)
    try:
        with bounded.session(read_only=True) as session:
            if bounded.backend == "sqlite":
                assert session.execute(text("PRAGMA busy_timeout")).scalar() == 1500
            else:
                assert session.execute(text("SHOW statement_timeout")).scalar() == "1500ms"
        assert bounded.engine.pool.timeout() == 1.5  # type: ignore[attr-defined]
    finally:
        bounded.dispose()
    if db.backend == "postgresql":
        with db.session(read_only=True) as session:
            assert session.execute(text("SHOW statement_timeout")).scalar() == "0"
