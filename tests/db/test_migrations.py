"""Migrations: from empty to head on both backends, matching the models, and safe to run in parallel."""

from __future__ import annotations

import threading

from alembic import command
from alembic.autogenerate import compare_metadata
from alembic.migration import MigrationContext
from alembic.script import ScriptDirectory
from sqlalchemy import create_engine, inspect
from sqlalchemy.pool import NullPool

from app.db.base import Base
from app.db.migrate import MIGRATIONS_DIR, alembic_config, import_models, migrate, newest_revision

import_models()

CORE_TABLES = {"api_keys", "problems", "problem_versions", "submissions", "attempt_counters"}


def _state(url: str) -> tuple[set[str], str | None, list[object]]:
    """Tables, current revision, and the differences between the database and the models."""
    engine = create_engine(url, poolclass=NullPool)
    try:
        with engine.connect() as connection:
            context = MigrationContext.configure(connection, opts={"compare_type": True})
            return (
                set(inspect(connection).get_table_names()),
                context.get_current_revision(),
                compare_metadata(context, Base.metadata),
            )
    finally:
        engine.dispose()


def test_migrate_creates_every_table_from_an_empty_database(database_url: str) -> None:
    assert _state(database_url)[0] == set()
    migrate(database_url)
    tables, revision, _ = _state(database_url)
    assert tables >= CORE_TABLES
    assert revision is not None


def test_migrated_schema_matches_the_models(database_url: str) -> None:
    migrate(database_url)
    assert _state(database_url)[2] == []


def test_migrate_twice_is_a_no_op(database_url: str) -> None:
    migrate(database_url)
    first = _state(database_url)
    migrate(database_url)
    assert _state(database_url)[:2] == first[:2]


def test_downgrade_to_base_then_upgrade_again(database_url: str) -> None:
    migrate(database_url)
    command.downgrade(alembic_config(database_url), "base")
    assert _state(database_url)[0] <= {"alembic_version"}
    migrate(database_url)
    assert _state(database_url)[0] >= CORE_TABLES


def test_two_migrations_started_at_once_both_succeed(database_url: str) -> None:
    barrier = threading.Barrier(2)
    errors: list[BaseException] = []

    def run() -> None:
        barrier.wait()
        try:
            migrate(database_url)
        except BaseException as error:
            errors.append(error)

    threads = [threading.Thread(target=run) for _ in range(2)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert errors == []
    tables, revision, differences = _state(database_url)
    assert tables >= CORE_TABLES and revision is not None and differences == []


def test_the_newest_revision_is_alembics_head_and_every_id_is_its_file_name(database_url: str) -> None:
    """A start finds the newest revision by file name, without Alembic: the names must say it."""
    scripts = ScriptDirectory.from_config(alembic_config(database_url))
    assert newest_revision() == scripts.get_current_head()
    for script in scripts.walk_revisions():
        assert script.path is not None
        assert (MIGRATIONS_DIR / "versions" / f"{script.revision}.py").samefile(script.path)


def test_a_database_at_the_newest_revision_is_not_handed_to_alembic(database_url: str, monkeypatch) -> None:
    migrate(database_url)

    def upgrade(*_args: object) -> None:
        raise AssertionError("Alembic ran on a database already at the newest revision")

    monkeypatch.setattr(command, "upgrade", upgrade)
    migrate(database_url)


def test_a_database_one_revision_behind_is_upgraded(database_url: str) -> None:
    migrate(database_url)
    command.downgrade(alembic_config(database_url), "-1")
    assert _state(database_url)[1] != newest_revision()
    migrate(database_url)
    assert _state(database_url)[1] == newest_revision()
