"""The session cookie as an API principal: identity from the launch, CSRF token for writes."""

from __future__ import annotations

from typing import Any

import httpx
import pytest
from fastapi import FastAPI, Request

from app.lti.sessions import (
    CSRF_HEADER,
    current_session,
    principal_from_session,
    role_from_claims,
    student_id,
)
from tests.lti.conftest import platform_launch
from tests.lti.fake_lms import INSTRUCTOR, LEARNER, TOOL, FakeLms

pytestmark = pytest.mark.anyio


@pytest.fixture
def whoami_app(tool_app: FastAPI) -> FastAPI:
    def whoami(request: Request) -> dict[str, Any]:
        principal = principal_from_session(request)
        if principal is None:
            return {"principal": None}
        found = current_session(request)
        assert found is not None
        return {"role": principal.role.value, "student": principal.student, "csrf": found[1].csrf_token}

    tool_app.add_api_route("/whoami", whoami, methods=["GET", "POST"])
    return tool_app


async def test_launched_student_is_a_student_principal(whoami_app: FastAPI, browser: httpx.AsyncClient):
    await platform_launch(browser)
    answer = (await browser.get(f"{TOOL}/whoami")).json()
    assert (answer["role"], answer["student"]) == ("student", "lti:1:student-1")


async def test_write_without_csrf_token_is_anonymous(whoami_app: FastAPI, browser: httpx.AsyncClient):
    await platform_launch(browser)
    assert (await browser.post(f"{TOOL}/whoami")).json() == {"principal": None}
    assert (await browser.post(f"{TOOL}/whoami", headers={CSRF_HEADER: "forged"})).json() == {
        "principal": None
    }


async def test_write_with_csrf_token_is_the_student(whoami_app: FastAPI, browser: httpx.AsyncClient):
    await platform_launch(browser)
    csrf = (await browser.get(f"{TOOL}/whoami")).json()["csrf"]
    answer = (await browser.post(f"{TOOL}/whoami", headers={CSRF_HEADER: csrf})).json()
    assert answer["student"] == "lti:1:student-1"


async def test_no_cookie_or_unknown_cookie_is_anonymous(whoami_app: FastAPI, browser: httpx.AsyncClient):
    assert (await browser.get(f"{TOOL}/whoami")).json() == {"principal": None}
    browser.cookies.set("physcheck_session", "made-up", domain="tool.test")
    assert (await browser.get(f"{TOOL}/whoami")).json() == {"principal": None}


async def test_instructor_session_files_no_student_identity(
    whoami_app: FastAPI, browser: httpx.AsyncClient, lms: FakeLms
):
    lms.next_launch.roles = [INSTRUCTOR]
    await platform_launch(browser)
    answer = (await browser.get(f"{TOOL}/whoami")).json()
    assert (answer["role"], answer["student"]) == ("instructor", None)


@pytest.mark.parametrize(
    ("roles", "expected"),
    [
        ([LEARNER], "student"),
        ([INSTRUCTOR], "instructor"),
        (
            [LEARNER, "http://purl.imsglobal.org/vocab/lis/v2/membership/Instructor#TeachingAssistant"],
            "instructor",
        ),
        (["Instructor"], "student"),  # short names are not LIS v2 URIs: not trusted as instructor
        ([], "student"),
    ],
    ids=["learner", "instructor", "teaching-assistant", "short-name", "none"],
)
def test_role_comes_from_lis_role_uris(roles: list[str], expected: str):
    assert role_from_claims(roles).value == expected


def test_overlong_sub_is_hashed_into_the_student_column():
    assert student_id(3, "x" * 300).startswith("lti:3:sha256:")
    assert len(student_id(3, "x" * 300)) <= 200
