"""Evaluate a sympy tree at many points at once, in exact-binary multiprecision (mpmath's libmp).

Values are raw libmp tuples (picklable, and free of mpmath's global precision, so two threads cannot
disturb each other). A point where the expression is undefined, infinite or not real is `None`:
the grader skips or judges such points, it never guesses a value for them. This walks sympy's own tree
(built by the whitelist parser or by the engine); it never reads text.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import mpmath
import sympy
from mpmath import libmp

from physics.overflow import overflows, too_costly

Mpf = tuple[int, int, int, int]
Column = list[Mpf | None]

RND = libmp.round_nearest
ZERO: Mpf = libmp.fzero
ONE: Mpf = libmp.fone
_SPECIAL = (libmp.fnan, libmp.finf, libmp.fninf)
# A sum that cancels down to fewer than this many significant bits of its largest term is rounding
# noise: it is set to exact zero, so that `sin²θ + cos²θ - 1` is 0 and not 1e-40.
_CANCELLATION_KEEP_BITS = 24
# Orders libmp values exactly (floats would overflow to inf or underflow to 0 beyond 1e±308).
BY_VALUE = functools.cmp_to_key(libmp.mpf_cmp)
_FAILURES = (ValueError, ZeroDivisionError, OverflowError, ArithmeticError)

Unary = Callable[[Mpf, int], Mpf | None]


def from_int(value: int) -> Mpf:
    result: Mpf = libmp.from_int(value)
    return result


def from_rational(p: int, q: int, prec: int) -> Mpf:
    result: Mpf = libmp.from_rational(p, q, prec, RND)
    return result


def to_float(value: Mpf) -> float:
    result: float = libmp.to_float(value)
    return result


def magnitude_bits(value: Mpf) -> int:
    """log2 of |value|, rounded up (a very negative number for zero)."""
    if value == ZERO:
        return -(10**9)
    return int(value[2] + value[3])


def is_negative(value: Mpf) -> bool:
    return value != ZERO and value[0] == 1


def _finite(value: Mpf | None) -> Mpf | None:
    if value is None or value in _SPECIAL:
        return None
    return value


def _safe(fn: Callable[..., Any], *args: Any) -> Mpf | None:
    """fn(*args), or None where it fails (complex result, division by zero) or is not finite."""
    try:
        value: Mpf | None = fn(*args)
    except _FAILURES:
        return None
    return _finite(value)


# No function is evaluated at |x| beyond 2^64: exp(x) has no value worth comparing there, and mpmath
# would first compute ln 2 or pi to as many bits as x has (m^(m^(m^m)) made that run for minutes).
MAX_ARGUMENT_BITS = 64


def _exp(x: Mpf, prec: int) -> Mpf | None:
    if magnitude_bits(x) > MAX_ARGUMENT_BITS:
        return None
    return as_mpf(libmp.mpf_exp(x, prec, RND))


def as_mpf(value: Any) -> Mpf:
    """Types a libmp result (mpmath is untyped)."""
    result: Mpf = value
    return result


def _inverse_sqrt(x: Mpf, prec: int) -> Mpf | None:
    if x == ZERO or is_negative(x):
        return None
    return as_mpf(libmp.mpf_div(ONE, libmp.mpf_sqrt(x, prec + 10, RND), prec, RND))


def _sqrt(x: Mpf, prec: int) -> Mpf | None:
    return None if is_negative(x) else libmp.mpf_sqrt(x, prec, RND)


def _log(x: Mpf, prec: int) -> Mpf | None:
    return None if x == ZERO or is_negative(x) else libmp.mpf_log(x, prec, RND)


def _inverse(fn: Callable[[Mpf, int, str], Mpf]) -> Unary:
    def apply(x: Mpf, prec: int) -> Mpf | None:
        value = fn(x, prec + 10, RND)
        return None if value == ZERO else libmp.mpf_div(ONE, value, prec, RND)

    return apply


def _of_inverse(fn: Callable[[Mpf, int, str], Mpf]) -> Unary:
    def apply(x: Mpf, prec: int) -> Mpf | None:
        return None if x == ZERO else fn(libmp.mpf_div(ONE, x, prec + 10, RND), prec, RND)

    return apply


def _plain(fn: Callable[[Mpf, int, str], Mpf]) -> Unary:
    return lambda x, prec: fn(x, prec, RND)


def _acot(x: Mpf, prec: int) -> Mpf:
    # sympy's acot is continuous at 0 with acot(0) = pi/2 and values in (-pi/2, pi/2].
    if x == ZERO:
        return as_mpf(libmp.mpf_shift(libmp.mpf_pi(prec), -1))
    result: Mpf = libmp.mpf_atan(libmp.mpf_div(ONE, x, prec + 10, RND), prec, RND)
    return result


def _sign(x: Mpf, prec: int) -> Mpf:
    return from_int(libmp.mpf_sign(x))


UNARY: dict[type, Unary] = {
    sympy.sin: _plain(libmp.mpf_sin),
    sympy.cos: _plain(libmp.mpf_cos),
    sympy.tan: _plain(libmp.mpf_tan),
    sympy.cot: _inverse(libmp.mpf_tan),
    sympy.sec: _inverse(libmp.mpf_cos),
    sympy.csc: _inverse(libmp.mpf_sin),
    sympy.asin: _plain(libmp.mpf_asin),
    sympy.acos: _plain(libmp.mpf_acos),
    sympy.atan: _plain(libmp.mpf_atan),
    sympy.acot: _acot,
    sympy.asec: _of_inverse(libmp.mpf_acos),
    sympy.acsc: _of_inverse(libmp.mpf_asin),
    sympy.sinh: _plain(libmp.mpf_sinh),
    sympy.cosh: _plain(libmp.mpf_cosh),
    sympy.tanh: _plain(libmp.mpf_tanh),
    sympy.asinh: _plain(libmp.mpf_asinh),
    sympy.acosh: _plain(libmp.mpf_acosh),
    sympy.atanh: _plain(libmp.mpf_atanh),
    sympy.exp: _exp,
    sympy.log: _log,
    sympy.Abs: lambda x, prec: libmp.mpf_abs(x),
    sympy.sign: _sign,
    sympy.floor: lambda x, prec: libmp.mpf_floor(x),
    sympy.ceiling: lambda x, prec: libmp.mpf_ceil(x),
}


def _pow_point(base: Mpf, exponent: Mpf, prec: int) -> Mpf | None:
    if base == ZERO:
        return ZERO if exponent != ZERO and not is_negative(exponent) else None
    if is_negative(base):
        # sympy's principal power of a negative base is real only for integer exponents.
        if libmp.mpf_floor(exponent) != exponent:
            return None
        return as_mpf(libmp.mpf_pow_int(base, int(libmp.to_int(exponent)), prec, RND))
    logarithm = libmp.mpf_log(base, prec + 20, RND)
    return _exp(libmp.mpf_mul(exponent, logarithm, prec + 20, RND), prec)


class Evaluator:
    """Evaluates expressions over fixed columns of symbol values; caches shared subtrees."""

    def __init__(
        self,
        columns: Mapping[sympy.Symbol, Column],
        size: int,
        prec: int,
        known: Mapping[sympy.Basic, Column] | None = None,
    ) -> None:
        self.columns = columns
        self.size = size
        self.prec = prec
        # Subtrees already evaluated over the same columns at the same precision (e.g. the reference's,
        # which an answer often shares: sin(theta), M + m sin(theta)^2).
        self._cache: dict[sympy.Basic, Column] = dict(known or {})

    @property
    def known(self) -> Mapping[sympy.Basic, Column]:
        """Every subtree evaluated so far (to start another evaluator over the same columns from)."""
        return self._cache

    def constant(self, value: Mpf | None) -> Column:
        return [value] * self.size

    def __call__(self, expr: sympy.Basic) -> Column:
        cached = self._cache.get(expr)
        if cached is None:
            cached = self._evaluate(expr)
            self._cache[expr] = cached
        return cached

    def _evaluate(self, expr: sympy.Basic) -> Column:
        prec = self.prec
        if expr.is_Symbol:
            return list(self.columns[expr])
        if expr.is_Integer:
            return self.constant(from_int(int(expr)))
        if expr.is_Rational:
            return self.constant(from_rational(int(expr.p), int(expr.q), prec))
        if expr is sympy.pi:
            return self.constant(libmp.mpf_pi(prec))
        if expr is sympy.E:
            return self.constant(libmp.mpf_e(prec))
        if expr.is_Float:
            return self.constant(_finite(libmp.mpf_pos(expr._mpf_, prec, RND)))
        if expr.is_Add:
            return self.add([self(arg) for arg in expr.args])
        if expr.is_Mul:
            return self._product([self(arg) for arg in expr.args])
        if expr.is_Pow:
            return self._pow(expr)
        unary = UNARY.get(type(expr))
        if unary is not None and len(expr.args) == 1:
            return [
                None if x is None or magnitude_bits(x) > MAX_ARGUMENT_BITS else _safe(unary, x, prec)
                for x in self(expr.args[0])
            ]
        if isinstance(expr, sympy.atan2):
            ys, xs = self(expr.args[0]), self(expr.args[1])
            return [
                None
                if y is None or x is None or (y == ZERO and x == ZERO)
                else _safe(libmp.mpf_atan2, y, x, prec, RND)
                for y, x in zip(ys, xs, strict=True)
            ]
        if isinstance(expr, sympy.Min | sympy.Max):
            pick = min if isinstance(expr, sympy.Min) else max
            columns = [self(arg) for arg in expr.args]
            return [
                None if any(v is None for v in row) else pick(row, key=BY_VALUE)
                for row in zip(*columns, strict=True)
            ]
        if expr.is_number and (expr.is_extended_real is False or not expr.is_finite):
            return self.constant(None)  # I, zoo, oo, nan: never a real value
        return self._by_sympy(expr)

    def add(self, columns: Sequence[Column]) -> Column:
        """Columns summed point by point; a sum that cancels to rounding noise is exact zero."""
        out: Column = []
        for row in zip(*columns, strict=True):
            if any(v is None for v in row):
                out.append(None)
                continue
            terms: list[Mpf] = row  # type: ignore[assignment]
            total = _safe(libmp.mpf_sum, terms, self.prec, RND)
            if total is not None and total != ZERO:
                largest = max(magnitude_bits(t) for t in terms)
                if magnitude_bits(total) < largest - (self.prec - _CANCELLATION_KEEP_BITS):
                    total = ZERO
            out.append(total)
        return out

    def _product(self, columns: Sequence[Column]) -> Column:
        """Point by point, the factors multiplied left to right: None from the first undefined factor
        or failed step on, as `_safe` would make of it. One pass per point rather than one list per
        factor: at the few points of a check, a product has more factors than points."""
        prec = self.prec
        multiply = libmp.mpf_mul
        out: Column = []
        for row in zip(*columns, strict=True):
            product = row[0]
            for factor in row[1:]:
                if product is None or factor is None:
                    product = None
                    break
                try:
                    product = multiply(product, factor, prec, RND)
                except _FAILURES:
                    product = None
                    break
                if product in _SPECIAL:
                    product = None
                    break
            out.append(product)
        return out

    def _pow(self, expr: sympy.Basic) -> Column:
        base, exponent = expr.args
        prec = self.prec
        if base is sympy.E:
            exponents = self(exponent)
            return [None if x is None else _safe(_exp, x, prec) for x in exponents]
        bases = self(base)
        if exponent.is_Integer:
            n = int(exponent)
            return [
                None if b is None or (b == ZERO and n < 0) else _safe(libmp.mpf_pow_int, b, n, prec, RND)
                for b in bases
            ]
        if exponent == sympy.S.Half:
            return [None if b is None else _safe(_sqrt, b, prec) for b in bases]
        if exponent == -sympy.S.Half:
            return [None if b is None else _safe(_inverse_sqrt, b, prec) for b in bases]
        exponents = self(exponent)
        return [
            None if b is None or e is None else _safe(_pow_point, b, e, prec)
            for b, e in zip(bases, exponents, strict=True)
        ]

    def _by_sympy(self, expr: sympy.Basic) -> Column:
        """Slow path for functions this module does not know: sympy's own evalf at each point."""
        symbols = sorted(expr.free_symbols, key=lambda s: s.name)
        columns = [self.columns[s] for s in symbols]
        if too_costly(expr):
            return self.constant(None)
        dps = libmp.prec_to_dps(self.prec)
        out: Column = []
        for index in range(self.size):
            row = [column[index] for column in columns]
            present = [v for v in row if v is not None]
            if len(present) < len(row):
                out.append(None)
                continue
            if overflows(expr, dict(zip(symbols, present, strict=True))):
                out.append(None)
                continue
            subs = {s: sympy_float(v, self.prec) for s, v in zip(symbols, present, strict=True)}
            out.append(_real_mpf(expr, subs, dps, self.prec))
        return out


