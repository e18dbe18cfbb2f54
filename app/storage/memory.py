"""In-memory fakes of the stores, for tests that exercise the service rather than the database.

They keep what the SQL stores guarantee and the callers rely on (`tests/storage/` runs the same
contract against both): records returned as copies, ids never reused, versions kept, an attempt
counted atomically with its submission, keyset pages in (created_at, id) order with the same cursors.
One lock per store stands in for a transaction.
"""

from __future__ import annotations

import copy
import hmac
import json
import secrets
import threading
import uuid
from collections import Counter, defaultdict
from collections.abc import Callable, Collection, Iterable, Mapping, Sequence
from dataclasses import dataclass, replace
from datetime import datetime
from typing import TYPE_CHECKING, Any

from app.db import keys as key_format
from app.db.class_results import (
    PREVIEW_PREFIX,
    WRONG_ANSWERS_SHOWN,
    Count,
    PartResults,
    StudentFeedback,
    WrongAnswer,
)
from app.db.cursor import Position, decode_cursor, encode_cursor
from app.db.errors import (
    AttemptsExhausted,
    InvalidLimit,
    KeyNotFound,
    ProblemExists,
    ProblemNotFound,
    ProblemVersionNotFound,
)
from app.db.problems import document_hash
from app.db.records import ApiKeyRecord, CreatedKey, Page, ProblemRecord, Role, SubmissionRecord
from app.db.types import utc_now
from app.lti import keys as tool_keys
from app.lti import outbox
from app.lti.grades import score_of
from app.lti.outbox import ClaimedScore, DeliveryProblem, Outcome
from app.lti.platforms import PlatformRecord
from app.storage.protocols import DEFAULT_PAGE_LIMIT, MAX_PAGE_LIMIT, CompiledEntry, Filed, QueuedScore
from physics.verdict import Outcome as Verdicts
from physics.verdict import Verdict

if TYPE_CHECKING:
    from joserfc.jwk import RSAKey

Clock = Callable[[], datetime]
# Runs under the submission store's lock, before the filing is visible (the fake LTI queue uses it).
FilingHook = Callable[[SubmissionRecord], object]


def _as_stored(document: Mapping[str, Any]) -> dict[str, Any]:
    """What a JSON column gives back: a deep copy with JSON's types (tuples become lists)."""
    loaded: dict[str, Any] = json.loads(json.dumps(document, allow_nan=False))
    return loaded


class MemoryApiKeyStore:
    def __init__(self, clock: Clock = utc_now) -> None:
        self._clock = clock
        self._rows: dict[int, tuple[str, ApiKeyRecord]] = {}  # id -> (hash, record)
        self._lock = threading.Lock()

    def create(self, role: Role, *, name: str | None = None, student: str | None = None) -> CreatedKey:
        if role is Role.STUDENT and student is None:
            student = "student-" + secrets.token_hex(6)
        if role is not Role.STUDENT and student is not None:
            raise ValueError("only student keys name a student")
        plaintext = key_format.generate_key()
        with self._lock:
            key_id = len(self._rows) + 1
            record = ApiKeyRecord(
                id=key_id,
                prefix=key_format.lookup_prefix(plaintext),
                role=role,
                name=name,
                student=student,
                created_at=self._clock(),
                revoked_at=None,
            )
            self._rows[key_id] = (key_format.hash_key(plaintext), record)
        return CreatedKey(plaintext=plaintext, record=record)

    def authenticate(self, plaintext: str) -> ApiKeyRecord | None:
        if not plaintext.startswith(key_format.KEY_PREFIX) or len(plaintext) > key_format.MAX_KEY_LENGTH:
            return None
        presented = key_format.hash_key(plaintext)
        with self._lock:
            rows = list(self._rows.values())
        found = None
        for stored_hash, record in rows:
            if not record.revoked and hmac.compare_digest(stored_hash, presented):
                found = record
        return found

    def get(self, key_id: int) -> ApiKeyRecord:
        with self._lock:
            if key_id not in self._rows:
                raise KeyNotFound(key_id)
            return self._rows[key_id][1]

    def revoke(self, key_id: int) -> ApiKeyRecord:
        with self._lock:
            if key_id not in self._rows:
                raise KeyNotFound(key_id)
            stored_hash, record = self._rows[key_id]
            if record.revoked_at is None:
                record = replace(record, revoked_at=self._clock())
                self._rows[key_id] = (stored_hash, record)
            key_format.revocations += 1  # caches of authenticated keys drop at once, as with SQL
            return record

    def list(self, *, include_revoked: bool = True) -> list[ApiKeyRecord]:
        with self._lock:
            records = [self._rows[key_id][1] for key_id in sorted(self._rows)]
        return [r for r in records if include_revoked or not r.revoked]


