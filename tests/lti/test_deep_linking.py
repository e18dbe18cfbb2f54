"""Deep Linking 2.0: an instructor picks problems; the platform receives signed resource links."""

from __future__ import annotations

import re
from html import unescape

import httpx
import pytest

from tests.lti.conftest import platform_launch
from tests.lti.fake_lms import INSTRUCTOR, ISSUER, LEARNER, TOOL, FakeLms, NextLaunch

pytestmark = pytest.mark.anyio


def field(html: str, name: str) -> str:
    match = re.search(rf'name="{name}" value="([^"]*)"', html)
    assert match, f"no field {name}"
    return unescape(match.group(1))


async def open_picker(browser: httpx.AsyncClient, lms: FakeLms) -> httpx.Response:
    lms.next_launch = NextLaunch(roles=[INSTRUCTOR], problem=None, lineitem=None, deep_linking=True)
    response = await platform_launch(browser)
    assert response.status_code == 200, response.text
    return response


def form_action(html: str) -> str:
    match = re.search(r'<form method="post" action="([^"]+)"', html)
    assert match
    return TOOL + unescape(match.group(1))


async def test_instructor_picks_problems_and_platform_gets_signed_links(
    browser: httpx.AsyncClient, lms: FakeLms
):
    picker = await open_picker(browser, lms)
    assert "moving-wedge" in picker.text and "yo-yo" in picker.text
    answer = await browser.post(
        form_action(picker.text),
        data={"csrf_token": field(picker.text, "csrf_token"), "problem": ["moving-wedge", "yo-yo"]},
    )
    assert answer.status_code == 200
    assert f'action="{ISSUER}/deep-link-return"' in answer.text
    config = lms.config()
    config.get_registration()
    items = config.validate_deeplinking_resp({"JWT": field(answer.text, "JWT")})
    assert [(i["type"], i["custom"], i["lineItem"]["scoreMaximum"]) for i in items] == [
        ("ltiResourceLink", {"problem": "moving-wedge"}, 2.0),
        ("ltiResourceLink", {"problem": "yo-yo"}, 1.0),
    ]
    assert all(item["url"] == f"{TOOL}/lti/launch" for item in items)


async def test_picker_page_may_only_be_framed_by_registered_platforms(
    browser: httpx.AsyncClient, lms: FakeLms
):
    picker = await open_picker(browser, lms)
    csp = picker.headers["content-security-policy"]
    assert f"frame-ancestors 'self' {ISSUER}" in csp


async def test_student_cannot_deep_link(browser: httpx.AsyncClient, lms: FakeLms):
    lms.next_launch = NextLaunch(roles=[LEARNER], problem=None, lineitem=None, deep_linking=True)
    response = await platform_launch(browser)
    assert response.status_code == 403
    assert "<code>not_instructor</code>" in response.text


async def test_selection_with_wrong_csrf_token_is_refused(browser: httpx.AsyncClient, lms: FakeLms):
    picker = await open_picker(browser, lms)
    answer = await browser.post(form_action(picker.text), data={"csrf_token": "forged", "problem": "yo-yo"})
    assert answer.status_code == 403
    assert "<code>bad_csrf_token</code>" in answer.text


async def test_selection_is_used_up(browser: httpx.AsyncClient, lms: FakeLms):
    picker = await open_picker(browser, lms)
    form = {"csrf_token": field(picker.text, "csrf_token"), "problem": "yo-yo"}
    assert (await browser.post(form_action(picker.text), data=form)).status_code == 200
    again = await browser.post(form_action(picker.text), data=form)
    assert again.status_code == 400
    assert "<code>unknown_deep_link</code>" in again.text


async def test_selection_of_unknown_problem_is_refused(browser: httpx.AsyncClient, lms: FakeLms):
    picker = await open_picker(browser, lms)
    form = {"csrf_token": field(picker.text, "csrf_token"), "problem": "<script>"}
    answer = await browser.post(form_action(picker.text), data=form)
    assert answer.status_code == 400
    assert "<script>" not in answer.text
