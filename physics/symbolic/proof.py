"""A bounded attempt to prove two expressions equal with sympy's rewriting (never to disprove).

Each step runs only when the difference is small enough (count_ops) for it to finish quickly; sympy
cannot be interrupted inside a worker thread, so size is the time box. A failure proves nothing:
simplify misses identities that hold only on a restricted range, which sampling handles instead.
"""

from __future__ import annotations

from collections.abc import Callable

import sympy

# count_ops limits per step, measured to keep each step well under ~100 ms on typical answers.
_CANCEL_OPS = 80
_TRIG_OPS = 40
_SIMPLIFY_OPS = 25
_MAX_POWER = 12  # expanding (a + b)**n beyond this grows too fast


def _too_wide_powers(expr: sympy.Basic) -> bool:
    return any(
        p.exp.is_Integer and abs(int(p.exp)) > _MAX_POWER and p.base.is_Add for p in expr.atoms(sympy.Pow)
    )


def _is_zero(expr: sympy.Basic) -> bool:
    return expr == 0 or (expr.is_number and expr.is_zero is True)


def proves_equal(answer: sympy.Expr, expected: sympy.Expr) -> bool:
    """True only when a bounded rewriting reduces answer - expected to 0."""
    difference = answer - expected
    if _is_zero(difference):
        return True
    ops = sympy.count_ops(difference)
    if _too_wide_powers(difference):
        return False
    steps: list[tuple[int, Callable[[sympy.Basic], sympy.Basic]]] = [
        (_CANCEL_OPS, sympy.cancel),
        (_TRIG_OPS, lambda e: sympy.cancel(sympy.expand_trig(e))),
        (_TRIG_OPS, sympy.trigsimp),
        (_SIMPLIFY_OPS, sympy.simplify),
    ]
    for limit, step in steps:
        if ops > limit:
            continue
        try:
            if _is_zero(step(difference)):
                return True
        except (TypeError, ValueError, NotImplementedError, RecursionError, ZeroDivisionError):
            continue
    return False
