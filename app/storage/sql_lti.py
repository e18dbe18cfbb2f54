"""The LTI launch stores on SQLAlchemy: platforms, launch state (logins, nonces, deep-link requests)
and our sessions, each call one transaction."""

from __future__ import annotations

from collections.abc import Sequence
from datetime import datetime

from sqlalchemy import delete, select
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session

from app.auth import Role
from app.db.database import Database
from app.db.types import utc_now
from app.lti.errors import PlatformNotFound
from app.lti.models import (
    LtiDeepLinkRequest,
    LtiDeployment,
    LtiLoginState,
    LtiPlatform,
    LtiSession,
    LtiUsedNonce,
)
from app.lti.platforms import PlatformRecord
from app.lti.sessions import SessionRecord
from app.storage.protocols import LoginState, PendingDeepLink
from app.storage.sql import Clock


def _platform(row: LtiPlatform) -> PlatformRecord:
    return PlatformRecord(row.id, row.issuer, row.client_id, row.auth_url, row.token_url, row.jwks_url)


class SqlPlatformStore:
    def __init__(self, database: Database, clock: Clock = utc_now) -> None:
        self._database, self._clock = database, clock

    def register(
        self,
        issuer: str,
        client_id: str,
        deployment_ids: Sequence[str],
        auth_url: str,
        token_url: str,
        jwks_url: str,
    ) -> PlatformRecord:
        with self._database.session() as session:
            row = session.scalars(
                select(LtiPlatform).where(LtiPlatform.issuer == issuer, LtiPlatform.client_id == client_id)
            ).one_or_none()
            if row is None:
                row = LtiPlatform(issuer=issuer, client_id=client_id, created_at=self._clock())
                session.add(row)
            row.auth_url, row.token_url, row.jwks_url = auth_url, token_url, jwks_url
            session.flush()
            known = set(self._deployments(session, row.id))
            for deployment_id in dict.fromkeys(deployment_ids):
                if deployment_id not in known:
                    session.add(LtiDeployment(platform_id=row.id, deployment_id=deployment_id))
            return _platform(row)

    def find(self, issuer: str, client_id: str | None) -> PlatformRecord:
        query = select(LtiPlatform).where(LtiPlatform.issuer == issuer)
        if client_id is not None:
            query = query.where(LtiPlatform.client_id == client_id)
        with self._database.session(read_only=True) as session:
            rows = list(session.scalars(query.limit(2)))
            if len(rows) != 1:
                raise PlatformNotFound(issuer, client_id)
            return _platform(rows[0])

    def get(self, platform_id: int) -> PlatformRecord:
        with self._database.session(read_only=True) as session:
            row = session.get(LtiPlatform, platform_id)
            if row is None:
                raise PlatformNotFound(str(platform_id), None)
            return _platform(row)

    def deployments(self, platform_id: int) -> list[str]:
        with self._database.session(read_only=True) as session:
            return self._deployments(session, platform_id)

    @staticmethod
    def _deployments(session: Session, platform_id: int) -> list[str]:
        query = select(LtiDeployment.deployment_id).where(LtiDeployment.platform_id == platform_id)
        return list(session.scalars(query.order_by(LtiDeployment.deployment_id)))

    def is_deployed(self, platform_id: int, deployment_id: str) -> bool:
        with self._database.session(read_only=True) as session:
            return session.get(LtiDeployment, (platform_id, deployment_id)) is not None

    def list(self) -> list[PlatformRecord]:
        with self._database.session(read_only=True) as session:
            return [_platform(row) for row in session.scalars(select(LtiPlatform).order_by(LtiPlatform.id))]


class SqlLaunchStore:
    def __init__(self, database: Database) -> None:
        self._database = database

    def save_login(self, state_hash: str, login: LoginState, now: datetime) -> None:
        with self._database.session() as session:
            session.execute(delete(LtiLoginState).where(LtiLoginState.expires_at < now))
            session.add(
                LtiLoginState(
                    state_hash=state_hash,
                    nonce=login.nonce,
                    browser_hash=login.browser_hash,
                    platform_id=login.platform_id,
                    expires_at=login.expires_at,
                )
            )

    def take_login(self, state_hash: str) -> LoginState | None:
        # DELETE ... RETURNING: of two concurrent launches with one state, one gets the row.
        taken = (
            delete(LtiLoginState)
            .where(LtiLoginState.state_hash == state_hash)
            .returning(
                LtiLoginState.nonce,
                LtiLoginState.browser_hash,
                LtiLoginState.platform_id,
                LtiLoginState.expires_at,
            )
        )
        with self._database.session() as session:
            row = session.execute(taken).one_or_none()
            return None if row is None else LoginState(*row)

    def spend_nonce(self, platform_id: int, nonce: str, expires_at: datetime, now: datetime) -> bool:
        with self._database.session() as session:
            session.execute(delete(LtiUsedNonce).where(LtiUsedNonce.expires_at < now))
            try:
                with session.begin_nested():
                    session.add(LtiUsedNonce(platform_id=platform_id, nonce=nonce, expires_at=expires_at))
            except IntegrityError:
                return False
            return True

    def save_deep_link(self, request: PendingDeepLink, now: datetime) -> None:
        with self._database.session() as session:
            session.execute(delete(LtiDeepLinkRequest).where(LtiDeepLinkRequest.expires_at < now))
            session.add(
                LtiDeepLinkRequest(
                    id=request.id,
                    session_hash=request.session_hash,
                    platform_id=request.platform_id,
                    deployment_id=request.deployment_id,
                    return_url=request.return_url,
                    data=request.data,
                    accept_multiple=request.accept_multiple,
                    expires_at=request.expires_at,
                )
            )

    def get_deep_link(self, request_id: str) -> PendingDeepLink | None:
        with self._database.session(read_only=True) as session:
            row = session.get(LtiDeepLinkRequest, request_id)
            if row is None:
                return None
            return PendingDeepLink(
                id=row.id,
                session_hash=row.session_hash,
                platform_id=row.platform_id,
                deployment_id=row.deployment_id,
                return_url=row.return_url,
                data=row.data,
                accept_multiple=row.accept_multiple,
                expires_at=row.expires_at,
            )

    def drop_deep_link(self, request_id: str) -> None:
        with self._database.session() as session:
            session.execute(delete(LtiDeepLinkRequest).where(LtiDeepLinkRequest.id == request_id))


class SqlLtiSessionStore:
    def __init__(self, database: Database) -> None:
        self._database = database

    def save(self, id_hash: str, record: SessionRecord, now: datetime) -> None:
        with self._database.session() as session:
            session.execute(delete(LtiSession).where(LtiSession.expires_at < now))
            session.add(
                LtiSession(
                    id_hash=id_hash,
                    platform_id=record.platform_id,
                    sub=record.sub,
                    student=record.student,
                    role=record.role.value,
                    name=record.name,
                    csrf_token=record.csrf_token,
                    created_at=now,
                    expires_at=record.expires_at,
                )
            )

    def get(self, id_hash: str) -> SessionRecord | None:
        with self._database.session(read_only=True) as session:
            row = session.get(LtiSession, id_hash)
            if row is None:
                return None
            return SessionRecord(
                platform_id=row.platform_id,
                sub=row.sub,
                student=row.student,
                role=Role(row.role),
                name=row.name,
                csrf_token=row.csrf_token,
                expires_at=row.expires_at,
            )
