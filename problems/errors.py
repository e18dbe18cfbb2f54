"""Errors of the problem bank.

physics.errors.SpecError
 └── ProblemInvalid    a problem document that cannot be used; carries EVERY fault found,
                       each as (path, message), e.g. ("parts[2].tolerance.rel", "must be > 0")
"""

from __future__ import annotations

from collections.abc import Sequence

from physics.errors import SpecError
from physics.wording import counted

ErrorItem = tuple[str, str]


class ProblemInvalid(SpecError):
    """A problem file (or upload) with one or more faults, all reported at once."""

    def __init__(self, errors: Sequence[ErrorItem], problem: str | None = None) -> None:
        self.errors: list[ErrorItem] = list(errors)
        self.problem = problem
        head = f"problem {problem!r} is invalid" if problem else "problem is invalid"
        listing = "; ".join(f"{path}: {message}" if path else message for path, message in self.errors)
        super().__init__(f"{head} ({counted(len(self.errors), 'error')}): {listing}")


def format_path(loc: tuple[str | int, ...]) -> str:
    """("parts", 2, "tolerance", "rel") -> "parts[2].tolerance.rel"."""
    out = ""
    for item in loc:
        if isinstance(item, int):
            out += f"[{item}]"
        else:
            out += f".{item}" if out else str(item)
    return out
