"""`simplify`, remembered within one derivation.

The methods meet the same expressions again and again: Lagrange's solution is simplified when solved,
again when read at the state (already substituted), again when the simplest of the methods' answers is
chosen; each method simplifies the same generalized force, the same stability slope. `sympy.simplify`
is most of a derivation's time and sympy does not cache it, so it is cached here: the same expression
in, the same result out, only computed once.
"""

from __future__ import annotations

import sympy

MAX_REMEMBERED = 4096  # a bound, should a caller outside `derive` never clear it

_remembered: dict[sympy.Basic, sympy.Expr] = {}


def simplify(expr: sympy.Expr) -> sympy.Expr:
    """`sympy.simplify(expr)`, from memory when this derivation has simplified expr already."""
    if not isinstance(expr, sympy.Basic):  # a mutable Matrix cannot be a key
        return sympy.simplify(expr)
    found = _remembered.get(expr)
    if found is None:
        found = sympy.simplify(expr)
        if len(_remembered) >= MAX_REMEMBERED:
            _remembered.clear()
        _remembered[expr] = found
    return found


def forget() -> None:
    """Start afresh: each derivation pays for its own simplifications, so vetting times stay honest."""
    _remembered.clear()
