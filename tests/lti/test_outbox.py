"""Grade passback: scores reach the platform once, survive an LMS outage, and refusals stay visible."""

from __future__ import annotations

from datetime import UTC, datetime, timedelta

import httpx
import pytest
from sqlalchemy import update

from app.db.database import Database
from app.db.types import utc_now
from app.lti.context import LtiContext
from app.lti.models import LtiScoreOutbox
from app.lti.outbox import (
    SCORE_CONTENT_TYPE,
    OutboxWorker,
    parse_retry_after,
    scores_url,
)
from app.settings import Settings
from app.storage import sql_stores
from app.storage.sql_outbox import enqueue_scores, list_delivery_problems
from tests.lti.conftest import platform_launch, unverified_claims
from tests.lti.fake_lms import FakeLms

pytestmark = pytest.mark.anyio
STUDENT_1 = "lti:1:student-1"


async def launch_as(browser: httpx.AsyncClient, lms: FakeLms, user: str) -> None:
    lms.next_launch.user = user
    assert (await platform_launch(browser)).status_code == 303


def enqueue(database: Database, student: str, given: float, at: datetime | None = None) -> int:
    with database.session() as session:
        return enqueue_scores(session, "moving-wedge", student, given, 2.0, at or utc_now())


def worker(database: Database, settings: Settings, lms: FakeLms) -> OutboxWorker:
    stores = sql_stores(database)
    return OutboxWorker(stores.outbox, stores.tool_keys, transport=httpx.ASGITransport(app=lms.app))


def make_all_due(database: Database) -> None:
    """Time passes: every waiting row is due now."""
    with database.session() as session:
        session.execute(update(LtiScoreOutbox).values(next_attempt_at=utc_now() - timedelta(seconds=1)))


def statuses(database: Database) -> list[str]:
    with database.session() as session:
        return [row.status for row in session.query(LtiScoreOutbox).order_by(LtiScoreOutbox.id)]


async def test_score_after_launch_reaches_platform_as_score_json(
    browser: httpx.AsyncClient, lms: FakeLms, database: Database, settings: Settings
):
    await launch_as(browser, lms, "student-1")
    assert enqueue(database, STUDENT_1, 1.5) == 1
    assert await worker(database, settings, lms).run_once() == 1
    [received] = lms.scores
    assert received.line_item_id == "1"
    assert received.content_type == SCORE_CONTENT_TYPE
    assert received.score["userId"] == "student-1"
    assert (received.score["scoreGiven"], received.score["scoreMaximum"]) == (1.5, 2.0)
    assert received.score["gradingProgress"] == "FullyGraded"
    assert statuses(database) == ["delivered"]


async def test_student_without_launch_enqueues_nothing(database: Database):
    assert enqueue(database, "someone-else", 1.0) == 0
    assert statuses(database) == []


async def test_lms_down_for_a_while_then_back_each_students_newest_score_arrives_once(
    browser: httpx.AsyncClient, lms: FakeLms, database: Database, settings: Settings
):
    await launch_as(browser, lms, "student-1")
    await launch_as(browser, lms, "student-2")
    enqueue(database, STUDENT_1, 0.5)
    enqueue(database, STUDENT_1, 1.0)
    enqueue(database, "lti:1:student-2", 2.0)
    lms.fail_scores = 7
    delivery = worker(database, settings, lms)
    for _ in range(10):
        await delivery.run_once()
        if "pending" not in statuses(database):
            break
        make_all_due(database)
    assert statuses(database) == ["superseded", "delivered", "delivered"]
    received = sorted((s.score["userId"], s.score["scoreGiven"]) for s in lms.scores)
    assert received == [("student-1", 1.0), ("student-2", 2.0)]
    assert await delivery.run_once() == 0  # nothing left to resend


async def test_outage_schedules_retry_no_sooner_than_retry_after(
    browser: httpx.AsyncClient, lms: FakeLms, database: Database, settings: Settings
):
    await launch_as(browser, lms, "student-1")
    enqueue(database, STUDENT_1, 1.0)
    lms.fail_scores, lms.retry_after = 1, "120"
    before = utc_now()
    await worker(database, settings, lms).run_once()
    with database.session() as session:
        row = session.query(LtiScoreOutbox).one()
        assert (row.status, row.attempts, row.last_status) == ("pending", 1, 503)
        assert row.next_attempt_at >= before + timedelta(seconds=120)
    assert await worker(database, settings, lms).run_once() == 0  # not due yet


@pytest.mark.parametrize("status", [422, 403], ids=["unprocessable", "forbidden"])
async def test_lms_refusal_is_kept_and_listed_for_instructors(
    browser: httpx.AsyncClient, lms: FakeLms, database: Database, settings: Settings, status: int
):
    await launch_as(browser, lms, "student-1")
    enqueue(database, STUDENT_1, 1.0)
    lms.score_status = status
    await worker(database, settings, lms).run_once()
    assert statuses(database) == ["failed"]
    with database.session() as session:
        [problem] = list_delivery_problems(session)
    assert (problem.student, problem.problem_id, problem.last_status) == (STUDENT_1, "moving-wedge", status)
    assert "refused by test" in (problem.last_error or "")


async def test_token_is_cached_between_scores(
    browser: httpx.AsyncClient, lms: FakeLms, database: Database, settings: Settings
):
    await launch_as(browser, lms, "student-1")
    enqueue(database, STUDENT_1, 1.0)
    delivery = worker(database, settings, lms)
    await delivery.run_once()
    enqueue(database, STUDENT_1, 2.0)
    await delivery.run_once()
    assert len(lms.scores) == 2
    assert lms.token_requests == 1


async def test_each_token_request_uses_a_fresh_jti(
    browser: httpx.AsyncClient, lms: FakeLms, database: Database, settings: Settings
):
    await launch_as(browser, lms, "student-1")
    lms.token_lifetime = 30  # shorter than the renewal margin: every score needs a new token
    delivery = worker(database, settings, lms)
    for given in (1.0, 2.0):
        enqueue(database, STUDENT_1, given)
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
    browser: httpx.AsyncClient, lms: FakeLms, database: Database, context: LtiContext, settings: Settings
):
    import anyio

    await launch_as(browser, lms, "student-1")
    enqueue(database, STUDENT_1, 1.0)
    stores = sql_stores(database)
    transport = httpx.ASGITransport(app=lms.app)
    delivery = OutboxWorker(stores.outbox, stores.tool_keys, transport, poll_interval=0.05)
    await delivery.start()
    with anyio.fail_after(20):
        while not lms.scores:
            await anyio.sleep(0.02)
    await delivery.stop()
    assert len(lms.scores) == 1
