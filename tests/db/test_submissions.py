"""Submissions: append-only, server-timestamped, attempt-limited, paged by an opaque keyset cursor."""

from __future__ import annotations

import base64
import json
import threading
import uuid
from datetime import UTC, datetime

import pytest
from sqlalchemy import text
from sqlalchemy.exc import DBAPIError

from app.db.cursor import Position, encode_cursor
from app.db.database import Database
from app.db.errors import AttemptsExhausted, InvalidCursor, InvalidLimit
from app.db.records import SubmissionRecord
from app.db.submissions import MAX_PAGE_LIMIT, attempts_used, list_submissions, record_submission
from physics.verdict import Outcome, Verdict
from tests.db.helpers import CORRECT, INCORRECT, INVALID, PART, PROBLEM, StepClock, store_problem


@pytest.fixture
def version(db: Database) -> int:
    with db.session() as session:
        return store_problem(session)


def _submit(
    db: Database,
    version: int,
    verdict: Verdict = INCORRECT,
    *,
    student: str = "s1",
    part: str = PART,
    problem: str = PROBLEM,
    max_attempts: int | None = None,
    clock=None,
) -> SubmissionRecord:
    extra = {} if clock is None else {"clock": clock}
    with db.session() as session:
        return record_submission(
            session,
            problem_id=problem,
            problem_version=version,
            part_id=part,
            student=student,
            answer="-m g",
            verdict=verdict,
            max_attempts=max_attempts,
            **extra,
        )


def _all(db: Database, **filters) -> list[SubmissionRecord]:
    items: list[SubmissionRecord] = []
    cursor = None
    while True:
        with db.session(read_only=True) as session:
            page = list_submissions(session, cursor=cursor, **filters)
        items.extend(page.items)
        if page.next is None:
            return items
        cursor = page.next


def test_a_recorded_submission_reads_back_with_every_field(db: Database, version: int) -> None:
    recorded = _submit(db, version, CORRECT)
    (stored,) = _all(db)
    assert stored == recorded
    assert (stored.verdict, stored.score, stored.reason) == (Outcome.CORRECT, 1.0, CORRECT.reason)
    assert stored.read_as == CORRECT.read_as
    assert (stored.problem_id, stored.part_id, stored.student, stored.attempt) == (PROBLEM, PART, "s1", 1)


def test_created_at_is_the_servers_time_in_utc(db: Database, version: int) -> None:
    before = datetime.now(UTC)
    recorded = _submit(db, version)
    after = datetime.now(UTC)
    (stored,) = _all(db)
    assert stored.created_at.tzinfo == UTC
    assert before <= stored.created_at == recorded.created_at <= after


def test_submission_ids_are_random_uuids(db: Database, version: int) -> None:
    ids = [_submit(db, version).id for _ in range(3)]
    assert len(set(ids)) == 3 and {submission_id.version for submission_id in ids} == {4}


@pytest.mark.parametrize(
    "statement",
    ["UPDATE submissions SET score = 1.0", "DELETE FROM submissions"],
    ids=["update", "delete"],
)
def test_the_database_refuses_to_change_stored_submissions(
    db: Database, version: int, statement: str
) -> None:
    _submit(db, version)
    with pytest.raises(DBAPIError, match="append-only"), db.session() as session:
        session.execute(text(statement))
    assert len(_all(db)) == 1


def test_an_invalid_answer_is_stored_without_using_an_attempt(db: Database, version: int) -> None:
    _submit(db, version, INCORRECT)
    invalid = _submit(db, version, INVALID)
    assert invalid.attempt is None and invalid.verdict is Outcome.INVALID
    with db.session(read_only=True) as session:
        assert attempts_used(session, PROBLEM, PART, "s1") == 1
    assert [submission.verdict for submission in _all(db)] == [Outcome.INCORRECT, Outcome.INVALID]


def test_an_invalid_answer_is_stored_even_when_attempts_are_exhausted(db: Database, version: int) -> None:
    _submit(db, version, max_attempts=1)
    assert _submit(db, version, INVALID, max_attempts=1).attempt is None


def test_graded_attempts_are_numbered_up_to_the_limit_then_refused(db: Database, version: int) -> None:
    attempts = [_submit(db, version, max_attempts=3).attempt for _ in range(3)]
    assert attempts == [1, 2, 3]
    with pytest.raises(AttemptsExhausted) as raised:
        _submit(db, version, CORRECT, max_attempts=3)
    assert (raised.value.student, raised.value.part_id, raised.value.max_attempts) == ("s1", PART, 3)
    assert len(_all(db)) == 3
    with db.session(read_only=True) as session:
        assert attempts_used(session, PROBLEM, PART, "s1") == 3


def test_no_limit_means_unlimited_attempts(db: Database, version: int) -> None:
    assert [_submit(db, version).attempt for _ in range(5)] == [1, 2, 3, 4, 5]


def test_attempts_are_counted_per_part_and_per_student(db: Database, version: int) -> None:
    _submit(db, version, max_attempts=1)
    assert _submit(db, version, student="s2", max_attempts=1).attempt == 1
    assert _submit(db, version, part="normal_force", max_attempts=1).attempt == 1
    with db.session(read_only=True) as session:
        assert attempts_used(session, PROBLEM, PART, "s1") == 1
        assert attempts_used(session, PROBLEM, PART, "nobody") == 0


