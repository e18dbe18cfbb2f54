"""The student page: after a launch (cookie) or with a student key; MathML, escaping, framing."""

from __future__ import annotations

import re
from typing import Any

import httpx
import pytest

from app.web.student_page import tolerance_text
from tests.lti.conftest import STUDENT_KEY, platform_launch
from tests.lti.fake_lms import ISSUER, TOOL

pytestmark = pytest.mark.anyio


async def launched_page(browser: httpx.AsyncClient) -> httpx.Response:
    launch = await platform_launch(browser)
    return await browser.get(TOOL + launch.headers["location"])


async def test_page_after_launch_shows_statement_as_mathml_and_one_box_per_part(browser: httpx.AsyncClient):
    page = await launched_page(browser)
    assert page.status_code == 200
    assert '<math display="inline" alttext="\\theta"><mrow><mi>θ</mi></mrow></math>' in page.text
    assert len(re.findall(r'<input id="answer-\d+" name="answer"', page.text)) == 2
    assert len(re.findall(r'<label for="answer-\d+">', page.text)) == 2
    assert 'aria-live="polite"' in page.text
    assert 'data-mode="session"' in page.text


async def test_page_escapes_everything_from_the_problem(browser: httpx.AsyncClient):
    page = await launched_page(browser)
    assert "<script>alert(1)</script>" not in page.text
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in page.text
    assert "<i>for</i>" not in page.text


async def test_page_carries_session_csrf_token_for_its_script(browser: httpx.AsyncClient):
    page = await launched_page(browser)
    assert re.search(r'<meta name="csrf-token" content="[A-Za-z0-9_-]{20,}">', page.text)
    assert '<script src="/static/student.js" defer></script>' in page.text


async def test_page_may_be_framed_only_by_registered_platforms(browser: httpx.AsyncClient):
    page = await launched_page(browser)
    csp = page.headers["content-security-policy"]
    assert f"frame-ancestors 'self' {ISSUER};" in csp
    assert "script-src 'self';" in csp and "unsafe-inline" not in csp


async def test_page_without_session_asks_for_a_student_key(browser: httpx.AsyncClient):
    page = await browser.get(f"{TOOL}/p/moving-wedge")
    assert page.status_code == 200
    assert 'id="key-form"' in page.text and 'data-mode="key"' in page.text
    assert "<math" not in page.text


@pytest.mark.parametrize(
    ("authorization", "status"),
    [(f"Bearer {STUDENT_KEY}", 200), ("Bearer wrong", 401), (None, 401)],
    ids=["student-key", "unknown-key", "no-key"],
)
async def test_content_for_a_student_key(browser: httpx.AsyncClient, authorization: str | None, status: int):
    headers = {"Authorization": authorization} if authorization else {}
    response = await browser.get(f"{TOOL}/p/moving-wedge/content", headers=headers)
    assert response.status_code == status
    if status == 200:
        assert "key-student" in response.text and "<math" in response.text


async def test_unknown_problem_is_a_plain_not_found_page(browser: httpx.AsyncClient):
    await platform_launch(browser)
    page = await browser.get(f"{TOOL}/p/no-such-problem")
    assert page.status_code == 404
    assert "No such problem" in page.text


@pytest.mark.parametrize(
    ("tolerance", "units", "expected"),
    [
        ({"rel": 0.01}, "m/s^2", "Counted right within 1 % of the expected value."),
        ({"abs": 0.5}, "m", "Counted right within ±0.5 m."),
        ({"abs": 0.5}, "1", "Counted right within ±0.5."),
        ({"sigfigs": 3}, "N", "Counted right given to exactly 3 significant figures."),
        (None, "N", ""),
    ],
    ids=["relative", "absolute", "absolute-dimensionless", "sigfigs", "none"],
)
def test_a_numeric_parts_tolerance_is_said_in_words(tolerance: Any, units: str, expected: str) -> None:
    assert tolerance_text(tolerance, units) == expected


async def test_content_for_a_student_key_names_that_student(browser: httpx.AsyncClient) -> None:
    response = await browser.get(
        f"{TOOL}/p/moving-wedge/content", headers={"Authorization": f"Bearer {STUDENT_KEY}"}
    )
    assert response.status_code == 200
    assert 'data-student="key-student"' in response.text


async def test_page_after_launch_names_the_launched_student(browser: httpx.AsyncClient) -> None:
    page = await launched_page(browser)
    assert re.search(r'<form class="answer" data-part="[^"]+" data-student="[^"]+"', page.text)


async def test_every_part_shows_its_attempts_from_the_start(browser: httpx.AsyncClient) -> None:
    page = await launched_page(browser)
    assert page.text.count("Attempts: 0 used (no limit).") == 2
    assert "Your score" not in page.text  # nothing attempted yet


@pytest.mark.parametrize(
    ("authorization", "status"),
    [(f"Bearer {STUDENT_KEY}", 200), ("Bearer wrong", 401), (None, 401)],
    ids=["student-key", "unknown-key", "no-key"],
)
async def test_a_parts_work_fragment_needs_a_student(
    browser: httpx.AsyncClient, authorization: str | None, status: int
) -> None:
    headers = {"Authorization": authorization} if authorization else {}
    response = await browser.get(f"{TOOL}/p/moving-wedge/parts/no-such-part/work", headers=headers)
    assert response.status_code == (404 if status == 200 else status)
