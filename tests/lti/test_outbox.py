"""Grade passback: scores reach the platform once, survive an LMS outage, and refusals stay visible."""

from __future__ import annotations

from dataclasses import dataclass
from datetime import UTC, datetime, timedelta

import httpx
import pytest

from app.db.types import utc_now
from app.lti.context import LtiContext
from app.lti.outbox import (
    SCORE_CONTENT_TYPE,
    OutboxWorker,
    parse_retry_after,
    scores_url,
)
from app.storage import Stores
from tests.lti.conftest import platform_launch, unverified_claims
from tests.lti.fake_lms import FakeLms

pytestmark = pytest.mark.anyio
STUDENT_1 = "lti:1:student-1"


async def launch_as(browser: httpx.AsyncClient, lms: FakeLms, user: str) -> None:
    lms.next_launch.user = user
    assert (await platform_launch(browser)).status_code == 303


def enqueue(stores: Stores, student: str, given: float, at: datetime | None = None) -> int:
    return stores.outbox.enqueue("moving-wedge", student, given, 2.0, at or utc_now())


@dataclass
class Clock:
    """The workers' clock: the real time, plus however long a test lets pass."""

    passed: timedelta = timedelta(0)

    def __call__(self) -> datetime:
        return utc_now() + self.passed


@pytest.fixture
def clock() -> Clock:
    return Clock()


def worker(stores: Stores, lms: FakeLms, clock: Clock) -> OutboxWorker:
    return OutboxWorker(stores.outbox, stores.tool_keys, httpx.ASGITransport(app=lms.app), clock=clock)


def make_all_due(stores: Stores, clock: Clock) -> None:
    """Time passes: every waiting score is due now."""
    latest = max(score.next_attempt_at for score in stores.outbox.scores())
    clock.passed = max(clock.passed, latest + timedelta(seconds=1) - utc_now())


def statuses(stores: Stores) -> list[str]:
    return [score.status for score in stores.outbox.scores()]


async def test_score_after_launch_reaches_platform_as_score_json(
    browser: httpx.AsyncClient, lms: FakeLms, stores: Stores, clock: Clock
):
    await launch_as(browser, lms, "student-1")
    assert enqueue(stores, STUDENT_1, 1.5) == 1
    assert await worker(stores, lms, clock).run_once() == 1
    [received] = lms.scores
    assert received.line_item_id == "1"
    assert received.content_type == SCORE_CONTENT_TYPE
    assert received.score["userId"] == "student-1"
    assert (received.score["scoreGiven"], received.score["scoreMaximum"]) == (1.5, 2.0)
    assert received.score["gradingProgress"] == "FullyGraded"
    assert statuses(stores) == ["delivered"]


async def test_student_without_launch_enqueues_nothing(stores: Stores):
    assert enqueue(stores, "someone-else", 1.0) == 0
    assert statuses(stores) == []


async def test_lms_down_for_a_while_then_back_each_students_newest_score_arrives_once(
    browser: httpx.AsyncClient, lms: FakeLms, stores: Stores, clock: Clock
):
    await launch_as(browser, lms, "student-1")
    await launch_as(browser, lms, "student-2")
    enqueue(stores, STUDENT_1, 0.5)
    enqueue(stores, STUDENT_1, 1.0)
    enqueue(stores, "lti:1:student-2", 2.0)
    lms.fail_scores = 7
    delivery = worker(stores, lms, clock)
    for _ in range(10):
        await delivery.run_once()
        if "pending" not in statuses(stores):
            break
        make_all_due(stores, clock)
    assert statuses(stores) == ["superseded", "delivered", "delivered"]
    received = sorted((s.score["userId"], s.score["scoreGiven"]) for s in lms.scores)
    assert received == [("student-1", 1.0), ("student-2", 2.0)]
    assert await delivery.run_once() == 0  # nothing left to resend


