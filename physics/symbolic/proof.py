"""A bounded attempt to prove two expressions equal with sympy's rewriting (never to disprove).

Each step runs only when the difference is small enough (count_ops) for it to finish quickly; sympy
cannot be interrupted inside a worker thread, so size is the time box. A failure proves nothing:
simplify misses identities that hold only on a restricted range, which sampling handles instead.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import sympy

# count_ops limits per step, measured to keep each step well under ~100 ms on typical answers
# (trigsimp took 0.8 s on the wedge's difference times (1 + sqrt(-θ) sin 3), 29 ops).
_CANCEL_OPS = 80
_TRIG_OPS = 20
_SIMPLIFY_OPS = 20
# Expanding a**n, sin(n θ) or exp(n) (a polynomial of degree n in e) grows with n: beyond this, too fast.
_MAX_POWER = 12
_MAX_TERMS = 400


def _too_hard(expr: sympy.Basic) -> bool:
    """Shapes whose rewriting grows far beyond their count_ops: a power or a multiple past _MAX_POWER
    (cos(θ)^100, exp(2^64), sin(10^6 θ): polynomials of that degree), a function of a function
    (trigsimp of sinh(sinh(sinh(x))) ran past the time limit at 11 ops), or an expansion into more than
    _MAX_TERMS terms ((a + b + c + d + e)^12 at 12 ops)."""
    for power in expr.atoms(sympy.Pow):
        if not power.base.is_number and power.exp.is_Integer and abs(int(power.exp)) > _MAX_POWER:
            return True
        if _largest_number(power.exp) > _MAX_POWER:
            return True
    for function in expr.atoms(sympy.Function):
        if any(arg.atoms(sympy.Function) or _largest_number(arg) > _MAX_POWER for arg in function.args):
            return True
    return _terms(expr) > _MAX_TERMS


def _largest_number(expr: sympy.Basic) -> int:
    return max((max(abs(int(n.p)), int(n.q)) for n in expr.atoms(sympy.Rational)), default=0)


def _terms(expr: sympy.Basic) -> int:
    """How many terms `expr` has when expanded, sin(nθ) and exp(nθ) counted as n (an estimate; its
    arguments are each at most _MAX_POWER, as `_too_hard` checks first)."""
    if expr.is_Add:
        return sum(_terms(arg) for arg in expr.args)
    if expr.is_Mul:
        return math.prod(_terms(arg) for arg in expr.args)
    if expr.is_Pow:
        base = _terms(expr.base)
        if expr.exp.is_Integer:
            return math.comb(abs(int(expr.exp)) + base - 1, base - 1)  # multinomial terms
        return base * _terms(expr.exp)
    if expr.is_Function:
        return max(1, _largest_number(expr)) * sum(_terms(arg) for arg in expr.args)
    return 1


def _is_zero(expr: sympy.Basic) -> bool:
    return expr == 0 or (expr.is_number and expr.is_zero is True)


def proves_equal(answer: sympy.Expr, expected: sympy.Expr) -> bool:
    """True only when a bounded rewriting reduces answer - expected to 0."""
    difference = answer - expected
    if _is_zero(difference):
        return True
    if _too_hard(difference):
        return False
    ops = sympy.count_ops(difference)
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
