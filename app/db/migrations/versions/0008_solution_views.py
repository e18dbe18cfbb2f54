"""When each student first opened each problem's worked solution: their grade on its parts is frozen
from then on (answers are still checked, they earn nothing).

Revision ID: 0008_solution_views
Revises: 0007_return_links
Create Date: 2026-11-29
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0008_solution_views"
down_revision: str | None = "0007_return_links"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    op.create_table(
        "solution_views",
        sa.Column("student", sa.String(200), nullable=False),
        sa.Column("problem_id", sa.String(100), nullable=False),
        sa.Column("opened_at", sa.DateTime(timezone=True), nullable=False),
        sa.PrimaryKeyConstraint("student", "problem_id", name=op.f("pk_solution_views")),
    )


def downgrade() -> None:
    op.drop_table("solution_views")