@dataclass
class _Problem:
    id: str
    owner_key_id: int | None
    created_at: datetime
    versions: list[tuple[dict[str, Any], str, datetime]]  # (document, hash, created_at) from version 1
    retired_at: datetime | None = None

    def record(self, version: int | None = None) -> ProblemRecord:
        number = len(self.versions) if version is None else version
        if not 1 <= number <= len(self.versions):
            raise ProblemVersionNotFound(self.id, number)
        document, digest, created = self.versions[number - 1]
        return ProblemRecord(
            id=self.id,
            version=number,
            latest_version=len(self.versions),
            document=copy.deepcopy(document),
            document_hash=digest,
            owner_key_id=self.owner_key_id,
            created_at=self.created_at,
            version_created_at=created,
            retired_at=self.retired_at,
        )


class MemoryProblemStore:
    def __init__(self, clock: Clock = utc_now, compiled: MemoryCompiledCache | None = None) -> None:
        self._clock = clock
        self._compiled = compiled or MemoryCompiledCache()  # where a version's compilation goes
        self._problems: dict[str, _Problem] = {}
        self._lock = threading.Lock()

    def get(
        self, problem_id: str, version: int | None = None, *, include_retired: bool = False
    ) -> ProblemRecord:
        with self._lock:
            problem = self._problems.get(problem_id)
            if problem is None or (problem.retired_at is not None and not include_retired):
                raise ProblemNotFound(problem_id)
            return problem.record(version)

    def list(self, *, include_retired: bool = False, owner_key_id: int | None = None) -> list[ProblemRecord]:
        with self._lock:
            return [
                problem.record()
                for _, problem in sorted(self._problems.items())
                if (include_retired or problem.retired_at is None)
                and (owner_key_id is None or problem.owner_key_id == owner_key_id)
            ]

    def save_builtin(
        self, problem_id: str, document: Mapping[str, Any], *, compiled: CompiledEntry | None = None
    ) -> ProblemRecord:
        with self._lock:
            problem = self._problems.get(problem_id)
            if problem is not None and problem.owner_key_id is not None:
                raise ProblemExists(problem_id)
            if problem is None:
                record = self._insert(problem_id, document, owner_key_id=None)
            else:
                record = self._append(problem, document)
            self._keep(compiled)
            return record

    def create(
        self,
        problem_id: str,
        document: Mapping[str, Any],
        *,
        owner_key_id: int,
        compiled: CompiledEntry | None = None,
    ) -> ProblemRecord:
        with self._lock:
            if problem_id in self._problems:
                raise ProblemExists(problem_id)
            record = self._insert(problem_id, document, owner_key_id=owner_key_id)
            self._keep(compiled)
            return record

    def add_version(
        self, problem_id: str, document: Mapping[str, Any], *, compiled: CompiledEntry | None = None
    ) -> ProblemRecord:
        with self._lock:
            problem = self._problems.get(problem_id)
            if problem is None or problem.retired_at is not None:
                raise ProblemNotFound(problem_id)
            record = self._append(problem, document)
            self._keep(compiled)
            return record

    def _keep(self, compiled: CompiledEntry | None) -> None:
        if compiled is not None:
            self._compiled.put(compiled.key, compiled.payload, compiled.mac)

    def retire(self, problem_id: str) -> ProblemRecord:
        with self._lock:
            problem = self._problems.get(problem_id)
            if problem is None or problem.retired_at is not None:
                raise ProblemNotFound(problem_id)
            problem.retired_at = self._clock()
            return problem.record()

    def exists(self, problem_id: str, version: int) -> bool:
        """For the fake submission store: the foreign key the SQL schema enforces."""
        with self._lock:
            problem = self._problems.get(problem_id)
            return problem is not None and 1 <= version <= len(problem.versions)

    def _insert(
        self, problem_id: str, document: Mapping[str, Any], *, owner_key_id: int | None
    ) -> ProblemRecord:
        now = self._clock()
        stored = _as_stored(document)
        problem = _Problem(problem_id, owner_key_id, now, [(stored, document_hash(stored), now)])
        self._problems[problem_id] = problem
        return problem.record()

    def _append(self, problem: _Problem, document: Mapping[str, Any]) -> ProblemRecord:
        stored = _as_stored(document)
        digest = document_hash(stored)
        if problem.versions[-1][1] != digest:
            problem.versions.append((stored, digest, self._clock()))
        return problem.record()