def test_twenty_parallel_submissions_never_exceed_a_limit_of_three(db: Database, version: int) -> None:
    threads_count, limit = 20, 3
    barrier = threading.Barrier(threads_count)
    outcomes: list[str] = []
    lock = threading.Lock()

    def submit() -> None:
        barrier.wait()
        try:
            _submit(db, version, max_attempts=limit)
            result = "stored"
        except AttemptsExhausted:
            result = "exhausted"
        except Exception as error:
            result = f"error: {error!r}"
        with lock:
            outcomes.append(result)

    threads = [threading.Thread(target=submit) for _ in range(threads_count)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert sorted(outcomes) == ["exhausted"] * (threads_count - limit) + ["stored"] * limit
    stored = _all(db)
    assert sorted(submission.attempt for submission in stored) == [1, 2, 3]
    with db.session(read_only=True) as session:
        assert attempts_used(session, PROBLEM, PART, "s1") == limit


@pytest.mark.parametrize(
    ("clock", "page_size"),
    [(StepClock, 3), (StepClock, 1), (lambda: lambda: datetime(2026, 1, 1, tzinfo=UTC), 4)],
    ids=["distinct-times", "one-per-page", "identical-times"],
)
def test_pages_cover_every_submission_once_in_order(db: Database, version: int, clock, page_size) -> None:
    tick = clock()
    recorded = [_submit(db, version, student=f"s{i % 3}", clock=tick) for i in range(10)]
    pages = []
    cursor = None
    while True:
        with db.session(read_only=True) as session:
            page = list_submissions(session, limit=page_size, cursor=cursor)
        pages.append(page.items)
        if page.next is None:
            break
        cursor = page.next
    listed = [item for page in pages for item in page]
    assert sorted(item.id for item in listed) == sorted(item.id for item in recorded)
    assert len(listed) == len(recorded)
    assert [(item.created_at, item.id) for item in listed] == sorted(
        (item.created_at, item.id) for item in listed
    )
    assert all(0 < len(page) <= page_size for page in pages)


def test_rows_added_between_pages_are_neither_skipped_nor_repeated(db: Database, version: int) -> None:
    tick = StepClock()
    first = [_submit(db, version, clock=tick) for _ in range(3)]
    with db.session(read_only=True) as session:
        page = list_submissions(session, limit=2)
    later = [_submit(db, version, clock=tick) for _ in range(2)]
    with db.session(read_only=True) as session:
        rest = list_submissions(session, limit=10, cursor=page.next)
    assert [item.id for item in [*page.items, *rest.items]] == [item.id for item in [*first, *later]]
    assert rest.next is None


@pytest.mark.parametrize(
    ("filters", "expected_students"),
    [
        ({"student": "s1"}, {"s1"}),
        ({"problem_id": "yo-yo"}, {"s2"}),
        ({"problem_id": "yo-yo", "student": "s1"}, set()),
    ],
    ids=["by-student", "by-problem", "both"],
)
def test_listing_filters_by_problem_and_student(
    db: Database, version: int, filters, expected_students
) -> None:
    with db.session() as session:
        other_version = store_problem(session, "yo-yo")
    for _ in range(3):
        _submit(db, version, student="s1")
        _submit(db, other_version, student="s2", problem="yo-yo")
    listed = _all(db, **filters)
    assert {item.student for item in listed} == expected_students
    assert len(listed) == 3 * len(expected_students)


def test_the_default_page_is_a_hundred(db: Database, version: int) -> None:
    tick = StepClock()
    for _ in range(101):
        _submit(db, version, clock=tick)
    with db.session(read_only=True) as session:
        page = list_submissions(session)
    assert len(page.items) == 100 and page.next is not None


@pytest.mark.parametrize("limit", [0, -1, MAX_PAGE_LIMIT + 1], ids=["zero", "negative", "over-max"])
def test_a_limit_out_of_range_is_refused(db: Database, limit: int) -> None:
    with pytest.raises(InvalidLimit), db.session(read_only=True) as session:
        list_submissions(session, limit=limit)


def _forged(payload: dict) -> str:
    return base64.urlsafe_b64encode(json.dumps(payload).encode()).decode().rstrip("=")


@pytest.mark.parametrize(
    "cursor",
    [
        "garbage!",
        "",
        "bm90IGpzb24",  # "not json"
        "eyJ2IjoyfQ",  # {"v":2}
        encode_cursor(Position(datetime(2026, 1, 1, tzinfo=UTC), uuid.UUID(int=7)))[:-6],
        _forged({"v": 1, "t": "2026-01-01T00:00:00+00:00", "i": 123}),
        _forged({"v": 1, "t": "0001-01-01T00:00:00+14:00", "i": uuid.UUID(int=7).hex}),
        _forged({"v": 1, "t": ["2026"], "i": uuid.UUID(int=7).hex}),
    ],
    ids=[
        "not-base64",
        "empty",
        "not-json",
        "unknown-version",
        "truncated",
        "id-not-text",
        "time-overflows",
        "time-not-text",
    ],
)
def test_a_cursor_we_did_not_issue_is_refused(db: Database, cursor: str) -> None:
    with pytest.raises(InvalidCursor), db.session(read_only=True) as session:
        list_submissions(session, cursor=cursor)
