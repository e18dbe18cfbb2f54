"""An instructor may release an assignment's worked solutions now: `solutions` may be 'released'.

Revision ID: 0009_release_solutions_now
Revises: 0008_solution_views
Create Date: 2026-11-29
"""

from __future__ import annotations

from collections.abc import Sequence

from alembic import op

revision: str = "0009_release_solutions_now"
down_revision: str | None = "0008_solution_views"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

_NAME = "ck_assignments_solutions"
_BEFORE = "solutions IN ('never', 'after_due', 'after_last_attempt')"
_AFTER = "solutions IN ('never', 'after_due', 'after_last_attempt', 'released')"


def upgrade() -> None:
    with op.batch_alter_table("assignments") as table:
        table.drop_constraint(op.f(_NAME), type_="check")
        table.create_check_constraint(op.f(_NAME), _AFTER)


def downgrade() -> None:
    op.execute("UPDATE assignments SET solutions = 'after_due' WHERE solutions = 'released'")
    with op.batch_alter_table("assignments") as table:
        table.drop_constraint(op.f(_NAME), type_="check")
        table.create_check_constraint(op.f(_NAME), _BEFORE)
