"""A real platform launches the tool: session opened, cookie attributes, redirect to the problem."""

from __future__ import annotations

import httpx
import pytest

from app.auth import Role
from tests.lti.conftest import Fakes, platform_launch
from tests.lti.fake_lms import INSTRUCTOR, FakeLms

pytestmark = pytest.mark.anyio


async def test_launch_opens_session_and_redirects_to_problem_page(browser: httpx.AsyncClient, fakes: Fakes):
    response = await platform_launch(browser)
    assert response.status_code == 303, response.text
    assert response.headers["location"] == "/p/moving-wedge"
    [opened] = fakes.sessions.records()
    assert opened.student == "lti:1:student-1"
    assert opened.role is Role.STUDENT
    assert fakes.launches.logins() == []


async def test_session_cookie_is_cross_site_secure_partitioned_and_http_only(browser: httpx.AsyncClient):
    response = await platform_launch(browser)
    cookie = next(
        v for k, v in response.headers.multi_items() if k == "set-cookie" and "physcheck_session" in v
    )
    attributes = {part.strip().lower() for part in cookie.split(";")}
    assert {"samesite=none", "secure", "partitioned", "httponly"} <= attributes


async def test_launch_records_grade_target_from_ags_claim(browser: httpx.AsyncClient, fakes: Fakes):
    await platform_launch(browser)
    [(_, problem_id, sub, lineitem_url)] = fakes.outbox.targets()
    assert (problem_id, sub, lineitem_url) == ("moving-wedge", "student-1", "https://lms.test/lineitems/1")


async def test_instructor_role_comes_from_signed_roles(
    browser: httpx.AsyncClient, lms: FakeLms, fakes: Fakes
):
    lms.next_launch.roles = [INSTRUCTOR]
    await platform_launch(browser)
    [opened] = fakes.sessions.records()
    assert opened.role is Role.INSTRUCTOR


async def test_link_without_problem_is_refused_with_page(browser: httpx.AsyncClient, lms: FakeLms):
    lms.next_launch.problem = None
    response = await platform_launch(browser)
    assert response.status_code == 400
    assert "custom parameter" in response.text
