"""Active keys are remembered briefly; a revocation still applies at once here, and within seconds
when another process (the CLI, another instance) revokes."""

from __future__ import annotations

from sqlalchemy import update

from app.db.database import Database
from app.db.models import ApiKey
from app.db.types import utc_now
from app.keys import create_key, revoke_key
from app.startup import KEY_CACHE_SECONDS, DatabaseKeyStore
from app.storage.sql import SqlApiKeyStore


class Clock:
    def __init__(self) -> None:
        self.now = 1000.0

    def __call__(self) -> float:
        return self.now


def test_a_key_revoked_in_this_process_is_refused_at_once(db: Database) -> None:
    store = DatabaseKeyStore(SqlApiKeyStore(db), Clock())
    plaintext, record = create_key(db, "instructor", "prof")
    assert store.authenticate(plaintext) is not None
    revoke_key(db, record.id)
    assert store.authenticate(plaintext) is None


def test_a_key_revoked_elsewhere_is_refused_once_the_cache_time_has_passed(db: Database) -> None:
    clock = Clock()
    store = DatabaseKeyStore(SqlApiKeyStore(db), clock)
    plaintext, record = create_key(db, "student", "ada", student="ada")
    assert store.authenticate(plaintext) is not None
    with db.session() as session:  # as another process would: not through this process's code
        session.execute(update(ApiKey).where(ApiKey.id == record.id).values(revoked_at=utc_now()))
    clock.now += KEY_CACHE_SECONDS
    assert store.authenticate(plaintext) is None


def test_unknown_keys_are_never_remembered(db: Database) -> None:
    store = DatabaseKeyStore(SqlApiKeyStore(db), Clock())
    assert store.authenticate("pck_not-a-key") is None
    plaintext, _ = create_key(db, "instructor", "prof")
    assert store.authenticate(plaintext) is not None


def test_the_memory_only_lookup_forgets_a_key_at_its_revocation(db: Database) -> None:
    clock = Clock()
    store = DatabaseKeyStore(SqlApiKeyStore(db), clock)
    plaintext, record = create_key(db, "instructor", "prof")
    assert store.cached(plaintext) is None  # never seen: the database decides
    assert store.authenticate(plaintext) is not None
    assert store.cached(plaintext) is not None
    clock.now += KEY_CACHE_SECONDS
    assert store.cached(plaintext) is None  # too old to believe without asking again
    assert store.authenticate(plaintext) is not None
    revoke_key(db, record.id)
    assert store.cached(plaintext) is None
