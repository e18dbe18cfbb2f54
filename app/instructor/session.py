"""Who is using the instructor pages, and the CSRF token every form of theirs carries.

Two ways in, scoped as the API scopes them:
- an instructor API key, typed once into the sign-in form: the browser then holds a signed cookie
  (HttpOnly, SameSite=Strict, Secure on https) naming the key, which is looked up on every request, so
  revoking the key signs the browser out at once;
- the session an LMS launch opened for an instructor (the LTI cookie): it acts only for itself, so it
  sees problems and solutions but no student's variant, work or grade passback, and uploads nothing.

Each form carries a token derived from the session (HMAC with the server secret), checked on POST; the
sign-in form, before there is a session, is tied the same way to a random cookie of its own.
"""

from __future__ import annotations

import hashlib
import hmac
import secrets
import time
from dataclasses import dataclass

from fastapi import Request
from starlette.concurrency import run_in_threadpool

from app.auth import Principal
from app.db.errors import KeyNotFound
from app.db.records import Role
from app.lti.sessions import current_session
from app.services import Services

COOKIE = "physcheck_instructor"
PRE_COOKIE = "physcheck_instructor_form"  # ties the sign-in form to this browser
COOKIE_PATH = "/instructor"
LIFETIME_SECONDS = 8 * 3600
CSRF_FIELD = "csrf"


@dataclass(frozen=True)
class Visitor:
    """A signed-in instructor and the token their forms must send back."""

    principal: Principal
    csrf: str

    @property
    def acts_for_students(self) -> bool:
        return self.principal.acts_for_students


class SignInRequired(Exception):
    """No usable session: the page sends the browser to the sign-in form."""


class NotAnInstructor(Exception):
    """A student's session (or key): these pages are not for them."""


class BadCsrf(Exception):
    """A POST without this session's CSRF token (a forged or stale form)."""


def _mac(secret: str, purpose: str, value: str) -> str:
    key = hashlib.sha256(f"physcheck instructor pages\x1f{secret}".encode()).digest()
    return hmac.new(key, f"{purpose}\x1f{value}".encode(), hashlib.sha256).hexdigest()


def session_cookie(secret: str, key_id: int, now: float | None = None) -> str:
    """`<key id>.<expires>.<nonce>.<mac>`: nothing secret in it, and nothing a browser can alter."""
    expires = int((time.time() if now is None else now) + LIFETIME_SECONDS)
    payload = f"{key_id}.{expires}.{secrets.token_urlsafe(12)}"
    return f"{payload}.{_mac(secret, 'session', payload)}"


def read_session_cookie(secret: str, value: str, now: float | None = None) -> tuple[int, str] | None:
    """(key id, the cookie's payload) if the cookie is ours and unexpired."""
    if not value or len(value) > 200:
        return None
    payload, _, mac = value.rpartition(".")
    if not hmac.compare_digest(mac.encode(), _mac(secret, "session", payload).encode()):
        return None
    fields = payload.split(".")
    if len(fields) != 3:
        return None
    key_id, expires, _nonce = fields
    if not key_id.isdigit() or not expires.isdigit():
        return None
    if int(expires) <= (time.time() if now is None else now):
        return None
    return int(key_id), payload


def csrf_token(secret: str, session_ref: str) -> str:
    return _mac(secret, "csrf", session_ref)


def form_nonce() -> str:
    return secrets.token_urlsafe(24)


def check_csrf(secret: str, session_ref: str, sent: str | None) -> None:
    if not sent or not hmac.compare_digest(sent.encode(), csrf_token(secret, session_ref).encode()):
        raise BadCsrf()


def _key_principal(services: Services, key_id: int) -> Principal | None:
    try:
        record = services.stores.keys.get(key_id)
    except KeyNotFound:
        return None
    if record.revoked:
        return None
    return Principal(key_id=str(record.id), role=record.role, name=record.name or "", student=record.student)


async def visitor(request: Request, services: Services) -> Visitor:
    """The instructor behind this request, or SignInRequired / NotAnInstructor."""
    secret = services.settings.secret
    found = read_session_cookie(secret, request.cookies.get(COOKIE, ""))
    if found is not None:
        key_id, payload = found
        principal = await run_in_threadpool(_key_principal, services, key_id)
        if principal is not None:
            if principal.role is not Role.INSTRUCTOR:
                raise NotAnInstructor()
            return Visitor(principal, csrf_token(secret, "key:" + payload))
    launched = await run_in_threadpool(current_session, request)
    if launched is not None:
        id_hash, record = launched
        if record.role is not Role.INSTRUCTOR:
            raise NotAnInstructor()
        return Visitor(record.principal(id_hash), csrf_token(secret, "lti:" + id_hash))
    raise SignInRequired()


async def require_csrf(request: Request, services: Services, who: Visitor) -> None:
    """Every POST of a signed-in instructor: the form's token must be this session's."""
    form = await request.form()
    sent = form.get(CSRF_FIELD)
    if not isinstance(sent, str) or not hmac.compare_digest(sent.encode(), who.csrf.encode()):
        raise BadCsrf()
