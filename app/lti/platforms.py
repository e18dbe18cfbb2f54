"""Registered platforms (LMSs) and their deployments: the rules on registering them and the web
origins they frame us from; storage is a `PlatformStore` (`app.storage`)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING
from urllib.parse import urlsplit

if TYPE_CHECKING:  # the stores name this module's record
    from app.storage.protocols import PlatformStore


@dataclass(frozen=True)
class PlatformRecord:
    id: int
    issuer: str
    client_id: str
    auth_url: str
    token_url: str
    jwks_url: str


def _require_url(name: str, value: str) -> None:
    parts = urlsplit(value)
    if parts.scheme not in ("https", "http") or not parts.netloc:
        raise ValueError(f"{name} must be an absolute http(s) URL, got {value!r}")


def add_platform(
    platforms: PlatformStore,
    issuer: str,
    client_id: str,
    deployment_ids: Sequence[str],
    auth_url: str,
    token_url: str,
    jwks_url: str,
) -> PlatformRecord:
    """Register a platform, or update its URLs and add deployments if (issuer, client_id) is known."""
    if not issuer or not client_id:
        raise ValueError("issuer and client_id must not be empty")
    for name, url in (("auth_url", auth_url), ("token_url", token_url), ("jwks_url", jwks_url)):
        _require_url(name, url)
    wanted = [deployment_id for deployment_id in dict.fromkeys(deployment_ids) if deployment_id]
    return platforms.register(issuer, client_id, wanted, auth_url, token_url, jwks_url)


def platform_origins(platforms: PlatformStore) -> list[str]:
    """The web origins of every platform (issuer and login page), for CSP `frame-ancestors`."""
    origins: dict[str, None] = {}
    for record in platforms.list():
        for url in (record.issuer, record.auth_url):
            parts = urlsplit(url)
            if parts.scheme in ("https", "http") and parts.netloc:
                origins[f"{parts.scheme}://{parts.netloc}"] = None
    return list(origins)
