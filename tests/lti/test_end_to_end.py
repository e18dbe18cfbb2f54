"""LTI end to end through the real service: the app from `create_app` (bank, grading workers, outbox,
API) and the fake LMS (the real `lti1p3platform` platform), both on loopback ASGI. An instructor deep
links a bank problem, a student launches it, answers on the student page through the API with the
session cookie and CSRF token, and the score reaches the LMS once.

The whole journey runs on SQLite and on PostgreSQL; the tests of who may do what run on the in-memory
stores (their `backend` fixture).
"""

from __future__ import annotations

import re
import time
from collections.abc import AsyncIterator
from dataclasses import dataclass
from html import unescape
from pathlib import Path
from typing import Any

import anyio
import httpx
import pytest
from fastapi import FastAPI
from starlette.concurrency import run_in_threadpool

from app.db.database import Database
from app.db.records import Role
from app.grading.pool import GradingPool
from app.lti.outbox import DELIVERED, PENDING, SENDING, OutboxWorker
from app.main import create_app
from app.settings import Settings
from app.storage import Stores
from app.storage.memory import MemoryScoreOutbox
from tests.lti.conftest import platform_launch
from tests.lti.fake_lms import (
    INSTRUCTOR,
    ISSUER,
    LEARNER,
    TOOL,
    FakeLms,
    NextLaunch,
    ReceivedScore,
    register_fake_lms,
)
from tests.memory_app import memory_app_storage

# About a second or two each (one bank problem, one shared grading worker): not marked slow.
pytestmark = pytest.mark.anyio

PROBLEM = "yo-yo"  # three parts, so the line item is out of 3
LINEITEM = f"{ISSUER}/lineitems/7"
RIGHT = "g r^2/(r^2 + k^2)"
WRONG = "g"  # a known mistake: graded incorrect, still a score (0) for the LMS
UNREADABLE = "g r^2 /"
DELIVERY_TIMEOUT = 20.0

# app/deps.py:current_principal reads only `Authorization: Bearer` and never calls
# `app.lti.sessions.principal_from_session`, so the page's API calls after a launch get 401. Strict:
# once it does, these pass and the marker must go.


SQL_BACKENDS = ["sqlite", pytest.param("postgres", marks=pytest.mark.postgres)]


@dataclass
class Sites:
    """The student's browser (cookies for both sites), the LMS, and the tool's app and stores."""

    browser: httpx.AsyncClient
    lms: FakeLms
    app: FastAPI
    stores: Stores
    settings: Settings


@pytest.fixture
def backend() -> str:
    """The in-memory stores, unless a test parametrizes `backend` with SQL_BACKENDS."""
    return "memory"


@pytest.fixture
def e2e_settings(backend: str, request: pytest.FixtureRequest, yo_yo_bank: Path) -> Settings:
    url = "sqlite://"  # never opened on the fakes
    if backend != "memory":
        db: Database = request.getfixturevalue("db")
        url = db.url
    return Settings(
        database_url=url,
        base_url=TOOL,
        secret="end-to-end-secret-0123",
        check_workers=1,
        bank_dir=yo_yo_bank,
        warm_up=False,  # the one problem compiles on first use
    )


@pytest.fixture
async def sites(backend: str, e2e_settings: Settings, lti_grading_pool: GradingPool) -> AsyncIterator[Sites]:
    lms = FakeLms()
    options: dict[str, Any] = {"open_storage": memory_app_storage} if backend == "memory" else {}
    transport = httpx.ASGITransport(app=lms.app)
    app = create_app(e2e_settings, pool=lti_grading_pool, lms_transport=transport, **options)
    async with app.router.lifespan_context(app):
        stores: Stores = app.state.services.stores
        await run_in_threadpool(register_fake_lms, stores)
        mounts = {
            "all://tool.test": httpx.ASGITransport(app=app),
            "all://lms.test": httpx.ASGITransport(app=lms.app),
        }
        async with httpx.AsyncClient(mounts=mounts, timeout=30) as browser:
            # What an LMS administrator does: paste the tool's JWKS URL (here: its keys).
            lms.trust_tool_keys((await browser.get(f"{TOOL}/.well-known/jwks.json")).json())
            yield Sites(browser, lms, app, stores, e2e_settings)


