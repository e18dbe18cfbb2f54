"""Problems and their versions: every version is kept forever; PUT adds one, DELETE retires the problem."""

from __future__ import annotations

import hashlib
import json
from collections.abc import Callable, Mapping
from datetime import datetime
from typing import Any

from sqlalchemy import select
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session

from app.db.errors import ProblemExists, ProblemNotFound, ProblemVersionNotFound
from app.db.models import Problem, ProblemVersion
from app.db.records import ProblemRecord
from app.db.types import utc_now

Clock = Callable[[], datetime]


def document_hash(document: Mapping[str, Any]) -> str:
    """SHA-256 of the document's canonical JSON: equal documents hash equal whatever their key order."""
    canonical = json.dumps(
        document, sort_keys=True, separators=(",", ":"), ensure_ascii=False, allow_nan=False
    )
    return hashlib.sha256(canonical.encode("utf-8")).hexdigest()


def save_builtin(
    session: Session, problem_id: str, document: Mapping[str, Any], *, clock: Clock = utc_now
) -> ProblemRecord:
    """Store a bank problem at start-up, idempotently: an unchanged document keeps its version, a changed
    one becomes the next version. A retired built-in stays retired. Raises ProblemExists if an
    instructor already owns the id."""
    row = _lock(session, problem_id)
    if row is None:
        try:
            return _insert(session, problem_id, document, owner_key_id=None, clock=clock)
        except ProblemExists:
            # Another process stored it between our look and our insert; continue from its row.
            row = _lock(session, problem_id)
            assert row is not None
    if row.owner_key_id is not None:
        raise ProblemExists(problem_id)
    return _append_version(session, row, document, clock=clock)


def create_problem(
    session: Session,
    problem_id: str,
    document: Mapping[str, Any],
    *,
    owner_key_id: int,
    clock: Clock = utc_now,
) -> ProblemRecord:
    """A new problem at version 1; raises ProblemExists if the id was ever used (even if retired)."""
    return _insert(session, problem_id, document, owner_key_id=owner_key_id, clock=clock)


def add_version(
    session: Session, problem_id: str, document: Mapping[str, Any], *, clock: Clock = utc_now
) -> ProblemRecord:
    """The next version of a live problem. Sending the latest document again changes nothing (PUT is
    idempotent). Raises ProblemNotFound if it does not exist or is retired."""
    row = _lock(session, problem_id)
    if row is None or row.retired_at is not None:
        raise ProblemNotFound(problem_id)
    return _append_version(session, row, document, clock=clock)


def retire_problem(session: Session, problem_id: str, *, clock: Clock = utc_now) -> ProblemRecord:
    """Hide a problem from listings and new work; its versions and submissions stay. Raises
    ProblemNotFound if it does not exist or is already retired."""
    row = _lock(session, problem_id)
    if row is None or row.retired_at is not None:
        raise ProblemNotFound(problem_id)
    row.retired_at = clock()
    session.flush()
    return get_problem(session, problem_id, include_retired=True)


def get_problem(
    session: Session, problem_id: str, version: int | None = None, *, include_retired: bool = False
) -> ProblemRecord:
    """The latest version, or the one asked for. A retired problem is ProblemNotFound unless
    `include_retired` (e.g. to show old submissions against it)."""
    problem = session.get(Problem, problem_id)
    if problem is None or (problem.retired_at is not None and not include_retired):
        raise ProblemNotFound(problem_id)
    wanted = problem.latest_version if version is None else version
    row = session.get(ProblemVersion, (problem_id, wanted))
    if row is None:
        raise ProblemVersionNotFound(problem_id, wanted)
    return _record(problem, row)


def list_problems(
    session: Session, *, include_retired: bool = False, owner_key_id: int | None = None
) -> list[ProblemRecord]:
    """The latest version of every problem, by id; retired ones only when asked."""
    query = (
        select(Problem, ProblemVersion)
        .join(
            ProblemVersion,
            (ProblemVersion.problem_id == Problem.id) & (ProblemVersion.version == Problem.latest_version),
        )
        .order_by(Problem.id)
    )
    if not include_retired:
        query = query.where(Problem.retired_at.is_(None))
    if owner_key_id is not None:
        query = query.where(Problem.owner_key_id == owner_key_id)
    return [_record(problem, version) for problem, version in session.execute(query)]


def _lock(session: Session, problem_id: str) -> Problem | None:
    """The problem row, locked until commit on PostgreSQL so concurrent writers take turns (SQLite
    transactions already hold the database's write lock)."""
    return session.scalars(select(Problem).where(Problem.id == problem_id).with_for_update()).one_or_none()


def _insert(
    session: Session,
    problem_id: str,
    document: Mapping[str, Any],
    *,
    owner_key_id: int | None,
    clock: Clock,
) -> ProblemRecord:
    now = clock()
    problem = Problem(id=problem_id, owner_key_id=owner_key_id, latest_version=1, created_at=now)
    version = ProblemVersion(
        problem_id=problem_id,
        version=1,
        document=dict(document),
        document_hash=document_hash(document),
        created_at=now,
    )
    try:
        # A savepoint, so that losing a race to the same id leaves the caller's transaction usable.
        with session.begin_nested():
            if session.get(Problem, problem_id) is not None:
                raise ProblemExists(problem_id)
            session.add(problem)
            session.flush()
            session.add(version)
            session.flush()
    except IntegrityError as error:
        if session.get(Problem, problem_id) is not None:
            raise ProblemExists(problem_id) from error
        raise
    return _record(problem, version)


def _append_version(
    session: Session, problem: Problem, document: Mapping[str, Any], *, clock: Clock
) -> ProblemRecord:
    latest = session.get(ProblemVersion, (problem.id, problem.latest_version))
    assert latest is not None, "latest_version always names a stored version"
    digest = document_hash(document)
    if latest.document_hash == digest:
        return _record(problem, latest)
    version = ProblemVersion(
        problem_id=problem.id,
        version=problem.latest_version + 1,
        document=dict(document),
        document_hash=digest,
        created_at=clock(),
    )
    session.add(version)
    problem.latest_version = version.version
    session.flush()
    return _record(problem, version)


def _record(problem: Problem, version: ProblemVersion) -> ProblemRecord:
    return ProblemRecord(
        id=problem.id,
        version=version.version,
        latest_version=problem.latest_version,
        document=version.document,
        document_hash=version.document_hash,
        owner_key_id=problem.owner_key_id,
        created_at=problem.created_at,
        version_created_at=version.created_at,
        retired_at=problem.retired_at,
    )
