"""Submissions: append-only, server-timestamped, attempt-limited, paged by an opaque keyset cursor
(every store)."""

from __future__ import annotations

import base64
import json
import uuid
from datetime import UTC, datetime

import pytest

from app.db.cursor import Position, encode_cursor
from app.db.errors import AttemptsExhausted, InvalidCursor, InvalidLimit
from app.db.records import SubmissionRecord
from app.storage import Stores
from app.storage.protocols import MAX_PAGE_LIMIT
from physics.verdict import Outcome
from tests.db.helpers import CORRECT, INCORRECT, INVALID, PART, PROBLEM, StepClock
from tests.storage.conftest import StoresFor
from tests.storage.helpers import in_parallel, store_problem, submit


@pytest.fixture
def stores(stores: Stores) -> Stores:
    """The stores, with the problem every submission here is filed against."""
    store_problem(stores)
    return stores


def _all(stores: Stores, **filters) -> list[SubmissionRecord]:
    items: list[SubmissionRecord] = []
    cursor = None
    while True:
        page = stores.submissions.page(cursor=cursor, **filters)
        items.extend(page.items)
        if page.next is None:
            return items
        cursor = page.next


def test_a_filed_submission_reads_back_with_every_field(stores: Stores) -> None:
    before = datetime.now(UTC)
    filed = submit(stores, verdict=CORRECT)
    after = datetime.now(UTC)
    (stored,) = _all(stores)
    assert stored == filed.record and filed.attempts_used == 1
    assert (stored.verdict, stored.score, stored.reason) == (Outcome.CORRECT, 1.0, CORRECT.reason)
    assert stored.read_as == CORRECT.read_as
    assert (stored.problem_id, stored.part_id, stored.student, stored.attempt) == (PROBLEM, PART, "s1", 1)
    assert stored.created_at.tzinfo == UTC and before <= stored.created_at <= after
    assert stored.id.version == 4


def test_an_invalid_answer_is_stored_without_using_an_attempt(stores: Stores) -> None:
    submit(stores, verdict=INCORRECT)
    invalid = submit(stores, verdict=INVALID)
    assert invalid.record.attempt is None and invalid.attempts_used == 1
    assert invalid.record.read_as is None
    assert stores.submissions.attempts_used(PROBLEM, PART, "s1") == 1
    assert [s.verdict for s in _all(stores)] == [Outcome.INCORRECT, Outcome.INVALID]


def test_an_invalid_answer_is_stored_even_when_attempts_are_exhausted(stores: Stores) -> None:
    submit(stores, max_attempts=1)
    assert submit(stores, verdict=INVALID, max_attempts=1).record.attempt is None


def test_graded_attempts_are_numbered_up_to_the_limit_then_refused(stores: Stores) -> None:
    assert [submit(stores, max_attempts=3).record.attempt for _ in range(3)] == [1, 2, 3]
    with pytest.raises(AttemptsExhausted) as raised:
        submit(stores, verdict=CORRECT, max_attempts=3)
    assert (raised.value.student, raised.value.part_id, raised.value.max_attempts) == ("s1", PART, 3)
    assert len(_all(stores)) == 3
    assert stores.submissions.attempts_used(PROBLEM, PART, "s1") == 3


def test_no_limit_means_unlimited_attempts(stores: Stores) -> None:
    assert [submit(stores).attempts_used for _ in range(5)] == [1, 2, 3, 4, 5]


def test_attempts_are_counted_per_part_and_per_student(stores: Stores) -> None:
    submit(stores, max_attempts=1)
    assert submit(stores, student="s2", max_attempts=1).record.attempt == 1
    assert submit(stores, part="normal_force", max_attempts=1).record.attempt == 1
    assert stores.submissions.attempts_used(PROBLEM, PART, "s1") == 1
    assert stores.submissions.attempts_used(PROBLEM, PART, "nobody") == 0


def test_twenty_parallel_submissions_never_exceed_a_limit_of_three(stores: Stores) -> None:
    def attempt(_: int) -> str:
        try:
            submit(stores, max_attempts=3)
        except AttemptsExhausted:
            return "exhausted"
        return "stored"

    assert sorted(in_parallel(20, attempt)) == ["exhausted"] * 17 + ["stored"] * 3
    assert sorted(s.attempt for s in _all(stores)) == [1, 2, 3]
    assert stores.submissions.attempts_used(PROBLEM, PART, "s1") == 3


@pytest.mark.parametrize(
    ("clock", "page_size"),
    [(StepClock, 3), (StepClock, 1), (lambda: lambda: datetime(2026, 1, 1, tzinfo=UTC), 4)],
    ids=["distinct-times", "one-per-page", "identical-times"],
)
def test_pages_cover_every_submission_once_in_order(stores_for: StoresFor, clock, page_size) -> None:
    stores = stores_for(clock())
    store_problem(stores)
    filed = [submit(stores, student=f"s{i % 3}").record for i in range(10)]
    pages = []
    cursor = None
    while True:
        page = stores.submissions.page(limit=page_size, cursor=cursor)
        pages.append(page.items)
        if page.next is None:
            break
        cursor = page.next
    listed = [item for page in pages for item in page]
    assert sorted(item.id for item in listed) == sorted(item.id for item in filed)
    assert len(listed) == len(filed)
    assert [(i.created_at, i.id) for i in listed] == sorted((i.created_at, i.id) for i in listed)
    assert all(0 < len(page) <= page_size for page in pages)


def test_rows_added_between_pages_are_neither_skipped_nor_repeated(stores_for: StoresFor) -> None:
    stores = stores_for(StepClock())
    store_problem(stores)
    first = [submit(stores).record for _ in range(3)]
    page = stores.submissions.page(limit=2)
    later = [submit(stores).record for _ in range(2)]
    rest = stores.submissions.page(limit=10, cursor=page.next)
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
def test_listing_filters_by_problem_and_student(stores: Stores, filters, expected_students) -> None:
    other = store_problem(stores, "yo-yo")
    for _ in range(3):
        submit(stores, student="s1")
        submit(stores, other, student="s2", problem="yo-yo")
    listed = _all(stores, **filters)
    assert {item.student for item in listed} == expected_students
    assert len(listed) == 3 * len(expected_students)


def test_the_default_page_is_a_hundred(stores_for: StoresFor) -> None:
    stores = stores_for(StepClock())
    store_problem(stores)
    for _ in range(101):
        submit(stores)
    page = stores.submissions.page()
    assert len(page.items) == 100 and page.next is not None


@pytest.mark.parametrize("limit", [0, -1, MAX_PAGE_LIMIT + 1], ids=["zero", "negative", "over-max"])
def test_a_limit_out_of_range_is_refused(stores: Stores, limit: int) -> None:
    with pytest.raises(InvalidLimit):
        stores.submissions.page(limit=limit)


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
def test_a_cursor_we_did_not_issue_is_refused(stores: Stores, cursor: str) -> None:
    with pytest.raises(InvalidCursor):
        stores.submissions.page(cursor=cursor)


def test_compiled_problems_are_kept_and_replaced_by_key(stores: Stores) -> None:
    assert stores.compiled.get("k") is None
    stores.compiled.put("k", b"\x00first", "mac1")
    stores.compiled.put("k", b"second", "mac2")
    stores.compiled.put("other", b"x", "mac3")
    assert stores.compiled.get("k") == (b"second", "mac2")
    assert stores.compiled.get_many(["k", "other", "missing"]) == {
        "k": (b"second", "mac2"),
        "other": (b"x", "mac3"),
    }