def field(html: str, name: str) -> str:
    match = re.search(rf'name="{name}" value="([^"]*)"', html)
    assert match, f"no field {name} in {html[:500]}"
    return unescape(match.group(1))


def meta(html: str, name: str) -> str:
    match = re.search(rf'<meta name="{name}" content="([^"]*)"', html)
    assert match, f"no meta {name}"
    return unescape(match.group(1))


async def deep_link(sites: Sites, problem: str) -> dict[str, Any]:
    """The instructor adds `problem` to the course; returns the content item as the platform read it."""
    sites.lms.next_launch = NextLaunch(
        user="teacher-1", roles=[INSTRUCTOR], problem=None, lineitem=None, deep_linking=True
    )
    picker = await platform_launch(sites.browser)
    assert picker.status_code == 200, picker.text
    action = re.search(r'<form method="post" action="([^"]+)"', picker.text)
    assert action is not None
    answer = await sites.browser.post(
        TOOL + unescape(action.group(1)),
        data={"csrf_token": field(picker.text, "csrf_token"), "problem": problem},
    )
    assert answer.status_code == 200, answer.text
    config = sites.lms.config()
    config.get_registration()
    [item] = config.validate_deeplinking_resp({"JWT": field(answer.text, "JWT")})
    return dict(item)


async def launch_student(sites: Sites, item: dict[str, Any]) -> str:
    """The student opens the resource link the instructor made; returns the page's CSRF token."""
    return await open_link(sites, item, "student-1", LEARNER)


async def open_link(sites: Sites, item: dict[str, Any], user: str, role: str) -> str:
    """`user` opens the resource link with `role`; returns the page's CSRF token."""
    sites.lms.next_launch = NextLaunch(
        user=user, roles=[role], problem=item["custom"]["problem"], lineitem=LINEITEM
    )
    launched = await platform_launch(sites.browser)
    assert launched.status_code == 303, launched.text
    page = await sites.browser.get(TOOL + launched.headers["location"])
    assert page.status_code == 200, page.text
    assert 'data-mode="session"' in page.text
    return meta(page.text, "csrf-token")


async def submit(sites: Sites, csrf: str, part: str, answer: str) -> httpx.Response:
    return await sites.browser.post(
        f"{TOOL}/v1/problems/{PROBLEM}/parts/{part}/submissions",
        json={"answer": answer},
        headers={"X-CSRF-Token": csrf},
    )


def _undelivered(stores: Stores) -> int:
    return sum(score.status in (PENDING, SENDING) for score in stores.outbox.scores())


async def deliver(sites: Sites) -> list[ReceivedScore]:
    """Drive delivery until nothing is queued (the app's own background worker may deliver some of
    them: claims keep every row to one sender); returns what the LMS has received so far."""
    stores = sites.stores
    worker = OutboxWorker(stores.outbox, stores.tool_keys, httpx.ASGITransport(app=sites.lms.app))
    deadline = time.monotonic() + DELIVERY_TIMEOUT
    while await run_in_threadpool(_undelivered, stores):
        assert time.monotonic() < deadline, "scores still queued"
        if await worker.run_once() == 0:
            await _pause()
    return list(sites.lms.scores)


async def _pause() -> None:
    await anyio.sleep(0.05)


def statuses(stores: Stores) -> list[str]:
    return [score.status for score in stores.outbox.scores()]