class MemorySubmissionStore:
    def __init__(
        self, problems: MemoryProblemStore, hooks: Sequence[FilingHook] = (), clock: Clock = utc_now
    ) -> None:
        # Kept as given (not copied): `memory_stores` adds the grade queue once the store exists.
        self._problems, self._hooks, self._clock = problems, hooks, clock
        self._rows: list[SubmissionRecord] = []
        self._used: dict[tuple[str, str, str], int] = {}
        self._lock = threading.RLock()  # a filing hook may read the log (`all`) before the row is added

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
        if not self._problems.exists(problem_id, problem_version):
            raise ProblemVersionNotFound(problem_id, problem_version)
        key = (problem_id, part_id, student)
        with self._lock:
            used = self._used.get(key, 0)
            attempt = None
            if verdict.outcome is not Verdicts.INVALID:
                if max_attempts is not None and used >= max_attempts:
                    raise AttemptsExhausted(problem_id, part_id, student, max_attempts)
                attempt = used = used + 1
            record = SubmissionRecord(
                id=uuid.uuid4(),
                problem_id=problem_id,
                problem_version=problem_version,
                part_id=part_id,
                student=student,
                answer=answer,
                verdict=verdict.outcome,
                score=verdict.score,
                reason=verdict.reason,
                feedback=verdict.feedback,
                read_as=verdict.read_as,
                attempt=attempt,
                created_at=self._clock(),
            )
            # Hooks first: one that raises leaves nothing behind, as a rolled-back transaction would.
            for hook in self._hooks:
                hook(record)
            self._used[key] = used
            self._rows.append(record)
        return Filed(record, used)

    def attempts_used(self, problem_id: str, part_id: str, student: str) -> int:
        with self._lock:
            return self._used.get((problem_id, part_id, student), 0)

    def page(
        self,
        *,
        problem_id: str | None = None,
        student: str | None = None,
        limit: int = DEFAULT_PAGE_LIMIT,
        cursor: str | None = None,
    ) -> Page[SubmissionRecord]:
        if not 1 <= limit <= MAX_PAGE_LIMIT:
            raise InvalidLimit(limit, MAX_PAGE_LIMIT)
        after = None if cursor is None else decode_cursor(cursor)
        with self._lock:
            rows = [
                row
                for row in self._rows
                if (problem_id is None or row.problem_id == problem_id)
                and (student is None or row.student == student)
                and (after is None or (row.created_at, row.id) > (after.created_at, after.id))
            ]
        rows.sort(key=lambda row: (row.created_at, row.id))
        items = rows[:limit]
        next_cursor = None
        if len(rows) > limit:
            next_cursor = encode_cursor(Position(created_at=items[-1].created_at, id=items[-1].id))
        return Page(items=items, next=next_cursor)

    def class_results(self, problem_id: str, part_ids: Sequence[str]) -> list[PartResults]:
        with self._lock:
            rows = [row for row in self._rows if row.problem_id == problem_id]
        return results_of(rows, part_ids)

    def all(self) -> list[SubmissionRecord]:
        """Every stored submission, in filing order (the fake LTI queue reads scores from them)."""
        with self._lock:
            return list(self._rows)


