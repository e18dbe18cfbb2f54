"""Headless Chromium drives the student page of the REAL app (`create_app`: bank, grading worker, API)
served by uvicorn on a loopback port: type an answer and see it typeset, submit, see the verdict and
the part's standing; reload and see the best score, the attempts and the history; run out of attempts
and find the part closed. Key mode with a student key; session mode after an LTI launch from the fake
LMS. The app runs on the in-memory stores. Screenshots go to `artifacts/` (or PHYSCHECK_ARTIFACTS_DIR);
axe-core runs on each state.
"""

from __future__ import annotations

import re
import shutil
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import anyio
import httpx
import pytest

from app.grading.pool import GradingPool
from app.lti.sessions import SESSION_COOKIE
from app.main import create_app
from app.settings import Settings
from problems.loader import BANK_DIR
from tests.browser import PHONE, LiveServer, check_page, serve
from tests.lti.conftest import platform_launch
from tests.lti.fake_lms import ISSUER, LEARNER, TOOL, FakeLms, NextLaunch, register_fake_lms
from tests.memory_app import memory_app_storage

pytestmark = [pytest.mark.browser, pytest.mark.slow]
PROBLEM = "yo-yo"
RIGHT = "g r^2/(r^2 + k^2)"
WRONG = "g/2"
WRONG_TENSION = "m g"  # a known mistake, whose feedback has `$...$` maths in it
UNREADABLE = "m g +"
SETTLED_BY_DIMENSION = "(g^2 r^4)^1/2/(r^2 + k^2)"  # a root, or halved: only the root is an acceleration
LIMIT = 2


