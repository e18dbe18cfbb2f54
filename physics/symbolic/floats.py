"""A first look in float64: an answer evaluated at every sample point at once (numpy), in microseconds.

It only ever *suggests*: the judge confirms a refutation at the point in multiprecision, and confirms
agreement at the precise points (physics.symbolic.judge); anything float64 cannot evaluate cleanly
(an unknown function, overflow, a value that is not real) sends the judge to the multiprecision path.
Like physics.symbolic.numeric it walks sympy's own tree; it never reads or generates text.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import sympy

from physics.symbolic.numeric import ZERO, Column, to_float

Floats = npt.NDArray[np.float64]

# Relative agreement that counts as "the same" in float64; well above rounding in typical physics
# expressions, far below any difference a wrong answer makes (3.1416 and π differ by 2e-6).
AGREE = 1e-9
# Only a difference this large is taken as a refutation worth confirming in multiprecision.
DIFFER = 1e-6


# Values beyond these magnitudes are near float64's overflow or underflow (exp(-1000 a) is 0.0 there,
# and 0.0 "agrees" with 2 exp(-1000 a)): such a sample is left to multiprecision.
_SAFE_MAGNITUDES = (1e-100, 1e100)


@dataclass(frozen=True)
class FloatSample:
    columns: Mapping[sympy.Symbol, Floats]
    values: Floats  # the reference at every sample point
    scale: float  # median |reference|
    usable: bool  # every point and value well inside float64's range (else the first look is skipped)


def in_range(values: Floats) -> bool:
    """Every value finite, and every nonzero one's magnitude within _SAFE_MAGNITUDES."""
    # Over the values as Python floats: a sample is a few dozen numbers, where each numpy call's fixed
    # cost is most of its time; the comparisons are the same IEEE comparisons.
    low, high = _SAFE_MAGNITUDES
    for value in values.ravel().tolist():
        magnitude = abs(value)
        if not (math.isfinite(value) and (magnitude == 0 or low < magnitude < high)):
            return False
    return True


def rounded(values: Column) -> tuple[Floats, bool]:
    """Multiprecision values in float64 (nan where undefined), and whether a nonzero one underflowed."""
    floats = np.array([math.nan if v is None else to_float(v) for v in values])
    # An exact zero stays 0.0; a nonzero value that rounds to 0.0 underflowed.
    underflow = any(v is not None and v != ZERO and f == 0 for v, f in zip(values, floats, strict=True))
    return floats, underflow


def float_sample(
    columns: Mapping[sympy.Symbol, Floats],
    floats: Floats,
    underflow: bool = False,
    columns_in_range: bool | None = None,
) -> FloatSample:
    """`columns_in_range`: whether every column is `in_range`, when known (else found here)."""
    if columns_in_range is None:
        columns_in_range = all(in_range(column) for column in columns.values())
    usable = not underflow and in_range(floats) and columns_in_range
    scale = _median_magnitude(floats)
    return FloatSample(columns, floats, scale if scale > 0 else 1.0, usable)


def _median_magnitude(values: Floats) -> float:
    """numpy.median of the finite values' magnitudes (1.0 when there are none), over Python floats: on
    a few dozen values numpy's own median costs six times as much, a tenth of preparing a reference."""
    magnitudes = sorted(abs(value) for value in values.ravel().tolist() if math.isfinite(value))
    count = len(magnitudes)
    if not count:
        return 1.0
    middle = count // 2
    return magnitudes[middle] if count % 2 else (magnitudes[middle - 1] + magnitudes[middle]) / 2


def _acot(x: Floats) -> Floats:
    # sympy's acot: continuous at 0 (pi/2), values in (-pi/2, pi/2].
    with np.errstate(divide="ignore"):
        result: Floats = np.where(x == 0, math.pi / 2, np.arctan(1 / x))
    return result


UNARY: dict[type, Callable[[Floats], Floats]] = {
    sympy.sin: np.sin,
    sympy.cos: np.cos,
    sympy.tan: np.tan,
    sympy.cot: lambda x: 1 / np.tan(x),
    sympy.sec: lambda x: 1 / np.cos(x),
    sympy.csc: lambda x: 1 / np.sin(x),
    sympy.asin: np.arcsin,
    sympy.acos: np.arccos,
    sympy.atan: np.arctan,
    sympy.acot: _acot,
    sympy.asec: lambda x: np.arccos(1 / x),
    sympy.acsc: lambda x: np.arcsin(1 / x),
    sympy.sinh: np.sinh,
    sympy.cosh: np.cosh,
    sympy.tanh: np.tanh,
    sympy.asinh: np.arcsinh,
    sympy.acosh: np.arccosh,
    sympy.atanh: np.arctanh,
    sympy.exp: np.exp,
    sympy.log: np.log,
    sympy.Abs: np.abs,
    sympy.sign: np.sign,
    sympy.floor: np.floor,
    sympy.ceiling: np.ceil,
}


