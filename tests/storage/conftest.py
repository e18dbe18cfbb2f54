"""The storage contract runs on SQLite, on PostgreSQL and on the in-memory fake, so the fake the
service tests use cannot drift from the database."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from app.db.database import Database
from app.db.types import utc_now
from app.storage import Stores, memory_stores, sql_stores

StoresFor = Callable[..., Stores]


@pytest.fixture(params=["sqlite", pytest.param("postgres", marks=pytest.mark.postgres), "memory"])
def backend(request: pytest.FixtureRequest) -> str:
    """Overrides the root `backend`: `db` (SQL) follows it; `memory` needs no database."""
    return str(request.param)


@pytest.fixture
def stores_for(backend: str, request: pytest.FixtureRequest) -> StoresFor:
    """Stores on this test's backend with the given clock (call it once per test: fakes share no data)."""
    if backend == "memory":
        return lambda clock=utc_now: memory_stores(clock=clock)
    database: Database = request.getfixturevalue("db")
    return lambda clock=utc_now: sql_stores(database, clock=clock)


@pytest.fixture
def stores(stores_for: StoresFor) -> Stores:
    return stores_for()
