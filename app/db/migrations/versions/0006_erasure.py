"""Erasing one student's data: submissions stay append-only except for a student being erased.

Revision ID: 0006_erasure
Revises: 0005_courses
Create Date: 2026-11-28
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0006_erasure"
down_revision: str | None = "0005_courses"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

_APPEND_ONLY_MESSAGE = "submissions are append-only"
_ERASING = "EXISTS (SELECT 1 FROM student_erasures WHERE student_erasures.student = OLD.student)"


def upgrade() -> None:
    op.create_table(
        "student_erasures",
        sa.Column("student", sa.String(200), nullable=False),
        sa.PrimaryKeyConstraint("student", name=op.f("pk_student_erasures")),
    )
    if op.get_bind().dialect.name == "postgresql":
        op.execute(
            "CREATE OR REPLACE FUNCTION submissions_append_only() RETURNS trigger LANGUAGE plpgsql AS $$ "
            f"BEGIN IF TG_OP = 'DELETE' AND {_ERASING} THEN RETURN OLD; END IF; "
            f"RAISE EXCEPTION '{_APPEND_ONLY_MESSAGE}'; END $$"
        )
    else:
        op.execute("DROP TRIGGER submissions_no_delete")
        op.execute(
            f"CREATE TRIGGER submissions_no_delete BEFORE DELETE ON submissions WHEN NOT {_ERASING} "
            f"BEGIN SELECT RAISE(ABORT, '{_APPEND_ONLY_MESSAGE}'); END"
        )


def downgrade() -> None:
    if op.get_bind().dialect.name == "postgresql":
        op.execute(
            "CREATE OR REPLACE FUNCTION submissions_append_only() RETURNS trigger LANGUAGE plpgsql AS $$ "
            f"BEGIN RAISE EXCEPTION '{_APPEND_ONLY_MESSAGE}'; END $$"
        )
    else:
        op.execute("DROP TRIGGER submissions_no_delete")
        op.execute(
            "CREATE TRIGGER submissions_no_delete BEFORE DELETE ON submissions "
            f"BEGIN SELECT RAISE(ABORT, '{_APPEND_ONLY_MESSAGE}'); END"
        )
    op.drop_table("student_erasures")
