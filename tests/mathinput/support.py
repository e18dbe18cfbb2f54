"""Shared helpers for the math reader tests: declared names and an equality that tolerates ordering."""

from __future__ import annotations

import sympy

from physics.mathinput import ParsedMath, parse_math


def names(*spellings: str) -> dict[str, sympy.Symbol]:
    """Declare names the way a caller does: spelling -> a Symbol (positive, like the API default)."""
    return {s: sympy.Symbol(s, positive=True) for s in spellings}


def sym(spelling: str) -> sympy.Symbol:
    """The Symbol `names(spelling)` declares (same name and assumptions, so they compare equal)."""
    return sympy.Symbol(spelling, positive=True)


def read(text: str, *spellings: str) -> ParsedMath:
    return parse_math(text, names(*spellings))


def same(got: sympy.Expr, expected: sympy.Expr) -> bool:
    return bool(got == expected or sympy.expand(got - expected) == 0)
