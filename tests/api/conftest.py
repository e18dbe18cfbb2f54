"""An app per test, sharing one pool of grading workers for the whole session.

By default the app runs on the in-memory stores (`memory_app_storage`): the routes are under test, and
the stores' contract is held by tests/storage. Tests that pin what the database does (durability,
readiness, PostgreSQL) ask for it by using `db` (they then run on SQLite and PostgreSQL) or by
parametrizing `backend` (["sqlite"]); `settings` and `client` then run on that fresh migrated database.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.db.database import Database
from app.db.records import Role
from app.grading.pool import GradingPool
from app.keys import create_key
from app.main import create_app
from app.settings import Settings
from tests.memory_app import memory_app_storage

SQL_BACKENDS = ["sqlite", pytest.param("postgres", marks=pytest.mark.postgres)]
SECRET = "test-secret-0123456789"


def pytest_generate_tests(metafunc: pytest.Metafunc) -> None:
    """A test that uses the database itself runs on both SQL backends (unless it names its own)."""
    named = any("backend" in str(mark.args[0]) for mark in metafunc.definition.iter_markers("parametrize"))
    if not named and {"db", "database_url"} & set(metafunc.fixturenames):
        metafunc.parametrize("backend", SQL_BACKENDS)


@pytest.fixture
def backend() -> str:
    """Overrides the root `backend`: the fakes, unless a test parametrizes `backend` itself."""
    return "memory"


@pytest.fixture(scope="session")
def grading_pool() -> Iterator[GradingPool]:
    pool = GradingPool(workers=2, timeout=2.0, memory_mb=1024, max_tasks=1000, queue_size=32)
    pool.start()
    yield pool
    pool.close()


@pytest.fixture
def settings(backend: str, request: pytest.FixtureRequest) -> Settings:
    """Settings on this test's backend: a fresh database for SQL (`db`), none for the fakes.

    No warm-up: each app would start deriving the whole bank in this process, stealing the tests' time;
    a problem a test uses is compiled when first asked for (and shared by every app of the process).
    """
    if backend == "memory":
        return Settings(database_url="sqlite://", secret=SECRET, warm_up=False)  # never opened
    db: Database = request.getfixturevalue("db")
    return Settings(database_url=db.url, secret=SECRET, warm_up=False)


def make_app(settings: Settings, backend: str, **options: Any) -> Any:
    """`create_app` on this test's backend (options as `create_app` takes them)."""
    if backend == "memory":
        options.setdefault("open_storage", memory_app_storage)
    return create_app(settings, **options)


@pytest.fixture
def client(settings: Settings, backend: str, grading_pool: GradingPool) -> Iterator[TestClient]:
    with TestClient(make_app(settings, backend, pool=grading_pool)) as test_client:
        yield test_client


def key_headers(client: TestClient, role: str, name: str, student: str | None = None) -> dict[str, str]:
    """A new key of the running app's (any backend), as a bearer header."""
    stores = client.app.state.services.stores  # type: ignore[attr-defined]
    created = stores.keys.create(Role(role), name=name, student=student)
    return {"Authorization": f"Bearer {created.plaintext}"}


def _headers(settings: Settings, role: str, name: str) -> dict[str, str]:
    """A new key in the database `settings` names (SQL backends only), as a bearer header."""
    database = Database(settings.database_url)
    try:
        plaintext, _ = create_key(database, role, name)
    finally:
        database.dispose()
    return {"Authorization": f"Bearer {plaintext}"}


@pytest.fixture
def student_headers(client: TestClient) -> dict[str, str]:
    return key_headers(client, "student", "ada")


@pytest.fixture
def instructor_headers(client: TestClient) -> dict[str, str]:
    return key_headers(client, "instructor", "prof")
