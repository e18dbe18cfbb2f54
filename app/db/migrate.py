"""Schema migrations (Alembic, kept in `app/db/migrations/`), run from code rather than a CLI."""

from __future__ import annotations

import importlib
import threading
from pathlib import Path
from typing import TYPE_CHECKING

from sqlalchemy import Engine, inspect, text

from app.db.database import create_database_engine

if TYPE_CHECKING:
    from alembic.config import Config

MIGRATIONS_DIR = Path(__file__).resolve().parent / "migrations"
# Arbitrary but fixed: every physcheck process agrees on it, nothing else on the server should use it.
MIGRATION_LOCK_KEY = 0x70687973_63686B31  # "physchk1"
# Every module that declares tables on Base; Alembic (and the schema test) need them all imported.
MODEL_MODULES = ("app.db.models", "app.lti.models", "app.courses.models")
# Alembic loads env.py and the revisions as modules, which is not safe from two threads at once.
_ALEMBIC_IMPORT_LOCK = threading.Lock()


def import_models() -> None:
    """Register every table on `Base.metadata`."""
    for name in MODEL_MODULES:
        importlib.import_module(name)


def alembic_config(url: str) -> Config:
    """An Alembic config for our migrations against `url`; also for writing new revisions by hand:
    `command.revision(alembic_config(url), message="...", rev_id="0002_lti")`."""
    from alembic.config import Config  # imported only when a migration runs (a tenth of a CPU-second)

    config = Config()
    config.set_main_option("script_location", str(MIGRATIONS_DIR))
    # ConfigParser would read a '%' in a password as interpolation.
    config.set_main_option("sqlalchemy.url", url.replace("%", "%%"))
    return config


def migrate(url: str) -> None:
    """Upgrade the database at `url` to the newest revision; a no-op when it is already there.

    Safe when several processes start at once: the whole upgrade runs in one transaction that first
    takes a PostgreSQL advisory lock (the others wait, then find nothing to do). On SQLite the same
    transaction begins IMMEDIATE, which holds the single write lock for the same effect.
    """
    engine = create_database_engine(url)
    try:
        if _at_newest(engine):  # the usual start: one query, no Alembic
            return
        from alembic import command

        with engine.begin() as connection:
            if connection.dialect.name == "postgresql":
                connection.execute(text("SELECT pg_advisory_xact_lock(:key)"), {"key": MIGRATION_LOCK_KEY})
            config = alembic_config(url)
            config.attributes["connection"] = connection
            with _ALEMBIC_IMPORT_LOCK:
                command.upgrade(config, "head")
    finally:
        engine.dispose()


def newest_revision() -> str:
    """The newest revision's id: its file's name, the last in order (tests/db/test_migrations.py pins
    both to Alembic's own reading, which a database found at any other revision is left to)."""
    return max(path.stem for path in (MIGRATIONS_DIR / "versions").glob("[0-9]*.py"))


def _at_newest(engine: Engine) -> bool:
    with engine.connect() as connection:
        if not inspect(connection).has_table("alembic_version"):
            return False
        found = connection.execute(text("SELECT version_num FROM alembic_version")).scalars().all()
    return found == [newest_revision()]
