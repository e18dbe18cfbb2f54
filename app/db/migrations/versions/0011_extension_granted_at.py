"""When each extension was granted: it counts for answers given from then on, so an answer already
graded keeps its grade (an extension reopens the assignment, it does not regrade earlier late work).

Revision ID: 0011_extension_granted_at
Revises: 0010_preview_problem
Create Date: 2026-12-01
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0011_extension_granted_at"
down_revision: str | None = "0010_preview_problem"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    # NULL: the extension covers every answer, earlier ones too; extensions granted before this
    # revision did, and keep the grades they gave.
    with op.batch_alter_table("assignment_extensions") as table:
        table.add_column(sa.Column("granted_at", sa.DateTime(timezone=True), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("assignment_extensions") as table:
        table.drop_column("granted_at")
