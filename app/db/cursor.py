"""Opaque keyset cursors: the (created_at, id) of the last row a page showed, in URL-safe base64."""

from __future__ import annotations

import base64
import binascii
import json
import uuid
from dataclasses import dataclass
from datetime import UTC, datetime

from app.db.errors import InvalidCursor

_VERSION = 1


@dataclass(frozen=True)
class Position:
    created_at: datetime
    id: uuid.UUID


def encode_cursor(position: Position) -> str:
    payload = {"v": _VERSION, "t": position.created_at.isoformat(), "i": position.id.hex}
    raw = json.dumps(payload, separators=(",", ":")).encode("ascii")
    return base64.urlsafe_b64encode(raw).decode("ascii").rstrip("=")


def decode_cursor(cursor: str) -> Position:
    """The position a cursor names; InvalidCursor for anything we did not issue."""
    try:
        raw = base64.urlsafe_b64decode(cursor + "=" * (-len(cursor) % 4))
        payload = json.loads(raw)
        if not isinstance(payload, dict) or payload.get("v") != _VERSION:
            raise InvalidCursor(cursor)
        stamp, row_id = payload["t"], payload["i"]
        if not isinstance(stamp, str) or not isinstance(row_id, str):
            raise InvalidCursor(cursor)
        created_at = datetime.fromisoformat(stamp)
        if created_at.tzinfo is None:
            raise InvalidCursor(cursor)
        # In UTC here: an offset at the ends of the calendar would overflow later, in the database.
        return Position(created_at=created_at.astimezone(UTC), id=uuid.UUID(hex=row_id))
    except (binascii.Error, UnicodeDecodeError, ValueError, KeyError, TypeError, OverflowError) as error:
        raise InvalidCursor(cursor) from error
