"""The tables (ORM rows). Only the repositories touch these; callers get the dataclasses in `records`."""

from __future__ import annotations

import uuid
from datetime import datetime
from typing import Any

from sqlalchemy import (
    JSON,
    CheckConstraint,
    Float,
    ForeignKey,
    ForeignKeyConstraint,
    Index,
    Integer,
    LargeBinary,
    String,
    Text,
    Uuid,
)
from sqlalchemy.orm import Mapped, mapped_column

from app.db.base import Base
from app.db.types import UTCDateTime

# Lengths shared with the migrations; a migration copies the number rather than importing it, so that
# changing a constant here can never silently rewrite history.
ID_LENGTH = 100
STUDENT_LENGTH = 200
NAME_LENGTH = 200
HASH_LENGTH = 64
PREFIX_LENGTH = 16


class ApiKey(Base):
    __tablename__ = "api_keys"
    __table_args__ = (
        CheckConstraint("role IN ('instructor', 'student')", name="role"),
        # A student key always names the identity its submissions are filed under; an instructor's never.
        CheckConstraint(
            "(role = 'student' AND student IS NOT NULL) OR (role <> 'student' AND student IS NULL)",
            name="student_identity",
        ),
    )

    id: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=True)
    prefix: Mapped[str] = mapped_column(String(PREFIX_LENGTH), index=True)
    key_hash: Mapped[str] = mapped_column(String(HASH_LENGTH), unique=True)
    role: Mapped[str] = mapped_column(String(16))
    name: Mapped[str | None] = mapped_column(String(NAME_LENGTH))
    student: Mapped[str | None] = mapped_column(String(STUDENT_LENGTH))
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())
    revoked_at: Mapped[datetime | None] = mapped_column(UTCDateTime())


class Problem(Base):
    __tablename__ = "problems"
    __table_args__ = (CheckConstraint("latest_version >= 1", name="latest_version_positive"),)

    id: Mapped[str] = mapped_column(String(ID_LENGTH), primary_key=True)
    # NULL for the built-in bank.
    owner_key_id: Mapped[int | None] = mapped_column(ForeignKey("api_keys.id"))
    latest_version: Mapped[int] = mapped_column(Integer)
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())
    retired_at: Mapped[datetime | None] = mapped_column(UTCDateTime())


class ProblemVersion(Base):
    __tablename__ = "problem_versions"
    __table_args__ = (CheckConstraint("version >= 1", name="version_positive"),)

    problem_id: Mapped[str] = mapped_column(ForeignKey("problems.id"), primary_key=True)
    version: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=False)
    document: Mapped[dict[str, Any]] = mapped_column(JSON)
    document_hash: Mapped[str] = mapped_column(String(HASH_LENGTH))
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())


class CompiledProblemRow(Base):
    """A problem version as this service compiled it (derivations, prepared references), sealed with an
    HMAC under the server's secret; keyed by the version's content hash and the checker code's
    fingerprint, so a changed document or changed code is compiled again. A cache: rows may go."""

    __tablename__ = "compiled_problems"

    key: Mapped[str] = mapped_column(String(HASH_LENGTH), primary_key=True)
    payload: Mapped[bytes] = mapped_column(LargeBinary)
    mac: Mapped[str] = mapped_column(String(HASH_LENGTH))
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())


class Submission(Base):
    """Append-only (triggers refuse UPDATE and DELETE); `attempt` is NULL exactly for `invalid`."""

    __tablename__ = "submissions"
    __table_args__ = (
        ForeignKeyConstraint(
            ["problem_id", "problem_version"],
            ["problem_versions.problem_id", "problem_versions.version"],
            name="fk_submissions_problem_version",
        ),
        CheckConstraint("verdict IN ('correct', 'incorrect', 'invalid')", name="verdict"),
        CheckConstraint(
            "(verdict = 'invalid' AND attempt IS NULL) OR (verdict <> 'invalid' AND attempt >= 1)",
            name="attempt_iff_graded",
        ),
        # Keyset pagination walks (created_at, id), optionally within one problem or one student.
        Index("ix_submissions_created_at_id", "created_at", "id"),
        Index("ix_submissions_problem_created_at_id", "problem_id", "created_at", "id"),
        Index("ix_submissions_student_created_at_id", "student", "created_at", "id"),
    )

    id: Mapped[uuid.UUID] = mapped_column(Uuid, primary_key=True)
    problem_id: Mapped[str] = mapped_column(String(ID_LENGTH))
    problem_version: Mapped[int] = mapped_column(Integer)
    part_id: Mapped[str] = mapped_column(String(ID_LENGTH))
    student: Mapped[str] = mapped_column(String(STUDENT_LENGTH))
    answer: Mapped[str] = mapped_column(Text)
    verdict: Mapped[str] = mapped_column(String(16))
    score: Mapped[float] = mapped_column(Float)
    reason: Mapped[str] = mapped_column(String(32))
    feedback: Mapped[str] = mapped_column(Text)
    read_as_text: Mapped[str | None] = mapped_column(Text)
    read_as_latex: Mapped[str | None] = mapped_column(Text)
    attempt: Mapped[int | None] = mapped_column(Integer)
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())


class AttemptCounter(Base):
    """Graded attempts used per (problem, part, student); bumped in the submission's own transaction."""

    __tablename__ = "attempt_counters"
    __table_args__ = (CheckConstraint("used >= 0", name="used_non_negative"),)

    problem_id: Mapped[str] = mapped_column(ForeignKey("problems.id"), primary_key=True)
    part_id: Mapped[str] = mapped_column(String(ID_LENGTH), primary_key=True)
    student: Mapped[str] = mapped_column(String(STUDENT_LENGTH), primary_key=True)
    used: Mapped[int] = mapped_column(Integer, default=0)


class StudentErasure(Base):
    """A permit to delete one student's submissions, held only inside the transaction that erases them
    (inserted, used, deleted): the append-only guard lets a DELETE through for a student named here,
    and refuses every other UPDATE and DELETE as before. Migration: `0006_erasure`."""

    __tablename__ = "student_erasures"

    student: Mapped[str] = mapped_column(String(STUDENT_LENGTH), primary_key=True)
