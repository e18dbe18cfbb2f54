"""Why the tool refuses a request; each error carries the HTTP status and a short code, and the
router turns it into a plain HTML page (never a stack trace).

    LtiError
     ├── LaunchRefused           status, code, message
     │    ├── MalformedRequest   400   missing or unreadable parameters, unknown or expired state
     │    ├── UntrustedToken     401   the id_token fails a signature, algorithm or claim check
     │    ├── NotPermitted       403   unregistered deployment, role not allowed, bad CSRF token
     │    └── NoSuchProblem      404   the link names a problem we do not have (or retired)
     ├── PlatformNotFound        (issuer, client_id)
     └── PlatformKeysUnavailable (jwks_url, detail): the platform's JWKS could not be fetched or read
"""

from __future__ import annotations


class LtiError(Exception):
    """Base of every error the LTI tool raises on purpose."""


class LaunchRefused(LtiError):
    status = 400

    def __init__(self, code: str, message: str) -> None:
        super().__init__(message)
        self.code = code
        self.message = message


class MalformedRequest(LaunchRefused):
    status = 400


class UntrustedToken(LaunchRefused):
    status = 401


class NotPermitted(LaunchRefused):
    status = 403


class NoSuchProblem(LaunchRefused):
    status = 404


class PlatformNotFound(LtiError):
    def __init__(self, issuer: str, client_id: str | None) -> None:
        super().__init__(f"no platform registered for issuer {issuer!r} and client_id {client_id!r}")
        self.issuer = issuer
        self.client_id = client_id


class PlatformKeysUnavailable(LtiError):
    def __init__(self, jwks_url: str, detail: str) -> None:
        super().__init__(f"could not read the platform's keys at {jwks_url}: {detail}")
        self.jwks_url = jwks_url
        self.detail = detail
