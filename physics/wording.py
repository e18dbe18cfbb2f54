"""Small pieces of English shared by every message the core, the bank tools and the web layer print."""

from __future__ import annotations


def counted(count: int, noun: str, plural: str | None = None) -> str:
    """`1 problem`, `2 problems`, `0 problems`: the count with the noun agreeing, never `problem(s)`."""
    return f"{count} {noun if count == 1 else plural or noun + 's'}"


def the_counted(count: int, noun: str, plural: str | None = None) -> str:
    """`the equation`, `the 2 equations`: a definite count, the number left out where it is one."""
    return f"the {noun}" if count == 1 else f"the {counted(count, noun, plural)}"
