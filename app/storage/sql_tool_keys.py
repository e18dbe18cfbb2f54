"""Our LTI signing keys in the database: made on first use, published, rotated with overlap (the
SQL side of `SqlToolKeys`; `app.lti.keys` makes and uses them)."""

from __future__ import annotations

from collections.abc import Callable
from datetime import datetime
from typing import TYPE_CHECKING, Any

from sqlalchemy import select
from sqlalchemy.orm import Session

from app.db.database import Database
from app.db.types import utc_now
from app.lti import keys
from app.lti.models import LtiToolKey

if TYPE_CHECKING:
    from joserfc.jwk import RSAKey


def _load(row: LtiToolKey) -> RSAKey:
    return keys.load(row.private_pem, row.kid)


def _live_rows(session: Session) -> list[LtiToolKey]:
    """Live keys, newest first (ties broken by kid so every process agrees which one signs)."""
    query = (
        select(LtiToolKey)
        .where(LtiToolKey.retired_at.is_(None))
        .order_by(LtiToolKey.created_at.desc(), LtiToolKey.kid)
    )
    return list(session.scalars(query))


def create_key(session: Session, *, clock: Callable[[], datetime] = utc_now) -> str:
    """A new key, which becomes the signing key at once; returns its kid."""
    key = keys.generate()
    assert key.kid is not None
    pem = key.as_pem(private=True)
    session.add(LtiToolKey(kid=key.kid, private_pem=pem.decode("ascii"), created_at=clock(), retired_at=None))
    session.flush()
    return key.kid


def signing_key(session: Session, *, clock: Callable[[], datetime] = utc_now) -> RSAKey:
    """The newest live key, made on first use."""
    rows = _live_rows(session)
    if not rows:
        create_key(session, clock=clock)
        rows = _live_rows(session)
    return _load(rows[0])


def public_jwks(session: Session) -> dict[str, list[dict[str, Any]]]:
    """Every live key's public half: the signing key and the one it replaced."""
    return {"keys": [dict(_load(row).as_dict(private=False)) for row in _live_rows(session)]}


def rotate_keys(database: Database, *, clock: Callable[[], datetime] = utc_now) -> str:
    """Make a new signing key; keep the previous one published (platforms may have cached it) and
    retire every older one. Returns the new kid."""
    with database.session() as session:
        previous = _live_rows(session)
        now = clock()
        for row in previous[1:]:
            row.retired_at = now
        return create_key(session, clock=clock)


def sign(session: Session, claims: dict[str, Any], *, clock: Callable[[], datetime] = utc_now) -> str:
    """A compact JWT over `claims`, signed RS256 with the current key and naming its kid."""
    return keys.sign_with(signing_key(session, clock=clock), claims)
