"""LTI 1.3 tables: platforms and deployments, our signing keys, login states, used nonces, sessions,
deep-linking requests, grade targets and the score outbox.

Revision ID: 0002_lti
Revises: 0001_core
Create Date: 2026-11-21
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0002_lti"
down_revision: str | None = "0001_core"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def _timestamp(name: str, *, nullable: bool = False) -> sa.Column[object]:
    return sa.Column(name, sa.DateTime(timezone=True), nullable=nullable)


def _platform_fk(table: str) -> sa.ForeignKeyConstraint:
    return sa.ForeignKeyConstraint(
        ["platform_id"], ["lti_platforms.id"], name=op.f(f"fk_{table}_platform_id_lti_platforms")
    )


def upgrade() -> None:
    op.create_table(
        "lti_platforms",
        sa.Column("id", sa.Integer(), autoincrement=True, nullable=False),
        sa.Column("issuer", sa.String(255), nullable=False),
        sa.Column("client_id", sa.String(255), nullable=False),
        sa.Column("auth_url", sa.Text(), nullable=False),
        sa.Column("token_url", sa.Text(), nullable=False),
        sa.Column("jwks_url", sa.Text(), nullable=False),
        _timestamp("created_at"),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_lti_platforms")),
        sa.UniqueConstraint("issuer", "client_id", name="uq_lti_platforms_issuer_client_id"),
    )
    op.create_table(
        "lti_deployments",
        sa.Column("platform_id", sa.Integer(), nullable=False),
        sa.Column("deployment_id", sa.String(255), nullable=False),
        _platform_fk("lti_deployments"),
        sa.PrimaryKeyConstraint("platform_id", "deployment_id", name=op.f("pk_lti_deployments")),
    )
    op.create_table(
        "lti_tool_keys",
        sa.Column("kid", sa.String(64), nullable=False),
        sa.Column("private_pem", sa.Text(), nullable=False),
        _timestamp("created_at"),
        _timestamp("retired_at", nullable=True),
        sa.PrimaryKeyConstraint("kid", name=op.f("pk_lti_tool_keys")),
    )
    op.create_table(
        "lti_login_states",
        sa.Column("state_hash", sa.String(64), nullable=False),
        sa.Column("nonce", sa.String(64), nullable=False),
        sa.Column("browser_hash", sa.String(64), nullable=False),
        sa.Column("platform_id", sa.Integer(), nullable=False),
        _timestamp("expires_at"),
        _platform_fk("lti_login_states"),
        sa.PrimaryKeyConstraint("state_hash", name=op.f("pk_lti_login_states")),
    )
    op.create_index(op.f("ix_lti_login_states_expires_at"), "lti_login_states", ["expires_at"])
    op.create_table(
        "lti_used_nonces",
        sa.Column("platform_id", sa.Integer(), nullable=False),
        sa.Column("nonce", sa.String(255), nullable=False),
        _timestamp("expires_at"),
        _platform_fk("lti_used_nonces"),
        sa.PrimaryKeyConstraint("platform_id", "nonce", name=op.f("pk_lti_used_nonces")),
    )
    op.create_index(op.f("ix_lti_used_nonces_expires_at"), "lti_used_nonces", ["expires_at"])
    op.create_table(
        "lti_sessions",
        sa.Column("id_hash", sa.String(64), nullable=False),
        sa.Column("platform_id", sa.Integer(), nullable=False),
        sa.Column("sub", sa.String(255), nullable=False),
        sa.Column("student", sa.String(200), nullable=False),
        sa.Column("role", sa.String(16), nullable=False),
        sa.Column("name", sa.String(255), nullable=False),
        sa.Column("csrf_token", sa.String(64), nullable=False),
        _timestamp("created_at"),
        _timestamp("expires_at"),
        _platform_fk("lti_sessions"),
        sa.PrimaryKeyConstraint("id_hash", name=op.f("pk_lti_sessions")),
    )
    op.create_index(op.f("ix_lti_sessions_expires_at"), "lti_sessions", ["expires_at"])
    op.create_table(
        "lti_deep_link_requests",
        sa.Column("id", sa.String(64), nullable=False),
        sa.Column("session_hash", sa.String(64), nullable=False),
        sa.Column("platform_id", sa.Integer(), nullable=False),
        sa.Column("deployment_id", sa.String(255), nullable=False),
        sa.Column("return_url", sa.Text(), nullable=False),
        sa.Column("data", sa.Text(), nullable=True),
        _timestamp("expires_at"),
        _platform_fk("lti_deep_link_requests"),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_lti_deep_link_requests")),
    )
    op.create_table(
        "lti_grade_targets",
        sa.Column("id", sa.Integer(), autoincrement=True, nullable=False),
        sa.Column("platform_id", sa.Integer(), nullable=False),
        sa.Column("student", sa.String(200), nullable=False),
        sa.Column("problem_id", sa.String(100), nullable=False),
        sa.Column("lineitem_url", sa.Text(), nullable=False),
        sa.Column("sub", sa.String(255), nullable=False),
        _timestamp("last_timestamp", nullable=True),
        _platform_fk("lti_grade_targets"),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_lti_grade_targets")),
        sa.UniqueConstraint(
            "platform_id", "student", "problem_id", "lineitem_url", name="uq_lti_grade_targets_target"
        ),
    )
    op.create_index("ix_lti_grade_targets_student_problem", "lti_grade_targets", ["student", "problem_id"])
    op.create_table(
        "lti_score_outbox",
        sa.Column("id", sa.Integer(), autoincrement=True, nullable=False),
        sa.Column("target_id", sa.Integer(), nullable=False),
        sa.Column("score_given", sa.Float(), nullable=False),
        sa.Column("score_maximum", sa.Float(), nullable=False),
        _timestamp("timestamp"),
        sa.Column("status", sa.String(16), nullable=False),
        sa.Column("attempts", sa.Integer(), nullable=False),
        _timestamp("next_attempt_at"),
        sa.Column("claimed_by", sa.String(64), nullable=True),
        _timestamp("claimed_until", nullable=True),
        sa.Column("last_status", sa.Integer(), nullable=True),
        sa.Column("last_error", sa.Text(), nullable=True),
        _timestamp("created_at"),
        _timestamp("delivered_at", nullable=True),
        sa.ForeignKeyConstraint(
            ["target_id"],
            ["lti_grade_targets.id"],
            name=op.f("fk_lti_score_outbox_target_id_lti_grade_targets"),
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_lti_score_outbox")),
    )
    op.create_index(
        "ix_lti_score_outbox_status_next_attempt_at", "lti_score_outbox", ["status", "next_attempt_at"]
    )


def downgrade() -> None:
    op.drop_index("ix_lti_score_outbox_status_next_attempt_at", table_name="lti_score_outbox")
    op.drop_table("lti_score_outbox")
    op.drop_index("ix_lti_grade_targets_student_problem", table_name="lti_grade_targets")
    op.drop_table("lti_grade_targets")
    op.drop_table("lti_deep_link_requests")
    op.drop_index(op.f("ix_lti_sessions_expires_at"), table_name="lti_sessions")
    op.drop_table("lti_sessions")
    op.drop_index(op.f("ix_lti_used_nonces_expires_at"), table_name="lti_used_nonces")
    op.drop_table("lti_used_nonces")
    op.drop_index(op.f("ix_lti_login_states_expires_at"), table_name="lti_login_states")
    op.drop_table("lti_login_states")
    op.drop_table("lti_tool_keys")
    op.drop_table("lti_deployments")
    op.drop_table("lti_platforms")
