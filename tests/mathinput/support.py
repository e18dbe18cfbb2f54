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
    """Equal as written, after expansion, or numerically at a few positive points (symbols are positive)."""
    if got == expected or sympy.expand(got - expected) == 0:
        return True
    free = sorted(got.free_symbols | expected.free_symbols, key=str)
    for point in ((0.37, 1.3, 2.9, 0.61, 1.7), (1.9, 0.23, 0.77, 2.2, 0.5)):
        values = {s: point[i % len(point)] + i / 7 for i, s in enumerate(free)}
        a, b = complex(got.evalf(30, subs=values)), complex(expected.evalf(30, subs=values))
        if abs(a - b) > 1e-9 * max(1.0, abs(a), abs(b)):
            return False
    return True
