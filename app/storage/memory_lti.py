"""In-memory fakes of the LTI launch stores (platforms, launch state, our sessions), held to the same
contract as `sql_lti.py` by tests/storage. `logins` and `records` are for tests alone: they show what a
test on SQL would count in the tables (the service never asks)."""

from __future__ import annotations

import threading
from collections.abc import Sequence
from dataclasses import dataclass, field
from datetime import datetime

from app.lti.errors import PlatformNotFound
from app.lti.platforms import PlatformRecord
from app.lti.sessions import SessionRecord
from app.storage.protocols import LoginState, PendingDeepLink


@dataclass
class _Platform:
    record: PlatformRecord
    deployments: list[str] = field(default_factory=list)


class MemoryPlatformStore:
    def __init__(self) -> None:
        self._platforms: dict[int, _Platform] = {}
        self._lock = threading.Lock()

    def register(
        self,
        issuer: str,
        client_id: str,
        deployment_ids: Sequence[str],
        auth_url: str,
        token_url: str,
        jwks_url: str,
    ) -> PlatformRecord:
        with self._lock:
            known = [
                p
                for p in self._platforms.values()
                if (p.record.issuer, p.record.client_id) == (issuer, client_id)
            ]
            platform_id = known[0].record.id if known else len(self._platforms) + 1
            record = PlatformRecord(platform_id, issuer, client_id, auth_url, token_url, jwks_url)
            platform = self._platforms.setdefault(platform_id, _Platform(record))
            platform.record = record
            for deployment_id in deployment_ids:
                if deployment_id not in platform.deployments:
                    platform.deployments.append(deployment_id)
            return record

    def find(self, issuer: str, client_id: str | None) -> PlatformRecord:
        with self._lock:
            found = [
                p.record
                for p in self._platforms.values()
                if p.record.issuer == issuer and client_id in (None, p.record.client_id)
            ]
        if len(found) != 1:
            raise PlatformNotFound(issuer, client_id)
        return found[0]

    def get(self, platform_id: int) -> PlatformRecord:
        with self._lock:
            if platform_id not in self._platforms:
                raise PlatformNotFound(str(platform_id), None)
            return self._platforms[platform_id].record

    def deployments(self, platform_id: int) -> list[str]:
        with self._lock:
            platform = self._platforms.get(platform_id)
            return [] if platform is None else sorted(platform.deployments)

    def is_deployed(self, platform_id: int, deployment_id: str) -> bool:
        return deployment_id in self.deployments(platform_id)

    def list(self) -> list[PlatformRecord]:
        with self._lock:
            return [self._platforms[platform_id].record for platform_id in sorted(self._platforms)]


class MemoryLaunchStore:
    def __init__(self) -> None:
        self._logins: dict[str, LoginState] = {}
        self._nonces: dict[tuple[int, str], datetime] = {}
        self._deep_links: dict[str, PendingDeepLink] = {}
        self._lock = threading.Lock()

    def save_login(self, state_hash: str, login: LoginState, now: datetime) -> None:
        with self._lock:
            self._logins = {k: v for k, v in self._logins.items() if v.expires_at >= now}
            self._logins[state_hash] = login

    def take_login(self, state_hash: str) -> LoginState | None:
        with self._lock:
            return self._logins.pop(state_hash, None)

    def spend_nonce(self, platform_id: int, nonce: str, expires_at: datetime, now: datetime) -> bool:
        with self._lock:
            self._nonces = {k: v for k, v in self._nonces.items() if v >= now}
            if (platform_id, nonce) in self._nonces:
                return False
            self._nonces[(platform_id, nonce)] = expires_at
            return True

    def save_deep_link(self, request: PendingDeepLink, now: datetime) -> None:
        with self._lock:
            self._deep_links = {k: v for k, v in self._deep_links.items() if v.expires_at >= now}
            self._deep_links[request.id] = request

    def get_deep_link(self, request_id: str) -> PendingDeepLink | None:
        with self._lock:
            return self._deep_links.get(request_id)

    def drop_deep_link(self, request_id: str) -> None:
        with self._lock:
            self._deep_links.pop(request_id, None)

    def logins(self) -> list[LoginState]:
        """The logins in progress (saved, not yet taken or dropped), oldest first."""
        with self._lock:
            return list(self._logins.values())


class MemoryLtiSessionStore:
    def __init__(self) -> None:
        self._sessions: dict[str, SessionRecord] = {}
        self._lock = threading.Lock()

    def save(self, id_hash: str, record: SessionRecord, now: datetime) -> None:
        with self._lock:
            self._sessions = {k: v for k, v in self._sessions.items() if v.expires_at >= now}
            self._sessions[id_hash] = record

    def get(self, id_hash: str) -> SessionRecord | None:
        with self._lock:
            return self._sessions.get(id_hash)

    def records(self) -> list[SessionRecord]:
        """Every stored session (expired ones not yet dropped too), oldest first."""
        with self._lock:
            return list(self._sessions.values())
