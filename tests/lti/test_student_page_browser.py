"""Headless Chromium drives the student page of the REAL app (`create_app`: bank, grading worker, API)
served by uvicorn on a loopback port: type an answer, see the live preview, submit, see the verdict;
reload and see each part's last answer, verdict and attempts restored.
Key mode with a student key from `app.keys.create_key`; session mode after an LTI launch from the fake
LMS. Screenshots go to `artifacts/` (or PHYSCHECK_ARTIFACTS_DIR). Skipped without Debian's chromium.
"""

from __future__ import annotations

import os
import re
import shutil
import socket
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import anyio
import httpx
import pytest
import uvicorn
from fastapi import FastAPI

from app.db.database import Database
from app.grading.pool import GradingPool
from app.keys import create_key
from app.lti.sessions import SESSION_COOKIE
from app.main import create_app
from app.settings import Settings
from tests.lti.conftest import platform_launch
from tests.lti.fake_lms import (
    ISSUER,
    LEARNER,
    TOOL,
    FakeLms,
    NextLaunch,
    register_fake_lms,
)

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
pytestmark = [
    pytest.mark.browser,
    pytest.mark.slow,
    pytest.mark.skipif(CHROMIUM is None, reason="Debian's chromium package is not installed"),
]
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]
PROBLEM = "yo-yo"
RIGHT = "g r^2/(r^2 + k^2)"
# The server's reading of RIGHT, shown with `^` and `·` rather than its `**` and `*`.
READ_AS = re.compile(r"^Read as: g[^*]*r\^2[^*]*k\^2[^*]*$")
WRONG_TENSION = "m g"  # a known mistake, whose feedback has `$...$` maths in it
UNREADABLE = "m g +"


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


@dataclass
class Served:
    url: str
    app: FastAPI
    lms: FakeLms

    @property
    def database(self) -> Database:
        database: Database = self.app.state.services.database
        return database


@pytest.fixture
def served(tmp_path: Path, lti_grading_pool: GradingPool, yo_yo_bank: Path) -> Iterator[Served]:
    """The real app in a uvicorn thread (its lifespan migrates, loads the bank, starts the outbox)."""
    lms = FakeLms()
    settings = Settings(
        database_url=f"sqlite:///{tmp_path / 'physcheck.db'}",
        base_url=TOOL,  # the LTI launch below reaches the same app in-process under this name
        secret="browser-test-secret-0123",
        check_workers=1,
        bank_dir=yo_yo_bank,
        warm_up=False,  # the one problem compiles on first use
    )
    app = create_app(settings, pool=lti_grading_pool, lms_transport=httpx.ASGITransport(app=lms.app))
    port = free_port()
    server = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning"))
    thread = threading.Thread(target=server.run, name="uvicorn", daemon=True)
    thread.start()
    deadline = time.monotonic() + 60
    while not server.started:
        assert thread.is_alive(), "uvicorn exited during startup"
        assert time.monotonic() < deadline, "uvicorn did not start"
        time.sleep(0.05)
    try:
        yield Served(f"http://127.0.0.1:{port}", app, lms)
    finally:
        server.should_exit = True
        thread.join(timeout=30)


def artifacts_dir() -> Path:
    path = Path(os.environ.get("PHYSCHECK_ARTIFACTS_DIR", "artifacts"))
    path.mkdir(parents=True, exist_ok=True)
    return path


def answer_first_part(page: Any, answer: str, screenshot: str) -> None:
    """Type an answer to the first part, see it read back, check it, see the verdict; screenshot."""
    from playwright.sync_api import expect

    box = page.get_by_label("Your answer").first
    box.click()
    box.press_sequentially(answer)
    expect(page.locator("#preview-0")).to_have_text(READ_AS)
    page.get_by_role("button", name="Check answer").first.click()
    # Said once, though the judge's own feedback for it is "Correct." as well.
    expect(page.locator(".verdict").first).to_have_text("Correct. Attempts used: 1.")
    page.screenshot(path=str(artifacts_dir() / screenshot), full_page=True)


def answer_second_part_wrongly(page: Any) -> None:
    """An unreadable answer is flagged while typing; a known mistake gets its feedback, as text."""
    from playwright.sync_api import expect

    box = page.get_by_label("Your answer").nth(1)
    box.fill(UNREADABLE)
    expect(page.locator("#preview-1")).to_contain_text("Cannot read this yet")
    box.press("Enter")  # checked anyway: unreadable, so no attempt is used
    expect(page.locator(".verdict").nth(1)).to_contain_text("Could not read this answer.")
    box.fill(WRONG_TENSION)
    expect(page.locator("#preview-1")).to_have_text("Read as: m·g")
    box.press("Enter")
    verdict = page.locator(".verdict").nth(1)
    expect(verdict).to_contain_text("Not correct. The tension would be mg only")
    expect(verdict).not_to_contain_text("$")


