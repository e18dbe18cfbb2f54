"""Problems in SQL: content hashes, and savepoints (the rest of the contract: tests/storage/test_problems.py)."""

from __future__ import annotations

import pytest

from app.db.database import Database
from app.db.errors import ProblemExists
from app.db.keys import create_key
from app.db.problems import create_problem, document_hash, list_problems, save_builtin
from app.db.records import Role

V1 = {"id": "yo-yo", "title": "Yo-yo", "parts": [{"id": "acceleration"}]}
V2 = {"id": "yo-yo", "title": "Yo-yo (revised)", "parts": [{"id": "acceleration"}, {"id": "tension"}]}


def test_document_hash_ignores_key_order() -> None:
    assert document_hash({"a": 1, "b": [1, 2]}) == document_hash({"b": [1, 2], "a": 1})
    assert document_hash({"a": 1}) != document_hash({"a": 2})


def test_a_failed_create_leaves_the_transaction_usable(db: Database) -> None:
    with db.session() as session:
        owner = create_key(session, Role.INSTRUCTOR).record.id
        save_builtin(session, "yo-yo", V1)
    with db.session() as session:
        with pytest.raises(ProblemExists):
            create_problem(session, "yo-yo", V2, owner_key_id=owner)
        create_problem(session, "other", V2, owner_key_id=owner)
    with db.session(read_only=True) as session:
        assert [problem.id for problem in list_problems(session)] == ["other", "yo-yo"]
