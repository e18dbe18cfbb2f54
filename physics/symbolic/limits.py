"""Limiting cases (M → ∞, θ → 0...) checked numerically: the point is pushed far along the limit.

No sympy.limit: it is unbounded in time. Each limit symbol moves from a sampled value x0 towards its
target c as c + t (x0 - c) (or x0 / t for ±∞) with t = 2^-40 and 2^-80, at 400 bits so that
cancellations such as 1 - cos(2^-80) survive. The reference's limit counts as known only where the two
levels agree; an answer whose value at the deeper level differs "does not give the right behaviour".
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import sympy
from mpmath import libmp

from physics.errors import SpecError
from physics.symbolic.compare import close
from physics.symbolic.domain import LimitCase
from physics.symbolic.numeric import RND, Column, Evaluator, Mpf, as_mpf
from physics.symbolic.sampling import DomainSample

LIMIT_PREC = 400
_SHALLOW_BITS = 40
_DEEP_BITS = 80
LIMIT_TOLERANCE_BITS = 30
LIMIT_POINTS = 4


@dataclass(frozen=True)
class PreparedLimit:
    description: str
    columns: Mapping[sympy.Symbol, Column]  # the deep-level points
    size: int
    values: Column  # the reference's limit at each point; None where it is not known


def _approach(target: Mpf | None, infinite: int, start: Mpf, bits: int) -> Mpf:
    if infinite:
        pushed = libmp.mpf_shift(libmp.mpf_abs(start), bits)
        return as_mpf(pushed if infinite > 0 else libmp.mpf_neg(pushed))
    assert target is not None
    offset = libmp.mpf_shift(libmp.mpf_sub(start, target, LIMIT_PREC, RND), -bits)
    return as_mpf(libmp.mpf_add(target, offset, LIMIT_PREC, RND))


def _limit_columns(case: LimitCase, sample: DomainSample, size: int, bits: int) -> dict[sympy.Symbol, Column]:
    base: dict[sympy.Symbol, Column] = {s: list(sample.columns[s][:size]) for s in sample.symbols}
    evaluate = Evaluator(base, size, LIMIT_PREC)
    moved: dict[sympy.Symbol, Column] = {}
    for symbol, value in case.substitutions.items():
        if symbol not in base:
            raise SpecError(f"a limit names {symbol}, which is not a declared symbol", ("limits",))
        infinite = 1 if value == sympy.oo else -1 if value == -sympy.oo else 0
        targets: Column = [None] * size if infinite else evaluate(value)
        moved[symbol] = [
            None
            if start is None or (target is None and not infinite)
            else _approach(target, infinite, start, bits)
            for start, target in zip(base[symbol], targets, strict=True)
        ]
    return base | moved


def prepare_limit(case: LimitCase, expected: sympy.Expr, sample: DomainSample, scale: Mpf) -> PreparedLimit:
    size = min(LIMIT_POINTS, sample.size)
    shallow = _limit_columns(case, sample, size, _SHALLOW_BITS)
    deep = _limit_columns(case, sample, size, _DEEP_BITS)
    near = Evaluator(shallow, size, LIMIT_PREC)(expected)
    far = Evaluator(deep, size, LIMIT_PREC)(expected)
    values: Column = [
        b if a is not None and b is not None and close(a, b, scale, LIMIT_TOLERANCE_BITS) else None
        for a, b in zip(near, far, strict=True)
    ]
    return PreparedLimit(case.description, deep, size, values)


def breaks_limit(answer: sympy.Expr, limit: PreparedLimit, scale: Mpf) -> bool:
    """True when the answer's value differs from the reference's known limit at some point."""
    if all(v is None for v in limit.values):
        return False
    values = Evaluator(limit.columns, limit.size, LIMIT_PREC)(answer)
    for reference, value in zip(limit.values, values, strict=True):
        if reference is None:
            continue
        if value is None or not close(value, reference, scale, LIMIT_TOLERANCE_BITS):
            return True
    return False
