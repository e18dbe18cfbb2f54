"""An instructor's "view as a student" session names the problem it was opened for, so that it acts
for that problem's pages only and never for a problem the browser's course student has open.

Revision ID: 0010_preview_problem
Revises: 0009_release_solutions_now
Create Date: 2026-11-30
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0010_preview_problem"
down_revision: str | None = "0009_release_solutions_now"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    # NULL for a course's session, and for a preview opened before this revision (it then acts for none)
    with op.batch_alter_table("course_sessions") as table:
        table.add_column(sa.Column("problem_id", sa.String(100), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("course_sessions") as table:
        table.drop_column("problem_id")