async def test_outage_schedules_retry_no_sooner_than_retry_after(
    browser: httpx.AsyncClient, lms: FakeLms, stores: Stores, clock: Clock
):
    await launch_as(browser, lms, "student-1")
    enqueue(stores, STUDENT_1, 1.0)
    lms.fail_scores, lms.retry_after = 1, "120"
    before = utc_now()
    await worker(stores, lms, clock).run_once()
    [row] = stores.outbox.scores()
    [problem] = stores.outbox.delivery_problems()  # a score tried without success is listed
    assert (row.status, row.attempts, problem.last_status) == ("pending", 1, 503)
    assert row.next_attempt_at >= before + timedelta(seconds=120)
    assert await worker(stores, lms, clock).run_once() == 0  # not due yet


@pytest.mark.parametrize("status", [422, 403], ids=["unprocessable", "forbidden"])
async def test_lms_refusal_is_kept_and_listed_for_instructors(
    browser: httpx.AsyncClient, lms: FakeLms, stores: Stores, clock: Clock, status: int
):
    await launch_as(browser, lms, "student-1")
    enqueue(stores, STUDENT_1, 1.0)
    lms.score_status = status
    await worker(stores, lms, clock).run_once()
    assert statuses(stores) == ["failed"]
    [problem] = stores.outbox.delivery_problems()
    assert (problem.student, problem.problem_id, problem.last_status) == (STUDENT_1, "moving-wedge", status)
    assert "refused by test" in (problem.last_error or "")


async def test_token_is_cached_between_scores(
    browser: httpx.AsyncClient, lms: FakeLms, stores: Stores, clock: Clock
):
    await launch_as(browser, lms, "student-1")
    enqueue(stores, STUDENT_1, 1.0)
    delivery = worker(stores, lms, clock)
    await delivery.run_once()
    enqueue(stores, STUDENT_1, 2.0)
    await delivery.run_once()
    assert len(lms.scores) == 2
    assert lms.token_requests == 1


async def test_each_token_request_uses_a_fresh_jti(
    browser: httpx.AsyncClient, lms: FakeLms, stores: Stores, clock: Clock
):
    await launch_as(browser, lms, "student-1")
    lms.token_lifetime = 30  # shorter than the renewal margin: every score needs a new token
    delivery = worker(stores, lms, clock)
    for given in (1.0, 2.0):
        enqueue(stores, STUDENT_1, given)
        await delivery.run_once()
    jtis = [unverified_claims(assertion)["jti"] for assertion in lms.assertions]
    assert len(jtis) == 2 and len(set(jtis)) == 2


@pytest.mark.parametrize(
    ("lineitem", "expected"),
    [
        ("https://lms.test/lineitems/1", "https://lms.test/lineitems/1/scores"),
        ("https://lms.test/lineitems/1/", "https://lms.test/lineitems/1/scores"),
        ("https://lms.test/api/lti/li?id=1&type=x", "https://lms.test/api/lti/li/scores?id=1&type=x"),
    ],
    ids=["plain", "trailing-slash", "query-string"],
)
def test_scores_url_appends_to_path_and_keeps_query(lineitem: str, expected: str):
    assert scores_url(lineitem) == expected


@pytest.mark.parametrize(
    ("header", "seconds"),
    [("120", 120), ("Sat, 21 Nov 2026 08:02:00 GMT", 120), ("soon", None), (None, None)],
    ids=["seconds", "http-date", "garbage", "absent"],
)
def test_retry_after_reads_seconds_and_dates(header: str | None, seconds: int | None):
    now = datetime(2026, 11, 21, 8, 0, 0, tzinfo=UTC)
    expected = None if seconds is None else timedelta(seconds=seconds)
    assert parse_retry_after(header, now) == expected


async def test_worker_started_in_background_delivers_and_stops(
    browser: httpx.AsyncClient, lms: FakeLms, stores: Stores, context: LtiContext
):
    import anyio

    await launch_as(browser, lms, "student-1")
    enqueue(stores, STUDENT_1, 1.0)
    transport = httpx.ASGITransport(app=lms.app)
    delivery = OutboxWorker(stores.outbox, stores.tool_keys, transport, poll_interval=0.05)
    await delivery.start()
    with anyio.fail_after(20):
        while not lms.scores:
            await anyio.sleep(0.02)
    await delivery.stop()
    assert len(lms.scores) == 1
