"""Storage behind small protocols, so the routes, the LTI code and the pages never open sessions.

protocols.py   one Protocol per store (keys, problems, submissions, compiled problems)
sql.py         their SQLAlchemy implementation over the `app.db` repositories (SQLite, PostgreSQL)
memory.py      in-memory fakes that keep the same contract (tests/storage runs it against all three)

`Stores` is what an application holds: one of each, plus `ping` for readiness.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from app.db.database import Database
from app.db.types import utc_now
from app.storage.memory import (
    MemoryApiKeyStore,
    MemoryCompiledCache,
    MemoryProblemStore,
    MemorySubmissionStore,
)
from app.storage.protocols import (
    ApiKeyStore,
    CompiledCache,
    Filed,
    ProblemStore,
    SubmissionStore,
)
from app.storage.sql import (
    Clock,
    FilingHook,
    SqlApiKeyStore,
    SqlCompiledCache,
    SqlProblemStore,
    SqlSubmissionStore,
)

__all__ = [
    "ApiKeyStore",
    "CompiledCache",
    "Filed",
    "ProblemStore",
    "Stores",
    "SubmissionStore",
    "memory_stores",
    "sql_stores",
]


@dataclass(frozen=True)
class Stores:
    keys: ApiKeyStore
    problems: ProblemStore
    submissions: SubmissionStore
    compiled: CompiledCache
    ping: Callable[[], bool] = field(default=lambda: True)


def sql_stores(database: Database, *, on_filed: Sequence[FilingHook] = (), clock: Clock = utc_now) -> Stores:
    """The stores on `database`; `on_filed` hooks run in each submission's own transaction."""
    return Stores(
        keys=SqlApiKeyStore(database, clock),
        problems=SqlProblemStore(database, clock),
        submissions=SqlSubmissionStore(database, on_filed, clock),
        compiled=SqlCompiledCache(database),
        ping=database.ping,
    )


def memory_stores(*, clock: Clock = utc_now) -> Stores:
    problems = MemoryProblemStore(clock)
    return Stores(
        keys=MemoryApiKeyStore(clock),
        problems=problems,
        submissions=MemorySubmissionStore(problems, clock=clock),
        compiled=MemoryCompiledCache(),
    )
