"""An app per test on a fresh database, sharing one pool of grading workers for the whole session."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from fastapi.testclient import TestClient

from app.db.database import Database
from app.grading.pool import GradingPool
from app.keys import create_key
from app.main import create_app
from app.settings import Settings


@pytest.fixture(scope="session")
def grading_pool() -> Iterator[GradingPool]:
    pool = GradingPool(workers=2, timeout=2.0, memory_mb=1024, max_tasks=1000, queue_size=32)
    pool.start()
    yield pool
    pool.close()


@pytest.fixture
def settings(db: Database) -> Settings:
    """Settings on a fresh database; `db` runs every API test on SQLite and on PostgreSQL.

    No warm-up: each app would start deriving the whole bank in this process, stealing the tests' time;
    a problem a test uses is compiled when first asked for (and shared by every app of the process).
    """
    return Settings(database_url=db.url, secret="test-secret-0123456789", warm_up=False)


@pytest.fixture
def client(settings: Settings, grading_pool: GradingPool) -> Iterator[TestClient]:
    with TestClient(create_app(settings, pool=grading_pool)) as test_client:
        yield test_client


def _headers(settings: Settings, role: str, name: str) -> dict[str, str]:
    database = Database(settings.database_url)
    try:
        plaintext, _ = create_key(database, role, name)
    finally:
        database.dispose()
    return {"Authorization": f"Bearer {plaintext}"}


@pytest.fixture
def student_headers(client: TestClient, settings: Settings) -> dict[str, str]:
    return _headers(settings, "student", "ada")


@pytest.fixture
def instructor_headers(client: TestClient, settings: Settings) -> dict[str, str]:
    return _headers(settings, "instructor", "prof")
