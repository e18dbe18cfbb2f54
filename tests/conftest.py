"""Database fixtures: every test that uses them runs on SQLite and on PostgreSQL.

Written to be moved to tests/conftest.py as is. `database_url` is a fresh, empty database per test;
`db` is a migrated `Database`, emptied before each test. PostgreSQL databases are created on the server
named by PHYSCHECK_TEST_POSTGRES_URL (through its maintenance database) under random names, because
other test runs share that server, and are dropped at the end.
"""

from __future__ import annotations

import contextlib
import os
import secrets
import shutil
import sqlite3
from collections.abc import Iterator
from pathlib import Path

import pytest
from sqlalchemy import Engine, create_engine, text
from sqlalchemy.engine import make_url
from sqlalchemy.exc import OperationalError
from sqlalchemy.pool import NullPool

from app.db.database import Database
from app.db.migrate import migrate
from tests.sampling import described, fix_seed, sample_marked

# Browser fixtures (live_server, browse, check_page...) shared by every page test.
pytest_plugins = ["tests.browser"]

POSTGRES_URL_ENV = "PHYSCHECK_TEST_POSTGRES_URL"
DEFAULT_POSTGRES_URL = "postgresql+psycopg://postgres@127.0.0.1:5432/test"


class PostgresServer:
    """Creates and drops throwaway databases on the test server."""

    def __init__(self, admin_url: str) -> None:
        self.admin_url = admin_url
        self._engine: Engine = create_engine(
            admin_url, isolation_level="AUTOCOMMIT", poolclass=NullPool, connect_args={"connect_timeout": 5}
        )
        self._created: list[str] = []

    def check_reachable(self) -> None:
        try:
            with self._engine.connect() as connection:
                connection.execute(text("SELECT 1"))
        except OperationalError as error:
            pytest.skip(
                f"PostgreSQL not reachable at {make_url(self.admin_url)!r}; set {POSTGRES_URL_ENV} "
                f"({type(error).__name__}: {str(error).splitlines()[0]})"
            )

    def create_database(self) -> str:
        name = f"physcheck_test_{secrets.token_hex(6)}"
        with self._engine.connect() as connection:
            connection.execute(text(f'CREATE DATABASE "{name}"'))
        self._created.append(name)
        return make_url(self.admin_url).set(database=name).render_as_string(hide_password=False)

    def drop_database(self, url: str) -> None:
        name = make_url(url).database
        assert name is not None and name in self._created, "only drop what this run created"
        with self._engine.connect() as connection:
            connection.execute(text(f'DROP DATABASE IF EXISTS "{name}" WITH (FORCE)'))
        self._created.remove(name)

    def close(self) -> None:
        for name in list(self._created):
            with self._engine.connect() as connection:
                connection.execute(text(f'DROP DATABASE IF EXISTS "{name}" WITH (FORCE)'))
        self._created.clear()
        self._engine.dispose()


@pytest.fixture(scope="session")
def postgres_server() -> Iterator[PostgresServer]:
    server = PostgresServer(os.environ.get(POSTGRES_URL_ENV, DEFAULT_POSTGRES_URL))
    try:
        server.check_reachable()
        yield server
    finally:
        server.close()


@pytest.fixture(scope="session")
def migrated_postgres_url(postgres_server: PostgresServer) -> str:
    """One migrated PostgreSQL database for the whole run (dropped by `postgres_server` at the end)."""
    url = postgres_server.create_database()
    migrate(url)
    return url


@pytest.fixture(params=["sqlite", pytest.param("postgres", marks=pytest.mark.postgres)])
def backend(request: pytest.FixtureRequest) -> str:
    return str(request.param)


@pytest.fixture
def database_url(
    backend: str, request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[str]:
    """A fresh, empty database (not migrated)."""
    assert backend in ("sqlite", "postgres"), f"a database on the {backend!r} backend"
    if backend == "sqlite":
        yield f"sqlite:///{tmp_path_factory.mktemp('db') / 'physcheck.db'}"
        return
    server: PostgresServer = request.getfixturevalue("postgres_server")
    url = server.create_database()
    yield url
    server.drop_database(url)


@pytest.fixture(scope="session")
def migrated_sqlite_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A migrated, empty SQLite file that each test copies (running the migrations is most of its cost)."""
    path = tmp_path_factory.mktemp("db-template") / "physcheck.db"
    migrate(f"sqlite:///{path}")
    with contextlib.closing(sqlite3.connect(path)) as connection:  # all of it in the one file (WAL)
        connection.execute("PRAGMA wal_checkpoint(TRUNCATE)")
    return path


@pytest.fixture
def db(
    backend: str, request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[Database]:
    """A migrated, empty `Database`."""
    assert backend in ("sqlite", "postgres"), f"a database on the {backend!r} backend"
    if backend == "sqlite":
        path = tmp_path_factory.mktemp("db") / "physcheck.db"
        shutil.copyfile(request.getfixturevalue("migrated_sqlite_file"), path)
        url = f"sqlite:///{path}"
    else:
        url = request.getfixturevalue("migrated_postgres_url")
        _empty_postgres(url)
    database = Database(url)
    try:
        yield database
    finally:
        database.dispose()


def _empty_postgres(url: str) -> None:
    """Remove every row but the migration version; TRUNCATE skips the append-only row triggers."""
    engine = create_engine(url, poolclass=NullPool)
    try:
        with engine.begin() as connection:
            tables = connection.scalars(
                text(
                    "SELECT tablename FROM pg_tables WHERE schemaname = current_schema() "
                    "AND tablename <> 'alembic_version'"
                )
            ).all()
            if tables:
                names = ", ".join(f'"{name}"' for name in tables)
                connection.execute(text(f"TRUNCATE {names} RESTART IDENTITY CASCADE"))
    finally:
        engine.dispose()


def pytest_configure(config: pytest.Config) -> None:
    fix_seed()


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """`@pytest.mark.sample(k)`: k of the test's parametrized cases run today (tests/sampling.py)."""

    def k_of(item: pytest.Item) -> int | None:
        mark = item.get_closest_marker("sample")
        return None if mark is None else int(mark.args[0])

    kept = sample_marked(items, k_of, lambda item: item.nodeid.split("[")[0])
    if len(kept) < len(items):
        running = {id(item) for item in kept}
        config.hook.pytest_deselected(items=[item for item in items if id(item) not in running])
        items[:] = kept


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    terminalreporter.write_line(described())  # -q prints no header: the seed goes at the end
