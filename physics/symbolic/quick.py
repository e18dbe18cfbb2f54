"""An answer judged on its parse tree, before sympy builds it, wherever the tree is enough.

The judge decides from values first (physics.symbolic.judge, `judged_in_floats`): float64 at every
sample point, multiprecision at the precise points to confirm a right answer, at a point or two to
confirm why a wrong one is wrong, and the answer's dimension. The parse tree gives all of that as well
as the sympy tree built from it, and building that tree costs about two-fifths of a check, judging it a
third. So the parse tree is evaluated first, and `judged` returns the judgement that way when:

- the builder could refuse nothing in the tree: few nodes; exact numbers of few bits in all, weighted
  by the powers they are raised to (so sympy makes no number the size checks refuse); every power's
  exponent a small constant whole or half number (or any exponent of e), the merged degree within the
  exponent limit; square roots not nested in one another and small function arguments (far inside
  the root-nesting and complex-parts budgets); no factorial, percent or degree sign;
- at the precise points, every intermediate value is real and finite and either exactly zero or of a
  magnitude within 2^±100. sympy's exact simplifications, which the tree does not make, can then turn
  no part into a division by zero, a log of zero or a constant that is not real: such a part is zero
  or out of a real function's domain exactly, and at 266 bits it shows as a value that is undefined
  or beyond those bounds (`1/sin(π)`: 1/1.2e-16 in float64, about 1/10^-80 there);
- the answer is not zero at both precise points (sympy may have built 0, whose dimension goes
  unasked), and where a wrong answer's dimension is asked, the tree's is consistent and every name's
  known (it is then the built tree's too; a clash is left to the full path, which names the terms in
  sympy's order); a wrong value's limit hints are asked only where the reference has no limiting case;
- `judged_in_floats` decides, as it would for sympy's tree.

Otherwise it returns None and the answer takes the full path: built, judged, diagnosed in
multiprecision where float64 cannot tell. Both paths apply the same rules to the same numbers,
computed on two trees that sympy's rewriting makes equal; they could differ only for an answer within
float64's rounding of a tolerance, where either verdict is defensible.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from fractions import Fraction

import numpy as np
import sympy
from mpmath import libmp

from physics.dimensions import DIMENSIONLESS, Dimension
from physics.mathinput.build import FUNCTIONS
from physics.mathinput.reader import TreeReading
from physics.mathinput.tree import Call, Const, Group, Name, Neg, Node, Num, Power, Product, Sum
from physics.symbolic import floats, numeric
from physics.symbolic.compare import PREC, PRECISE_PREC, PRECISE_TOLERANCE_BITS, close
from physics.symbolic.floats import Floats
from physics.symbolic.judge import dimension_difference, judged_in_floats
from physics.symbolic.numeric import (
    MAX_ARGUMENT_BITS,
    RND,
    ZERO,
    Column,
    Evaluator,
    Mpf,
    from_rational,
    is_negative,
    magnitude_bits,
)
from physics.symbolic.reference import PRECISE_POINTS, PreparedReference
from physics.verdict import Judgement

MAX_NODES = 120
# All exact numbers' bits, each times the powers it is raised to: what sympy can merge them into stays
# below the builder's smallest size check (256 bits).
MAX_NUMBER_BITS = 200
# The builder's complex-parts budget is 40; a tree this light is far inside it.
MAX_ARGUMENT_WEIGHT = 10
MAGNITUDE_BITS = 100
# The tree is evaluated this far above the judge's precisions (PREC, PRECISE_PREC): its sums may cancel
# terms as large as 2^MAGNITUDE_BITS that sympy cancelled exactly, and what is left must still be as
# exact as the judge's values of sympy's tree, down to a reference scale as small as 2^-MAGNITUDE_BITS.
EXTRA_BITS = 2 * MAGNITUDE_BITS
_NUMBER_SYMBOLS = {"pi": sympy.pi, "e": sympy.E}


class _Declined(Exception):
    """The tree is outside what this look decides: the full path decides."""


def judged(reading: TreeReading, reference: PreparedReference, max_exponent: int) -> Judgement | None:
    """The judgement the full path (build, judge) would give, where the parse tree is enough to find
    it; None where it is not (see the module). A right answer before the reference's precise values
    are computed takes the full path: there, an answer built equal to the reference is right at once,
    before they are (a new reference's first answer is often its own text). A wrong one never needs
    them, and a reference that meets only wrong answers never has them."""
    points = min(PRECISE_POINTS, reference.sample.size)
    if not reference.floats.usable or not points or abs(magnitude_bits(reference.scale)) > MAGNITUDE_BITS:
        return None
    try:
        shape = _Shape(max_exponent)
        shape.check(reading.tree)
        symbols = {name: reading.symbols[name] for name in shape.names}
        if not all(
            s in reference.floats.columns and s in reference.precise_columns for s in symbols.values()
        ):
            return None
        with np.errstate(all="ignore"):
            values = _FloatTree(reference, symbols).value(reading.tree)
        precise = _TreeValues(reference.precise_columns, points, symbols, PRECISE_PREC + EXTRA_BITS).value(
            reading.tree
        )
        if all(value == ZERO for value in precise):
            return None  # sympy may have built 0, whose dimension is not asked
        return judged_in_floats(
            values,
            reference,
            _TreeAtPoints(reading.tree, symbols, reference),
            lambda: _precisely_equal(precise, reference),
            lambda: dimension_difference(_dimension(reading.tree, symbols, reference), reference),
            lambda: _no_limits(reference),
        )
    except (_Declined, ArithmeticError, ValueError):
        return None


def _precisely_equal(precise: Sequence[Mpf], reference: PreparedReference) -> bool:
    """The tree's values equal the reference's at the precise points; _Declined while those are not
    computed yet (the full path may find the answer right without them)."""
    if "precise_values" not in reference.__dict__:
        raise _Declined
    return all(
        b is not None and close(a, b, reference.scale, PRECISE_TOLERANCE_BITS)
        for a, b in zip(precise, reference.precise_values, strict=True)
    )


def _no_limits(reference: PreparedReference) -> list[str]:
    """The limit hints of a wrong value, where there is no limiting case to fail (else: the full path)."""
    if reference.limit_cases:
        raise _Declined
    return []


def _dimension(node: Node, symbols: Mapping[str, sympy.Symbol], reference: PreparedReference) -> Dimension:
    """The tree's dimension where it is consistent and every name's is known, which is then the built
    tree's too (sympy's rewriting keeps a consistent dimension); else _Declined, and the full path
    says which terms clash, in the order sympy keeps them."""
    if isinstance(node, Name):
        found = reference.dims.get(symbols[node.name])
        if found is None:
            raise _Declined
        return found
    if isinstance(node, Num | Const):
        return DIMENSIONLESS
    if isinstance(node, Group):
        return _dimension(node.inner, symbols, reference)
    if isinstance(node, Neg):
        return _dimension(node.operand, symbols, reference)
    if isinstance(node, Sum):
        first = _dimension(node.first, symbols, reference)
        if any(_dimension(term, symbols, reference) != first for _, term in node.rest):
            raise _Declined
        return first
    if isinstance(node, Product):
        result = _dimension(node.first, symbols, reference)
        for operator, factor in node.rest:
            other = _dimension(factor, symbols, reference)
            result = result * other if operator == "*" else result * other**-1
        return result
    if isinstance(node, Power):
        if _is_e(node.base):
            return _dimensionless(node.exponent, symbols, reference)
        exponent = _exponent(node.exponent)
        assert exponent is not None  # admitted
        return _dimension(node.base, symbols, reference) ** exponent
    assert isinstance(node, Call)  # admitted
    if node.func == "abs":
        return _dimension(node.arg, symbols, reference)
    if node.func == "sqrt":
        return _dimension(node.arg, symbols, reference) ** Fraction(1, 2)
    return _dimensionless(node.arg, symbols, reference)


def _dimensionless(
    node: Node, symbols: Mapping[str, sympy.Symbol], reference: PreparedReference
) -> Dimension:
    if not _dimension(node, symbols, reference).is_dimensionless:
        raise _Declined
    return DIMENSIONLESS


class _TreeAtPoints:
    """The tree at PREC at sample points, as judge._AtPoints evaluates sympy's (each point once); None
    at a point where a value is undefined or beyond 2^±100 on the way, where the judge cannot tell."""

    def __init__(self, tree: Node, symbols: Mapping[str, sympy.Symbol], reference: PreparedReference) -> None:
        self._tree = tree
        self._symbols = symbols
        self._columns = reference.sample.columns
        self._values: dict[int, Mpf | None] = {}

    def __call__(self, indexes: tuple[int, ...]) -> Column:
        for index in indexes:
            if index not in self._values:
                point = {symbol: [self._columns[symbol][index]] for symbol in self._symbols.values()}
                try:
                    (self._values[index],) = _TreeValues(point, 1, self._symbols, PREC + EXTRA_BITS).value(
                        self._tree
                    )
                except (_Declined, ArithmeticError, ValueError):
                    self._values[index] = None
        return [self._values[index] for index in indexes]


def _exponent(node: Node) -> Fraction | None:
    """The exponent as an exact constant when it is one (`2`, `-1/2`, `(3/2)`), else None."""
    if isinstance(node, Num):
        return node.value
    if isinstance(node, Group):
        return _exponent(node.inner)
    if isinstance(node, Neg):
        inner = _exponent(node.operand)
        return None if inner is None else -inner
    if isinstance(node, Product):
        value = _exponent(node.first)
        for operator, factor in node.rest:
            other = _exponent(factor)
            if value is None or other is None or (operator == "/" and other == 0):
                return None
            value = value * other if operator == "*" else value / other
        return value
    return None


def _is_e(node: Node) -> bool:
    return isinstance(node, Const) and node.which == "e"


class _Shape:
    """The shape the builder could refuse nothing of (the module's first condition), in one walk that
    also collects the names the tree uses."""

    def __init__(self, max_exponent: int) -> None:
        self._max_exponent = max_exponent
        self._nodes = 0
        self._bits = 0
        self.names: set[str] = set()

    def check(self, tree: Node) -> None:
        if self._walk(tree, 1, False)[0] > self._max_exponent:
            raise _Declined

    def _argument(self, node: Node, times: int, in_root: bool) -> tuple[float, int]:
        """`_walk` of a function's argument or a root's base, whose degree must be within the exponent
        limit and whose weight within the budget (the builder weighs each)."""
        degree, weight = self._walk(node, times, in_root)
        if degree > self._max_exponent or weight > MAX_ARGUMENT_WEIGHT:
            raise _Declined
        return degree, weight

    def _walk(self, node: Node, times: int, in_root: bool) -> tuple[float, int]:
        """(degree, weight) of `node`, where `times` is the product of the powers enclosing it and
        `in_root` says it is under a square root.

        degree: a bound on every exponent sympy can merge out of it (x^60·x^50 is x^110);
        weight: a bound on the size of the real and imaginary parts sympy would write out for it (the
        builder's `_complex_weight`, which counts what is surely real as 1)."""
        self._nodes += 1
        if self._nodes > MAX_NODES:
            raise _Declined
        if isinstance(node, Name):
            self.names.add(node.name)
            return 1.0, 1
        if isinstance(node, Num):
            # The numbers under a power count as often as it multiplies them (2^100 is 100 bits).
            self._bits += (node.value.numerator.bit_length() + node.value.denominator.bit_length()) * times
            if self._bits > MAX_NUMBER_BITS:
                raise _Declined
            return 1.0, 1
        if isinstance(node, Const):
            return 1.0, 1
        if isinstance(node, Group):
            return self._walk(node.inner, times, in_root)
        if isinstance(node, Neg):
            return self._walk(node.operand, times, in_root)
        if isinstance(node, Sum | Product):
            degree, weight = self._walk(node.first, times, in_root)
            for _, child in node.rest:
                more, heavier = self._walk(child, times, in_root)
                degree = max(degree, more) if isinstance(node, Sum) else degree + more
                weight += heavier
            return degree, weight
        if isinstance(node, Call):
            if node.func not in FUNCTIONS and node.func != "sqrt":
                raise _Declined  # factorial
            root = node.func == "sqrt"
            if root and in_root:
                raise _Declined
            return 1.0, 1 + self._argument(node.arg, times, in_root or root)[1]
        if isinstance(node, Power):
            if _is_e(node.base):
                return 1.0, 2 + self._argument(node.exponent, times, in_root)[1]
            exponent = _exponent(node.exponent)
            if exponent is None or exponent.denominator > 2:
                raise _Declined
            self._nodes += 1  # the exponent, a constant bounded by the degree
            p, q = abs(exponent.numerator), exponent.denominator
            if q == 2:
                if in_root:
                    raise _Declined
                degree, weight = self._argument(node.base, times * -(-p // q), True)
                return degree * p / q, 2 + weight
            degree, weight = self._walk(node.base, times * max(1, p), in_root)
            return degree * p, weight * max(1, p)
        raise _Declined  # a postfix: factorial, percent, degrees


class _FloatTree:
    """The tree in float64 at every sample point (numpy), as the judge's first look evaluates sympy's."""

    def __init__(self, reference: PreparedReference, symbols: Mapping[str, sympy.Symbol]) -> None:
        self._columns = {name: reference.floats.columns[symbol] for name, symbol in symbols.items()}
        self._size = reference.sample.size

    def value(self, node: Node) -> Floats:
        if isinstance(node, Num):
            return np.full(self._size, float(node.value))
        if isinstance(node, Name):
            return self._columns[node.name]
        if isinstance(node, Const):
            return np.full(self._size, float(_NUMBER_SYMBOLS[node.which]))
        if isinstance(node, Group):
            return self.value(node.inner)
        if isinstance(node, Neg):
            return -self.value(node.operand)
        if isinstance(node, Sum):
            total = self.value(node.first)
            for sign, term in node.rest:
                total = total + self.value(term) if sign == "+" else total - self.value(term)
            return total
        if isinstance(node, Product):
            product = self.value(node.first)
            for operator, factor in node.rest:
                product = product * self.value(factor) if operator == "*" else product / self.value(factor)
            return product
        if isinstance(node, Power):
            if _is_e(node.base):
                return np.exp(self.value(node.exponent))
            exponent = _exponent(node.exponent)
            assert exponent is not None  # admitted
            powered: Floats = np.power(self.value(node.base), float(exponent))
            return powered
        assert isinstance(node, Call)  # admitted
        argument = self.value(node.arg)
        if node.func == "sqrt":
            return np.sqrt(argument)
        if node.func == "log10":
            return np.log10(argument)
        return floats.UNARY[_function(node.func)](argument)


class _TreeValues:
    """The tree at a few points at `prec`, as numeric.Evaluator computes sympy's; raises _Declined at an
    intermediate value that is undefined, or nonzero and beyond 2^±100 (the module's second condition)."""

    def __init__(
        self,
        columns: Mapping[sympy.Symbol, Column],
        size: int,
        symbols: Mapping[str, sympy.Symbol],
        prec: int,
    ) -> None:
        self._columns = {name: _checked(columns[symbol]) for name, symbol in symbols.items()}
        self._size = size
        self._prec = prec
        self._sums = Evaluator({}, self._size, prec)  # its sums: cancellation to exact zero

    def value(self, node: Node) -> list[Mpf]:
        while isinstance(node, Group):
            node = node.inner
        if isinstance(node, Name):
            return self._columns[node.name]
        return _checked(self._evaluate(node))

    def _constant(self, value: Mpf) -> list[Mpf]:
        return [value] * self._size

    def _evaluate(self, node: Node) -> Sequence[Mpf | None]:
        prec = self._prec
        if isinstance(node, Num):
            return self._constant(from_rational(node.value.numerator, node.value.denominator, prec))
        if isinstance(node, Const):
            return self._constant(libmp.mpf_pi(prec) if node.which == "pi" else libmp.mpf_e(prec))
        if isinstance(node, Neg):
            return [libmp.mpf_neg(v) for v in self.value(node.operand)]
        if isinstance(node, Sum):
            terms: list[Column] = [list(self.value(node.first))]
            for sign, term in node.rest:
                values = self.value(term)
                signed: Column = list(values) if sign == "+" else [libmp.mpf_neg(v) for v in values]
                terms.append(signed)
            return self._sums.add(terms)
        if isinstance(node, Product):
            product = self.value(node.first)
            for operator, factor in node.rest:
                values = self.value(factor)
                if operator == "*":
                    product = [libmp.mpf_mul(a, b, prec, RND) for a, b in zip(product, values, strict=True)]
                elif ZERO in values:
                    raise _Declined
                else:
                    product = [libmp.mpf_div(a, b, prec, RND) for a, b in zip(product, values, strict=True)]
            return product
        if isinstance(node, Power):
            if _is_e(node.base):
                return [_unary(sympy.exp, x, prec) for x in self.value(node.exponent)]
            exponent = _exponent(node.exponent)
            assert exponent is not None  # admitted
            return [_power(b, exponent, prec) for b in self.value(node.base)]
        assert isinstance(node, Call)  # admitted
        arguments = self.value(node.arg)
        if node.func == "sqrt":
            return [_power(x, Fraction(1, 2), prec) for x in arguments]
        if any(magnitude_bits(x) > MAX_ARGUMENT_BITS for x in arguments):
            raise _Declined  # as numeric.Evaluator, which gives no function of such an argument a value
        if node.func == "log10":
            ten = libmp.mpf_log(libmp.from_int(10), prec + 10, RND)
            return [
                None
                if x == ZERO or is_negative(x)
                else libmp.mpf_div(libmp.mpf_log(x, prec + 10, RND), ten, prec, RND)
                for x in arguments
            ]
        function = _function(node.func)
        return [_unary(function, x, prec) for x in arguments]


# (function, argument, precision) -> its value, for the latest answers. The sample points are the
# reference's, so an answer's sin θ or e^(-k t) is the one the previous answers to it had (a check
# found 20 distinct values among 4,000 function calls, a tenth of its CPU).
_UNARY_VALUES: dict[tuple[type, Mpf, int], Mpf | None] = {}
UNARY_VALUES_KEPT = 4096


def _unary(function: type, x: Mpf, prec: int) -> Mpf | None:
    key = (function, x, prec)
    try:
        return _UNARY_VALUES[key]
    except KeyError:
        pass
    value = numeric.UNARY[function](x, prec)
    if len(_UNARY_VALUES) >= UNARY_VALUES_KEPT:
        _UNARY_VALUES.clear()
    _UNARY_VALUES[key] = value
    return value


def _checked(values: Sequence[Mpf | None]) -> list[Mpf]:
    """The values, if each is defined and either zero or within 2^±MAGNITUDE_BITS; else _Declined."""
    checked = []
    for value in values:
        # value[2] + value[3]: the binary magnitude of a nonzero value (numeric.magnitude_bits).
        if value is None or (value != ZERO and abs(value[2] + value[3]) > MAGNITUDE_BITS):
            raise _Declined
        checked.append(value)
    return checked


def _power(base: Mpf, exponent: Fraction, prec: int) -> Mpf | None:
    """base^exponent for a whole or half exponent, real as sympy's principal power is (else None)."""
    if exponent.denominator == 2:
        if is_negative(base):
            return None  # the root of a negative number
        base = libmp.mpf_sqrt(base, prec + 10, RND)
    if base == ZERO and exponent.numerator < 0:
        return None
    result: Mpf = libmp.mpf_pow_int(base, exponent.numerator, prec, RND)
    return result


def _function(name: str) -> type:
    """The sympy function the builder makes of `name` (every admitted name but sqrt and log10 is one)."""
    made: Callable[[sympy.Expr], sympy.Expr] = FUNCTIONS[name]
    assert isinstance(made, type)
    return made
