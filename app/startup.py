"""Opening storage for a process: migrations, the database, the key store, the built-in bank."""

from __future__ import annotations

from dataclasses import dataclass

from app.auth import Principal
from app.catalog import Catalog
from app.db import keys as key_repository
from app.db.database import Database
from app.db.migrate import migrate
from app.settings import Settings


def open_database(settings: Settings) -> Database:
    """Migrate to the newest schema (safe when several instances start at once), then connect."""
    migrate(settings.database_url)
    return Database(settings.database_url)


class DatabaseKeyStore:
    def __init__(self, database: Database):
        self._database = database

    def authenticate(self, plaintext: str) -> Principal | None:
        with self._database.session(read_only=True) as session:
            record = key_repository.authenticate(session, plaintext)
        if record is None:
            return None
        return Principal(
            key_id=str(record.id), role=record.role, name=record.name or "", student=record.student
        )


@dataclass
class Storage:
    database: Database
    keys: DatabaseKeyStore
    catalog: Catalog

    def close(self) -> None:
        self.catalog.close()
        self.database.dispose()


def open_storage(settings: Settings) -> Storage:
    database = open_database(settings)
    catalog = Catalog(database, settings.secret, settings.bank_dir)
    catalog.sync_builtin()
    return Storage(database=database, keys=DatabaseKeyStore(database), catalog=catalog)
