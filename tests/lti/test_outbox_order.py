"""Grade passback after an LMS outage, on SQLite and PostgreSQL: only a student's newest score is sent,
in timestamp order, and promptly once the platform answers again."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field
from datetime import datetime, timedelta

import httpx
import pytest
from sqlalchemy import select, update

from app.db.database import Database
from app.db.types import utc_now
from app.lti import keys
from app.lti.models import LtiGradeTarget, LtiPlatform, LtiScoreOutbox
from app.lti.outbox import (
    FIRST_BACKOFF,
    SENDING,
    OutboxWorker,
    enqueue_scores,
    list_delivery_problems,
)
from tests.lti.fake_lms import FakeLms, register_fake_lms

pytestmark = pytest.mark.anyio
PROBLEM = "moving-wedge"


@pytest.fixture
def anyio_backend() -> str:
    return "asyncio"


@dataclass
class Clock:
    now: datetime = field(default_factory=utc_now)

    def __call__(self) -> datetime:
        return self.now

    def advance(self, seconds: float) -> None:
        self.now += timedelta(seconds=seconds)


@dataclass
class Passback:
    db: Database
    lms: FakeLms
    clock: Clock
    worker: OutboxWorker

    def add_student(self, student: str) -> None:
        with self.db.session() as session:
            platform_id = session.scalars(select(LtiPlatform.id)).one()
            session.add(
                LtiGradeTarget(
                    platform_id=platform_id,
                    student=f"lti:1:{student}",
                    problem_id=PROBLEM,
                    lineitem_url="https://lms.test/lineitems/1",
                    sub=student,
                )
            )

    def enqueue(self, student: str, given: float) -> None:
        with self.db.session() as session:
            enqueue_scores(session, PROBLEM, f"lti:1:{student}", given, 2.0, self.clock())

    def rows(self) -> list[tuple[str, float]]:
        with self.db.session() as session:
            rows = session.scalars(select(LtiScoreOutbox).order_by(LtiScoreOutbox.id))
            return [(row.status, row.score_given) for row in rows]

    def sent(self) -> list[tuple[str, float]]:
        return [(s.score["userId"], s.score["scoreGiven"]) for s in self.lms.scores]


@pytest.fixture
def passback(db: Database) -> Iterator[Passback]:
    register_fake_lms(db)
    with db.session() as session:
        keys.create_key(session)
        jwks = keys.public_jwks(session)
    lms = FakeLms()
    lms.trust_tool_keys(jwks)
    clock = Clock()
    worker = OutboxWorker(db, transport=httpx.ASGITransport(app=lms.app), clock=clock)
    yield Passback(db, lms, clock, worker)


async def test_three_scores_queued_in_an_outage_only_the_newest_arrives_once(passback: Passback):
    passback.add_student("student-1")
    passback.lms.refusals = [(503, None), (429, "20"), (503, None)]
    passback.enqueue("student-1", 0.5)
    await passback.worker.run_once()  # 503
    passback.clock.advance(1)
    passback.enqueue("student-1", 1.0)
    await passback.worker.run_once()  # 429, Retry-After: 20
    passback.clock.advance(1)
    passback.enqueue("student-1", 1.5)
    newest = passback.clock()
    await passback.worker.run_once()  # 503; the LMS is back after this
    assert passback.lms.refusals == []

    passback.clock.advance(FIRST_BACKOFF.total_seconds() * 1.1 + 0.1)  # the newest score's own backoff
    await passback.worker.run_once()
    assert passback.sent() == [("student-1", 1.5)]
    [received] = passback.lms.scores
    assert datetime.fromisoformat(received.score["timestamp"]) == newest.replace(
        microsecond=newest.microsecond // 1000 * 1000
    )
    for _ in range(3):  # nothing is left to send, however long we wait
        passback.clock.advance(3600)
        assert await passback.worker.run_once() == 0
    assert passback.sent() == [("student-1", 1.5)]
    assert passback.rows() == [("superseded", 0.5), ("superseded", 1.0), ("delivered", 1.5)]


async def test_superseded_scores_are_listed_for_instructors_but_not_as_failures(passback: Passback):
    passback.add_student("student-1")
    passback.lms.refusals = [(503, None), (429, "20")]
    for given in (0.5, 1.0):
        passback.enqueue("student-1", given)
        await passback.worker.run_once()
        passback.clock.advance(1)
    passback.enqueue("student-1", 1.5)
    await passback.worker.run_once()
    with passback.db.session() as session:
        listed = [(p.status, p.score_given, p.last_status) for p in list_delivery_problems(session)]
    assert listed == [("superseded", 1.0, 429), ("superseded", 0.5, 503)]


async def test_platform_answering_again_ends_every_backoff_on_it(passback: Passback):
    for student in ("student-1", "student-2"):
        passback.add_student(student)
    passback.lms.refusals = [(503, None)] * 6
    passback.enqueue("student-1", 1.0)
    for _ in range(6):  # a long outage: student-1's score now waits minutes between tries
        await passback.worker.run_once()
        with passback.db.session() as session:
            row = session.scalars(select(LtiScoreOutbox)).one()
        passback.clock.now = row.next_attempt_at
    assert passback.worker.clock() - row.created_at > timedelta(minutes=2)
    passback.clock.advance(-FIRST_BACKOFF.total_seconds())  # before student-1's next try
    passback.enqueue("student-2", 2.0)
    await passback.worker.run_once()  # student-2's score gets through: the platform is back
    await passback.worker.run_once()
    assert sorted(passback.sent()) == [("student-1", 1.0), ("student-2", 2.0)]


async def test_deliveries_follow_timestamp_order_across_students(passback: Passback):
    for student in ("student-1", "student-2", "student-3"):
        passback.add_student(student)
    for student, given in (("student-3", 0.5), ("student-1", 1.0), ("student-2", 1.5)):
        passback.enqueue(student, given)
        passback.clock.advance(0.01)
    with passback.db.session() as session:  # row ids no longer follow timestamps
        first = session.scalars(select(LtiScoreOutbox).order_by(LtiScoreOutbox.id)).first()
        assert first is not None
        first.timestamp += timedelta(seconds=1)
    await passback.worker.run_once()
    assert [user for user, _ in passback.sent()] == ["student-1", "student-2", "student-3"]


async def test_score_waits_while_an_older_one_is_being_sent(passback: Passback):
    passback.add_student("student-1")
    passback.enqueue("student-1", 0.5)
    with passback.db.session() as session:  # another instance holds the older score, lease live
        session.execute(
            update(LtiScoreOutbox).values(
                status=SENDING, claimed_by="other", claimed_until=passback.clock() + timedelta(minutes=1)
            )
        )
    passback.clock.advance(0.01)
    passback.enqueue("student-1", 1.0)
    assert await passback.worker.run_once() == 0
    assert passback.rows() == [("sending", 0.5), ("pending", 1.0)]


async def test_crashed_delivery_of_an_older_score_is_not_resent_after_a_newer_one(passback: Passback):
    passback.add_student("student-1")
    passback.enqueue("student-1", 0.5)
    with passback.db.session() as session:  # an instance crashed while sending it; the lease ran out
        session.execute(
            update(LtiScoreOutbox).values(
                status=SENDING, claimed_by="crashed", claimed_until=passback.clock() - timedelta(seconds=1)
            )
        )
    passback.clock.advance(0.01)
    passback.enqueue("student-1", 1.0)
    await passback.worker.run_once()
    assert passback.sent() == [("student-1", 1.0)]
    assert passback.rows() == [("superseded", 0.5), ("delivered", 1.0)]
