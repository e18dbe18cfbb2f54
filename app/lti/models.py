"""The LTI tables; only modules of `app.lti` touch them. Migration: `0002_lti`."""

from __future__ import annotations

from datetime import datetime

from sqlalchemy import Boolean, Float, ForeignKey, Index, Integer, String, Text, UniqueConstraint, false
from sqlalchemy.orm import Mapped, mapped_column

from app.db.base import Base
from app.db.types import UTCDateTime

# Lengths shared with the migration, which copies the numbers rather than importing them.
URL_ID_LENGTH = 255  # issuer, client_id, deployment_id, sub: opaque strings from the platform
HASH_LENGTH = 64
KID_LENGTH = 64
STUDENT_LENGTH = 200  # as `submissions.student`
PROBLEM_ID_LENGTH = 100  # as `problems.id`


class LtiPlatform(Base):
    """A registered LMS, keyed by (issuer, client_id): one issuer may register the tool several times."""

    __tablename__ = "lti_platforms"
    __table_args__ = (UniqueConstraint("issuer", "client_id", name="uq_lti_platforms_issuer_client_id"),)

    id: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=True)
    issuer: Mapped[str] = mapped_column(String(URL_ID_LENGTH))
    client_id: Mapped[str] = mapped_column(String(URL_ID_LENGTH))
    auth_url: Mapped[str] = mapped_column(Text)
    token_url: Mapped[str] = mapped_column(Text)
    jwks_url: Mapped[str] = mapped_column(Text)
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())


class LtiDeployment(Base):
    __tablename__ = "lti_deployments"

    platform_id: Mapped[int] = mapped_column(ForeignKey("lti_platforms.id"), primary_key=True)
    deployment_id: Mapped[str] = mapped_column(String(URL_ID_LENGTH), primary_key=True)


class LtiToolKey(Base):
    """Our RSA signing keys. The newest live key signs; every live key is published in the JWKS, so a
    platform that cached the previous key still verifies until that key is retired."""

    __tablename__ = "lti_tool_keys"

    kid: Mapped[str] = mapped_column(String(KID_LENGTH), primary_key=True)
    private_pem: Mapped[str] = mapped_column(Text)
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())
    retired_at: Mapped[datetime | None] = mapped_column(UTCDateTime())


class LtiLoginState(Base):
    """One OIDC login in flight: the state (hashed), its nonce, and the browser it was issued to."""

    __tablename__ = "lti_login_states"

    state_hash: Mapped[str] = mapped_column(String(HASH_LENGTH), primary_key=True)
    nonce: Mapped[str] = mapped_column(String(HASH_LENGTH))
    browser_hash: Mapped[str] = mapped_column(String(HASH_LENGTH))
    platform_id: Mapped[int] = mapped_column(ForeignKey("lti_platforms.id"))
    expires_at: Mapped[datetime] = mapped_column(UTCDateTime(), index=True)


class LtiUsedNonce(Base):
    """Nonces of accepted id_tokens, kept past the token's life so a replay is refused."""

    __tablename__ = "lti_used_nonces"

    platform_id: Mapped[int] = mapped_column(ForeignKey("lti_platforms.id"), primary_key=True)
    nonce: Mapped[str] = mapped_column(String(URL_ID_LENGTH), primary_key=True)
    expires_at: Mapped[datetime] = mapped_column(UTCDateTime(), index=True)


class LtiSession(Base):
    """A session of our own opened by a launch; the cookie holds the id, this row only its hash."""

    __tablename__ = "lti_sessions"

    id_hash: Mapped[str] = mapped_column(String(HASH_LENGTH), primary_key=True)
    platform_id: Mapped[int] = mapped_column(ForeignKey("lti_platforms.id"))
    sub: Mapped[str] = mapped_column(String(URL_ID_LENGTH))
    student: Mapped[str] = mapped_column(String(STUDENT_LENGTH))
    role: Mapped[str] = mapped_column(String(16))
    name: Mapped[str] = mapped_column(String(URL_ID_LENGTH))
    csrf_token: Mapped[str] = mapped_column(String(HASH_LENGTH))
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())
    expires_at: Mapped[datetime] = mapped_column(UTCDateTime(), index=True)


class LtiDeepLinkRequest(Base):
    """A deep-linking launch awaiting the instructor's choice; bound to the session it opened."""

    __tablename__ = "lti_deep_link_requests"

    id: Mapped[str] = mapped_column(String(HASH_LENGTH), primary_key=True)
    session_hash: Mapped[str] = mapped_column(String(HASH_LENGTH))
    platform_id: Mapped[int] = mapped_column(ForeignKey("lti_platforms.id"))
    deployment_id: Mapped[str] = mapped_column(String(URL_ID_LENGTH))
    return_url: Mapped[str] = mapped_column(Text)
    data: Mapped[str | None] = mapped_column(Text)
    expires_at: Mapped[datetime] = mapped_column(UTCDateTime())
    # The platform's `accept_multiple`: if false the instructor picks one problem (migration 0003).
    accept_multiple: Mapped[bool] = mapped_column(Boolean, server_default=false())


class LtiGradeTarget(Base):
    """Where a student's score on a problem goes: a platform's line item, for the user `sub`."""

    __tablename__ = "lti_grade_targets"
    __table_args__ = (
        UniqueConstraint(
            "platform_id", "student", "problem_id", "lineitem_url", name="uq_lti_grade_targets_target"
        ),
        Index("ix_lti_grade_targets_student_problem", "student", "problem_id"),
    )

    id: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=True)
    platform_id: Mapped[int] = mapped_column(ForeignKey("lti_platforms.id"))
    student: Mapped[str] = mapped_column(String(STUDENT_LENGTH))
    problem_id: Mapped[str] = mapped_column(String(PROBLEM_ID_LENGTH))
    lineitem_url: Mapped[str] = mapped_column(Text)
    sub: Mapped[str] = mapped_column(String(URL_ID_LENGTH))
    # The newest score timestamp sent here; a new score is stamped strictly later.
    last_timestamp: Mapped[datetime | None] = mapped_column(UTCDateTime())


class LtiScoreOutbox(Base):
    """One score to deliver. `pending` -> `sending` (claimed, with a lease) -> `delivered` or `failed`
    (the LMS refused it: kept with its status and message for the instructor)."""

    __tablename__ = "lti_score_outbox"
    __table_args__ = (Index("ix_lti_score_outbox_status_next_attempt_at", "status", "next_attempt_at"),)

    id: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=True)
    target_id: Mapped[int] = mapped_column(ForeignKey("lti_grade_targets.id"))
    score_given: Mapped[float] = mapped_column(Float)
    score_maximum: Mapped[float] = mapped_column(Float)
    timestamp: Mapped[datetime] = mapped_column(UTCDateTime())
    status: Mapped[str] = mapped_column(String(16))
    attempts: Mapped[int] = mapped_column(Integer)
    next_attempt_at: Mapped[datetime] = mapped_column(UTCDateTime())
    claimed_by: Mapped[str | None] = mapped_column(String(HASH_LENGTH))
    claimed_until: Mapped[datetime | None] = mapped_column(UTCDateTime())
    last_status: Mapped[int | None] = mapped_column(Integer)
    last_error: Mapped[str | None] = mapped_column(Text)
    created_at: Mapped[datetime] = mapped_column(UTCDateTime())
    delivered_at: Mapped[datetime | None] = mapped_column(UTCDateTime())
