"""Grade passback through the outbox, on every store: a launched student's graded submission queues
the best-per-part score; after an LMS outage only the newest score is sent, once, in timestamp order;
workers (several instances) never hold the same score, and a crashed one's lease runs out."""

from __future__ import annotations

import uuid
from collections.abc import Iterator
from dataclasses import dataclass, field
from datetime import UTC, datetime, timedelta

import httpx
import pytest

from app.db.errors import AttemptsExhausted
from app.db.types import utc_now
from app.lti.outbox import FIRST_BACKOFF, LEASE, PENDING, OutboxWorker, Outcome
from app.lti.platforms import PlatformRecord, add_platform
from app.storage import Stores
from physics.verdict import Outcome as Verdicts
from physics.verdict import Reason, Verdict
from tests.lti.fake_lms import CLIENT_ID, DEPLOYMENT_ID, ISSUER, FakeLms
from tests.storage.helpers import in_parallel, submit

PROBLEM = "moving-wedge"
URLS = (f"{ISSUER}/auth", f"{ISSUER}/token", f"{ISSUER}/jwks")
DOCUMENT = {"id": PROBLEM, "title": "Wedge", "parts": [{"id": "a"}, {"id": "b"}]}


def _a_moment_ago() -> datetime:
    # The fake LMS checks the tool's token against the real time: a clock that stood still at the
    # fixture's start and was advanced a few milliseconds could sign an `iat` a second ahead of it.
    return utc_now() - timedelta(seconds=5)


@dataclass
class Clock:
    now: datetime = field(default_factory=_a_moment_ago)

    def __call__(self) -> datetime:
        return self.now

    def advance(self, seconds: float) -> None:
        self.now += timedelta(seconds=seconds)


@dataclass
class Passback:
    stores: Stores
    platform: PlatformRecord
    lms: FakeLms
    clock: Clock
    worker: OutboxWorker

    def add_student(self, student: str) -> None:
        self.stores.outbox.add_target(
            self.platform,
            student=f"lti:1:{student}",
            problem_id=PROBLEM,
            lineitem_url=f"{ISSUER}/lineitems/1",
            sub=student,
        )

    def enqueue(self, student: str, given: float, at: datetime | None = None) -> int:
        return self.stores.outbox.enqueue(PROBLEM, f"lti:1:{student}", given, 2.0, at or self.clock())

    def rows(self) -> list[tuple[str, float]]:
        return [(row.status, row.score_given) for row in self.stores.outbox.scores()]

    def sent(self) -> list[tuple[str, float]]:
        return [(s.score["userId"], s.score["scoreGiven"]) for s in self.lms.scores]


@pytest.fixture
def platform(stores: Stores) -> PlatformRecord:
    """The LMS, registered where the stores keep platforms."""
    return add_platform(stores.platforms, ISSUER, CLIENT_ID, [DEPLOYMENT_ID], *URLS)


@pytest.fixture
def passback(stores: Stores, platform: PlatformRecord) -> Iterator[Passback]:
    stores.problems.save_builtin(PROBLEM, DOCUMENT)
    lms = FakeLms()
    lms.trust_tool_keys(stores.tool_keys.public_jwks())
    clock = Clock()
    transport = httpx.ASGITransport(app=lms.app)
    yield Passback(
        stores, platform, lms, clock, OutboxWorker(stores.outbox, stores.tool_keys, transport, clock=clock)
    )


pytestmark = pytest.mark.anyio


@pytest.fixture
def anyio_backend() -> str:
    return "asyncio"


# ---- queued with the submission (app.lti.grades) ---------------------------------------------------

CORRECT = Verdict(Verdicts.CORRECT, 1.0, Reason.EQUIVALENT, "")
WRONG = Verdict(Verdicts.INCORRECT, 0.0, Reason.WRONG_VALUE, "")
INVALID = Verdict(Verdicts.INVALID, 0.0, Reason.PARSE_ERROR, "")