@pytest.fixture(scope="module")
def limited_bank(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The built-in yo-yo alone, allowing two graded attempts per part."""
    bank = tmp_path_factory.mktemp("bank")
    shutil.copytree(BANK_DIR / PROBLEM, bank / PROBLEM)
    problem = bank / PROBLEM / "problem.yaml"
    problem.write_text(problem.read_text() + f"max_attempts: {LIMIT}\n")
    return bank


@pytest.fixture(scope="module")
def lms() -> FakeLms:
    return FakeLms()


@pytest.fixture(scope="module")
def served(
    tmp_path_factory: pytest.TempPathFactory, page_grading_pool: GradingPool, limited_bank: Path, lms: FakeLms
) -> Iterator[LiveServer]:
    settings = Settings(
        database_url="sqlite://",  # never opened: the app runs on the in-memory stores
        base_url=TOOL,  # the LTI launch below reaches the same app in-process under this name
        secret="browser-test-secret-0123",
        check_workers=1,
        bank_dir=limited_bank,
        warm_up=False,
    )
    transport = httpx.ASGITransport(app=lms.app)
    app = create_app(
        settings, pool=page_grading_pool, lms_transport=transport, open_storage=memory_app_storage
    )
    for url in serve(app):
        yield LiveServer(url, app)


def open_with_key(browse: Callable[..., Any], served: LiveServer, student: str, width: int = 1280) -> Any:
    from playwright.sync_api import expect

    key = served.key("student", student.title(), student=student)
    page = browse(f"{served.url}/p/{PROBLEM}", width=width)
    expect(page.get_by_label("Your student key")).to_be_focused()
    page.keyboard.type(key)
    page.keyboard.press("Enter")
    # Focus moves to the problem's heading once it is loaded, for keyboard and screen reader users.
    expect(page.get_by_role("heading", level=1)).to_be_focused()
    expect(page.locator("#key-form")).to_be_hidden()
    return page


def submit(page: Any, index: int, answer: str) -> Any:
    from playwright.sync_api import expect

    box = page.get_by_label("Your answer").nth(index)
    box.fill(answer)
    box.press("Enter")
    verdict = page.locator(".verdict").nth(index)
    expect(verdict).not_to_have_text(re.compile(r"^(Checking…)?$"))
    return verdict


def test_student_sees_the_reading_typeset_and_where_an_answer_cannot_be_read(
    served: LiveServer, browse: Callable[..., Any]
) -> None:
    from playwright.sync_api import expect

    page = open_with_key(browse, served, "ada")
    box = page.get_by_label("Your answer").first
    box.press_sequentially(RIGHT)
    preview = page.locator("#preview-0")
    expect(preview.locator("math")).to_be_visible()
    expect(preview.locator("math mfrac")).to_have_count(1)  # a fraction, typeset: not linear text
    expect(preview).to_contain_text("Read as")
    box.fill(SETTLED_BY_DIMENSION)
    # Two readings, one an acceleration: the page says which was taken and why.
    expect(preview.locator(".reading-note")).to_contain_text("the only reading that is")
    box.fill(UNREADABLE)
    expect(preview).to_contain_text("Cannot read this yet")
    expect(box).to_have_attribute("aria-invalid", "true")
    expect(preview.locator("mark")).to_have_count(1)  # the spot it could not read is marked
    check_page(page, "student-page-preview")


def test_student_sees_verdicts_feedback_as_maths_best_score_and_history_after_reload(
    served: LiveServer, browse: Callable[..., Any]
) -> None:
    from playwright.sync_api import expect

    page = open_with_key(browse, served, "bea")
    parts = page.locator("section.part")
    expect(parts.nth(0).locator(".attempts")).to_have_text(f"Attempts: 0 of {LIMIT} used.")
    verdict = submit(page, 1, UNREADABLE)
    expect(verdict).to_contain_text("Could not read this answer; no attempt used.")
    verdict = submit(page, 1, WRONG_TENSION)
    expect(verdict).to_contain_text("Not correct. The tension would be")
    expect(verdict.locator("math")).not_to_have_count(0)  # the feedback's maths is typeset
    expect(verdict).not_to_contain_text("$")
    expect(verdict).not_to_contain_text("\\")
    verdict = submit(page, 0, RIGHT)
    expect(verdict).to_contain_text("Correct.")
    expect(parts.nth(0).locator(".best")).to_have_text("Solved: best score 1 of 1.")
    verdict = submit(page, 0, WRONG)  # a retry that is wrong does not lower the standing
    expect(verdict).to_contain_text("Not correct.")
    expect(parts.nth(0).locator(".best")).to_have_text("Solved: best score 1 of 1.")
    expect(page.locator("#standing")).to_contain_text("Your score: 1 of 3")
    check_page(page, "student-page-desktop")
    page.reload()
    page.get_by_label("Your student key").wait_for(state="hidden")
    expect(page.get_by_role("heading", level=1)).to_be_focused()
    expect(page.get_by_label("Your answer").nth(0)).to_have_value(WRONG)
    expect(parts.nth(0).locator(".best")).to_have_text("Solved: best score 1 of 1.")
    expect(parts.nth(0).locator(".best")).to_have_attribute("data-verdict", "correct")
    history = parts.nth(1).locator(".history")
    history.locator("summary").click()
    expect(history.locator("li")).to_have_count(2)  # the unreadable answer and the known mistake
    expect(history.locator("li").first).to_contain_text("Not correct.")
    expect(history.locator("li").first.locator("math")).not_to_have_count(0)
    expect(history.locator("li").nth(1)).to_contain_text("no attempt used")
    check_page(page, "student-page-reloaded")


def test_a_part_is_closed_with_a_clear_message_when_its_attempts_are_used_up(
    served: LiveServer, browse: Callable[..., Any]
) -> None:
    from playwright.sync_api import expect

    page = open_with_key(browse, served, "cal", width=PHONE)
    for _ in range(LIMIT):
        submit(page, 0, WRONG)
    part = page.locator("section.part").first
    expect(part.locator(".notice.locked")).to_contain_text(f"You have used all {LIMIT} attempts on this part")
    expect(page.get_by_label("Your answer").first).to_be_disabled()
    expect(part.get_by_role("button", name="Check answer")).to_be_disabled()
    expect(part.locator(".attempts")).to_have_text(f"Attempts: {LIMIT} of {LIMIT} used.")
    check_page(page, "student-page-locked-phone")
    page.reload()
    expect(page.get_by_label("Your answer").first).to_be_disabled()
    expect(page.locator("section.part").first.locator(".notice.locked")).to_be_visible()
    expect(page.get_by_text("has used all")).to_have_count(0)  # never the storage layer's wording


def test_wrong_key_is_refused_on_the_page(served: LiveServer, browse: Callable[..., Any]) -> None:
    from playwright.sync_api import expect

    page = browse(f"{served.url}/p/{PROBLEM}")
    page.get_by_label("Your student key").fill("not-a-key")
    page.get_by_role("button", name="Open").click()
    expect(page.get_by_role("alert")).to_have_text("This key was not accepted.")
    check_page(page, "student-page-key-form")


async def _launch(served: LiveServer, lms: FakeLms) -> str:
    """An LTI launch from the fake LMS into the served app (in-process, under its configured name);
    returns the session cookie the browser would now hold."""
    await anyio.to_thread.run_sync(register_fake_lms, served.stores)
    mounts = {
        "all://tool.test": httpx.ASGITransport(app=served.app),
        "all://lms.test": httpx.ASGITransport(app=lms.app),
    }
    async with httpx.AsyncClient(mounts=mounts, timeout=30) as client:
        lms.trust_tool_keys((await client.get(f"{TOOL}/lti/jwks")).json())
        lms.next_launch = NextLaunch(
            user="student-1", roles=[LEARNER], problem=PROBLEM, lineitem=f"{ISSUER}/lineitems/7"
        )
        launched = await platform_launch(client)
        assert launched.status_code == 303, launched.text
        cookie = client.cookies.get(SESSION_COOKIE)
        assert cookie
        return cookie


def test_launched_student_works_the_problem_and_finds_it_after_reload(
    served: LiveServer, lms: FakeLms, browse: Callable[..., Any]
) -> None:
    from playwright.sync_api import expect

    # Playwright's sync API runs an event loop in this thread: launch from another one.
    with ThreadPoolExecutor(1) as thread:
        session_id = thread.submit(anyio.run, _launch, served, lms).result(timeout=60)
    cookies = [{"name": SESSION_COOKIE, "value": session_id, "url": served.url}]
    page = browse(f"{served.url}/p/{PROBLEM}", cookies=cookies)
    expect(page.locator(".verdict").first).to_be_hidden()
    verdict = submit(page, 0, RIGHT)
    expect(verdict).to_contain_text("Correct.")
    # The session cookie alone (no key) shows the student's work again on a reload.
    page.reload()
    expect(page.get_by_label("Your answer").first).to_have_value(RIGHT)
    expect(page.locator("section.part").first.locator(".best")).to_have_text("Solved: best score 1 of 1.")
    expect(page.locator("section.part").nth(1).locator(".history")).to_have_count(0)  # nothing there yet
    check_page(page, "student-page-session")
