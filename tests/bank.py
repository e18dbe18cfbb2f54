"""The built-in bank's documents by id, loaded once per test process: loading checks every model's
meaning, most of a second, which each test module paid again at collection."""

from __future__ import annotations

from functools import cache

from problems.loader import load_bank
from problems.schema import ProblemDocument


@cache
def bank_documents() -> dict[str, ProblemDocument]:
    return {doc.id: doc for doc in load_bank()}
