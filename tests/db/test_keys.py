"""API keys in SQL: only a hash is stored (the rest of the contract: tests/storage/test_keys.py)."""

from __future__ import annotations

from sqlalchemy import text

from app.db.database import Database
from app.db.keys import create_key
from app.db.records import Role


def test_the_plaintext_key_is_stored_nowhere(db: Database) -> None:
    with db.session() as session:
        created = create_key(session, Role.STUDENT, name="Bea")
    secret_part = created.plaintext[len(created.record.prefix) :]
    with db.session(read_only=True) as session:
        rows = session.execute(text("SELECT * FROM api_keys")).all()
    stored = " ".join(str(value) for row in rows for value in row)
    assert created.plaintext not in stored
    assert secret_part not in stored
