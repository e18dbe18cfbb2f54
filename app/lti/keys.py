"""RSA keys and JSON Web Tokens, the one place that uses joserfc (imported on first use: with the
cryptography library under it, a tenth of a CPU-second that every start would otherwise pay before it is
ready, though most instances sign or verify nothing until an LMS launches).

Our signing keys (RSA 2048, `kid` = RFC 7638 thumbprint) are made and used here, kept by a `ToolKeys`
store (`app.storage`: the database's keeps them, publishes the JWKS and rotates with overlap); the
platforms' public keys are read and their tokens verified here too."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from joserfc.jwk import KeyParameters, RSAKey

KEY_SIZE = 2048
ALGORITHM = "RS256"
KEY_PARAMETERS: KeyParameters = {"alg": ALGORITHM, "use": "sig"}


class BadKey(ValueError):
    """A JWK or token that joserfc refuses."""


def generate() -> RSAKey:
    """A fresh private key with its thumbprint as kid."""
    from joserfc.jwk import RSAKey

    key = RSAKey.generate_key(KEY_SIZE, parameters=KEY_PARAMETERS, private=True, auto_kid=True)
    assert key.kid is not None
    return key


def sign_with(key: RSAKey, claims: dict[str, Any]) -> str:
    from joserfc import jwt

    return jwt.encode({"alg": ALGORITHM, "kid": key.kid}, claims, key, algorithms=[ALGORITHM])


def load(private_pem: str, kid: str) -> RSAKey:
    from joserfc.jwk import RSAKey

    return RSAKey.import_key(private_pem, parameters={**KEY_PARAMETERS, "kid": kid})


def public_key(entry: dict[str, Any]) -> RSAKey:
    """A platform's public key from its JWKS entry; raises BadKey if it is not one."""
    from joserfc.errors import JoseError
    from joserfc.jwk import RSAKey

    try:
        return RSAKey.import_key(entry)
    except (JoseError, ValueError, TypeError) as error:
        raise BadKey(str(error)) from error


def verified_claims(token: str, key: RSAKey) -> dict[str, Any]:
    """The token's claims once its RS256 signature verifies with `key`; raises BadKey if it does not."""
    from joserfc import jwt
    from joserfc.errors import JoseError

    try:
        return dict(jwt.decode(token, key, algorithms=[ALGORITHM]).claims)
    except JoseError as error:
        raise BadKey(str(error)) from error