def see_earlier_work_restored(page: Any) -> None:
    """After a reload: each part's last answer is back in its box with its verdict and the attempts
    used (the unreadable answer used none), shown outside the live regions so nothing is announced."""
    from playwright.sync_api import expect

    boxes = page.get_by_label("Your answer")
    earlier = page.locator(".earlier")
    expect(boxes.nth(0)).to_have_value(RIGHT)
    expect(earlier.nth(0)).to_have_text("Your last answer: Correct. Attempts used: 1.")
    expect(earlier.nth(0)).to_have_attribute("data-verdict", "correct")
    expect(boxes.nth(1)).to_have_value(WRONG_TENSION)
    expect(earlier.nth(1)).to_have_text(
        re.compile(r"^Your last answer: Not correct\. The tension would be mg only[^$]*Attempts used: 1\.$")
    )
    for index in range(2):
        assert earlier.nth(index).get_attribute("aria-live") is None
        assert earlier.nth(index).get_attribute("role") is None
        expect(page.locator(".verdict").nth(index)).to_have_text("")
    page.screenshot(path=str(artifacts_dir() / "student-page-key-restored.png"), full_page=True)
    # A new submission speaks in the live region and replaces the restored line.
    boxes.nth(0).press("Enter")
    expect(page.locator(".verdict").first).to_have_text("Correct. Attempts used: 2.")
    expect(earlier.nth(0)).to_be_hidden()


def with_browser(action: Any) -> None:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        try:
            context = browser.new_context(viewport={"width": 900, "height": 900})
            action(context)
        finally:
            browser.close()


def test_student_with_key_sees_preview_then_verdict_then_earlier_work_after_reload(served: Served) -> None:
    plaintext, _ = create_key(served.database, "student", "Ada", student="ada")

    def run(context: Any) -> None:
        from playwright.sync_api import expect

        page = context.new_page()
        page.goto(f"{served.url}/p/{PROBLEM}")
        key = page.get_by_label("Your student key")
        expect(key).to_be_focused()
        page.screenshot(path=str(artifacts_dir() / "student-page-key-form.png"))
        page.keyboard.type(plaintext)
        page.keyboard.press("Enter")
        # Focus moves to the problem's heading once it is loaded, for keyboard and screen reader users.
        expect(page.get_by_role("heading", level=1)).to_be_focused()
        expect(page.locator("#key-form")).to_be_hidden()
        answer_second_part_wrongly(page)
        answer_first_part(page, RIGHT, "student-page-key.png")
        # Coming back (the key is kept in the tab): the earlier work is on the page again.
        page.reload()
        expect(page.get_by_role("heading", level=1)).to_be_focused()
        see_earlier_work_restored(page)

    with_browser(run)


def test_wrong_key_is_refused_on_the_page(served: Served) -> None:
    def run(context: Any) -> None:
        from playwright.sync_api import expect

        page = context.new_page()
        page.goto(f"{served.url}/p/{PROBLEM}")
        page.get_by_label("Your student key").fill("not-a-key")
        page.get_by_role("button", name="Open").click()
        expect(page.get_by_role("alert")).to_have_text("This key was not accepted.")

    with_browser(run)


async def _launch(served: Served) -> str:
    """An LTI launch from the fake LMS into the served app (in-process, under its configured name);
    returns the session cookie the browser would now hold."""
    await anyio.to_thread.run_sync(register_fake_lms, served.database)
    mounts = {
        "all://tool.test": httpx.ASGITransport(app=served.app),
        "all://lms.test": httpx.ASGITransport(app=served.lms.app),
    }
    async with httpx.AsyncClient(mounts=mounts, timeout=30) as client:
        served.lms.trust_tool_keys((await client.get(f"{TOOL}/lti/jwks")).json())
        served.lms.next_launch = NextLaunch(
            user="student-1", roles=[LEARNER], problem=PROBLEM, lineitem=f"{ISSUER}/lineitems/7"
        )
        launched = await platform_launch(client)
        assert launched.status_code == 303, launched.text
        cookie = client.cookies.get(SESSION_COOKIE)
        assert cookie
        return cookie


def test_launched_student_sees_preview_then_verdict_then_earlier_work_after_reload(served: Served) -> None:
    session_id = anyio.run(_launch, served)

    def run(context: Any) -> None:
        from playwright.sync_api import expect

        context.add_cookies([{"name": SESSION_COOKIE, "value": session_id, "url": served.url}])
        page = context.new_page()
        page.goto(f"{served.url}/p/{PROBLEM}")
        try:
            answer_first_part(page, RIGHT, "student-page-session.png")
            # The session cookie alone (no key) reads the student's earlier work back on a reload.
            page.reload()
            expect(page.get_by_label("Your answer").first).to_have_value(RIGHT)
            expect(page.locator(".earlier").first).to_have_text(
                "Your last answer: Correct. Attempts used: 1."
            )
            expect(page.locator(".earlier").nth(1)).to_be_hidden()  # nothing submitted there yet
        finally:
            page.screenshot(path=str(artifacts_dir() / "student-page-session-last.png"), full_page=True)

    with_browser(run)