def _queued(stores: Stores) -> list[tuple[float, float]]:
    return [(row.score_given, row.score_maximum) for row in stores.outbox.scores()]


async def test_a_graded_submission_queues_the_best_score_per_part_out_of_the_parts(passback: Passback):
    passback.add_student("student-1")
    for part, verdict in (("a", CORRECT), ("a", WRONG), ("b", CORRECT)):  # a later wrong one never lowers it
        submit(passback.stores, verdict=verdict, part=part, problem=PROBLEM, student="lti:1:student-1")
    assert _queued(passback.stores) == [(1.0, 2.0), (1.0, 2.0), (2.0, 2.0)]
    assert [row.status for row in passback.stores.outbox.scores()] == ["superseded", "superseded", "pending"]


@pytest.mark.parametrize(
    ("verdict", "student"),
    [(INVALID, "lti:1:student-1"), (CORRECT, "api-student")],
    ids=["invalid", "not-launched"],
)
async def test_an_invalid_answer_or_a_student_not_launched_queues_nothing(
    passback: Passback, verdict, student
):
    passback.add_student("student-1")
    submit(passback.stores, verdict=verdict, part="a", problem=PROBLEM, student=student)
    assert _queued(passback.stores) == []


async def test_a_refused_submission_queues_nothing(passback: Passback):
    passback.add_student("student-1")
    submit(
        passback.stores, verdict=CORRECT, part="a", problem=PROBLEM, student="lti:1:student-1", max_attempts=1
    )
    with pytest.raises(AttemptsExhausted):
        submit(
            passback.stores,
            verdict=CORRECT,
            part="b",
            problem=PROBLEM,
            student="lti:1:student-1",
            max_attempts=0,
        )
    assert _queued(passback.stores) == [(1.0, 2.0)]


async def test_scores_for_the_same_moment_get_strictly_increasing_timestamps(passback: Passback):
    passback.add_student("student-1")
    moment = datetime(2026, 1, 1, 12, 0, 0, 123456, tzinfo=UTC)
    for given in (1.0, 2.0, 3.0):
        passback.enqueue("student-1", given, at=moment)
    stamps = [row.timestamp for row in passback.stores.outbox.scores()]
    assert stamps == [moment.replace(microsecond=123000) + timedelta(milliseconds=i) for i in range(3)]


# ---- delivery after an outage ----------------------------------------------------------------------


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
    listed = [(p.status, p.score_given, p.last_status) for p in passback.stores.outbox.delivery_problems()]
    assert listed == [("superseded", 1.0, 429), ("superseded", 0.5, 503)]


async def test_a_refusal_is_kept_and_listed_as_failed(passback: Passback):
    passback.add_student("student-1")
    passback.lms.refusals = [(422, None)]
    passback.enqueue("student-1", 1.0)
    await passback.worker.run_once()
    [problem] = passback.stores.outbox.delivery_problems()
    assert (problem.status, problem.last_status, problem.issuer, problem.student) == (
        "failed",
        422,
        ISSUER,
        "lti:1:student-1",
    )
    passback.clock.advance(3600)
    assert await passback.worker.run_once() == 0


async def test_platform_answering_again_ends_every_backoff_on_it(passback: Passback):
    for student in ("student-1", "student-2"):
        passback.add_student(student)
    passback.lms.refusals = [(503, None)] * 6
    started = passback.clock()
    passback.enqueue("student-1", 1.0)
    for _ in range(6):  # a long outage: student-1's score now waits minutes between tries
        await passback.worker.run_once()
        [row] = passback.stores.outbox.scores()
        passback.clock.now = row.next_attempt_at
    assert passback.clock() - started > timedelta(minutes=2)
    passback.clock.advance(-FIRST_BACKOFF.total_seconds())  # before student-1's next try
    passback.enqueue("student-2", 2.0)
    await passback.worker.run_once()  # student-2's score gets through: the platform is back
    await passback.worker.run_once()
    assert sorted(passback.sent()) == [("student-1", 1.0), ("student-2", 2.0)]


