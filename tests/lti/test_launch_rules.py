"""Launch rules beyond the signature: the form post is the only source of id_token and state, an old
token is refused, a link must name a problem we have, and deep linking honours what the platform takes."""

from __future__ import annotations

import re
from html import unescape

import httpx
import pytest

from app.lti.context import LtiContext
from app.storage import Stores
from tests.lti.conftest import Fakes, platform_launch, start_login
from tests.lti.fake_lms import INSTRUCTOR, ISSUER, TOOL, FakeLms, NextLaunch
from tests.lti.forge import FromNow, launch_claims, rs256
from tests.lti.test_launch_refusals import assert_refusal_page

pytestmark = pytest.mark.anyio


# ---- id_token and state come from the form post only -----------------------------------------------


@pytest.mark.parametrize(
    ("in_query", "code"),
    [({"id_token", "state"}, "missing_id_token"), ({"state"}, "missing_state"), ({"id_token"}, "missing_id_token")],
    ids=["both-in-query", "state-in-query", "id_token-in-query"],
)  # fmt: skip
async def test_id_token_or_state_in_the_query_string_is_not_read(
    browser: httpx.AsyncClient,
    lms: FakeLms,
    fakes: Fakes,
    in_query: set[str],
    code: str,
):
    login = await start_login(browser)
    fields = {"id_token": rs256(launch_claims(login.nonce), lms.private_pem, lms.kid), "state": login.state}
    query = {k: v for k, v in fields.items() if k in in_query}
    body = {k: v for k, v in fields.items() if k not in in_query}
    response = await browser.post(f"{TOOL}/lti/launch", params=query, data=body)
    assert_refusal_page(response, 400, code)
    assert fakes.sessions.records() == []


# ---- token age ---------------------------------------------------------------------------------------


def token_issued(lms: FakeLms, seconds_ago: int):
    def forge(nonce: str) -> str:
        claims = launch_claims(nonce, iat=FromNow(-seconds_ago), exp=FromNow(300))
        return rs256(claims, lms.private_pem, lms.kid)

    return forge


async def launch_with(browser: httpx.AsyncClient, forge) -> httpx.Response:
    login = await start_login(browser)
    return await browser.post(
        f"{TOOL}/lti/launch", data={"id_token": forge(login.nonce), "state": login.state}
    )


@pytest.mark.parametrize(
    ("max_age", "seconds_ago", "accepted"),
    [(None, 3600 + 120, False), (None, 3000, True), (600, 700, False), (600, 300, True)],
    ids=["default-hour-exceeded", "within-default-hour", "configured-exceeded", "within-configured"],
)
async def test_token_issued_longer_ago_than_the_maximum_is_refused(
    browser: httpx.AsyncClient,
    lms: FakeLms,
    context: LtiContext,
    fakes: Fakes,
    max_age: int | None,
    seconds_ago: int,
    accepted: bool,
):
    if max_age is not None:
        context.settings = context.settings.model_copy(update={"lti_max_token_age_seconds": max_age})
    response = await launch_with(browser, token_issued(lms, seconds_ago))
    if accepted:
        assert response.status_code == 303, response.text
    else:
        assert_refusal_page(response, 401, "token_too_old")
        assert fakes.sessions.records() == []


# ---- the problem a link names ----------------------------------------------------------------------


async def test_launch_for_an_unknown_problem_gets_a_clear_page(
    browser: httpx.AsyncClient, lms: FakeLms, fakes: Fakes
):
    lms.next_launch.problem = "no-such-problem"
    response = await platform_launch(browser)
    assert_refusal_page(response, 404, "unknown_problem")
    assert "no-such-problem" in response.text
    assert fakes.sessions.records() == fakes.outbox.targets() == []


async def test_launch_for_a_retired_problem_gets_a_clear_page(
    browser: httpx.AsyncClient, lms: FakeLms, stores: Stores, fakes: Fakes
):
    stores.problems.retire("yo-yo")
    lms.next_launch.problem = "yo-yo"
    assert_refusal_page(await platform_launch(browser), 404, "unknown_problem")
    assert fakes.outbox.targets() == []


# ---- deep linking: accept_multiple and accept_types ------------------------------------------------


def field(html: str, name: str) -> str:
    match = re.search(rf'name="{name}" value="([^"]*)"', html)
    assert match, f"no field {name}"
    return unescape(match.group(1))


def form_action(html: str) -> str:
    match = re.search(r'<form method="post" action="([^"]+)"', html)
    assert match
    return TOOL + unescape(match.group(1))


async def open_picker(browser: httpx.AsyncClient, lms: FakeLms, **settings) -> httpx.Response:
    lms.next_launch = NextLaunch(
        roles=[INSTRUCTOR], problem=None, lineitem=None, deep_linking=True, **settings
    )
    return await platform_launch(browser)


async def test_single_choice_platform_gets_a_one_choice_picker(browser: httpx.AsyncClient, lms: FakeLms):
    picker = await open_picker(browser, lms, accept_multiple=False)
    assert picker.status_code == 200, picker.text
    assert 'type="radio" name="problem"' in picker.text
    assert 'type="checkbox"' not in picker.text
    answer = await browser.post(
        form_action(picker.text), data={"csrf_token": field(picker.text, "csrf_token"), "problem": "yo-yo"}
    )
    assert answer.status_code == 200
    config = lms.config()
    config.get_registration()
    items = config.validate_deeplinking_resp({"JWT": field(answer.text, "JWT")})
    assert [item["custom"] for item in items] == [{"problem": "yo-yo"}]


async def test_single_choice_platform_is_never_sent_two_links(browser: httpx.AsyncClient, lms: FakeLms):
    picker = await open_picker(browser, lms, accept_multiple=False)
    form = {"csrf_token": field(picker.text, "csrf_token"), "problem": ["moving-wedge", "yo-yo"]}
    answer = await browser.post(form_action(picker.text), data=form)
    assert_refusal_page(answer, 400, "one_problem_only")
    assert f'action="{ISSUER}/deep-link-return"' not in answer.text


async def test_multiple_choice_platform_gets_checkboxes(browser: httpx.AsyncClient, lms: FakeLms):
    picker = await open_picker(browser, lms, accept_multiple=True)
    assert 'type="checkbox" name="problem"' in picker.text


async def test_platform_that_takes_no_resource_links_gets_a_clear_page(
    browser: httpx.AsyncClient, lms: FakeLms, fakes: Fakes
):
    response = await open_picker(browser, lms, accept_types={"link", "file"})
    assert_refusal_page(response, 400, "resource_links_not_accepted")
    assert "picker" not in response.text and 'name="problem"' not in response.text
    assert fakes.sessions.records() == []
