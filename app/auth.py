"""Who is calling: an API key from `Authorization: Bearer <key>` resolved to a Principal."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

from app.db.records import Role

__all__ = ["KeyStore", "Principal", "Role", "bearer_token"]


@dataclass(frozen=True)
class Principal:
    key_id: str
    role: Role
    name: str
    student: str | None  # the identity a student's submissions are filed under

    @property
    def is_instructor(self) -> bool:
        return self.role is Role.INSTRUCTOR


class KeyStore(Protocol):
    def authenticate(self, plaintext: str) -> Principal | None: ...


def bearer_token(header: str | None) -> str | None:
    if not header:
        return None
    scheme, _, token = header.partition(" ")
    token = token.strip()
    if scheme.lower() != "bearer" or not token or len(token) > 200:
        return None
    return token
