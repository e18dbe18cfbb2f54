"""The real app (`create_app`) on a fresh SQLite database with a one-problem bank, and helpers to sign
in to the instructor pages as a browser would (the form's CSRF token read from the page)."""

from __future__ import annotations

import re
import shutil
import time
from collections.abc import Iterator
from pathlib import Path

import httpx
import pytest
from fastapi.testclient import TestClient

from app.db.database import Database
from app.grading.pool import GradingPool
from app.keys import create_key
from app.main import create_app
from app.settings import Settings
from problems.loader import BANK_DIR
from tests.browser import LiveServer, serve

CSRF = re.compile(r'name="csrf" value="([^"]+)"')


@pytest.fixture(scope="session")
def pages_pool() -> Iterator[GradingPool]:
    pool = GradingPool(workers=1, timeout=5.0, memory_mb=1024, max_tasks=1000, queue_size=16)
    pool.start()
    yield pool
    pool.close()


@pytest.fixture(scope="session")
def yo_yo_only(tmp_path_factory: pytest.TempPathFactory) -> Path:
    bank = tmp_path_factory.mktemp("bank")
    shutil.copytree(BANK_DIR / "yo-yo", bank / "yo-yo")
    return bank


@pytest.fixture
def settings(tmp_path: Path, yo_yo_only: Path) -> Settings:
    return Settings(
        database_url=f"sqlite:///{tmp_path / 'physcheck.db'}",
        secret="instructor-pages-secret-0123",
        bank_dir=yo_yo_only,
        warm_up=False,
        check_workers=1,
    )


@pytest.fixture
def client(settings: Settings, pages_pool: GradingPool) -> Iterator[TestClient]:
    with TestClient(create_app(settings, pool=pages_pool), follow_redirects=False) as test_client:
        yield test_client


@pytest.fixture
def database(client: TestClient) -> Database:
    database: Database = client.app.state.services.database  # type: ignore[attr-defined]
    return database


def new_key(database: Database, role: str, name: str = "Prof", student: str | None = None) -> str:
    plaintext, _ = create_key(database, role, name, student=student)
    return plaintext


def csrf_of(html: str) -> str:
    found = CSRF.search(html)
    assert found, "the page has no form with a CSRF token"
    return found.group(1)


def sign_in(client: TestClient, key: str, next_url: str = "/instructor/problems") -> object:
    form = client.get("/instructor/sign-in", params={"next": next_url})
    assert form.status_code == 200
    return client.post("/instructor/sign-in", data={"key": key, "csrf": csrf_of(form.text), "next": next_url})


@pytest.fixture
def instructor_key(database: Database) -> str:
    return new_key(database, "instructor", "Prof Ada")


@pytest.fixture
def signed_in(client: TestClient, instructor_key: str) -> TestClient:
    response = sign_in(client, instructor_key)
    assert response.status_code == 303, response.text  # type: ignore[attr-defined]
    return client


@pytest.fixture(scope="module")
def live_server(
    tmp_path_factory: pytest.TempPathFactory, page_grading_pool: GradingPool, yo_yo_only: Path
) -> Iterator[LiveServer]:
    """tests/browser.py's live server, with the yo-yo alone for a bank: these pages need one problem,
    and compiling the whole bank first would take minutes of the run."""
    folder = tmp_path_factory.mktemp("live")
    settings = Settings(
        database_url=f"sqlite:///{folder / 'physcheck.db'}",
        secret="page-test-secret-0123456789",
        check_workers=1,
        bank_dir=yo_yo_only,
    )
    app = create_app(settings, pool=page_grading_pool)
    for url in serve(app):
        deadline = time.monotonic() + 120
        while httpx.get(f"{url}/ready").status_code != 200:
            assert time.monotonic() < deadline, "the yo-yo did not compile"
            time.sleep(0.2)
        yield LiveServer(url, app)