class _Unsupported(Exception):
    """Something float64 cannot stand in for: the multiprecision path decides alone."""


class FloatEvaluator:
    def __init__(
        self,
        columns: Mapping[sympy.Symbol, Floats],
        size: int,
        known: Mapping[sympy.Basic, Floats] | None = None,
    ) -> None:
        self._columns = columns
        self._size = size
        # Subtrees already evaluated over the same columns (the reference's, which answers share).
        # Values are never changed in place, so they may be shared.
        self._cache: dict[sympy.Basic, Floats] = dict(known or {})

    @property
    def known(self) -> Mapping[sympy.Basic, Floats]:
        """Every subtree evaluated so far (to start another evaluator over the same columns from)."""
        return self._cache

    def __call__(self, expr: sympy.Basic) -> Floats | None:
        """Values at every point (nan where undefined or not real); None if float64 cannot tell."""
        try:
            with np.errstate(all="ignore"):
                return self._value(expr)
        except (_Unsupported, OverflowError, ValueError, TypeError, ZeroDivisionError):
            return None

    def _constant(self, value: float) -> Floats:
        return np.full(self._size, value)

    def _value(self, expr: sympy.Basic) -> Floats:
        cached = self._cache.get(expr)
        if cached is None:
            cached = self._evaluate(expr)
            self._cache[expr] = cached
        return cached

    def _evaluate(self, expr: sympy.Basic) -> Floats:
        if expr.is_Symbol:
            return self._columns[expr]
        if expr.is_Rational or expr.is_Float or expr is sympy.pi or expr is sympy.E:
            value = float(expr)  # OverflowError for a huge integer: unsupported
            if not math.isfinite(value):
                raise _Unsupported
            return self._constant(value)
        if expr.is_Add:
            total = self._value(expr.args[0])
            for arg in expr.args[1:]:
                total = total + self._value(arg)
            return total
        if expr.is_Mul:
            product = self._value(expr.args[0])
            for arg in expr.args[1:]:
                product = product * self._value(arg)
            return product
        if expr.is_Pow:
            base, exponent = expr.args
            if base is sympy.E:
                return np.exp(self._value(exponent))
            bases = self._value(base)
            if exponent.is_Integer:
                n = int(exponent)
                if abs(n) > 1024:
                    raise _Unsupported
                powered: Floats = np.power(bases, float(n))  # inf at 0 for n < 0: not finite
                return powered
            if exponent == sympy.S.Half:
                return np.sqrt(bases)
            return np.power(bases, self._value(exponent))  # nan for a negative base: not real
        unary = UNARY.get(type(expr))
        if unary is not None and len(expr.args) == 1:
            return unary(self._value(expr.args[0]))
        if isinstance(expr, sympy.atan2):
            return np.arctan2(self._value(expr.args[0]), self._value(expr.args[1]))
        if isinstance(expr, sympy.Min | sympy.Max):
            pick = np.minimum if isinstance(expr, sympy.Min) else np.maximum
            result = self._value(expr.args[0])
            for arg in expr.args[1:]:
                result = pick(result, self._value(arg))
            return result
        raise _Unsupported


def differs(answer: Floats, target: Floats, scale: float) -> npt.NDArray[np.bool_]:
    """Where both are finite and differ by more than DIFFER (relative, with `scale` as the floor)."""
    with np.errstate(all="ignore"):
        allowed = DIFFER * (np.maximum(np.abs(answer), np.abs(target)) + scale)
        result: npt.NDArray[np.bool_] = (
            np.isfinite(answer) & np.isfinite(target) & (np.abs(answer - target) > allowed)
        )
    return result


def agrees(answer: Floats, target: Floats, scale: float) -> bool:
    """Finite and equal within AGREE at every point."""
    # As in_range: Python floats, the same float64 operations in the same order as numpy would do them
    # (|a - b| <= AGREE * (max(|a|, |b|) + scale)), at a fraction of the cost for a few dozen points.
    for a, b in zip(answer.tolist(), target.tolist(), strict=True):
        if not (
            math.isfinite(a) and math.isfinite(b) and abs(a - b) <= AGREE * (max(abs(a), abs(b)) + scale)
        ):
            return False
    return True
