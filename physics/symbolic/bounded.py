"""float64 values with a bound on their distance from the multiprecision ones, to vouch for points cheaply.

Preparing a reference needs to know where the 133-bit evaluator (physics.symbolic.numeric) finds it
defined, and its values there. float64 can vouch for a point when every step's result is finite and
clear of its function's edge by more than the step's error bound (a square root's argument certainly
positive, a divisor certainly nonzero, an arcsine's argument certainly inside [-1, 1]): the
multiprecision evaluation, far more accurate, then takes the same branches and is defined too, and
differs from the float64 value by less than the bound. Anywhere else (a sum that cancels, a value near
an edge, an unknown function) the point is not vouched for, and multiprecision decides there.

A point not vouched for has an infinite error bound. Every value carries an absolute error of at least
_TINY, so a value that underflowed (or is zero) is never taken as certainly nonzero. The bounds are first
order with interval derivatives (a function's steepest slope over the argument's error interval), which
holds to well within the factor of two kept at every edge while errors are small; an argument whose
error is not small (_SMALL) is never vouched for.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import numpy.typing as npt
import sympy

from physics.mathinput.build import FUNCTIONS
from physics.mathinput.tree import Call, Const, Group, Name, Neg, Node, Num, Power, Product, Sum
from physics.symbolic.floats import Floats

Mask = npt.NDArray[np.bool_]

_U = 2.0**-53  # float64's unit roundoff
# The absolute error every value carries: far above float64's subnormals, far below any sampled value.
_TINY = 1e-290
# The multiprecision evaluator refuses function arguments beyond 2^64 (numeric.MAX_ARGUMENT_BITS).
_HUGE_ARGUMENT = 2.0**62
_MAX_POWER = 1024
# Relative errors beyond this are not small: first-order bounds no longer hold.
_SMALL = 2.0**-20
_INF = math.inf


@dataclass(frozen=True)
class Bounded:
    """Values and error bounds; an infinite (or nan) bound where float64 does not vouch."""

    values: Floats
    errors: Floats

    @property
    def vouched(self) -> Mask:
        result: Mask = np.isfinite(self.errors) & np.isfinite(self.values)
        return result

    def precise(self, relative: float) -> Mask:
        """Vouched for, and within `relative` of the multiprecision value."""
        result: Mask = np.isfinite(self.values) & (self.errors <= relative * np.abs(self.values))
        return result


class Unsupported(Exception):
    """An expression float64 cannot stand in for anywhere: multiprecision decides alone."""


def _unless(ok: Mask, errors: Floats) -> Floats:
    """The error bounds, made infinite where `ok` does not hold."""
    result: Floats = np.where(ok, errors, _INF)
    return result


def _inside(low: float, high: float) -> Callable[[Floats, Floats], Mask]:
    return lambda a, e: (a - 2 * e > low) & (a + 2 * e < high)


def _one(a: Floats, e: Floats) -> Floats:
    return np.ones_like(a)


def _away_from_zero(function: Callable[[Floats], Floats]) -> Callable[[Floats, Floats], Mask]:
    """Where `function` of the argument is certainly nonzero (the poles of tan, cot, sec and csc)."""
    return lambda a, e: np.abs(function(a)) > 2 * e + 8 * _U


def _gap(function: Callable[[Floats], Floats]) -> Callable[[Floats, Floats], Floats]:
    """1 / (|function| - error)^2: the steepest slope of tan, cot, sec and csc near their poles."""
    return lambda a, e: 1 / (np.abs(function(a)) - e - 8 * _U) ** 2


def _edge_slope(a: Floats, e: Floats) -> Floats:
    """1 / sqrt(1 - x^2) at the end of the interval nearest ±1 (arcsine, arccosine)."""
    return 1 / np.sqrt(1 - (np.abs(a) + e) ** 2)


# sympy function: (numpy function, where the argument is certainly inside its domain, the steepest
# slope over the argument's error interval, given the argument and its error bound).
_Rule = tuple[
    Callable[[Floats], Floats], Callable[[Floats, Floats], Mask] | None, Callable[[Floats, Floats], Floats]
]
_RULES: dict[type, _Rule] = {
    sympy.sin: (np.sin, None, _one),
    sympy.cos: (np.cos, None, _one),
    sympy.tan: (np.tan, _away_from_zero(np.cos), _gap(np.cos)),
    sympy.cot: (lambda x: 1 / np.tan(x), _away_from_zero(np.sin), _gap(np.sin)),
    sympy.sec: (lambda x: 1 / np.cos(x), _away_from_zero(np.cos), _gap(np.cos)),
    sympy.csc: (lambda x: 1 / np.sin(x), _away_from_zero(np.sin), _gap(np.sin)),
    sympy.asin: (np.arcsin, _inside(-1, 1), _edge_slope),
    sympy.acos: (np.arccos, _inside(-1, 1), _edge_slope),
    sympy.atan: (np.arctan, None, _one),
    sympy.sinh: (np.sinh, None, lambda a, e: np.cosh(np.abs(a) + e)),
    sympy.cosh: (np.cosh, None, lambda a, e: np.cosh(np.abs(a) + e)),
    sympy.tanh: (np.tanh, None, _one),
    sympy.asinh: (np.arcsinh, None, _one),
    sympy.acosh: (np.arccosh, _inside(1, _INF), lambda a, e: 1 / np.sqrt((a - e) ** 2 - 1)),
    sympy.atanh: (np.arctanh, _inside(-1, 1), lambda a, e: 1 / (1 - (np.abs(a) + e) ** 2)),
    sympy.exp: (np.exp, None, lambda a, e: np.exp(a + e)),
    sympy.log: (np.log, _inside(0, _INF), lambda a, e: 1 / (a - e)),
    sympy.Abs: (np.abs, None, _one),
}


class BoundedEvaluator:
    """Evaluates expressions over float64 columns with error bounds; caches shared subtrees."""

    def __init__(
        self,
        columns: Mapping[sympy.Symbol, Floats],
        size: int,
        cache: dict[sympy.Basic, Bounded] | None = None,
    ) -> None:
        self._columns = columns
        self._size = size
        # Filled as subtrees are evaluated: pass one to share it between evaluators of the same columns.
        self._cache: dict[sympy.Basic, Bounded] = {} if cache is None else cache

    def __call__(self, expr: sympy.Basic) -> Bounded:
        """Raises Unsupported for an expression float64 cannot evaluate at all."""
        with np.errstate(all="ignore"):
            return self._value(expr)

    def _value(self, expr: sympy.Basic) -> Bounded:
        cached = self._cache.get(expr)
        if cached is None:
            cached = self._evaluate(expr)
            self._cache[expr] = cached
        return cached

    def _evaluate(self, expr: sympy.Basic) -> Bounded:
        if expr.is_Symbol:
            values = self._columns[expr]  # within an ulp of the multiprecision column's value
            return Bounded(values, 2 * _U * np.abs(values) + _TINY)
        if expr.is_Rational or expr.is_Float or expr is sympy.pi or expr is sympy.E:
            try:
                value = float(expr)
            except OverflowError:
                raise Unsupported from None
            if not math.isfinite(value):
                raise Unsupported
            return Bounded(np.full(self._size, value), np.full(self._size, _U * abs(value) + _TINY))
        if expr.is_Add:
            return _add([self._value(arg) for arg in expr.args])
        if expr.is_Mul:
            product = self._value(expr.args[0])
            for arg in expr.args[1:]:
                product = _multiply(product, self._value(arg))
            return product
        if expr.is_Pow:
            return self._pow(expr)
        rule = _RULES.get(type(expr))
        if rule is not None and len(expr.args) == 1:
            return _apply(rule, self._value(expr.args[0]))
        if isinstance(expr, sympy.Min | sympy.Max):
            pick = np.minimum if isinstance(expr, sympy.Min) else np.maximum
            args = [self._value(arg) for arg in expr.args]
            values, errors = args[0].values, args[0].errors
            for arg in args[1:]:
                values = pick(values, arg.values)
                errors = np.maximum(errors, arg.errors)  # nan (not vouched) propagates
            return Bounded(values, errors)
        raise Unsupported  # atan2, sign, floor, unknown functions, I, oo: multiprecision decides

    def _pow(self, expr: sympy.Basic) -> Bounded:
        base, exponent = expr.args
        if base is sympy.E:
            return _apply(_RULES[sympy.exp], self._value(exponent))
        b = self._value(base)
        if exponent.is_Integer:
            n = int(exponent)
            if abs(n) > _MAX_POWER:
                raise Unsupported
            return _integer_power(b, n)
        if exponent == sympy.S.Half or exponent == -sympy.S.Half:
            return _root(b, inverse=exponent == -sympy.S.Half)
        return _real_power(b, self._value(exponent))


def _add(terms: list[Bounded]) -> Bounded:
    values = terms[0].values
    magnitudes = np.abs(values)
    errors = terms[0].errors
    for term in terms[1:]:
        values = values + term.values
        magnitudes = magnitudes + np.abs(term.values)
        errors = errors + term.errors
    # Summation rounds each partial sum: at most n units of roundoff of the sum of magnitudes.
    return Bounded(values, errors + len(terms) * _U * magnitudes)


def _multiply(a: Bounded, b: Bounded) -> Bounded:
    values = a.values * b.values
    errors = np.abs(a.values) * b.errors + np.abs(b.values) * a.errors + a.errors * b.errors
    return Bounded(values, errors + _U * np.abs(values) + _TINY)


def _apply(rule: _Rule, arg: Bounded) -> Bounded:
    """A function's error: its steepest slope over the argument's error interval times that error."""
    function, domain, slope = rule
    a, e = arg.values, arg.errors
    values = function(a)
    errors = slope(a, e) * e + 4 * _U * np.abs(values) + _TINY
    ok = (e <= _SMALL * np.maximum(np.abs(a), 1.0)) & (np.abs(a) < _HUGE_ARGUMENT)
    if domain is not None:
        ok &= domain(a, e)
    return Bounded(values, _unless(ok, errors))


def _relative(arg: Bounded) -> Floats:
    """The relative error, where it is small (else infinite)."""
    relative: Floats = arg.errors / np.abs(arg.values)
    return _unless(relative <= _SMALL, relative)


def _integer_power(base: Bounded, n: int) -> Bounded:
    values: Floats = np.power(base.values, float(n))
    # (1 - r)^-|n| - 1 bounds the relative error of b^n for either sign of n.
    grown = np.expm1(-abs(n) * np.log1p(-_relative(base)))
    return Bounded(values, (grown + 4 * _U) * np.abs(values) + _TINY)


def _root(base: Bounded, inverse: bool) -> Bounded:
    """sqrt(b) or 1/sqrt(b), for a certainly positive b."""
    values: Floats = 1 / np.sqrt(base.values) if inverse else np.sqrt(base.values)
    # sqrt halves a small relative error and 1/sqrt at most doubles half of it: r bounds both.
    relative = _relative(base)  # infinite unless small, so b is certainly positive where finite
    return Bounded(values, (relative + 4 * _U) * np.abs(values) + _TINY)


def _real_power(base: Bounded, exponent: Bounded) -> Bounded:
    """b^x = exp(x ln b), for a certainly positive b."""
    values: Floats = np.power(base.values, exponent.values)
    log_error = -np.log1p(-_relative(base))  # the error of ln b
    log_base = np.abs(np.log(base.values))
    spread = np.abs(exponent.values) * log_error + exponent.errors * (log_base + log_error)
    errors = (np.expm1(spread) + 8 * _U) * np.abs(values) + _TINY
    return Bounded(values, _unless(spread <= _SMALL, errors))


class BoundedTree:
    """`BoundedEvaluator` over a parse tree (physics.mathinput.tree) instead of sympy's: a reference
    read from text is vouched for at the sample points before sympy builds it (tree_reference.py).
    The same rules, step by step as the text is written; a subtraction is the sum of a negation, a
    division the product of a reciprocal (its error bound that of b^-1)."""

    def __init__(
        self,
        columns: Mapping[str, Floats],
        size: int,
        key: Callable[[Node], int],
        known: dict[int, Bounded],
    ) -> None:
        self._columns = columns  # by the name in the tree
        self._size = size
        # Subtrees by their structure (`key`, equal for equal subtrees over the same symbols), filled as
        # they are evaluated: pass one per set of columns to share it (a new reference over a known
        # domain is mostly made of subtrees an earlier one had).
        self._key = key
        self._known = known

    def __call__(self, node: Node) -> Bounded:
        """Raises Unsupported for a node float64 does not stand in for here (log10, a postfix, an
        exponent that is not a whole or half number)."""
        with np.errstate(all="ignore"):
            return self._value(node)

    def _constant(self, value: float) -> Bounded:
        if not math.isfinite(value):
            raise Unsupported
        return Bounded(np.full(self._size, value), np.full(self._size, _U * abs(value) + _TINY))

    def _value(self, node: Node) -> Bounded:
        if isinstance(node, Name | Num | Const | Group):
            return self._evaluate(node)
        key = self._key(node)
        found = self._known.get(key)
        if found is None:
            found = self._known[key] = self._evaluate(node)
        return found

    def _evaluate(self, node: Node) -> Bounded:
        if isinstance(node, Name):
            values = self._columns[node.name]
            return Bounded(values, 2 * _U * np.abs(values) + _TINY)
        if isinstance(node, Num):
            try:
                return self._constant(float(node.value))
            except OverflowError:
                raise Unsupported from None
        if isinstance(node, Const):
            return self._constant(math.pi if node.which == "pi" else math.e)
        if isinstance(node, Group):
            return self._value(node.inner)
        if isinstance(node, Neg):
            inner = self._value(node.operand)
            return Bounded(-inner.values, inner.errors)
        if isinstance(node, Sum):
            terms = [self._value(node.first)]
            for sign, term in node.rest:
                found = self._value(term)
                terms.append(found if sign == "+" else Bounded(-found.values, found.errors))
            return _add(terms)
        if isinstance(node, Product):
            product = self._value(node.first)
            for operator, factor in node.rest:
                found = self._value(factor)
                product = _multiply(product, found if operator == "*" else _integer_power(found, -1))
            return product
        if isinstance(node, Power):
            return self._power(node)
        if isinstance(node, Call):
            argument = self._value(node.arg)
            if node.func == "sqrt":
                return _root(argument, inverse=False)
            rule = _RULES.get(_TREE_FUNCTIONS.get(node.func, type(None)))
            if rule is None:
                raise Unsupported
            return _apply(rule, argument)
        raise Unsupported  # a postfix

    def _power(self, node: Power) -> Bounded:
        if isinstance(node.base, Const) and node.base.which == "e":
            return _apply(_RULES[sympy.exp], self._value(node.exponent))
        exponent = constant_exponent(node.exponent)
        if exponent is None or exponent.denominator > 2 or abs(exponent.numerator) > _MAX_POWER:
            raise Unsupported
        base = self._value(node.base)
        if exponent.denominator == 2:
            base = _root(base, inverse=False)
        return _integer_power(base, exponent.numerator)


# The functions of the tree (by their canonical names) that _RULES knows.
_TREE_FUNCTIONS: dict[str, type] = {
    name: made for name, made in FUNCTIONS.items() if isinstance(made, type) and made in _RULES
}


def constant_exponent(node: Node) -> Fraction | None:
    """An exponent as an exact constant (`2`, `-1/2`, `(3/2)`), else None."""
    if isinstance(node, Num):
        return node.value
    if isinstance(node, Group):
        return constant_exponent(node.inner)
    if isinstance(node, Neg):
        inner = constant_exponent(node.operand)
        return None if inner is None else -inner
    if isinstance(node, Product):
        value = constant_exponent(node.first)
        for operator, factor in node.rest:
            other = constant_exponent(factor)
            if value is None or other is None or (operator == "/" and other == 0):
                return None
            value = value * other if operator == "*" else value / other
        return value
    return None