def results_of(rows: Iterable[SubmissionRecord], part_ids: Sequence[str]) -> list[PartResults]:
    """`app.db.class_results.class_results`, counted in Python over one problem's submissions."""
    students: dict[str, set[str]] = defaultdict(set)
    right: dict[str, set[str]] = defaultdict(set)
    graded: Counter[str] = Counter()
    first: dict[tuple[str, str], int] = {}
    groups: dict[tuple[str, str, str], list[SubmissionRecord]] = defaultdict(list)
    wrong: dict[tuple[str, str, str], list[SubmissionRecord]] = defaultdict(list)
    previews: Counter[str] = Counter()
    told: dict[str, Counter[tuple[str, str]]] = defaultdict(Counter)
    for row in rows:
        part = row.part_id
        if row.student.startswith(PREVIEW_PREFIX):
            previews[part] += 1
            continue
        students[part].add(row.student)
        graded[part] += row.attempt is not None
        if row.verdict is Verdicts.CORRECT:
            right[part].add(row.student)
            if row.attempt is not None:
                known = first.get((part, row.student))
                first[(part, row.student)] = row.attempt if known is None else min(known, row.attempt)
        else:
            groups[(part, row.verdict.value, row.reason.value)].append(row)
        if row.reason.value == "known_mistake":
            groups[(part, "mistake", row.feedback)].append(row)
        if row.verdict is Verdicts.INCORRECT:
            shown = row.read_as.text if row.read_as is not None else row.answer
            wrong[(part, shown, row.reason.value)].append(row)
            told[part][(row.student, row.feedback)] += 1

    def counts(kind: str) -> dict[str, list[Count]]:
        found: dict[str, list[Count]] = defaultdict(list)
        for (part, group, key), members in groups.items():
            if group == kind:
                found[part].append(Count(key, len(members), len({m.student for m in members})))
        for items in found.values():
            items.sort(key=lambda c: (-c.submissions, c.key))
        return found

    answers: dict[str, list[WrongAnswer]] = defaultdict(list)
    for (part, shown, reason), members in wrong.items():
        latexes = [m.read_as.latex for m in members if m.read_as is not None]
        latex = max(latexes) if latexes else None
        answers[part].append(
            WrongAnswer(shown, latex or None, reason, len(members), len({m.student for m in members}))
        )
    firsts: dict[str, Counter[int]] = defaultdict(Counter)
    for (part, _), attempt in first.items():
        firsts[part][attempt] += 1
    wrong_reasons, invalid_reasons, mistakes = counts("incorrect"), counts("invalid"), counts("mistake")
    return [
        PartResults(
            part_id=part,
            tried=len(students.get(part, ())),
            correct=len(right.get(part, ())),
            graded=graded.get(part, 0),
            first_correct=dict(sorted(firsts.get(part, Counter()).items())),
            wrong_reasons=wrong_reasons.get(part, []),
            invalid_reasons=invalid_reasons.get(part, []),
            mistakes=mistakes.get(part, []),
            wrong_answers=sorted(answers.get(part, []), key=lambda a: (-a.submissions, a.answer))[
                :WRONG_ANSWERS_SHOWN
            ],
            previews=previews.get(part, 0),
            wrong_feedback=[StudentFeedback(s, f, n) for (s, f), n in told.get(part, Counter()).items()],
        )
        for part in part_ids
    ]


class MemoryCompiledCache:
    def __init__(self) -> None:
        self._rows: dict[str, tuple[bytes, str]] = {}
        self._lock = threading.Lock()

    def get(self, key: str) -> tuple[bytes, str] | None:
        with self._lock:
            return self._rows.get(key)

    def get_many(self, keys: Collection[str]) -> dict[str, tuple[bytes, str]]:
        with self._lock:
            return {key: self._rows[key] for key in keys if key in self._rows}

    def put(self, key: str, payload: bytes, mac: str) -> None:
        with self._lock:
            self._rows[key] = (bytes(payload), mac)


