"""Our signing keys (RSA 2048, `kid` = RFC 7638 thumbprint): made and used here, kept by a `ToolKeys`
store (`app.storage`: the database's keeps them, publishes the JWKS and rotates with overlap)."""

from __future__ import annotations

from typing import Any

from joserfc import jwt
from joserfc.jwk import KeyParameters, RSAKey

KEY_SIZE = 2048
ALGORITHM = "RS256"
KEY_PARAMETERS: KeyParameters = {"alg": ALGORITHM, "use": "sig"}


def generate() -> RSAKey:
    """A fresh private key with its thumbprint as kid."""
    key = RSAKey.generate_key(KEY_SIZE, parameters=KEY_PARAMETERS, private=True, auto_kid=True)
    assert key.kid is not None
    return key


def sign_with(key: RSAKey, claims: dict[str, Any]) -> str:
    return jwt.encode({"alg": ALGORITHM, "kid": key.kid}, claims, key, algorithms=[ALGORITHM])


def load(private_pem: str, kid: str) -> RSAKey:
    return RSAKey.import_key(private_pem, parameters={**KEY_PARAMETERS, "kid": kid})
