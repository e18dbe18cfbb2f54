"""Submissions: an append-only log, with graded attempts counted in the same transaction as the insert."""

from __future__ import annotations

import uuid
from collections.abc import Callable
from datetime import datetime
from typing import cast

from sqlalchemy import Table, and_, or_, select, update
from sqlalchemy.dialects.postgresql import insert as postgresql_insert
from sqlalchemy.dialects.sqlite import insert as sqlite_insert
from sqlalchemy.orm import Session

from app.db.cursor import Position, decode_cursor, encode_cursor
from app.db.errors import AttemptsExhausted, InvalidLimit
from app.db.models import AttemptCounter, Submission
from app.db.records import Page, SubmissionRecord
from app.db.types import utc_now
from physics.verdict import Outcome, ReadAs, Reason, Verdict

DEFAULT_PAGE_LIMIT = 100
MAX_PAGE_LIMIT = 1000

_counters = cast(Table, AttemptCounter.__table__)


def record_submission(
    session: Session,
    *,
    problem_id: str,
    problem_version: int,
    part_id: str,
    student: str,
    answer: str,
    verdict: Verdict,
    max_attempts: int | None,
    clock: Callable[[], datetime] = utc_now,
) -> SubmissionRecord:
    """Store one submission, timestamped by the server. A graded verdict uses an attempt; past
    `max_attempts` (None: unlimited) it raises AttemptsExhausted and nothing is stored (the caller's
    transaction must then be rolled back, as `Database.session` does). `invalid` uses none."""
    attempt = None
    if verdict.outcome is not Outcome.INVALID:
        attempt = _use_attempt(session, problem_id, part_id, student, max_attempts)
    row = Submission(
        id=uuid.uuid4(),
        problem_id=problem_id,
        problem_version=problem_version,
        part_id=part_id,
        student=student,
        answer=answer,
        verdict=verdict.outcome.value,
        score=verdict.score,
        reason=verdict.reason.value,
        feedback=verdict.feedback,
        read_as_text=None if verdict.read_as is None else verdict.read_as.text,
        read_as_latex=None if verdict.read_as is None else verdict.read_as.latex,
        attempt=attempt,
        created_at=clock(),
    )
    session.add(row)
    session.flush()
    return _record(row)


def attempts_used(session: Session, problem_id: str, part_id: str, student: str) -> int:
    """Graded attempts this student has used on this part (0 before the first)."""
    used = session.scalar(
        select(AttemptCounter.used).where(
            AttemptCounter.problem_id == problem_id,
            AttemptCounter.part_id == part_id,
            AttemptCounter.student == student,
        )
    )
    return used or 0


def list_submissions(
    session: Session,
    *,
    problem_id: str | None = None,
    student: str | None = None,
    limit: int = DEFAULT_PAGE_LIMIT,
    cursor: str | None = None,
) -> Page[SubmissionRecord]:
    """Submissions oldest first, optionally for one problem and/or one student, `limit` per page.

    Keyset pagination over (created_at, id): pages never repeat a row, and never skip one that was
    committed when the first page was read; rows stored later appear on later pages (a row stamped
    before the cursor but committed after that page was read, by a slower concurrent writer, is not
    revisited).
    """
    if not 1 <= limit <= MAX_PAGE_LIMIT:
        raise InvalidLimit(limit, MAX_PAGE_LIMIT)
    query = select(Submission).order_by(Submission.created_at, Submission.id).limit(limit + 1)
    if problem_id is not None:
        query = query.where(Submission.problem_id == problem_id)
    if student is not None:
        query = query.where(Submission.student == student)
    if cursor is not None:
        after = decode_cursor(cursor)
        query = query.where(
            or_(
                Submission.created_at > after.created_at,
                and_(Submission.created_at == after.created_at, Submission.id > after.id),
            )
        )
    rows = session.scalars(query).all()
    items = [_record(row) for row in rows[:limit]]
    next_cursor = None
    if len(rows) > limit:
        last = items[-1]
        next_cursor = encode_cursor(Position(created_at=last.created_at, id=last.id))
    return Page(items=items, next=next_cursor)


def _use_attempt(
    session: Session, problem_id: str, part_id: str, student: str, max_attempts: int | None
) -> int:
    """Take the next attempt, or raise AttemptsExhausted. The conditional UPDATE is what makes parallel
    submissions safe: PostgreSQL re-checks `used < max` on the row a concurrent writer just committed,
    and SQLite runs one writer at a time."""
    key = {"problem_id": problem_id, "part_id": part_id, "student": student}
    insert = postgresql_insert if session.get_bind().dialect.name == "postgresql" else sqlite_insert
    session.execute(insert(_counters).values(**key, used=0).on_conflict_do_nothing())
    bump = (
        update(_counters)
        .where(
            _counters.c.problem_id == problem_id,
            _counters.c.part_id == part_id,
            _counters.c.student == student,
        )
        .values(used=_counters.c.used + 1)
        .returning(_counters.c.used)
    )
    if max_attempts is not None:
        bump = bump.where(_counters.c.used < max_attempts)
    used = session.execute(bump).scalar_one_or_none()
    if used is None:
        assert max_attempts is not None, "an unconditional UPDATE of an existing row always returns it"
        raise AttemptsExhausted(problem_id, part_id, student, max_attempts)
    return int(used)


def _record(row: Submission) -> SubmissionRecord:
    read_as = None
    if row.read_as_text is not None:
        read_as = ReadAs(text=row.read_as_text, latex=row.read_as_latex or "")
    return SubmissionRecord(
        id=row.id,
        problem_id=row.problem_id,
        problem_version=row.problem_version,
        part_id=row.part_id,
        student=row.student,
        answer=row.answer,
        verdict=Outcome(row.verdict),
        score=row.score,
        reason=Reason(row.reason),
        feedback=row.feedback,
        read_as=read_as,
        attempt=row.attempt,
        created_at=row.created_at,
    )