@dataclass
class _Target:
    id: int
    platform: PlatformRecord
    student: str
    problem_id: str
    lineitem_url: str
    sub: str
    last_timestamp: datetime | None = None


@dataclass
class _Score:
    id: int
    target: _Target
    score_given: float
    score_maximum: float
    timestamp: datetime
    status: str
    next_attempt_at: datetime
    attempts: int = 0
    claimed_by: str | None = None
    claimed_until: datetime | None = None
    last_status: int | None = None
    last_error: str | None = None

    def change(self, values: Mapping[str, Any]) -> None:
        """Set the columns an SQL UPDATE would (those the fake keeps)."""
        for name, value in values.items():
            if hasattr(self, name):
                setattr(self, name, value)


class MemoryScoreOutbox:
    """The outbox's claim, supersede and retry rules (`app.lti.outbox`), on lists under one lock."""

    def __init__(self) -> None:
        self._targets: list[_Target] = []
        self._rows: list[_Score] = []
        self._lock = threading.Lock()

    def add_target(
        self, platform: PlatformRecord, *, student: str, problem_id: str, lineitem_url: str, sub: str
    ) -> None:
        with self._lock:
            for target in self._targets:
                if (target.platform.id, target.student, target.problem_id, target.lineitem_url) == (
                    platform.id,
                    student,
                    problem_id,
                    lineitem_url,
                ):
                    return
            self._targets.append(
                # Ids never reused, even after a student's targets are erased.
                _Target(
                    max((t.id for t in self._targets), default=0) + 1,
                    platform,
                    student,
                    problem_id,
                    lineitem_url,
                    sub,
                )
            )

    def targets(self) -> list[tuple[str, str, str, str]]:
        """(student, problem_id, sub, lineitem_url) of every grade target, oldest first: for tests,
        what a test on SQL would read from the table (the service never asks)."""
        with self._lock:
            return [(t.student, t.problem_id, t.sub, t.lineitem_url) for t in self._targets]

    def launched(self, student: str, problem_id: str) -> bool:
        with self._lock:
            return any(t.student == student and t.problem_id == problem_id for t in self._targets)

    def enqueue(
        self, problem_id: str, student: str, score_given: float, score_maximum: float, timestamp: datetime
    ) -> int:
        with self._lock:
            targets = [t for t in self._targets if t.student == student and t.problem_id == problem_id]
            for target in targets:
                for row in self._rows:
                    if row.target is target and row.status == outbox.PENDING:
                        row.change(outbox.SUPERSEDE)
                sent = outbox.sent_timestamp(timestamp, target.last_timestamp)
                target.last_timestamp = sent
                self._rows.append(
                    _Score(
                        max((row.id for row in self._rows), default=0) + 1,
                        target,
                        score_given,
                        score_maximum,
                        sent,
                        outbox.PENDING,
                        next_attempt_at=timestamp,
                    )
                )
        return len(targets)

    def claim(self, claim: str, now: datetime, limit: int) -> list[ClaimedScore]:
        with self._lock:
            due = sorted(
                (
                    row
                    for row in self._rows
                    if (row.status == outbox.PENDING and row.next_attempt_at <= now)
                    or (
                        row.status == outbox.SENDING
                        and row.claimed_until is not None
                        and row.claimed_until < now
                    )
                ),
                key=lambda row: (row.timestamp, row.id),
            )[:limit]
            # Judged before any is changed, as the SQL query reads them in one statement.
            judged = [(row, self._newer_exists(row), self._in_flight(row, now)) for row in due]
            claimed = []
            for row, newer, busy in judged:
                values = outbox.claim_values(newer, busy, claim, now)
                if values is None:
                    continue
                row.change(values)
                if newer:
                    continue
                claimed.append(outbox.claimed_score(claim, row, row.target, row.target.platform))
            return claimed

    def _newer_exists(self, row: _Score) -> bool:
        return any(
            other.target is row.target
            and other is not row
            and other.timestamp > row.timestamp
            and other.status != outbox.SUPERSEDED
            for other in self._rows
        )

    def _in_flight(self, row: _Score, now: datetime) -> bool:
        return any(
            other.target is row.target
            and other is not row
            and other.status == outbox.SENDING
            and other.claimed_until is not None
            and other.claimed_until >= now
            for other in self._rows
        )

    def finish(self, score: ClaimedScore, outcome: Outcome, now: datetime) -> None:
        change = outbox.finished_values(score, outcome, now)
        with self._lock:
            for row in self._rows:
                if row.id == score.id and row.claimed_by == score.claim:
                    row.change(change)
            if outbox.wakes_platform(outcome, change):
                for row in self._rows:
                    if (
                        row.status == outbox.PENDING
                        and row.next_attempt_at > now
                        and row.target.platform.id == score.platform_id
                    ):
                        row.next_attempt_at = now

    def delivery_problems(self, *, limit: int = 200) -> list[DeliveryProblem]:
        shown = (outbox.FAILED, outbox.PENDING, outbox.SENDING, outbox.SUPERSEDED)
        with self._lock:
            rows = [
                row
                for row in reversed(self._rows)
                if (row.status == outbox.FAILED or row.attempts > 0) and row.status in shown
            ][:limit]
            return [outbox.delivery_problem(row, row.target, row.target.platform) for row in rows]

    def scores(self) -> list[QueuedScore]:
        with self._lock:
            return [
                QueuedScore(
                    id=row.id,
                    student=row.target.student,
                    problem_id=row.target.problem_id,
                    score_given=row.score_given,
                    score_maximum=row.score_maximum,
                    timestamp=row.timestamp,
                    status=row.status,
                    attempts=row.attempts,
                    claimed_by=row.claimed_by,
                    next_attempt_at=row.next_attempt_at,
                )
                for row in self._rows
            ]


