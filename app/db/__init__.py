"""Storage: SQLAlchemy 2 tables, sessions and repositories; SQLite by default, PostgreSQL by URL.

database.py     Database (engine + sessions), create_database_engine
migrate.py      migrate(url): Alembic upgrade to head, safe to run from several processes at once
models.py       the tables (ORM rows; only the repositories use them)
records.py      the dataclasses the repositories return
keys.py         API keys           problems.py    problems and versions
submissions.py  submissions and attempt counters   errors.py   domain errors

The service reaches these through `app.storage` (a protocol per store; its SQL stores call these).
"""

from app.db.database import Database
from app.db.migrate import migrate

__all__ = ["Database", "migrate"]
