"""The due dates a moved extension replaced, each with when it was granted: an answer keeps the due
date in force when it was given, so moving an extension regrades nothing a new one would not.

Revision ID: 0012_extension_earlier
Revises: 0011_extension_granted_at
Create Date: 2026-12-01
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0012_extension_earlier"
down_revision: str | None = "0011_extension_granted_at"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    # NULL: never moved (extensions moved before this revision cover what they covered then).
    with op.batch_alter_table("assignment_extensions") as table:
        table.add_column(sa.Column("earlier", sa.JSON(), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("assignment_extensions") as table:
        table.drop_column("earlier")
