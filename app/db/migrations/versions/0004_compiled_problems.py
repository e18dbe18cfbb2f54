"""Compiled problems persisted across restarts (a cache: derivations and prepared references).

Revision ID: 0004_compiled_problems
Revises: 0003_deep_link_single_choice
Create Date: 2026-11-24
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0004_compiled_problems"
down_revision: str | None = "0003_deep_link_single_choice"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    op.create_table(
        "compiled_problems",
        sa.Column("key", sa.String(64), nullable=False),
        sa.Column("payload", sa.LargeBinary(), nullable=False),
        sa.Column("mac", sa.String(64), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.PrimaryKeyConstraint("key", name=op.f("pk_compiled_problems")),
    )


def downgrade() -> None:
    op.drop_table("compiled_problems")
