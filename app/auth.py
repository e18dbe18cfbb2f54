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
    # False for a session opened by an LMS launch: it acts only for itself, whatever its role, since an
    # instructor of one course must not reach the students (or gradebooks) of another.
    api_key: bool = True
    # The stable identity of an LMS user ("lti:<platform>:<sub>"): course staff are listed by it.
    account: str | None = None

    @property
    def is_instructor(self) -> bool:
        return self.role is Role.INSTRUCTOR

    @property
    def member(self) -> str | None:
        """Who this caller is on a course's staff list: "key:<id>" for an API key, the LMS identity
        for a launched session."""
        if self.account is not None:
            return self.account
        return f"key:{self.key_id}" if self.api_key else None

    @property
    def own_identity(self) -> str:
        """Whose work this caller's own answers are: the student, or an instructor's preview identity."""
        return self.student if self.student is not None else f"preview:{self.key_id}"

    @property
    def grading_share(self) -> str | None:
        """Whose share of the grading workers a check counts against: students and LMS sessions each
        have a small one; instructor API keys (course scripts, LMS plug-ins) are limited by rate only."""
        return None if self.acts_for_students else self.own_identity

    @property
    def acts_for_students(self) -> bool:
        """May name other students (their variants, submissions): instructor API keys only."""
        return self.is_instructor and self.api_key


class KeyStore(Protocol):
    def authenticate(self, plaintext: str) -> Principal | None: ...

    def cached(self, plaintext: str) -> Principal | None:
        """Answered from memory only (no I/O), or None: then `authenticate` decides."""
        ...


def bearer_token(header: str | None) -> str | None:
    if not header:
        return None
    scheme, _, token = header.partition(" ")
    token = token.strip()
    if scheme.lower() != "bearer" or not token or len(token) > 200:
        return None
    return token
