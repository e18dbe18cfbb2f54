"""Several server instances share the outbox: a due row is claimed by one worker at a time."""

from __future__ import annotations

import threading
import uuid
from datetime import timedelta

from app.db.database import Database
from app.db.types import utc_now
from app.lti.models import LtiGradeTarget, LtiScoreOutbox
from app.lti.outbox import LEASE, PENDING, Outcome, claim_batch, enqueue_scores, finish
from app.lti.platforms import add_platform

ROWS = 60


def seed(db: Database) -> None:
    platform = add_platform(
        db,
        "https://lms.test",
        "client",
        ["d"],
        "https://lms.test/a",
        "https://lms.test/t",
        "https://lms.test/j",
    )
    # One score for each of ROWS students: a student's newer score would supersede an older one.
    with db.session() as session:
        for student in range(ROWS):
            session.add(
                LtiGradeTarget(
                    platform_id=platform.id,
                    student=f"s{student}",
                    problem_id="p",
                    lineitem_url="https://lms.test/li",
                    sub=f"u{student}",
                )
            )
    for student in range(ROWS):
        with db.session() as session:
            enqueue_scores(session, "p", f"s{student}", 1.0, 100.0, utc_now() - timedelta(seconds=1))


def test_concurrent_workers_never_claim_the_same_row(db: Database):
    seed(db)
    claimed: dict[str, list[int]] = {}
    errors: list[BaseException] = []

    def work(name: str) -> None:
        mine = claimed.setdefault(name, [])
        try:
            while batch := claim_batch(db, uuid.uuid4().hex, utc_now(), 7):
                mine.extend(score.id for score in batch)
        except BaseException as error:  # surfaced below
            errors.append(error)

    threads = [threading.Thread(target=work, args=(f"worker-{i}",)) for i in range(3)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(timeout=60)
    assert not errors
    every = [row_id for ids in claimed.values() for row_id in ids]
    assert len(every) == len(set(every)) == ROWS


def test_row_of_a_crashed_worker_is_claimed_again_after_its_lease(db: Database):
    seed(db)
    now = utc_now()
    first = claim_batch(db, "crashed", now, ROWS)
    assert len(first) == ROWS
    assert claim_batch(db, "other", now + LEASE / 2, ROWS) == []
    again = claim_batch(db, "other", now + LEASE + timedelta(seconds=1), ROWS)
    assert [s.id for s in again] == [s.id for s in first]
    # The crashed worker waking up late cannot overwrite the new claim's outcome.
    finish(db, first[0], Outcome(PENDING, 503, "late"), now)
    with db.session() as session:
        row = session.get(LtiScoreOutbox, first[0].id)
        assert row is not None and (row.claimed_by, row.attempts) == ("other", 0)
