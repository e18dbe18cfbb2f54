"""Core tables: API keys, versioned problems, append-only submissions, attempt counters.

Revision ID: 0001_core
Revises:
Create Date: 2026-11-21
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0001_core"
down_revision: str | None = None
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

_APPEND_ONLY_MESSAGE = "submissions are append-only"


def _timestamp(name: str, *, nullable: bool = False) -> sa.Column[object]:
    return sa.Column(name, sa.DateTime(timezone=True), nullable=nullable)


def upgrade() -> None:
    op.create_table(
        "api_keys",
        sa.Column("id", sa.Integer(), autoincrement=True, nullable=False),
        sa.Column("prefix", sa.String(16), nullable=False),
        sa.Column("key_hash", sa.String(64), nullable=False),
        sa.Column("role", sa.String(16), nullable=False),
        sa.Column("name", sa.String(200), nullable=True),
        sa.Column("student", sa.String(200), nullable=True),
        _timestamp("created_at"),
        _timestamp("revoked_at", nullable=True),
        sa.CheckConstraint("role IN ('instructor', 'student')", name=op.f("ck_api_keys_role")),
        sa.CheckConstraint(
            "(role = 'student' AND student IS NOT NULL) OR (role <> 'student' AND student IS NULL)",
            name=op.f("ck_api_keys_student_identity"),
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_api_keys")),
        sa.UniqueConstraint("key_hash", name=op.f("uq_api_keys_key_hash")),
    )
    op.create_index(op.f("ix_api_keys_prefix"), "api_keys", ["prefix"])

    op.create_table(
        "problems",
        sa.Column("id", sa.String(100), nullable=False),
        sa.Column("owner_key_id", sa.Integer(), nullable=True),
        sa.Column("latest_version", sa.Integer(), nullable=False),
        _timestamp("created_at"),
        _timestamp("retired_at", nullable=True),
        sa.CheckConstraint("latest_version >= 1", name=op.f("ck_problems_latest_version_positive")),
        sa.ForeignKeyConstraint(
            ["owner_key_id"], ["api_keys.id"], name=op.f("fk_problems_owner_key_id_api_keys")
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_problems")),
    )

    op.create_table(
        "problem_versions",
        sa.Column("problem_id", sa.String(100), nullable=False),
        sa.Column("version", sa.Integer(), autoincrement=False, nullable=False),
        sa.Column("document", sa.JSON(), nullable=False),
        sa.Column("document_hash", sa.String(64), nullable=False),
        _timestamp("created_at"),
        sa.CheckConstraint("version >= 1", name=op.f("ck_problem_versions_version_positive")),
        sa.ForeignKeyConstraint(
            ["problem_id"], ["problems.id"], name=op.f("fk_problem_versions_problem_id_problems")
        ),
        sa.PrimaryKeyConstraint("problem_id", "version", name=op.f("pk_problem_versions")),
    )

    op.create_table(
        "submissions",
        sa.Column("id", sa.Uuid(), nullable=False),
        sa.Column("problem_id", sa.String(100), nullable=False),
        sa.Column("problem_version", sa.Integer(), nullable=False),
        sa.Column("part_id", sa.String(100), nullable=False),
        sa.Column("student", sa.String(200), nullable=False),
        sa.Column("answer", sa.Text(), nullable=False),
        sa.Column("verdict", sa.String(16), nullable=False),
        sa.Column("score", sa.Float(), nullable=False),
        sa.Column("reason", sa.String(32), nullable=False),
        sa.Column("feedback", sa.Text(), nullable=False),
        sa.Column("read_as_text", sa.Text(), nullable=True),
        sa.Column("read_as_latex", sa.Text(), nullable=True),
        sa.Column("attempt", sa.Integer(), nullable=True),
        _timestamp("created_at"),
        sa.CheckConstraint(
            "verdict IN ('correct', 'incorrect', 'invalid')", name=op.f("ck_submissions_verdict")
        ),
        sa.CheckConstraint(
            "(verdict = 'invalid' AND attempt IS NULL) OR (verdict <> 'invalid' AND attempt >= 1)",
            name=op.f("ck_submissions_attempt_iff_graded"),
        ),
        sa.ForeignKeyConstraint(
            ["problem_id", "problem_version"],
            ["problem_versions.problem_id", "problem_versions.version"],
            name=op.f("fk_submissions_problem_version"),
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_submissions")),
    )
    op.create_index("ix_submissions_created_at_id", "submissions", ["created_at", "id"])
    op.create_index("ix_submissions_problem_created_at_id", "submissions", ["problem_id", "created_at", "id"])
    op.create_index("ix_submissions_student_created_at_id", "submissions", ["student", "created_at", "id"])

    op.create_table(
        "attempt_counters",
        sa.Column("problem_id", sa.String(100), nullable=False),
        sa.Column("part_id", sa.String(100), nullable=False),
        sa.Column("student", sa.String(200), nullable=False),
        sa.Column("used", sa.Integer(), nullable=False),
        sa.CheckConstraint("used >= 0", name=op.f("ck_attempt_counters_used_non_negative")),
        sa.ForeignKeyConstraint(
            ["problem_id"], ["problems.id"], name=op.f("fk_attempt_counters_problem_id_problems")
        ),
        sa.PrimaryKeyConstraint("problem_id", "part_id", "student", name=op.f("pk_attempt_counters")),
    )

    _create_append_only_guard()


def _create_append_only_guard() -> None:
    """Refuse UPDATE and DELETE on submissions in the database itself, whatever code connects."""
    if op.get_bind().dialect.name == "postgresql":
        op.execute(
            "CREATE FUNCTION submissions_append_only() RETURNS trigger LANGUAGE plpgsql AS $$ "
            f"BEGIN RAISE EXCEPTION '{_APPEND_ONLY_MESSAGE}'; END $$"
        )
        op.execute(
            "CREATE TRIGGER submissions_append_only BEFORE UPDATE OR DELETE ON submissions "
            "FOR EACH ROW EXECUTE FUNCTION submissions_append_only()"
        )
    else:
        for event in ("UPDATE", "DELETE"):
            op.execute(
                f"CREATE TRIGGER submissions_no_{event.lower()} BEFORE {event} ON submissions "
                f"BEGIN SELECT RAISE(ABORT, '{_APPEND_ONLY_MESSAGE}'); END"
            )


def downgrade() -> None:
    if op.get_bind().dialect.name == "postgresql":
        op.execute("DROP TRIGGER IF EXISTS submissions_append_only ON submissions")
        op.execute("DROP FUNCTION IF EXISTS submissions_append_only()")
    op.drop_table("attempt_counters")
    op.drop_index("ix_submissions_student_created_at_id", table_name="submissions")
    op.drop_index("ix_submissions_problem_created_at_id", table_name="submissions")
    op.drop_index("ix_submissions_created_at_id", table_name="submissions")
    op.drop_table("submissions")
    op.drop_table("problem_versions")
    op.drop_table("problems")
    op.drop_index(op.f("ix_api_keys_prefix"), table_name="api_keys")
    op.drop_table("api_keys")
