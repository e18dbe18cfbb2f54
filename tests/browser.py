"""Browser fixtures for every page test (registered in tests/conftest.py): the REAL app served by uvicorn
on a loopback port with the whole built-in bank, Debian's Chromium driven by Playwright, axe-core
(shipped inside the axe-playwright-python wheel, so nothing comes from npm) and screenshots kept as
test artifacts in `artifacts/` (or PHYSCHECK_ARTIFACTS_DIR).

    def test_x(live_server, browse):
        page = browse(live_server.url + "/", width=390)   # a fresh tab at phone width
        ...
        check_page(page, "home-phone")                     # axe: no serious/critical; screenshot

Tests using `browse` are skipped where /usr/bin/chromium is missing; mark them `browser` and `slow`.
"""

from __future__ import annotations

import os
import shutil
import socket
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
import uvicorn
from fastapi import FastAPI

from app.db.records import Role
from app.grading.pool import GradingPool
from app.http_protocol import HttpProtocol
from app.main import create_app
from app.settings import Settings
from app.storage import Stores

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]
DESKTOP, PHONE = 1280, 390
WIDTHS = {"desktop": DESKTOP, "phone": PHONE}
BLOCKING_IMPACTS = ("serious", "critical")
FIRST_USE_MS = 90_000  # a problem's first preview waits for its derivation on a busy machine


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def artifacts_dir() -> Path:
    path = Path(os.environ.get("PHYSCHECK_ARTIFACTS_DIR", "artifacts"))
    path.mkdir(parents=True, exist_ok=True)
    return path


@dataclass
class LiveServer:
    url: str
    app: FastAPI

    @property
    def stores(self) -> Stores:
        """The running app's stores (SQL or the in-memory fakes)."""
        stores: Stores = self.app.state.services.stores
        return stores

    def key(self, role: str, name: str, student: str | None = None) -> str:
        """A new API key's plaintext (`student` names a student key's student)."""
        return self.stores.keys.create(Role(role), name=name, student=student).plaintext


def serve(app: FastAPI) -> Iterator[str]:
    """`app` in a uvicorn thread (its lifespan runs), with `physcheck serve`'s HTTP protocol; yields its
    base URL."""
    port = free_port()
    config = uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning", http=HttpProtocol)
    server = uvicorn.Server(config)
    thread = threading.Thread(target=server.run, name="uvicorn", daemon=True)
    thread.start()
    deadline = time.monotonic() + 60
    while not server.started:
        assert thread.is_alive(), "uvicorn exited during startup"
        assert time.monotonic() < deadline, "uvicorn did not start"
        time.sleep(0.05)
    try:
        yield f"http://127.0.0.1:{port}"
    finally:
        server.should_exit = True
        thread.join(timeout=30)


@pytest.fixture(scope="session")
def page_grading_pool() -> Iterator[GradingPool]:
    pool = GradingPool(workers=1, timeout=10.0, memory_mb=1024, max_tasks=1000, queue_size=16)
    pool.start()
    yield pool
    pool.close()


@pytest.fixture(scope="module")
def live_server(
    tmp_path_factory: pytest.TempPathFactory, page_grading_pool: GradingPool
) -> Iterator[LiveServer]:
    """The real app with the whole built-in bank on SQLite, one per test module. Problems compile on
    first use (seconds each): give the first grading or preview of a problem FIRST_USE_MS to appear."""
    folder = tmp_path_factory.mktemp("live")
    settings = Settings(
        database_url=f"sqlite:///{folder / 'physcheck.db'}",
        secret="page-test-secret-0123456789",
        check_workers=1,
        warm_up=False,
    )
    app = create_app(settings, pool=page_grading_pool)
    for url in serve(app):
        yield LiveServer(url, app)


@pytest.fixture(scope="module")
def chromium() -> Iterator[Any]:
    """One headless Chromium per test module (each test gets its own contexts through `browse`).
    Not per session: Playwright's sync API keeps an event loop running in the main thread while it is
    open, and async tests in later modules could not start theirs."""
    if CHROMIUM is None:
        pytest.skip("Debian's chromium package is not installed")
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        try:
            yield browser
        finally:
            browser.close()


@pytest.fixture
def browse(chromium: Any) -> Iterator[Callable[..., Any]]:
    """`browse(url, width=1280, cookies=None)`: a new page in a fresh context (its own storage),
    `url` loaded; every context is closed after the test."""
    contexts: list[Any] = []

    def open_page(url: str, width: int = DESKTOP, cookies: list[dict[str, str]] | None = None) -> Any:
        context = chromium.new_context(viewport={"width": width, "height": 900})
        contexts.append(context)
        if cookies:
            context.add_cookies(cookies)
        page = context.new_page()
        page.goto(url)
        return page

    yield open_page
    for context in contexts:
        context.close()


def axe_violations(page: Any) -> list[dict[str, Any]]:
    """axe-core's serious and critical violations on the page as it is now."""
    from axe_playwright_python.sync_playwright import Axe

    results = Axe().run(page)
    return [v for v in results.response["violations"] if v.get("impact") in BLOCKING_IMPACTS]


def describe_violations(violations: list[dict[str, Any]]) -> str:
    return "\n".join(
        f"{v['id']} ({v['impact']}): {v['help']} at "
        + ", ".join(str(node.get("target")) for node in v.get("nodes", [])[:5])
        for v in violations
    )


def page_width_overflow(page: Any) -> int:
    """How many CSS pixels the document is wider than the viewport (0: no sideways scrolling)."""
    return int(page.evaluate("document.documentElement.scrollWidth - window.innerWidth"))


def check_page(page: Any, name: str) -> Path:
    """Screenshot the whole page to artifacts/<name>.png, then assert that axe-core finds no serious
    or critical violation and that nothing makes the page scroll sideways."""
    path = artifacts_dir() / f"{name}.png"
    page.screenshot(path=str(path), full_page=True)
    violations = axe_violations(page)
    assert not violations, f"{name}: accessibility violations:\n{describe_violations(violations)}"
    overflow = page_width_overflow(page)
    assert overflow <= 0, f"{name}: the page is {overflow} px wider than the window"
    return path
