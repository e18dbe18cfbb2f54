"""Courses: staff, enrolments, sign-in links and sessions, assignments, extensions, bank shares.

Revision ID: 0005_courses
Revises: 0004_compiled_problems
Create Date: 2026-11-28
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0005_courses"
down_revision: str | None = "0004_compiled_problems"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def _timestamp(name: str, *, nullable: bool = False) -> sa.Column[object]:
    return sa.Column(name, sa.DateTime(timezone=True), nullable=nullable)


def _fk(table: str, column: str, target: str, target_column: str = "id") -> sa.ForeignKeyConstraint:
    return sa.ForeignKeyConstraint(
        [column], [f"{target}.{target_column}"], name=op.f(f"fk_{table}_{column}_{target}")
    )


def upgrade() -> None:
    op.create_table(
        "courses",
        sa.Column("id", sa.Integer(), autoincrement=True, nullable=False),
        sa.Column("title", sa.String(200), nullable=False),
        sa.Column("timezone", sa.String(64), nullable=False),
        sa.Column("join_code", sa.String(32), nullable=True),
        sa.Column("lti_platform_id", sa.Integer(), nullable=True),
        sa.Column("lti_context_id", sa.String(255), nullable=True),
        _timestamp("created_at"),
        _fk("courses", "lti_platform_id", "lti_platforms"),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_courses")),
        sa.UniqueConstraint("join_code", name=op.f("uq_courses_join_code")),
        sa.UniqueConstraint("lti_platform_id", "lti_context_id", name="uq_courses_lti_context"),
    )
    op.create_table(
        "course_staff",
        sa.Column("course_id", sa.Integer(), nullable=False),
        sa.Column("member", sa.String(200), nullable=False),
        sa.Column("role", sa.String(16), nullable=False),
        sa.Column("name", sa.String(200), nullable=False),
        sa.CheckConstraint("role IN ('instructor', 'ta')", name=op.f("ck_course_staff_role")),
        _fk("course_staff", "course_id", "courses"),
        sa.PrimaryKeyConstraint("course_id", "member", name=op.f("pk_course_staff")),
    )
    op.create_index("ix_course_staff_member", "course_staff", ["member"])
    op.create_table(
        "enrolments",
        sa.Column("course_id", sa.Integer(), nullable=False),
        sa.Column("student", sa.String(200), nullable=False),
        sa.Column("roster_id", sa.String(100), nullable=True),
        sa.Column("name", sa.String(200), nullable=False),
        sa.Column("email", sa.String(254), nullable=False),
        _timestamp("created_at"),
        _fk("enrolments", "course_id", "courses"),
        sa.PrimaryKeyConstraint("course_id", "student", name=op.f("pk_enrolments")),
        sa.UniqueConstraint("course_id", "roster_id", name="uq_enrolments_roster_id"),
    )
    op.create_index("ix_enrolments_student", "enrolments", ["student"])
    op.create_table(
        "sign_in_tokens",
        sa.Column("token_hash", sa.String(64), nullable=False),
        sa.Column("course_id", sa.Integer(), nullable=False),
        sa.Column("student", sa.String(200), nullable=False),
        _timestamp("expires_at"),
        _timestamp("used_at", nullable=True),
        _fk("sign_in_tokens", "course_id", "courses"),
        sa.PrimaryKeyConstraint("token_hash", name=op.f("pk_sign_in_tokens")),
    )
    op.create_index("ix_sign_in_tokens_student", "sign_in_tokens", ["course_id", "student"])
    op.create_table(
        "course_sessions",
        sa.Column("id_hash", sa.String(64), nullable=False),
        sa.Column("course_id", sa.Integer(), nullable=True),
        sa.Column("student", sa.String(200), nullable=False),
        sa.Column("name", sa.String(200), nullable=False),
        sa.Column("csrf_token", sa.String(64), nullable=False),
        _timestamp("expires_at"),
        _fk("course_sessions", "course_id", "courses"),
        sa.PrimaryKeyConstraint("id_hash", name=op.f("pk_course_sessions")),
    )
    op.create_index(op.f("ix_course_sessions_expires_at"), "course_sessions", ["expires_at"])
    op.create_table(
        "assignments",
        sa.Column("id", sa.Integer(), autoincrement=True, nullable=False),
        sa.Column("course_id", sa.Integer(), nullable=False),
        sa.Column("title", sa.String(200), nullable=False),
        sa.Column("problems", sa.JSON(), nullable=False),
        _timestamp("opens_at"),
        _timestamp("due_at"),
        sa.Column("late_policy", sa.String(16), nullable=False),
        sa.Column("penalty_per_day", sa.Float(), nullable=False),
        sa.Column("penalty_limit", sa.Float(), nullable=False),
        sa.Column("max_attempts", sa.Integer(), nullable=True),
        sa.Column("solutions", sa.String(32), nullable=False),
        _timestamp("created_at"),
        sa.CheckConstraint("late_policy IN ('closed', 'penalty')", name=op.f("ck_assignments_late_policy")),
        sa.CheckConstraint(
            "solutions IN ('never', 'after_due', 'after_last_attempt')", name=op.f("ck_assignments_solutions")
        ),
        sa.CheckConstraint("due_at >= opens_at", name=op.f("ck_assignments_due_after_open")),
        _fk("assignments", "course_id", "courses"),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_assignments")),
    )
    op.create_index(op.f("ix_assignments_course_id"), "assignments", ["course_id"])
    op.create_table(
        "assignment_extensions",
        sa.Column("assignment_id", sa.Integer(), nullable=False),
        sa.Column("student", sa.String(200), nullable=False),
        _timestamp("due_at"),
        _fk("assignment_extensions", "assignment_id", "assignments"),
        sa.PrimaryKeyConstraint("assignment_id", "student", name=op.f("pk_assignment_extensions")),
    )
    op.create_table(
        "bank_shares",
        sa.Column("problem_id", sa.String(100), nullable=False),
        _timestamp("shared_at"),
        _fk("bank_shares", "problem_id", "problems"),
        sa.PrimaryKeyConstraint("problem_id", name=op.f("pk_bank_shares")),
    )


def downgrade() -> None:
    for table in (
        "bank_shares",
        "assignment_extensions",
        "assignments",
        "course_sessions",
        "sign_in_tokens",
        "enrolments",
        "course_staff",
        "courses",
    ):
        op.drop_table(table)
