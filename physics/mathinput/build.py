"""Building the sympy expression from the parse tree through constructors, with size checks first.

Every power of exact numbers is sized (bits ~ |exponent| * log2|base|) before sympy computes it, integer
exponents on anything else are capped, and every exact number that comes out is measured, so `9^9^9`,
`(x+2)^10000` and `factorial(10^9)` are refused in microseconds instead of running for minutes.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import cast

import sympy

from physics.errors import ParseError, TooLarge
from physics.mathinput.exact import exact_number
from physics.mathinput.limits import InputLimits
from physics.mathinput.tree import Call, Const, Group, Name, Neg, Node, Num, Power, Product, Sum

# sympy factors the number under a numeric root (seconds for a 2000-bit fraction; a q-th root of a
# fraction first raises its denominator to the power q-1) and merges roots in products, so all numeric
# roots of one answer share this budget of radicand bits times root degree.
_ROOT_BITS_BUDGET = 512
# Exact numbers above this size each cost sympy real work (trig of pi/big, logs, gcds); an answer may
# build distinct ones only up to twice max_int_bits in total.
_BIG_NUMBER_BITS = 256

_FUNCTIONS: dict[str, Callable[[sympy.Expr], sympy.Expr]] = {
    "exp": sympy.exp,
    "log": sympy.log,
    "log10": lambda x: sympy.log(x, 10),
    "abs": sympy.Abs,
    "sin": sympy.sin,
    "cos": sympy.cos,
    "tan": sympy.tan,
    "sec": sympy.sec,
    "csc": sympy.csc,
    "cot": sympy.cot,
    "asin": sympy.asin,
    "acos": sympy.acos,
    "atan": sympy.atan,
    "asec": sympy.asec,
    "acsc": sympy.acsc,
    "acot": sympy.acot,
    "sinh": sympy.sinh,
    "cosh": sympy.cosh,
    "tanh": sympy.tanh,
    "asinh": sympy.asinh,
    "acosh": sympy.acosh,
    "atanh": sympy.atanh,
}


class Builder:
    def __init__(self, symbols: Mapping[str, sympy.Symbol], limits: InputLimits) -> None:
        self._symbols = symbols
        self._limits = limits
        self._position = 0  # of the operator being built, for size errors
        self._root_bits = 0
        self._big_numbers: set[sympy.Rational] = set()
        self._big_bits = 0

    def build(self, node: Node) -> sympy.Expr:
        return self._checked(self._build(node))

    def _too_large(self, message: str) -> TooLarge:
        return TooLarge(message, self._position)

    def _build(self, node: Node) -> sympy.Expr:
        if isinstance(node, Group):
            return self._build(node.inner)
        if isinstance(node, Num):
            return cast(sympy.Expr, exact_number(node.value.numerator, node.value.denominator))
        if isinstance(node, Name):
            return cast(sympy.Expr, self._symbols[node.name])
        if isinstance(node, Const):
            return cast(sympy.Expr, sympy.pi if node.which == "pi" else sympy.E)
        if isinstance(node, Neg):
            return self._checked(-self._build(node.operand))
        if isinstance(node, Sum):
            terms = [self._build(node.first)]
            for sign, term in node.rest:
                value = self._build(term)
                terms.append(value if sign == "+" else -value)
            return self._checked(sympy.Add(*terms))
        if isinstance(node, Product):
            result = self._build(node.first)
            for operator, factor in node.rest:
                value = self._build(factor)
                if operator == "/":
                    value = _reciprocal(value)
                result = self._checked(sympy.Mul(result, value))
            return result
        if isinstance(node, Power):
            base, exponent = self._build(node.base), self._build(node.exponent)
            self._position = node.pos
            return self._power(base, exponent)
        if isinstance(node, Call):
            arg = self._build(node.arg)
            self._position = node.pos
            if node.func == "factorial":
                return self._factorial(arg)
            if node.func == "sqrt":
                return self._power(arg, sympy.Rational(1, 2))
            return self._real(self._checked(_FUNCTIONS[node.func](arg)), node.func)
        operand = self._build(node.operand)
        self._position = node.pos
        if node.kind == "factorial":
            return self._factorial(operand)
        if node.kind == "percent":
            return self._checked(operand * sympy.Rational(1, 100))
        return self._checked(operand * sympy.pi / 180)

    def _power(self, base: sympy.Expr, exponent: sympy.Expr) -> sympy.Expr:
        limits = self._limits
        if exponent.is_Rational:
            p, q = int(exponent.p), int(exponent.q)
            if base.is_Rational:
                if base == 10 and q == 1 and abs(p) > limits.max_sci_exponent:
                    raise self._too_large(
                        f"A power of ten is too large (at most 10^{limits.max_sci_exponent})."
                    )
                size = max(abs(int(base.p)), int(base.q))
                if base != 0 and size > 1:
                    if q > limits.max_exponent:
                        raise self._too_large("A root of a number is too deep to compute exactly.")
                    if q > 1:
                        self._root_bits += (int(base.p).bit_length() + int(base.q).bit_length()) * q
                        if self._root_bits > _ROOT_BITS_BUDGET:
                            raise self._too_large("The numbers under roots in the answer are too large.")
                    budget = limits.max_int_bits * q  # the first test keeps a huge p out of float()
                    if abs(p) > budget or abs(p) * math.log2(size) > budget:
                        raise self._too_large("A power of numbers in the answer is too large to compute.")
            elif base is not sympy.E and (abs(p) > limits.max_exponent * q or q > limits.max_exponent):
                raise self._too_large(f"An exponent is too large (at most {limits.max_exponent}).")
        return self._real(self._checked(sympy.Pow(base, exponent)), "power")

    def _real(self, expr: sympy.Expr, what: str) -> sympy.Expr:
        """Refuse a constant with no real value (acos(2), sqrt(-1)): nothing physical is imaginary, and
        sympy's automatic simplification of powers of such constants can run for minutes."""
        # zoo and nan (1/0, log(0)) are refused elsewhere, as having no value at all.
        if expr.is_number and expr.is_finite is not False and expr.is_extended_real is False:
            message = (
                "This power has no real value; check its base and exponent."
                if what == "power"
                else f"{what}(…) has no real value here; check its argument."
            )
            raise ParseError(message, self._position)
        return expr

    def _factorial(self, arg: sympy.Expr) -> sympy.Expr:
        if arg.is_Rational and abs(arg) > self._limits.max_factorial:
            raise self._too_large(f"A factorial is too large (at most {self._limits.max_factorial}!).")
        return self._checked(sympy.factorial(arg))

    def _checked(self, expr: sympy.Expr) -> sympy.Expr:
        """Refuse an exact number that grew too large, or a power that sympy merged past the cap."""
        for part in (expr, *expr.args):
            if part.is_Rational:
                bits = max(abs(int(part.p)), int(part.q)).bit_length()
                if bits > self._limits.max_int_bits:
                    raise self._too_large("A number in the answer is too large to compute exactly.")
                if bits > _BIG_NUMBER_BITS and part not in self._big_numbers:
                    self._big_numbers.add(part)
                    self._big_bits += bits
                    if self._big_bits > 2 * self._limits.max_int_bits:
                        raise self._too_large("The answer computes with too many large numbers.")
            elif part.is_Pow and part.exp.is_Rational and not part.base.is_Rational:
                exp = part.exp
                if abs(int(exp.p)) > self._limits.max_exponent * int(exp.q):
                    raise self._too_large(f"An exponent is too large (at most {self._limits.max_exponent}).")
        return expr


def _reciprocal(value: sympy.Expr) -> sympy.Expr:
    """1/value. A nonzero exact number is inverted directly: the object `Pow(value, -1)` would return,
    without the sign queries that sympy's Pow makes of it first (over a tenth of a millisecond for each
    number not met before, such as the 7 of `x/7`)."""
    if value.is_Rational and value.p != 0:
        return cast(sympy.Expr, exact_number(int(value.q), int(value.p)))
    return cast(sympy.Expr, sympy.Pow(value, -1))
