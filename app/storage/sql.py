"""The stores on SQLAlchemy (SQLite or PostgreSQL): each call one transaction over the `app.db`
repositories, so no caller opens a session."""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping, Sequence
from datetime import datetime
from typing import Any

from sqlalchemy import exists, select
from sqlalchemy.orm import Session

from app.db import class_results as results_repository
from app.db import compiled as compiled_repository
from app.db import keys as key_repository
from app.db import problems as problem_repository
from app.db import submissions as submission_repository
from app.db.class_results import PartResults
from app.db.database import Database
from app.db.records import ApiKeyRecord, CreatedKey, Page, ProblemRecord, Role, SubmissionRecord
from app.db.types import utc_now
from app.lti.models import LtiGradeTarget, LtiScoreOutbox
from app.lti.outbox import ClaimedScore, DeliveryProblem, Outcome
from app.lti.platforms import PlatformRecord
from app.storage import sql_outbox as outbox
from app.storage import sql_tool_keys as tool_keys
from app.storage.protocols import DEFAULT_PAGE_LIMIT, CompiledEntry, Filed, QueuedScore
from physics.verdict import Verdict

Clock = Callable[[], datetime]
# Runs inside the transaction that files a submission (LTI grade passback queues there).
FilingHook = Callable[[Session, SubmissionRecord], object]


class SqlApiKeyStore:
    def __init__(self, database: Database, clock: Clock = utc_now) -> None:
        self._database, self._clock = database, clock

    def create(self, role: Role, *, name: str | None = None, student: str | None = None) -> CreatedKey:
        with self._database.session() as session:
            return key_repository.create_key(session, role, name=name, student=student, clock=self._clock)

    def authenticate(self, plaintext: str) -> ApiKeyRecord | None:
        with self._database.session(read_only=True) as session:
            return key_repository.authenticate(session, plaintext)

    def get(self, key_id: int) -> ApiKeyRecord:
        with self._database.session(read_only=True) as session:
            return key_repository.get_key(session, key_id)

    def revoke(self, key_id: int) -> ApiKeyRecord:
        with self._database.session() as session:
            return key_repository.revoke_key(session, key_id, clock=self._clock)

    def list(self, *, include_revoked: bool = True) -> list[ApiKeyRecord]:
        with self._database.session(read_only=True) as session:
            return key_repository.list_keys(session, include_revoked=include_revoked)


class SqlProblemStore:
    def __init__(self, database: Database, clock: Clock = utc_now) -> None:
        self._database, self._clock = database, clock

    def get(
        self, problem_id: str, version: int | None = None, *, include_retired: bool = False
    ) -> ProblemRecord:
        with self._database.session(read_only=True) as session:
            return problem_repository.get_problem(
                session, problem_id, version, include_retired=include_retired
            )

    def list(self, *, include_retired: bool = False, owner_key_id: int | None = None) -> list[ProblemRecord]:
        with self._database.session(read_only=True) as session:
            return problem_repository.list_problems(
                session, include_retired=include_retired, owner_key_id=owner_key_id
            )

    def save_builtin(
        self, problem_id: str, document: Mapping[str, Any], *, compiled: CompiledEntry | None = None
    ) -> ProblemRecord:
        with self._database.session() as session:
            record = problem_repository.save_builtin(session, problem_id, document, clock=self._clock)
            _keep(session, compiled)
            return record

    def create(
        self,
        problem_id: str,
        document: Mapping[str, Any],
        *,
        owner_key_id: int,
        compiled: CompiledEntry | None = None,
    ) -> ProblemRecord:
        with self._database.session() as session:
            record = problem_repository.create_problem(
                session, problem_id, document, owner_key_id=owner_key_id, clock=self._clock
            )
            _keep(session, compiled)
            return record

    def add_version(
        self, problem_id: str, document: Mapping[str, Any], *, compiled: CompiledEntry | None = None
    ) -> ProblemRecord:
        with self._database.session() as session:
            record = problem_repository.add_version(session, problem_id, document, clock=self._clock)
            _keep(session, compiled)
            return record

    def retire(self, problem_id: str) -> ProblemRecord:
        with self._database.session() as session:
            return problem_repository.retire_problem(session, problem_id, clock=self._clock)


def _keep(session: Session, compiled: CompiledEntry | None) -> None:
    """A version's compilation, in the version's own transaction."""
    if compiled is not None:
        compiled_repository.put_compiled(session, compiled.key, compiled.payload, compiled.mac)


