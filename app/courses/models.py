"""The course tables. Only `app/storage/sql_courses.py` touches them; callers get `records`."""

from __future__ import annotations

from datetime import datetime
from typing import Any

from sqlalchemy import (
    JSON,
    Boolean,
    CheckConstraint,
    Float,
    ForeignKey,
    Index,
    Integer,
    String,
    UniqueConstraint,
)
from sqlalchemy.orm import Mapped, mapped_column
from sqlalchemy.sql.expression import false

from app.db.base import Base
from app.db.models import HASH_LENGTH, ID_LENGTH, NAME_LENGTH, STUDENT_LENGTH
from app.db.types import UTCDateTime

# Copied, not imported, by the migration (as app/db/models.py's lengths are).
TITLE_LENGTH = 200
CODE_LENGTH = 32
EMAIL_LENGTH = 254
ROSTER_ID_LENGTH = 100
CONTEXT_LENGTH = 255


class Course(Base):
    __tablename__ = "courses"
    __table_args__ = (UniqueConstraint("lti_platform_id", "lti_context_id", name="uq_courses_lti_context"),)

    id: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=True)
    title: Mapped[str] = mapped_column(String(TITLE_LENGTH))
    timezone: Mapped[str] = mapped_column(String(64))
    join_code: Mapped[str | None] = mapped_column(String(CODE_LENGTH), unique=True)
    lti_platform_id: Mapped[int | None] = mapped_column(ForeignKey("lti_platforms.id"))
    lti_context_id: Mapped[str | None] = mapped_column(String(CONTEXT_LENGTH))
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())


class CourseStaff(Base):
    __tablename__ = "course_staff"
    __table_args__ = (
        CheckConstraint("role IN ('instructor', 'ta')", name="role"),
        Index("ix_course_staff_member", "member"),
    )

    course_id: Mapped[int] = mapped_column(ForeignKey("courses.id"), primary_key=True)
    member: Mapped[str] = mapped_column(String(STUDENT_LENGTH), primary_key=True)
    role: Mapped[str] = mapped_column(String(16))
    name: Mapped[str] = mapped_column(String(NAME_LENGTH))


class Enrolment(Base):
    __tablename__ = "enrolments"
    __table_args__ = (
        UniqueConstraint("course_id", "roster_id", name="uq_enrolments_roster_id"),
        Index("ix_enrolments_student", "student"),
    )

    course_id: Mapped[int] = mapped_column(ForeignKey("courses.id"), primary_key=True)
    student: Mapped[str] = mapped_column(String(STUDENT_LENGTH), primary_key=True)
    roster_id: Mapped[str | None] = mapped_column(String(ROSTER_ID_LENGTH))
    name: Mapped[str] = mapped_column(String(NAME_LENGTH))
    email: Mapped[str] = mapped_column(String(EMAIL_LENGTH))
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())


class SignInToken(Base):
    """A personal sign-in link's token (its hash): spent on first use, or replaced by a newer link. A
    student's link to come back (`reusable`) is never spent: it signs in until replaced or expired."""

    __tablename__ = "sign_in_tokens"
    __table_args__ = (Index("ix_sign_in_tokens_student", "course_id", "student"),)

    token_hash: Mapped[str] = mapped_column(String(HASH_LENGTH), primary_key=True)
    course_id: Mapped[int] = mapped_column(ForeignKey("courses.id"))
    student: Mapped[str] = mapped_column(String(STUDENT_LENGTH))
    expires_at: Mapped[datetime] = mapped_column(UTCDateTime())
    used_at: Mapped[datetime | None] = mapped_column(UTCDateTime())
    reusable: Mapped[bool] = mapped_column(Boolean, server_default=false())


class CourseSessionRow(Base):
    """A student's session opened by a sign-in link; the cookie holds the id, this row its hash."""

    __tablename__ = "course_sessions"

    id_hash: Mapped[str] = mapped_column(String(HASH_LENGTH), primary_key=True)
    # NULL for an instructor's "view as a student" session (their preview identity, in no course).
    course_id: Mapped[int | None] = mapped_column(ForeignKey("courses.id"))
    student: Mapped[str] = mapped_column(String(STUDENT_LENGTH))
    name: Mapped[str] = mapped_column(String(NAME_LENGTH))
    csrf_token: Mapped[str] = mapped_column(String(HASH_LENGTH))
    expires_at: Mapped[datetime] = mapped_column(UTCDateTime(), index=True)
    # A preview's problem: it acts for that problem's pages only, never shadowing a course's student.
    problem_id: Mapped[str | None] = mapped_column(String(ID_LENGTH))


class Assignment(Base):
    __tablename__ = "assignments"
    __table_args__ = (
        CheckConstraint("late_policy IN ('closed', 'penalty')", name="late_policy"),
        CheckConstraint(
            "solutions IN ('never', 'after_due', 'after_last_attempt', 'released')", name="solutions"
        ),
        CheckConstraint("due_at >= opens_at", name="due_after_open"),
    )

    id: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=True)
    course_id: Mapped[int] = mapped_column(ForeignKey("courses.id"), index=True)
    title: Mapped[str] = mapped_column(String(TITLE_LENGTH))
    problems: Mapped[list[Any]] = mapped_column(JSON)  # problem ids, in order
    opens_at: Mapped[datetime] = mapped_column(UTCDateTime())
    due_at: Mapped[datetime] = mapped_column(UTCDateTime())
    late_policy: Mapped[str] = mapped_column(String(16))
    penalty_per_day: Mapped[float] = mapped_column(Float)
    penalty_limit: Mapped[float] = mapped_column(Float)
    max_attempts: Mapped[int | None] = mapped_column(Integer)
    solutions: Mapped[str] = mapped_column(String(32))
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())


class Extension(Base):
    __tablename__ = "assignment_extensions"

    assignment_id: Mapped[int] = mapped_column(ForeignKey("assignments.id"), primary_key=True)
    student: Mapped[str] = mapped_column(String(STUDENT_LENGTH), primary_key=True)
    due_at: Mapped[datetime] = mapped_column(UTCDateTime())
    # NULL: it covers answers given before it was granted too (see records.ExtensionRecord)
    granted_at: Mapped[datetime | None] = mapped_column(UTCDateTime())
    # The due dates it replaced when moved, oldest first: [[granted_at ISO or null, due_at ISO], …]
    earlier: Mapped[list[Any] | None] = mapped_column(JSON)


class SolutionView(Base):
    """The first time a student opened a problem's worked solution: no credit on its parts after."""

    __tablename__ = "solution_views"

    # No foreign key to problems: a retired problem's record stays, and so does the view.
    student: Mapped[str] = mapped_column(String(STUDENT_LENGTH), primary_key=True)
    problem_id: Mapped[str] = mapped_column(String(ID_LENGTH), primary_key=True)
    opened_at: Mapped[datetime] = mapped_column(UTCDateTime())


class BankShare(Base):
    """An instructor's upload shared to the bank: every instructor may use it, not only its courses."""

    __tablename__ = "bank_shares"

    problem_id: Mapped[str] = mapped_column(ForeignKey("problems.id"), primary_key=True)
    shared_at: Mapped[datetime] = mapped_column(UTCDateTime())
