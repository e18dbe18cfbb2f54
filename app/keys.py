"""Key management for the command line, each call in its own transaction."""

from __future__ import annotations

from app.db import keys as key_repository
from app.db.database import Database
from app.db.records import ApiKeyRecord, Role


def create_key(
    database: Database, role: str, name: str | None, student: str | None = None
) -> tuple[str, ApiKeyRecord]:
    with database.session() as session:
        created = key_repository.create_key(session, Role(role), name=name, student=student)
    return created.plaintext, created.record


def revoke_key(database: Database, key_id: int) -> ApiKeyRecord:
    with database.session() as session:
        return key_repository.revoke_key(session, key_id)