# On SQL: the score queued in the submission's transaction, two workers' claims under row locks.
@pytest.mark.parametrize("backend", SQL_BACKENDS)
async def test_deep_linked_problem_is_launched_answered_and_graded_in_the_lms(sites: Sites) -> None:
    item = await deep_link(sites, PROBLEM)
    assert item["type"] == "ltiResourceLink"
    assert item["custom"] == {"problem": PROBLEM}
    assert item["url"] == f"{TOOL}/lti/launch"
    assert item["lineItem"]["scoreMaximum"] == 3.0

    csrf = await launch_student(sites, item)
    problem = await sites.browser.get(f"{TOOL}/v1/problems/{PROBLEM}")
    assert problem.status_code == 200, problem.text
    assert problem.json()["student"].startswith("lti:")

    preview = await sites.browser.post(
        f"{TOOL}/v1/problems/{PROBLEM}/parts/acceleration/preview",
        json={"answer": RIGHT},
        headers={"X-CSRF-Token": csrf},
    )
    assert preview.status_code == 200, preview.text
    assert preview.json()["error"] is None
    assert preview.json()["read_as"]["text"]
    assert await deliver(sites) == [], "a preview is not graded"

    wrong = await submit(sites, csrf, "acceleration", WRONG)
    assert wrong.status_code == 201, wrong.text
    assert (wrong.json()["verdict"], wrong.json()["attempts_used"]) == ("incorrect", 1)
    [first] = await deliver(sites)
    assert first.line_item_id == "7"
    assert first.score["userId"] == "student-1"
    assert (first.score["scoreGiven"], first.score["scoreMaximum"]) == (0.0, 3.0)

    right = await submit(sites, csrf, "acceleration", RIGHT)
    assert right.status_code == 201, right.text
    assert (right.json()["verdict"], right.json()["score"]) == ("correct", 1.0)
    [_, better] = await deliver(sites)
    assert (better.score["scoreGiven"], better.score["scoreMaximum"]) == (1.0, 3.0)
    assert better.score["timestamp"] > first.score["timestamp"]

    unreadable = await submit(sites, csrf, "tension", UNREADABLE)
    assert unreadable.status_code == 201, unreadable.text
    assert unreadable.json()["verdict"] == "invalid"
    assert len(await deliver(sites)) == 2, "an invalid answer sends nothing"
    assert await run_in_threadpool(statuses, sites.stores) == [DELIVERED, DELIVERED]


async def test_api_refuses_a_session_post_without_its_csrf_token(sites: Sites) -> None:
    item = await deep_link(sites, PROBLEM)
    await launch_student(sites, item)
    forged = await sites.browser.post(
        f"{TOOL}/v1/problems/{PROBLEM}/parts/acceleration/submissions", json={"answer": RIGHT}
    )
    assert forged.status_code == 401
    assert await deliver(sites) == []


async def test_instructor_sees_a_refused_score_among_delivery_problems(sites: Sites) -> None:
    item = await deep_link(sites, PROBLEM)
    csrf = await launch_student(sites, item)
    sites.lms.score_status = 422
    assert (await submit(sites, csrf, "acceleration", RIGHT)).status_code == 201
    assert await deliver(sites) == []
    created = await run_in_threadpool(lambda: sites.stores.keys.create(Role.INSTRUCTOR, name="prof"))
    plaintext = created.plaintext
    listed = await sites.browser.get(
        f"{TOOL}/v1/lti/delivery-problems", headers={"Authorization": f"Bearer {plaintext}"}
    )
    assert listed.status_code == 200, listed.text
    [problem] = listed.json()
    assert (problem["problem_id"], problem["status"], problem["last_status"]) == (PROBLEM, "failed", 422)


async def test_an_lms_instructor_session_cannot_reach_other_students_or_their_gradebooks(
    sites: Sites,
) -> None:
    item = await deep_link(sites, PROBLEM)
    await launch_student(sites, item)  # records a grade target for the student
    csrf = await open_link(sites, item, "teacher-2", INSTRUCTOR)
    assert isinstance(sites.stores.outbox, MemoryScoreOutbox)
    victim = next(student for student, *_ in sites.stores.outbox.targets())
    headers = {"X-CSRF-Token": csrf}
    as_victim = await sites.browser.post(
        f"{TOOL}/v1/problems/{PROBLEM}/parts/acceleration/submissions",
        json={"answer": RIGHT, "student": victim},
        headers=headers,
    )
    assert as_victim.status_code == 403
    assert (await sites.browser.get(f"{TOOL}/v1/submissions", params={"student": victim})).status_code == 403
    assert (await sites.browser.get(f"{TOOL}/v1/lti/delivery-problems")).status_code == 403
    own = await sites.browser.get(f"{TOOL}/v1/submissions")
    assert own.status_code == 200 and own.json()["items"] == []
    assert await deliver(sites) == []
