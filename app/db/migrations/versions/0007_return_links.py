"""A student's link to come back: a sign-in token that is not spent by signing in.

Revision ID: 0007_return_links
Revises: 0006_erasure
Create Date: 2026-11-29
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0007_return_links"
down_revision: str | None = "0006_erasure"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    with op.batch_alter_table("sign_in_tokens") as table:
        table.add_column(sa.Column("reusable", sa.Boolean(), server_default=sa.false(), nullable=False))


def downgrade() -> None:
    with op.batch_alter_table("sign_in_tokens") as table:
        table.drop_column("reusable")