async def test_deliveries_follow_timestamp_order_not_queue_order(passback: Passback):
    for student in ("student-1", "student-2", "student-3"):
        passback.add_student(student)
    start = passback.clock() - timedelta(seconds=1)
    for student, given, offset in (("student-3", 0.5, 2), ("student-1", 1.0, 0), ("student-2", 1.5, 1)):
        passback.enqueue(student, given, at=start + timedelta(milliseconds=10 * offset))
    await passback.worker.run_once()
    assert [user for user, _ in passback.sent()] == ["student-1", "student-2", "student-3"]


async def test_score_waits_while_an_older_one_is_being_sent(passback: Passback):
    passback.add_student("student-1")
    passback.enqueue("student-1", 0.5)
    [held] = passback.stores.outbox.claim("other-instance", passback.clock(), 10)  # lease live
    passback.clock.advance(0.01)
    passback.enqueue("student-1", 1.0)
    assert await passback.worker.run_once() == 0
    assert passback.rows() == [("sending", 0.5), ("pending", 1.0)]
    passback.stores.outbox.finish(held, Outcome("delivered", 200), passback.clock())
    assert await passback.worker.run_once() == 1
    assert passback.sent() == [("student-1", 1.0)]


async def test_crashed_delivery_of_an_older_score_is_not_resent_after_a_newer_one(passback: Passback):
    passback.add_student("student-1")
    passback.enqueue("student-1", 0.5, at=passback.clock() - LEASE - timedelta(seconds=2))
    # An instance claimed it and crashed while sending; its lease has run out since.
    assert passback.stores.outbox.claim("crashed", passback.clock() - LEASE - timedelta(seconds=1), 10)
    passback.clock.advance(0.01)
    passback.enqueue("student-1", 1.0)
    await passback.worker.run_once()
    assert passback.sent() == [("student-1", 1.0)]
    assert passback.rows() == [("superseded", 0.5), ("delivered", 1.0)]


# ---- claims shared by several instances ------------------------------------------------------------

STUDENTS = 40


def _one_score_each(passback: Passback) -> None:
    """One score for each of STUDENTS students (a student's newer score would supersede an older one)."""
    for student in range(STUDENTS):
        passback.add_student(f"s{student}")
        passback.enqueue(f"s{student}", 1.0, at=passback.clock() - timedelta(seconds=1))


async def test_concurrent_workers_never_claim_the_same_score(passback: Passback):
    _one_score_each(passback)

    def drain(_: int) -> list[int]:
        mine: list[int] = []
        while batch := passback.stores.outbox.claim(uuid.uuid4().hex, utc_now(), 7):
            mine.extend(score.id for score in batch)
        return mine

    claimed = in_parallel(3, drain)
    every = [score_id for ids in claimed for score_id in ids]
    assert len(every) == len(set(every)) == STUDENTS


async def test_a_crashed_workers_score_is_claimed_again_after_its_lease(passback: Passback):
    _one_score_each(passback)
    now = utc_now()
    first = passback.stores.outbox.claim("crashed", now, STUDENTS)
    assert len(first) == STUDENTS
    assert passback.stores.outbox.claim("other", now + LEASE / 2, STUDENTS) == []
    again = passback.stores.outbox.claim("other", now + LEASE + timedelta(seconds=1), STUDENTS)
    assert [s.id for s in again] == [s.id for s in first]
    # The crashed worker waking up late cannot overwrite the new claim's outcome.
    passback.stores.outbox.finish(first[0], Outcome(PENDING, 503, "late"), now)
    row = next(row for row in passback.stores.outbox.scores() if row.id == first[0].id)
    assert (row.claimed_by, row.attempts) == ("other", 0)
