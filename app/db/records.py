"""What the repositories return: plain frozen dataclasses, so callers never hold ORM rows."""

from __future__ import annotations

import uuid
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from datetime import datetime
from enum import StrEnum
from typing import Any, Generic, TypeVar

from physics.verdict import Outcome, ReadAs, Reason

T = TypeVar("T")


class Role(StrEnum):
    INSTRUCTOR = "instructor"
    STUDENT = "student"


@dataclass(frozen=True)
class ApiKeyRecord:
    id: int
    prefix: str  # the key's first characters, safe to show so people can tell their keys apart
    role: Role
    name: str | None
    student: str | None  # for student keys: the identity their submissions are filed under
    created_at: datetime
    revoked_at: datetime | None

    @property
    def revoked(self) -> bool:
        return self.revoked_at is not None


@dataclass(frozen=True)
class CreatedKey:
    """A new key: `plaintext` exists only here, once; it is kept out of repr so it cannot reach a log."""

    plaintext: str = field(repr=False)
    record: ApiKeyRecord


@dataclass(frozen=True)
class ProblemRecord:
    """One version of a problem (the latest, unless a version was asked for)."""

    id: str
    version: int
    latest_version: int
    document: Mapping[str, Any]
    document_hash: str
    owner_key_id: int | None  # None for the built-in bank
    created_at: datetime  # when the problem was first stored
    version_created_at: datetime
    retired_at: datetime | None

    @property
    def builtin(self) -> bool:
        return self.owner_key_id is None

    @property
    def retired(self) -> bool:
        return self.retired_at is not None


@dataclass(frozen=True)
class SubmissionRecord:
    id: uuid.UUID
    problem_id: str
    problem_version: int
    part_id: str
    student: str
    answer: str
    verdict: Outcome
    score: float
    reason: Reason
    feedback: str
    read_as: ReadAs | None
    attempt: int | None  # 1-based number of this graded attempt; None for `invalid` (no attempt used)
    created_at: datetime


@dataclass(frozen=True)
class Page(Generic[T]):
    """One page of a listing; pass `next` back as the cursor for the following page (None: last page)."""

    items: Sequence[T]
    next: str | None
