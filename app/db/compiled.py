"""Compiled problems kept across restarts: opaque sealed bytes by key (the catalog seals and opens them)."""

from __future__ import annotations

from collections.abc import Collection

from sqlalchemy import select
from sqlalchemy.orm import Session

from app.db.models import CompiledProblemRow
from app.db.types import utc_now


def get_compiled(session: Session, key: str) -> tuple[bytes, str] | None:
    """(payload, mac) stored under `key`, or None."""
    row = session.get(CompiledProblemRow, key)
    return None if row is None else (bytes(row.payload), row.mac)


def put_compiled(session: Session, key: str, payload: bytes, mac: str) -> None:
    """Store or replace (a row that failed its check is overwritten by a good one)."""
    row = session.get(CompiledProblemRow, key)
    if row is None:
        session.add(CompiledProblemRow(key=key, payload=payload, mac=mac, created_at=utc_now()))
    else:
        row.payload, row.mac, row.created_at = payload, mac, utc_now()


def get_many_compiled(session: Session, keys: Collection[str]) -> dict[str, tuple[bytes, str]]:
    """(payload, mac) of each of `keys` that is stored, in one query."""
    rows = session.execute(
        select(CompiledProblemRow.key, CompiledProblemRow.payload, CompiledProblemRow.mac).where(
            CompiledProblemRow.key.in_(list(keys))
        )
    )
    return {key: (bytes(payload), mac) for key, payload, mac in rows}
