"""The real app (`create_app`) on the in-memory stores with a one-problem bank, and helpers to sign in
to the instructor pages as a browser would (the form's CSRF token read from the page)."""

from __future__ import annotations

import re
import shutil
import time
from collections.abc import Iterator
from pathlib import Path

import httpx
import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient

from app.db.records import Role
from app.grading.pool import GradingPool
from app.main import create_app
from app.settings import Settings
from app.storage import Stores
from problems.loader import BANK_DIR
from tests.browser import LiveServer, serve
from tests.memory_app import memory_app_storage

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
def settings(yo_yo_only: Path) -> Settings:
    return Settings(
        database_url="sqlite://",  # never opened: the stores are the in-memory fakes
        secret="instructor-pages-secret-0123",
        bank_dir=yo_yo_only,
        warm_up=False,
        check_workers=1,
    )


def make_app(settings: Settings, pool: GradingPool) -> FastAPI:
    """`create_app` on fresh in-memory stores."""
    return create_app(settings, pool=pool, open_storage=memory_app_storage)


@pytest.fixture
def client(settings: Settings, pages_pool: GradingPool) -> Iterator[TestClient]:
    with TestClient(make_app(settings, pages_pool), follow_redirects=False) as test_client:
        yield test_client


def stores_of(client: TestClient) -> Stores:
    stores: Stores = client.app.state.services.stores  # type: ignore[attr-defined]
    return stores


@pytest.fixture
def stores(client: TestClient) -> Stores:
    """The running app's stores."""
    return stores_of(client)


def new_key(stores: Stores, role: str, name: str = "Prof", student: str | None = None) -> str:
    return stores.keys.create(Role(role), name=name, student=student).plaintext


def csrf_of(html: str) -> str:
    found = CSRF.search(html)
    assert found, "the page has no form with a CSRF token"
    return found.group(1)


def sign_in(client: TestClient, key: str, next_url: str = "/instructor/problems") -> object:
    form = client.get("/instructor/sign-in", params={"next": next_url})
    assert form.status_code == 200
    return client.post("/instructor/sign-in", data={"key": key, "csrf": csrf_of(form.text), "next": next_url})


@pytest.fixture
def instructor_key(stores: Stores) -> str:
    return new_key(stores, "instructor", "Prof Ada")


@pytest.fixture
def signed_in(client: TestClient, instructor_key: str) -> TestClient:
    response = sign_in(client, instructor_key)
    assert response.status_code == 303, response.text  # type: ignore[attr-defined]
    return client


def serve_bank(pool: GradingPool, bank_dir: Path, ready_within: float = 120) -> Iterator[LiveServer]:
    """tests/browser.py's live server on the in-memory stores with `bank_dir` for a bank, once it is
    ready (its problems compiled)."""
    settings = Settings(
        database_url="sqlite://",  # never opened: the app runs on the in-memory stores
        secret="page-test-secret-0123456789",
        check_workers=1,
        bank_dir=bank_dir,
    )
    app = make_app(settings, pool)
    for url in serve(app):
        deadline = time.monotonic() + ready_within
        while httpx.get(f"{url}/ready").status_code != 200:
            assert time.monotonic() < deadline, f"the bank in {bank_dir} did not compile"
            time.sleep(0.2)
        yield LiveServer(url, app)


@pytest.fixture(scope="module")
def live_server(page_grading_pool: GradingPool, yo_yo_only: Path) -> Iterator[LiveServer]:
    """The yo-yo alone for a bank: these pages need one problem, and compiling the whole bank first
    would take minutes of the run."""
    yield from serve_bank(page_grading_pool, yo_yo_only)
