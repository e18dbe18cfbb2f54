"""Hand-made id_tokens for negative launches: any header, any claims, any (or no) signature."""

from __future__ import annotations

import base64
import hashlib
import hmac
import json
import time
from dataclasses import dataclass
from typing import Any

from cryptography.hazmat.primitives import hashes, serialization
from cryptography.hazmat.primitives.asymmetric import padding, rsa

from tests.lti.fake_lms import CLIENT_ID, DEPLOYMENT_ID, ISSUER, LEARNER

LTI = "https://purl.imsglobal.org/spec/lti/claim/"


def b64(data: bytes) -> str:
    return base64.urlsafe_b64encode(data).rstrip(b"=").decode()


def launch_claims(login_nonce: str, /, **overrides: Any) -> dict[str, Any]:
    now = int(time.time())
    claims: dict[str, Any] = {
        "iss": ISSUER,
        "aud": CLIENT_ID,
        "sub": "student-1",
        "iat": now,
        "exp": now + 300,
        "nonce": login_nonce,
        LTI + "deployment_id": DEPLOYMENT_ID,
        LTI + "message_type": "LtiResourceLinkRequest",
        LTI + "version": "1.3.0",
        LTI + "roles": [LEARNER],
        LTI + "resource_link": {"id": "link-1"},
        LTI + "custom": {"problem": "moving-wedge"},
    }
    for name, value in overrides.items():
        if value is _DROP:
            claims.pop(name, None)
        elif isinstance(value, FromNow):
            claims[name] = now + value.seconds
        else:
            claims[name] = value
    return claims


@dataclass(frozen=True)
class FromNow:
    """A time claim relative to when the token is made (not when the test module was imported)."""

    seconds: int


_DROP = object()
DROP: Any = _DROP


def _signing_input(header: dict[str, Any], claims: dict[str, Any]) -> bytes:
    return f"{b64(json.dumps(header).encode())}.{b64(json.dumps(claims).encode())}".encode()


def rs256(claims: dict[str, Any], private_pem: str, kid: str | None, **header: Any) -> str:
    key = serialization.load_pem_private_key(private_pem.encode(), password=None)
    assert isinstance(key, rsa.RSAPrivateKey)
    full_header = {"alg": "RS256", "typ": "JWT", **({"kid": kid} if kid else {}), **header}
    signing_input = _signing_input(full_header, claims)
    signature = key.sign(signing_input, padding.PKCS1v15(), hashes.SHA256())
    return f"{signing_input.decode()}.{b64(signature)}"


def hs256(claims: dict[str, Any], secret: bytes, kid: str) -> str:
    """The key-confusion attack: HMAC keyed with the platform's *public* key."""
    signing_input = _signing_input({"alg": "HS256", "typ": "JWT", "kid": kid}, claims)
    return f"{signing_input.decode()}.{b64(hmac.new(secret, signing_input, hashlib.sha256).digest())}"


def unsigned(claims: dict[str, Any], kid: str) -> str:
    return f"{_signing_input({'alg': 'none', 'typ': 'JWT', 'kid': kid}, claims).decode()}."
