"""Domain errors of the storage layer, each carrying fields; the web layer maps them to HTTP in one place.

StorageError
 ├── NotFound                  404
 │    ├── KeyNotFound               (key_id)
 │    ├── ProblemNotFound           (problem_id): unknown, or retired where retired ones are hidden
 │    └── ProblemVersionNotFound    (problem_id, version)
 ├── ProblemExists             409 (problem_id): ids are never reused, not even after retiring
 ├── AttemptsExhausted         409 or 429 (problem_id, part_id, student, max_attempts)
 └── InvalidPage               422 (a cursor that is not ours, or a limit out of range)
      ├── InvalidCursor             (cursor)
      └── InvalidLimit              (limit, maximum)
"""

from __future__ import annotations


class StorageError(Exception):
    """Base of every error the storage layer raises on purpose."""


class NotFound(StorageError):
    """The named row does not exist (or is hidden)."""


class KeyNotFound(NotFound):
    def __init__(self, key_id: int) -> None:
        super().__init__(f"no API key with id {key_id}")
        self.key_id = key_id


class ProblemNotFound(NotFound):
    def __init__(self, problem_id: str) -> None:
        super().__init__(f"no problem {problem_id!r}")
        self.problem_id = problem_id


class ProblemVersionNotFound(NotFound):
    def __init__(self, problem_id: str, version: int) -> None:
        super().__init__(f"problem {problem_id!r} has no version {version}")
        self.problem_id = problem_id
        self.version = version


class ProblemExists(StorageError):
    def __init__(self, problem_id: str) -> None:
        super().__init__(f"a problem with id {problem_id!r} already exists")
        self.problem_id = problem_id


class AttemptsExhausted(StorageError):
    """A graded submission beyond the part's attempt limit; nothing was stored."""

    def __init__(self, problem_id: str, part_id: str, student: str, max_attempts: int) -> None:
        super().__init__(
            f"student {student!r} has used all {max_attempts} attempts on {problem_id}/{part_id}"
        )
        self.problem_id = problem_id
        self.part_id = part_id
        self.student = student
        self.max_attempts = max_attempts


class InvalidPage(StorageError):
    """A page request the repository cannot serve."""


class InvalidCursor(InvalidPage):
    def __init__(self, cursor: str) -> None:
        super().__init__("the cursor is not one this service issued")
        self.cursor = cursor


class InvalidLimit(InvalidPage):
    def __init__(self, limit: int, maximum: int) -> None:
        super().__init__(f"limit must be between 1 and {maximum}, got {limit}")
        self.limit = limit
        self.maximum = maximum
