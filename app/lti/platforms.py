"""Registered platforms (LMSs) and their deployments."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from datetime import datetime
from urllib.parse import urlsplit

from sqlalchemy import select
from sqlalchemy.orm import Session

from app.db.database import Database
from app.db.types import utc_now
from app.lti.errors import PlatformNotFound
from app.lti.models import LtiDeployment, LtiPlatform


@dataclass(frozen=True)
class PlatformRecord:
    id: int
    issuer: str
    client_id: str
    auth_url: str
    token_url: str
    jwks_url: str


def _record(row: LtiPlatform) -> PlatformRecord:
    return PlatformRecord(row.id, row.issuer, row.client_id, row.auth_url, row.token_url, row.jwks_url)


def _require_url(name: str, value: str) -> None:
    parts = urlsplit(value)
    if parts.scheme not in ("https", "http") or not parts.netloc:
        raise ValueError(f"{name} must be an absolute http(s) URL, got {value!r}")


def add_platform(
    database: Database,
    issuer: str,
    client_id: str,
    deployment_ids: Sequence[str],
    auth_url: str,
    token_url: str,
    jwks_url: str,
    *,
    clock: Callable[[], datetime] = utc_now,
) -> PlatformRecord:
    """Register a platform, or update its URLs and add deployments if (issuer, client_id) is known."""
    if not issuer or not client_id:
        raise ValueError("issuer and client_id must not be empty")
    for name, url in (("auth_url", auth_url), ("token_url", token_url), ("jwks_url", jwks_url)):
        _require_url(name, url)
    with database.session() as session:
        row = session.scalars(
            select(LtiPlatform).where(LtiPlatform.issuer == issuer, LtiPlatform.client_id == client_id)
        ).one_or_none()
        if row is None:
            row = LtiPlatform(issuer=issuer, client_id=client_id, created_at=clock())
            session.add(row)
        row.auth_url, row.token_url, row.jwks_url = auth_url, token_url, jwks_url
        session.flush()
        known = set(deployments(session, row.id))
        for deployment_id in dict.fromkeys(deployment_ids):
            if deployment_id and deployment_id not in known:
                session.add(LtiDeployment(platform_id=row.id, deployment_id=deployment_id))
        return _record(row)


def find_platform(session: Session, issuer: str, client_id: str | None) -> PlatformRecord:
    """The platform for (issuer, client_id); without a client_id, the issuer's only registration."""
    query = select(LtiPlatform).where(LtiPlatform.issuer == issuer)
    if client_id is not None:
        query = query.where(LtiPlatform.client_id == client_id)
    rows = list(session.scalars(query.limit(2)))
    if len(rows) != 1:
        raise PlatformNotFound(issuer, client_id)
    return _record(rows[0])


def get_platform(session: Session, platform_id: int) -> PlatformRecord:
    row = session.get(LtiPlatform, platform_id)
    if row is None:
        raise PlatformNotFound(str(platform_id), None)
    return _record(row)


def deployments(session: Session, platform_id: int) -> list[str]:
    query = select(LtiDeployment.deployment_id).where(LtiDeployment.platform_id == platform_id)
    return list(session.scalars(query))


def is_deployed(session: Session, platform_id: int, deployment_id: str) -> bool:
    return session.get(LtiDeployment, (platform_id, deployment_id)) is not None


def platform_origins(session: Session) -> list[str]:
    """The web origins of every platform (issuer and login page), for CSP `frame-ancestors`."""
    origins: dict[str, None] = {}
    for row in session.scalars(select(LtiPlatform)):
        for url in (row.issuer, row.auth_url):
            parts = urlsplit(url)
            if parts.scheme in ("https", "http") and parts.netloc:
                origins[f"{parts.scheme}://{parts.netloc}"] = None
    return list(origins)
