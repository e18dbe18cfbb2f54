"""The student page: after a launch (cookie) or with a student key; MathML, escaping, framing."""

from __future__ import annotations

import re
from typing import Any

import httpx
import pytest

from app.lti.mathml import tex_to_mathml, text_to_html
from app.lti.student_page import render_content
from tests.lti.conftest import STUDENT_KEY, platform_launch
from tests.lti.fake_lms import ISSUER, TOOL

pytestmark = pytest.mark.anyio


async def launched_page(browser: httpx.AsyncClient) -> httpx.Response:
    launch = await platform_launch(browser)
    return await browser.get(TOOL + launch.headers["location"])


async def test_page_after_launch_shows_statement_as_mathml_and_one_box_per_part(browser: httpx.AsyncClient):
    page = await launched_page(browser)
    assert page.status_code == 200
    assert '<math display="inline" alttext="\\theta"><mi>θ</mi></math>' in page.text
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
    assert '<script nonce="' in page.text and 'src="/lti/static/student.js"' in page.text


async def test_page_may_be_framed_only_by_registered_platforms(browser: httpx.AsyncClient):
    page = await launched_page(browser)
    csp = page.headers["content-security-policy"]
    assert f"frame-ancestors 'self' {ISSUER};" in csp
    assert "script-src 'nonce-" in csp and "unsafe-inline" not in csp.split("style-src")[0]


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


async def test_page_script_is_served_from_this_origin(browser: httpx.AsyncClient):
    script = await browser.get(f"{TOOL}/lti/static/student.js")
    assert script.status_code == 200
    assert script.headers["content-type"].startswith("text/javascript")
    assert "innerHTML = html" in script.text  # only our own fragment is ever inserted as HTML


@pytest.mark.parametrize(
    ("tex", "expected"),
    [
        ("m", "<mi>m</mi>"),
        ("\\theta", "<mi>θ</mi>"),
        ("v_0^2", "<msubsup><mi>v</mi><mn>0</mn><mn>2</mn></msubsup>"),
        ("\\frac{1}{2}", "<mfrac><mn>1</mn><mn>2</mn></mfrac>"),
        ("\\sqrt{k}", "<msqrt><mi>k</mi></msqrt>"),
        ("\\sin^2\\theta", "<msup><mi>sin</mi><mn>2</mn></msup><mi>θ</mi>"),
        ("U_0[(r_0/r)^{12}]", "<msup><mo>)</mo><mn>12</mn></msup>"),  # as TeX: the script sits on the bracket
        ("a < b", "<mo>&lt;</mo>"),
        ("\\unknown", "<mtext>\\unknown</mtext>"),
    ],
    ids=["letter", "greek", "sub-sup", "frac", "sqrt", "function-power", "nested", "escaped-op", "unknown"],
)
def test_tex_becomes_mathml(tex: str, expected: str):
    assert expected in tex_to_mathml(tex)


@pytest.mark.parametrize(
    "text",
    ["$</math><script>x</script>$", "<img src=x onerror=alert(1)>", '$"onmouseover="x$'],
    ids=["closing-math", "markup", "attribute-break"],
)
def test_no_markup_survives_rendering(text: str):
    html = text_to_html(text)
    assert "<script" not in html and "<img" not in html and '"onmouseover' not in html


YO_YO_VIEW: dict[str, Any] = {
    "title": "Yo-yo",
    "statement": "A yo-yo.",
    "parts": [
        {"id": "acceleration", "kind": "symbolic", "prompt": "a", "units": None, "symbols": ["g"]},
        {
            "id": "tension",
            "kind": "symbolic",
            "prompt": "T",
            "units": None,
            "symbols": ["g"],
            "max_attempts": 3,
        },
    ],
}


@pytest.mark.parametrize(
    ("student", "expected", "absent"),
    [
        ("ada", 'data-part="acceleration" data-student="ada" novalidate', "data-max-attempts"),
        ('x"><script>', 'data-student="x&quot;&gt;&lt;script&gt;"', "<script>"),
        (None, '<form class="answer" data-part="acceleration" novalidate>', "data-student"),
    ],
    ids=["names-the-student", "student-is-escaped", "no-student-no-attribute"],
)
def test_answer_forms_name_whose_earlier_work_the_script_restores(
    student: str | None, expected: str, absent: str
) -> None:
    html = render_content({**YO_YO_VIEW, "parts": YO_YO_VIEW["parts"][:1]}, student=student)
    assert expected in html
    assert absent not in html


@pytest.mark.parametrize(
    ("limit", "expected"),
    [(3, ' data-max-attempts="3"'), (None, ""), (0, ""), (True, ""), ("3", "")],
    ids=["limit", "none", "zero", "bool", "text"],
)
def test_a_part_limit_in_the_view_becomes_the_forms_max_attempts(limit: object, expected: str) -> None:
    part = {**YO_YO_VIEW["parts"][0], "max_attempts": limit}
    html = render_content({**YO_YO_VIEW, "parts": [part]}, student="ada")
    assert f'data-student="ada"{expected} novalidate' in html


def test_restored_work_goes_outside_the_live_region_so_it_is_not_announced() -> None:
    html = render_content(YO_YO_VIEW, student="ada")
    assert html.count('<p class="earlier" hidden></p>') == 2
    assert html.count('<p class="verdict" role="status" aria-live="polite"></p>') == 2


async def test_content_for_a_student_key_names_that_student(browser: httpx.AsyncClient) -> None:
    response = await browser.get(
        f"{TOOL}/p/moving-wedge/content", headers={"Authorization": f"Bearer {STUDENT_KEY}"}
    )
    assert response.status_code == 200
    assert 'data-student="key-student"' in response.text


async def test_page_after_launch_names_the_launched_student(browser: httpx.AsyncClient) -> None:
    page = await launched_page(browser)
    assert re.search(r'<form class="answer" data-part="[^"]+" data-student="[^"]+"', page.text)


async def test_page_script_restores_earlier_work_from_the_submissions_api(browser: httpx.AsyncClient) -> None:
    script = await browser.get(f"{TOOL}/lti/static/student.js")
    assert "/v1/submissions?problem=" in script.text
    assert "earlier.textContent" in script.text and "earlier.innerHTML" not in script.text
