"""Whether an expression's value at a point runs out of float64's range on the way, in complex128.

sympy's evalf computes `exp(exp(exp(exp(m))))` and `sin(10^10^5)` exactly as asked, with working
precision as large as the numbers (bits of e or π by the million): minutes, for no value worth
comparing. Where evalf stands in for our own evaluators (a complex intermediate, a function they do
not know), this look in complex floats first, a few microseconds, tells whether every intermediate stays
finite. It only ever vetoes: its values are never compared with anything.

evalf is also slow without any large number: it evaluates a complex intermediate again at a higher
precision for every level of functions and fractional powers above it, so its time grows about fourfold
per level and with the width of each level (`((-x)^(1/3))` seven deep took 1.5 s a point, `log10`
twelve deep ran to the time limit). `too_costly` weighs that nesting before evalf is called.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable, Mapping

import sympy
from mpmath import libmp

_UNARY: dict[type, Callable[[complex], complex]] = {
    sympy.sin: cmath.sin,
    sympy.cos: cmath.cos,
    sympy.tan: cmath.tan,
    sympy.cot: lambda z: 1 / cmath.tan(z),
    sympy.sec: lambda z: 1 / cmath.cos(z),
    sympy.csc: lambda z: 1 / cmath.sin(z),
    sympy.asin: cmath.asin,
    sympy.acos: cmath.acos,
    sympy.atan: cmath.atan,
    sympy.acot: lambda z: cmath.atan(1 / z),
    sympy.asec: lambda z: cmath.acos(1 / z),
    sympy.acsc: lambda z: cmath.asin(1 / z),
    sympy.sinh: cmath.sinh,
    sympy.cosh: cmath.cosh,
    sympy.tanh: cmath.tanh,
    sympy.asinh: cmath.asinh,
    sympy.acosh: cmath.acosh,
    sympy.atanh: cmath.atanh,
    sympy.exp: cmath.exp,
    sympy.log: cmath.log,
    sympy.Abs: lambda z: complex(abs(z)),
}


# Each level of functions or fractional powers multiplies the weight of what it holds by _LEVEL_COST;
# at _EVALF_BUDGET evalf takes about 5 ms a point. The complex answers people write weigh under 40
# (sqrt(cos(2θ)), (e^{iθ} - e^{-iθ})/(2i), sqrt(-a) sqrt(-b)).
_LEVEL_COST = 4
_EVALF_BUDGET = 500


def too_costly(expr: sympy.Basic) -> bool:
    """True when evalf's nested re-evaluations of `expr` would cost more than _EVALF_BUDGET."""
    return _weight(expr) > _EVALF_BUDGET


def _weight(expr: sympy.Basic) -> int:
    total = 0
    for arg in expr.args:
        total += _weight(arg)
        if total > _EVALF_BUDGET:
            break  # already too costly: the rest of the tree need not be walked
    if expr.is_Function or (expr.is_Pow and not expr.exp.is_Integer):
        return _LEVEL_COST * total
    return max(total, 1)


class _Unknown(Exception):
    """A node this look cannot follow (an unevaluated function, a factorial of a complex number): it
    vetoes nothing."""


class _Overflow(Exception):
    pass


def overflows(expr: sympy.Basic, point: Mapping[sympy.Symbol, tuple[int, int, int, int]]) -> bool:
    """True when some intermediate of `expr` at `point` (libmp values) is not a finite complex128 (an
    overflow, a division by zero, a log of zero): evalf would compute with numbers of unbounded size
    there, or find no value. False when every intermediate is finite, or when a node or a point value
    is one this look cannot stand in for (it then leaves the decision to evalf, under the check's time
    limit)."""
    try:
        _value(expr, {symbol: _float(value) for symbol, value in point.items()})
    except _Unknown:
        return False
    except (_Overflow, OverflowError, ZeroDivisionError, ValueError):
        return True
    return False


def _float(value: tuple[int, int, int, int]) -> float:
    """The point value in float64; beyond its range (inf, or a nonzero value that underflows to 0) the
    look would veto what evalf computes well, so it stands aside."""
    result = float(libmp.to_float(value))
    if not math.isfinite(result) or (result == 0 and value != libmp.fzero):
        raise _Unknown
    return result


def beyond_float(constant: sympy.Basic) -> bool:
    """True when some intermediate of `constant` overflows float64 (sec(sinh(10^40)^2), exp(2^4000));
    not when it divides by zero or leaves a function's domain, which a look in floats cannot tell from
    rounding. sympy's own questions about such a constant (is it real? finite?) evaluate it with π to
    as many bits as its magnitude has."""
    try:
        _value(constant, {})
    except (_Overflow, OverflowError):
        return True
    except (_Unknown, ZeroDivisionError, ValueError):
        return False
    return False


def _finite(z: complex) -> complex:
    if not (math.isfinite(z.real) and math.isfinite(z.imag)):
        raise _Overflow
    return z


def _factorial(z: complex) -> complex:
    """Γ(z + 1) of a real z: factorial(factorial(factorial(x))) is far past float64 (math.gamma raises
    OverflowError), and evalf would compute it with π and ln √(2π) to as many bits as its value has."""
    if z.imag != 0:
        raise _Unknown
    return _finite(complex(math.gamma(z.real + 1)))  # ValueError at a pole (a negative integer)


def _value(expr: sympy.Basic, point: Mapping[sympy.Symbol, float]) -> complex:
    if expr.is_Symbol:
        if expr not in point:
            raise _Unknown
        return complex(point[expr])
    if expr.is_Number or expr is sympy.pi or expr is sympy.E:
        if not expr.is_finite or expr.is_extended_real is False:
            raise _Unknown  # zoo, nan: evalf finds no value either, quickly
        return _finite(complex(float(expr)))
    if expr is sympy.I:
        return 1j
    args = [_value(arg, point) for arg in expr.args]
    if expr.is_Add:
        return _finite(sum(args, 0j))
    if expr.is_Mul:
        product = 1 + 0j
        for factor in args:
            product = _finite(product * factor)
        return product
    if expr.is_Pow:
        base, exponent = args
        if base == 0:
            if exponent.real <= 0:
                raise ZeroDivisionError
            return 0j
        return _finite(cmath.exp(exponent * cmath.log(base)))
    if isinstance(expr, sympy.factorial):
        return _factorial(args[0])
    unary = _UNARY.get(type(expr))
    if unary is None or len(args) != 1:
        raise _Unknown
    return _finite(unary(args[0]))
