"""Key management for the command line, each call in its own transaction."""

from __future__ import annotations

from app.db.database import Database
from app.db.records import ApiKeyRecord, Role
from app.storage.sql import SqlApiKeyStore


def create_key(
    database: Database, role: str, name: str | None, student: str | None = None
) -> tuple[str, ApiKeyRecord]:
    created = SqlApiKeyStore(database).create(Role(role), name=name, student=student)
    return created.plaintext, created.record


def revoke_key(database: Database, key_id: int) -> ApiKeyRecord:
    return SqlApiKeyStore(database).revoke(key_id)
