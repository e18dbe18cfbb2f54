"""Submissions in SQL: the database itself refuses to change them (the rest of the contract:
tests/storage/test_submissions.py)."""

from __future__ import annotations

import pytest
from sqlalchemy import text
from sqlalchemy.exc import DBAPIError

from app.db.database import Database
from app.db.submissions import list_submissions, record_submission
from tests.db.helpers import INCORRECT, PART, PROBLEM, store_problem


@pytest.mark.parametrize(
    "statement",
    ["UPDATE submissions SET score = 1.0", "DELETE FROM submissions"],
    ids=["update", "delete"],
)
def test_the_database_refuses_to_change_stored_submissions(db: Database, statement: str) -> None:
    with db.session() as session:
        version = store_problem(session)
        record_submission(
            session,
            problem_id=PROBLEM,
            problem_version=version,
            part_id=PART,
            student="s1",
            answer="-m g",
            verdict=INCORRECT,
            max_attempts=None,
        )
    with pytest.raises(DBAPIError, match="append-only"), db.session() as session:
        session.execute(text(statement))
    with db.session(read_only=True) as session:
        assert len(list_submissions(session).items) == 1
