"""The platforms' public keys, fetched from their JWKS URLs and cached, with one refetch when a token
names a kid we have not seen (the platform rotated its key)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from datetime import datetime, timedelta
from typing import TYPE_CHECKING, Any

import httpx

from app.lti.errors import PlatformKeysUnavailable, UntrustedToken
from app.lti.keys import BadKey, public_key
from app.lti.platforms import PlatformRecord

if TYPE_CHECKING:
    from joserfc.jwk import RSAKey

CACHE_TTL = timedelta(minutes=10)
# A flood of tokens with made-up kids must not turn into a flood of fetches.
MIN_REFETCH_INTERVAL = timedelta(seconds=5)
MAX_JWKS_BYTES = 256 * 1024


@dataclass
class _Entry:
    keys: dict[str, RSAKey]
    fetched_at: datetime
    refetched_at: datetime | None = None


def parse_jwks(document: Any) -> dict[str, RSAKey]:
    """RS256 signing keys by kid; keys of other types or uses, or without a kid, are ignored."""
    if not isinstance(document, dict) or not isinstance(document.get("keys"), list):
        raise ValueError("not a JWKS document")
    keys: dict[str, RSAKey] = {}
    for entry in document["keys"]:
        if not isinstance(entry, dict) or entry.get("kty") != "RSA" or "d" in entry:
            continue
        kid = entry.get("kid")
        if not isinstance(kid, str) or not kid:
            continue
        if entry.get("alg", "RS256") != "RS256" or entry.get("use", "sig") != "sig":
            continue
        try:
            keys[kid] = public_key(entry)
        except BadKey:
            continue
    return keys


class PlatformKeyCache:
    """Per process; `client` makes the httpx client (the seam tests replace with a loopback transport)."""

    def __init__(self, client: Callable[[], httpx.AsyncClient], clock: Callable[[], datetime]) -> None:
        self._client = client
        self._clock = clock
        self._entries: dict[str, _Entry] = {}

    async def key_for(self, platform: PlatformRecord, kid: str) -> RSAKey:
        now = self._clock()
        entry = self._entries.get(platform.jwks_url)
        if entry is None or now - entry.fetched_at > CACHE_TTL:
            entry = _Entry(await self._fetch(platform.jwks_url), now)
            self._entries[platform.jwks_url] = entry
        elif kid not in entry.keys and (
            entry.refetched_at is None or now - entry.refetched_at >= MIN_REFETCH_INTERVAL
        ):
            entry = _Entry(await self._fetch(platform.jwks_url), now, refetched_at=now)
            self._entries[platform.jwks_url] = entry
        key = entry.keys.get(kid)
        if key is None:
            raise UntrustedToken(
                "unknown_kid", "The token is signed with a key the platform does not publish."
            )
        return key

    async def _fetch(self, url: str) -> dict[str, RSAKey]:
        try:
            async with self._client() as client:
                response = await client.get(
                    url, headers={"Accept": "application/json"}, follow_redirects=True
                )
        except httpx.HTTPError as error:
            raise PlatformKeysUnavailable(url, type(error).__name__) from error
        if response.status_code != 200:
            raise PlatformKeysUnavailable(url, f"HTTP {response.status_code}")
        if len(response.content) > MAX_JWKS_BYTES:
            raise PlatformKeysUnavailable(url, "document too large")
        try:
            return parse_jwks(response.json())
        except ValueError as error:
            raise PlatformKeysUnavailable(url, str(error)) from error