class SqlSubmissionStore:
    def __init__(self, database: Database, hooks: Sequence[FilingHook] = (), clock: Clock = utc_now) -> None:
        self._database, self._hooks, self._clock = database, tuple(hooks), clock

    def file(
        self,
        *,
        problem_id: str,
        problem_version: int,
        part_id: str,
        student: str,
        answer: str,
        verdict: Verdict,
        max_attempts: int | None,
    ) -> Filed:
        with self._database.session() as session:
            stored = submission_repository.record_submission(
                session,
                problem_id=problem_id,
                problem_version=problem_version,
                part_id=part_id,
                student=student,
                answer=answer,
                verdict=verdict,
                max_attempts=max_attempts,
                clock=self._clock,
            )
            used = stored.attempt or submission_repository.attempts_used(
                session, problem_id, part_id, student
            )
            for hook in self._hooks:
                hook(session, stored)
        return Filed(stored, used)

    def attempts_used(self, problem_id: str, part_id: str, student: str) -> int:
        with self._database.session(read_only=True) as session:
            return submission_repository.attempts_used(session, problem_id, part_id, student)

    def page(
        self,
        *,
        problem_id: str | None = None,
        student: str | None = None,
        limit: int = DEFAULT_PAGE_LIMIT,
        cursor: str | None = None,
    ) -> Page[SubmissionRecord]:
        with self._database.session(read_only=True) as session:
            return submission_repository.list_submissions(
                session, problem_id=problem_id, student=student, limit=limit, cursor=cursor
            )

    def class_results(self, problem_id: str, part_ids: Sequence[str]) -> list[PartResults]:
        with self._database.session(read_only=True) as session:
            return results_repository.class_results(session, problem_id, part_ids)


class SqlCompiledCache:
    def __init__(self, database: Database) -> None:
        self._database = database

    def get(self, key: str) -> tuple[bytes, str] | None:
        with self._database.session(read_only=True) as session:
            return compiled_repository.get_compiled(session, key)

    def get_many(self, keys: Collection[str]) -> dict[str, tuple[bytes, str]]:
        with self._database.session(read_only=True) as session:
            return compiled_repository.get_many_compiled(session, keys)

    def put(self, key: str, payload: bytes, mac: str) -> None:
        with self._database.session() as session:
            compiled_repository.put_compiled(session, key, payload, mac)


class SqlScoreOutbox:
    def __init__(self, database: Database) -> None:
        self._database = database

    def add_target(
        self, platform: PlatformRecord, *, student: str, problem_id: str, lineitem_url: str, sub: str
    ) -> None:
        with self._database.session() as session:
            outbox.add_grade_target(
                session,
                platform.id,
                student=student,
                problem_id=problem_id,
                lineitem_url=lineitem_url,
                sub=sub,
            )

    def enqueue(
        self, problem_id: str, student: str, score_given: float, score_maximum: float, timestamp: datetime
    ) -> int:
        with self._database.session() as session:
            return outbox.enqueue_scores(session, problem_id, student, score_given, score_maximum, timestamp)

    def claim(self, claim: str, now: datetime, limit: int) -> list[ClaimedScore]:
        return outbox.claim_batch(self._database, claim, now, limit)

    def finish(self, score: ClaimedScore, outcome: Outcome, now: datetime) -> None:
        outbox.finish(self._database, score, outcome, now)

    def launched(self, student: str, problem_id: str) -> bool:
        query = select(
            exists().where(LtiGradeTarget.student == student, LtiGradeTarget.problem_id == problem_id)
        )
        with self._database.session(read_only=True) as session:
            return bool(session.scalar(query))

    def delivery_problems(self, *, limit: int = 200) -> list[DeliveryProblem]:
        with self._database.session(read_only=True) as session:
            return outbox.list_delivery_problems(session, limit=limit)

    def scores(self) -> list[QueuedScore]:
        query = (
            select(LtiScoreOutbox, LtiGradeTarget)
            .join(LtiGradeTarget, LtiGradeTarget.id == LtiScoreOutbox.target_id)
            .order_by(LtiScoreOutbox.id)
        )
        with self._database.session(read_only=True) as session:
            return [
                QueuedScore(
                    id=row.id,
                    student=target.student,
                    problem_id=target.problem_id,
                    score_given=row.score_given,
                    score_maximum=row.score_maximum,
                    timestamp=row.timestamp,
                    status=row.status,
                    attempts=row.attempts,
                    claimed_by=row.claimed_by,
                    next_attempt_at=row.next_attempt_at,
                )
                for row, target in session.execute(query)
            ]


class SqlToolKeys:
    def __init__(self, database: Database, clock: Clock = utc_now) -> None:
        self._database, self._clock = database, clock

    def sign(self, claims: dict[str, Any]) -> str:
        with self._database.session() as session:
            return tool_keys.sign(session, claims, clock=self._clock)

    def public_jwks(self) -> dict[str, list[dict[str, Any]]]:
        with self._database.session() as session:
            tool_keys.signing_key(session, clock=self._clock)  # so the set is never empty
            return tool_keys.public_jwks(session)

    def rotate(self) -> str:
        return tool_keys.rotate_keys(self._database, clock=self._clock)
