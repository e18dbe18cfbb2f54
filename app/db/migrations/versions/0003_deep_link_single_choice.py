"""Deep-linking requests remember whether the platform accepts several content items.

Revision ID: 0003_deep_link_single_choice
Revises: 0002_lti
Create Date: 2026-11-24
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0003_deep_link_single_choice"
down_revision: str | None = "0002_lti"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    with op.batch_alter_table("lti_deep_link_requests") as table:
        table.add_column(
            sa.Column("accept_multiple", sa.Boolean(), nullable=False, server_default=sa.false())
        )


def downgrade() -> None:
    with op.batch_alter_table("lti_deep_link_requests") as table:
        table.drop_column("accept_multiple")
