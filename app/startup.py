"""Opening storage for a process: migrations, the database, the key store, the built-in bank."""

from __future__ import annotations

import hashlib
import logging
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass

from sqlalchemy.engine import make_url
from sqlalchemy.exc import InterfaceError, OperationalError

from app.auth import Principal
from app.catalog import Catalog
from app.db import keys as key_repository
from app.db.database import Database
from app.db.migrate import migrate
from app.derivation import DerivationPool
from app.settings import Settings
from app.shipped_bank import SHIPPED_BANK
from app.storage import ApiKeyStore, Stores, sql_stores

log = logging.getLogger("physcheck.startup")
STARTUP_RETRY_MAX_SECONDS = 10.0


def open_database(settings: Settings) -> Database:
    """Migrate to the newest schema (safe when several instances start at once), then connect."""
    migrate(settings.database_url)
    return Database(settings.database_url, timeout_seconds=settings.database_timeout_seconds)


# How long a key, once found active, is believed without asking the database again: a revocation in
# this process applies at once (the revocation count), one in another process (the CLI, another
# instance) within this time.
KEY_CACHE_SECONDS = 2.0
KEY_CACHE_SIZE = 10_000


class DatabaseKeyStore:
    def __init__(self, keys: ApiKeyStore, clock: Callable[[], float] = time.monotonic):
        self._keys = keys
        self._clock = clock
        # sha256(key) -> (principal, when found, revocation count then); only active keys are kept
        self._known: dict[bytes, tuple[Principal, float, int]] = {}
        self._lock = threading.Lock()

    def cached(self, plaintext: str) -> Principal | None:
        """The key's principal if it was found active within KEY_CACHE_SECONDS and nothing was revoked
        since; no I/O, so the event loop may call it (None: ask `authenticate`)."""
        digest = hashlib.sha256(plaintext.encode("utf-8", "surrogatepass")).digest()
        with self._lock:
            known = self._known.get(digest)
        if known is None:
            return None
        principal, found_at, revocations = known
        if self._clock() - found_at < KEY_CACHE_SECONDS and revocations == key_repository.revocations:
            return principal
        return None

    def authenticate(self, plaintext: str) -> Principal | None:
        found = self.cached(plaintext)
        if found is not None:
            return found
        digest = hashlib.sha256(plaintext.encode("utf-8", "surrogatepass")).digest()
        now = self._clock()
        revocations = key_repository.revocations
        record = self._keys.authenticate(plaintext)
        if record is None:
            return None
        principal = Principal(
            key_id=str(record.id), role=record.role, name=record.name or "", student=record.student
        )
        with self._lock:
            if len(self._known) >= KEY_CACHE_SIZE:
                self._known.clear()
            self._known[digest] = (principal, now, revocations)
        return principal


@dataclass
class Storage:
    database: Database | None  # None on the in-memory fakes
    stores: Stores
    keys: DatabaseKeyStore
    catalog: Catalog

    def close(self) -> None:
        self.catalog.close()
        if self.database is not None:
            self.database.dispose()


def deriver(settings: Settings) -> DerivationPool:
    """Derivations (what is not stored yet) in `derive_jobs` workers, under an upload's limits."""
    return DerivationPool(settings.derive_jobs, settings.upload_timeout_seconds, settings.check_memory_mb)


def open_storage(settings: Settings) -> Storage:
    database = open_database(settings)
    stores = sql_stores(database)
    catalog = Catalog(
        stores,
        settings.secret,
        settings.bank_dir,
        deriver=deriver(settings),
        shipped=SHIPPED_BANK if settings.shipped_bank else None,
    )
    catalog.sync_builtin()
    return Storage(database=database, stores=stores, keys=DatabaseKeyStore(stores.keys), catalog=catalog)


class Stopped(Exception):
    """Asked to stop (SIGTERM, Ctrl-C) before the database answered."""


def open_storage_when_reachable(settings: Settings, stopping: threading.Event | None = None) -> Storage:
    """`open_storage`, waiting for a database that is down (a server started during an outage, or
    before its database) instead of exiting: one log line per try, retrying at growing intervals.
    Raises Stopped once `stopping` is set (checked between tries, and it cuts a wait short)."""
    where = make_url(settings.database_url).render_as_string(hide_password=True)
    stopping = stopping or threading.Event()
    delay = 1.0
    while not stopping.is_set():
        try:
            return open_storage(settings)
        except (OperationalError, InterfaceError) as error:
            reason = str(getattr(error, "orig", None) or error).strip().splitlines() or [type(error).__name__]
            log.warning(
                "waiting for the database: %s is not reachable (%s); retrying in %.0f s",
                where,
                reason[0],
                delay,
            )
            stopping.wait(delay)
            delay = min(delay * 2, STARTUP_RETRY_MAX_SECONDS)
    raise Stopped(f"stopped while waiting for the database at {where}")
