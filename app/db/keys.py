"""API keys: created with 256 random bits, stored only as a SHA-256 hash, found by a short prefix."""

from __future__ import annotations

import hashlib
import hmac
import secrets
from collections.abc import Callable
from datetime import datetime

from sqlalchemy import select
from sqlalchemy.orm import Session

from app.db.errors import KeyNotFound
from app.db.models import ApiKey
from app.db.records import ApiKeyRecord, CreatedKey, Role
from app.db.types import utc_now

KEY_PREFIX = "pck_"
KEY_RANDOM_BYTES = 32
# Characters of the key (after KEY_PREFIX) kept in clear to find the row; 48 of its 256 bits.
LOOKUP_CHARS = 8
# Longer than any key we issue; anything longer is refused before it is hashed.
MAX_KEY_LENGTH = 128
# Bumped by every revocation in this process, so that caches of authenticated keys drop at once.
revocations = 0


def generate_key() -> str:
    return KEY_PREFIX + secrets.token_urlsafe(KEY_RANDOM_BYTES)


def hash_key(plaintext: str) -> str:
    # A plain (unsalted) hash is enough: the key is random, so there is nothing to guess from it.
    return hashlib.sha256(plaintext.encode("utf-8")).hexdigest()


def lookup_prefix(plaintext: str) -> str:
    return plaintext[: len(KEY_PREFIX) + LOOKUP_CHARS]


def create_key(
    session: Session,
    role: Role,
    *,
    name: str | None = None,
    student: str | None = None,
    clock: Callable[[], datetime] = utc_now,
) -> CreatedKey:
    """A new key. A student key files submissions under `student` (a fresh id when not given)."""
    if role is Role.STUDENT and student is None:
        student = "student-" + secrets.token_hex(6)
    if role is not Role.STUDENT and student is not None:
        raise ValueError("only student keys name a student")
    plaintext = generate_key()
    row = ApiKey(
        prefix=lookup_prefix(plaintext),
        key_hash=hash_key(plaintext),
        role=role.value,
        name=name,
        student=student,
        created_at=clock(),
    )
    session.add(row)
    session.flush()
    return CreatedKey(plaintext=plaintext, record=_record(row))


def authenticate(session: Session, plaintext: str) -> ApiKeyRecord | None:
    """The active key `plaintext` names, or None (unknown, malformed or revoked)."""
    if not plaintext.startswith(KEY_PREFIX) or len(plaintext) > MAX_KEY_LENGTH:
        return None
    presented = hash_key(plaintext)
    candidates = session.scalars(
        select(ApiKey).where(ApiKey.prefix == lookup_prefix(plaintext), ApiKey.revoked_at.is_(None))
    ).all()
    found: ApiKey | None = None
    for row in candidates:
        # Compare every candidate, in constant time, rather than stopping at the first match.
        if hmac.compare_digest(row.key_hash, presented):
            found = row
    return None if found is None else _record(found)


def revoke_key(session: Session, key_id: int, *, clock: Callable[[], datetime] = utc_now) -> ApiKeyRecord:
    """Revoke a key for good; revoking it again keeps the first revocation time."""
    row = session.get(ApiKey, key_id, with_for_update=True)
    if row is None:
        raise KeyNotFound(key_id)
    if row.revoked_at is None:
        row.revoked_at = clock()
        session.flush()
    global revocations
    revocations += 1
    return _record(row)


def get_key(session: Session, key_id: int) -> ApiKeyRecord:
    row = session.get(ApiKey, key_id)
    if row is None:
        raise KeyNotFound(key_id)
    return _record(row)


def list_keys(session: Session, *, include_revoked: bool = True) -> list[ApiKeyRecord]:
    """Every key, oldest first (never the key itself: it is not stored)."""
    query = select(ApiKey).order_by(ApiKey.id)
    if not include_revoked:
        query = query.where(ApiKey.revoked_at.is_(None))
    return [_record(row) for row in session.scalars(query)]


def _record(row: ApiKey) -> ApiKeyRecord:
    return ApiKeyRecord(
        id=row.id,
        prefix=row.prefix,
        role=Role(row.role),
        name=row.name,
        student=row.student,
        created_at=row.created_at,
        revoked_at=row.revoked_at,
    )