def sympy_float(value: Mpf, prec: int) -> sympy.Float:
    """The exact same binary number as a sympy Float (mpmath.mpf() would round it to 53 bits)."""
    return sympy.Float(mpmath.mp.make_mpf(value), precision=max(prec, value[3]))


def _real_mpf(expr: sympy.Basic, subs: Mapping[sympy.Symbol, Any], dps: int, prec: int) -> Mpf | None:
    try:
        value = expr.evalf(dps, subs=dict(subs))
    except (*_FAILURES, TypeError, AttributeError):
        return None
    if not value.is_Number:
        return None
    if value.is_Rational:
        return from_rational(int(value.p), int(value.q), prec)
    if value.is_Float:
        return _finite(libmp.mpf_pos(value._mpf_, prec, RND))
    return None


def evaluate_constant(expr: sympy.Basic, prec: int) -> Mpf | None:
    """The real value of an expression without symbols (a range bound such as pi/2), or None."""
    return Evaluator({}, 1, prec)(expr)[0]


def complex_value(expr: sympy.Basic, point: Mapping[sympy.Symbol, Mpf], prec: int) -> tuple[Mpf, Mpf] | None:
    """(real, imaginary) parts by sympy's evalf, for answers with complex intermediates; None if undefined."""
    symbols = expr.free_symbols
    if too_costly(expr) or overflows(expr, {s: v for s, v in point.items() if s in symbols}):
        return None
    dps = libmp.prec_to_dps(prec)
    subs = {s: sympy_float(v, prec) for s, v in point.items() if s in symbols}
    try:
        parts = expr.evalf(dps, subs=subs).as_real_imag()
    except (*_FAILURES, TypeError, AttributeError):
        return None
    out = []
    for part in parts:
        part = part.evalf(dps)
        if not part.is_Number or not part.is_finite:  # nan and zoo are Numbers without an _mpf_
            return None
        value = from_rational(int(part.p), int(part.q), prec) if part.is_Rational else _finite(part._mpf_)
        if value is None:
            return None
        out.append(value)
    return out[0], out[1]
