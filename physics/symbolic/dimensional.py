"""The physical dimension of a sympy expression, from its symbols' dimensions.

An inconsistent expression (adding a mass to an acceleration, sin of a length) raises
DimensionMismatch. That is not an AnswerError: an answer with it was read fine and is *graded*
wrong (reason `wrong_dimension`); on the reference side the caller turns it into a SpecError.

    PhyscheckError
     ├── DimensionMismatch   kind: "add" | "function" | "power" | "exponent"; the dimensions involved
     └── UnknownDimension    a symbol without a declared dimension (no dimension check is possible)
"""

from __future__ import annotations

from collections.abc import Mapping
from fractions import Fraction

import sympy

from physics.dimensions import DIMENSIONLESS, Dimension, describe
from physics.errors import PhyscheckError


class DimensionMismatch(PhyscheckError):
    """An expression that combines dimensions in a way physics does not allow."""

    def __init__(
        self, message: str, kind: str, dims: tuple[Dimension, ...], function: str | None = None
    ) -> None:
        super().__init__(message)
        self.message = message  # phrased to follow "your expression ", e.g. "adds a mass to a length"
        self.kind = kind
        self.dims = dims
        self.function = function


class UnknownDimension(PhyscheckError):
    def __init__(self, symbol: str) -> None:
        super().__init__(f"the symbol {symbol} has no declared dimension")
        self.symbol = symbol


# Functions whose result has the dimension of their (single) argument.
_KEEPS_DIMENSION = (sympy.Abs, sympy.floor, sympy.ceiling, sympy.re, sympy.im)


def named_dimension(expr: sympy.Expr, dimensions: Mapping[str, Dimension]) -> Dimension | None:
    """The dimension of `expr` from its symbols' names, or None where it has none (unlike quantities
    added, a symbol of unknown dimension): a reading's dimension, compared with the answer's."""
    known = {s: dimensions[s.name] for s in expr.free_symbols if s.name in dimensions}
    try:
        return expression_dimension(expr, known)
    except (DimensionMismatch, UnknownDimension):
        return None


def expression_dimension(expr: sympy.Basic, dims: Mapping[sympy.Symbol, Dimension]) -> Dimension:
    """The dimension of `expr`; raises DimensionMismatch or UnknownDimension."""
    if expr.is_Symbol:
        if expr not in dims:
            raise UnknownDimension(expr.name)
        return dims[expr]
    if expr.is_Atom:
        return DIMENSIONLESS  # numbers, pi, e, I (a closed-form constant is dimensionless by recursion)
    if expr.is_Add:
        return _sum_dimension(expr, dims)
    if expr.is_Mul:
        result = DIMENSIONLESS
        for factor in expr.args:
            result = result * expression_dimension(factor, dims)
        return result
    if expr.is_Pow:
        return _power_dimension(expr, dims)
    if isinstance(expr, _KEEPS_DIMENSION):
        return expression_dimension(expr.args[0], dims)
    if isinstance(expr, sympy.sign):
        expression_dimension(expr.args[0], dims)
        return DIMENSIONLESS
    if isinstance(expr, sympy.Min | sympy.Max | sympy.atan2):
        parts = [expression_dimension(arg, dims) for arg in expr.args]
        _same(parts, "compares" if not isinstance(expr, sympy.atan2) else "divides")
        return DIMENSIONLESS if isinstance(expr, sympy.atan2) else parts[0]
    # sin, exp, log and every other function need a pure-number argument.
    name = getattr(expr.func, "__name__", str(expr.func))
    for arg in expr.args:
        dim = expression_dimension(arg, dims)
        if not dim.is_dimensionless:
            raise DimensionMismatch(f"takes {name} of {describe(dim)}", "function", (dim,), name)
    return DIMENSIONLESS


def _same(parts: list[Dimension], verb: str) -> None:
    for dim in parts[1:]:
        if dim != parts[0]:
            message = f"{verb} {describe(dim)} and {describe(parts[0])}"
            raise DimensionMismatch(message, "add", (parts[0], dim))


def _sum_dimension(expr: sympy.Basic, dims: Mapping[sympy.Symbol, Dimension]) -> Dimension:
    # Report the first offending pair in the order the student most likely wrote it.
    terms = sorted(expr.args, key=lambda t: t.is_number)
    first = expression_dimension(terms[0], dims)
    for term in terms[1:]:
        dim = expression_dimension(term, dims)
        if dim != first:
            raise DimensionMismatch(f"adds {describe(dim)} to {describe(first)}", "add", (first, dim))
    return first


def _power_dimension(expr: sympy.Basic, dims: Mapping[sympy.Symbol, Dimension]) -> Dimension:
    base, exponent = expr.args
    exponent_dim = expression_dimension(exponent, dims)
    if not exponent_dim.is_dimensionless:
        raise DimensionMismatch(
            f"has an exponent with the dimension of {describe(exponent_dim)}", "exponent", (exponent_dim,)
        )
    base_dim = expression_dimension(base, dims)
    if base_dim.is_dimensionless:
        return DIMENSIONLESS
    if exponent.is_Rational:
        return base_dim ** Fraction(int(exponent.p), int(exponent.q))
    raise DimensionMismatch(
        f"raises {describe(base_dim)} to a power that is not a fixed number", "power", (base_dim,)
    )