class MemoryToolKeys:
    """Signing keys in memory: made on first use, the newest signs, the one before stays published."""

    def __init__(self, live: Sequence[RSAKey] = ()) -> None:
        self._live: list[RSAKey] = list(live)  # newest first (tests pass one made once: RSA is slow)
        self._lock = threading.Lock()

    def _current(self) -> RSAKey:
        if not self._live:
            self._live.insert(0, tool_keys.generate())
        return self._live[0]

    def sign(self, claims: dict[str, Any]) -> str:
        with self._lock:
            key = self._current()
        return tool_keys.sign_with(key, claims)

    def public_jwks(self) -> dict[str, list[dict[str, Any]]]:
        with self._lock:
            self._current()
            return {"keys": [dict(key.as_dict(private=False)) for key in self._live]}

    def rotate(self) -> str:
        with self._lock:
            self._live = [tool_keys.generate(), *self._live[:1]]
            kid = self._live[0].kid
        assert kid is not None
        return kid


def grade_queue(
    outbox_store: MemoryScoreOutbox,
    problems: MemoryProblemStore,
    submissions: Callable[[], list[SubmissionRecord]],
) -> FilingHook:
    """`app.lti.grades.queue_grade` for the fakes: a launched student's problem score, queued with
    the submission (the hook runs before the submission is visible, so it is counted here)."""

    def queue(stored: SubmissionRecord) -> None:
        if stored.verdict is Verdicts.INVALID or not outbox_store.launched(stored.student, stored.problem_id):
            return
        document = problems.get(stored.problem_id, stored.problem_version, include_retired=True).document
        best: dict[str, float] = {}
        for row in [*submissions(), stored]:
            if (row.problem_id, row.student) == (stored.problem_id, stored.student) and (
                row.verdict is not Verdicts.INVALID
            ):
                best[row.part_id] = max(best.get(row.part_id, 0.0), row.score)
        given, maximum = score_of(document, best)
        outbox_store.enqueue(stored.problem_id, stored.student, given, maximum, stored.created_at)

    return queue
