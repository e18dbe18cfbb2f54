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

import contextlib
import itertools
from collections.abc import Callable, Mapping, Sequence
from fractions import Fraction
from typing import Any

import numpy as np
import sympy
from mpmath import libmp

from physics.dimensions import DIMENSIONLESS, Dimension
from physics.mathinput.build import FUNCTIONS
from physics.mathinput.reader import TreeReading
from physics.mathinput.tree import Call, Const, Group, Name, Neg, Node, Num, Power, Product, Sum
from physics.symbolic import floats, numeric
from physics.symbolic.bounded import constant_exponent
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
# Grids of the subtree memory, beside tuples of sample indexes (and what is kept of a subtree there).
_FLOATS, _PRECISE, _DIMENSIONS = "float64", "precise", "dimensions"


class _Declined(Exception):
    """The tree is outside what this look decides: the full path decides."""


def judged(reading: TreeReading, reference: PreparedReference, max_exponent: int) -> Judgement | None:
    """The judgement the full path (build, judge) would give, where the parse tree is enough to find
    it; None where it is not (see the module). A right answer computes the reference's precise values
    if no answer did before (one evaluation of the reference at two points: less than building the
    answer to compare it with the reference); a wrong one never needs them, and a reference that meets
    only wrong answers never has them."""
    points = min(PRECISE_POINTS, reference.sample.size)
    if not reference.floats.usable or not points or abs(magnitude_bits(reference.scale)) > MAGNITUDE_BITS:
        return None
    try:
        shape = _Shape(max_exponent, reading.symbols)
        shape.check(reading.tree)
        symbols = {name: reading.symbols[name] for name in shape.names}
        if not all(
            s in reference.floats.columns and s in reference.precise_columns for s in symbols.values()
        ):
            return None
        keys = shape.keys
        with np.errstate(all="ignore"):
            values = _FloatTree(reference, symbols, keys).value(reading.tree)
        precise = _TreeValues(
            reference.precise_columns,
            points,
            symbols,
            PRECISE_PREC + EXTRA_BITS,
            keys,
            (reference.token, _PRECISE),
        ).value(reading.tree)
        if all(value == ZERO for value in precise):
            return None  # sympy may have built 0, whose dimension is not asked
        return judged_in_floats(
            values,
            reference,
            _TreeAtPoints(reading.tree, symbols, reference, keys),
            lambda: _precisely_equal(precise, reference),
            lambda: dimension_difference(_Dimensions(symbols, reference, keys).of(reading.tree), reference),
            lambda: _no_limits(reference),
        )
    except (_Declined, ArithmeticError, ValueError):
        return None


def _precisely_equal(precise: Sequence[Mpf], reference: PreparedReference) -> bool:
    """The tree's values equal the reference's at the precise points."""
    return all(
        b is not None and close(a, b, reference.scale, PRECISE_TOLERANCE_BITS)
        for a, b in zip(precise, reference.precise_values, strict=True)
    )


def _no_limits(reference: PreparedReference) -> list[str]:
    """The limit hints of a wrong value, where there is no limiting case to fail (else: the full path)."""
    if reference.limit_cases:
        raise _Declined
    return []


class _Dimensions:
    """The tree's dimension where it is consistent and every name's is known, which is then the built
    tree's too (sympy's rewriting keeps a consistent dimension); else _Declined, and the full path
    says which terms clash, in the order sympy keeps them. A subtree's dimension depends only on its
    structure and the reference's dimensions: kept with the subtrees' values (wrong answers to a
    reference share most of their subtrees)."""

    def __init__(
        self, symbols: Mapping[str, sympy.Symbol], reference: PreparedReference, keys: Mapping[int, int]
    ) -> None:
        self._symbols = symbols
        self._dims = reference.dims
        self._keys = keys
        self._grid = (reference.token, _DIMENSIONS)

    def of(self, node: Node) -> Dimension:
        kind = type(node)
        if kind is Name:
            found = self._dims.get(self._symbols[node.name])  # type: ignore[union-attr]
            if found is None:
                raise _Declined
            return found
        if kind is Num or kind is Const:
            return DIMENSIONLESS
        key = (*self._grid, self._keys[id(node)])
        known = _recalled(key)
        if known is None:
            known = _remember(key, self._composite(node))
        return known  # type: ignore[no-any-return]

    def _composite(self, node: Node) -> Dimension:
        if isinstance(node, Group):
            return self.of(node.inner)
        if isinstance(node, Neg):
            return self.of(node.operand)
        if isinstance(node, Sum):
            first = self.of(node.first)
            if any(self.of(term) != first for _, term in node.rest):
                raise _Declined
            return first
        if isinstance(node, Product):
            result = self.of(node.first)
            for operator, factor in node.rest:
                other = self.of(factor)
                result = result * other if operator == "*" else result * other**-1
            return result
        if isinstance(node, Power):
            if _is_e(node.base):
                return self._dimensionless(node.exponent)
            exponent = constant_exponent(node.exponent)
            assert exponent is not None  # admitted
            return self.of(node.base) ** exponent
        assert isinstance(node, Call)  # admitted
        if node.func == "abs":
            return self.of(node.arg)
        if node.func == "sqrt":
            return self.of(node.arg) ** Fraction(1, 2)
        return self._dimensionless(node.arg)

    def _dimensionless(self, node: Node) -> Dimension:
        if not self.of(node).is_dimensionless:
            raise _Declined
        return DIMENSIONLESS


class _TreeAtPoints:
    """The tree at PREC at sample points, as judge._AtPoints evaluates sympy's (each point once); None
    at a point where a value is undefined or beyond 2^±100 on the way, where the judge cannot tell."""

    def __init__(
        self,
        tree: Node,
        symbols: Mapping[str, sympy.Symbol],
        reference: PreparedReference,
        keys: Mapping[int, int],
    ) -> None:
        self._tree = tree
        self._symbols = symbols
        self._columns = reference.sample.columns
        self._token = reference.token
        self._keys = keys
        self._values: dict[int, Mpf | None] = {}

    def __call__(self, indexes: tuple[int, ...]) -> Column:
        missing = [index for index in dict.fromkeys(indexes) if index not in self._values]
        if len(missing) > 1:
            # The points in one walk; where a point declines, each point alone (as if never batched).
            with contextlib.suppress(_Declined, ArithmeticError, ValueError):
                self._values.update(zip(missing, self._at(missing), strict=True))
        for index in missing:
            if index not in self._values:
                try:
                    (self._values[index],) = self._at([index])
                except (_Declined, ArithmeticError, ValueError):
                    self._values[index] = None
        return [self._values[index] for index in indexes]

    def _at(self, indexes: list[int]) -> list[Mpf]:
        columns = self._columns
        points = {symbol: [columns[symbol][i] for i in indexes] for symbol in self._symbols.values()}
        grid = (self._token, tuple(indexes))
        return _TreeValues(points, len(indexes), self._symbols, PREC + EXTRA_BITS, self._keys, grid).value(
            self._tree
        )


def _is_e(node: Node) -> bool:
    return isinstance(node, Const) and node.which == "e"


class _Shape:
    """The shape the builder could refuse nothing of (the module's first condition), in one walk that
    also collects the names the tree uses and gives each node its structural key (`keys`: by the node's
    id, a number equal for equal subtrees over the same symbols)."""

    def __init__(self, max_exponent: int, symbols: Mapping[str, sympy.Symbol]) -> None:
        self._max_exponent = max_exponent
        self._symbols = symbols
        self._nodes = 0
        self._bits = 0
        self.names: set[str] = set()
        self.keys: dict[int, int] = {}

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
        `in_root` says it is under a square root; its key is kept.

        degree: a bound on every exponent sympy can merge out of it (x^60·x^50 is x^110);
        weight: a bound on the size of the real and imaginary parts sympy would write out for it (the
        builder's `_complex_weight`, which counts what is surely real as 1)."""
        self._nodes += 1
        if self._nodes > MAX_NODES:
            raise _Declined
        # By the type, the commonest first: a chain of isinstance tests per node was a tenth of a look.
        kind = type(node)
        keys = self.keys
        structure: tuple[object, ...]
        found: tuple[float, int]
        if kind is Name:
            self.names.add(node.name)  # type: ignore[union-attr]
            structure, found = ("n", self._symbols[node.name]), _LEAF  # type: ignore[union-attr]
        elif kind is Sum or kind is Product:
            summed = kind is Sum
            degree, weight = self._walk(node.first, times, in_root)  # type: ignore[union-attr]
            parts: list[object] = [kind, keys[id(node.first)]]  # type: ignore[union-attr]
            for operator, child in node.rest:  # type: ignore[union-attr]
                more, heavier = self._walk(child, times, in_root)
                degree = max(degree, more) if summed else degree + more
                weight += heavier
                parts += (operator, keys[id(child)])
            structure, found = tuple(parts), (degree, weight)
        elif kind is Num:
            value: Fraction = node.value  # type: ignore[union-attr]
            # The numbers under a power count as often as it multiplies them (2^100 is 100 bits).
            self._bits += (value.numerator.bit_length() + value.denominator.bit_length()) * times
            if self._bits > MAX_NUMBER_BITS:
                raise _Declined
            # Numerator and denominator, not the Fraction: its hash is computed in Python, theirs is not.
            structure, found = ("#", value.numerator, value.denominator), _LEAF
        elif kind is Group:
            found = self._walk(node.inner, times, in_root)  # type: ignore[union-attr]
            keys[id(node)] = keys[id(node.inner)]  # type: ignore[union-attr]
            return found
        elif kind is Neg:
            found = self._walk(node.operand, times, in_root)  # type: ignore[union-attr]
            structure = ("-", keys[id(node.operand)])  # type: ignore[union-attr]
        elif kind is Power:
            found, structure = self._power(node, times, in_root)  # type: ignore[arg-type]
        elif kind is Call:
            if node.func not in FUNCTIONS and node.func != "sqrt":  # type: ignore[union-attr]
                raise _Declined  # factorial
            root = node.func == "sqrt"  # type: ignore[union-attr]
            if root and in_root:
                raise _Declined
            weight = self._argument(node.arg, times, in_root or root)[1]  # type: ignore[union-attr]
            structure, found = ("f", node.func, keys[id(node.arg)]), (1.0, 1 + weight)  # type: ignore[union-attr]
        elif kind is Const:
            structure, found = ("c", node.which), _LEAF  # type: ignore[union-attr]
        else:
            raise _Declined  # a postfix: factorial, percent, degrees
        number = _STRUCTURES.get(structure)
        if number is None:
            if len(_STRUCTURES) >= STRUCTURES_KEPT:
                _STRUCTURES.clear()
            number = _STRUCTURES[structure] = next(_numbers)
        keys[id(node)] = number
        return found

    def _power(self, node: Power, times: int, in_root: bool) -> tuple[tuple[float, int], tuple[object, ...]]:
        keys = self.keys
        if _is_e(node.base):
            weight = self._argument(node.exponent, times, in_root)[1]
            return (1.0, 2 + weight), ("e", keys[id(node.exponent)])
        exponent = constant_exponent(node.exponent)
        if exponent is None or exponent.denominator > 2:
            raise _Declined
        self._nodes += 1  # the exponent, a constant bounded by the degree
        p, q = abs(exponent.numerator), exponent.denominator
        if q == 2:
            if in_root:
                raise _Declined
            degree, weight = self._argument(node.base, times * -(-p // q), True)
            found = (degree * p / q, 2 + weight)
        else:
            degree, weight = self._walk(node.base, times * max(1, p), in_root)
            found = (degree * p, weight * max(1, p))
        # The exponent by its value: it is all the evaluation reads of it.
        return found, ("^", keys[id(node.base)], exponent.numerator, exponent.denominator)


_LEAF = (1.0, 1)  # a name's, a number's or a constant's degree and weight


# Subtrees' values at a reference's points, by (reference, grid, subtree): many answers to a reference
# share subtrees (`sin θ`, `M + m sin^2 θ`, a whole answer times a factor), and a subtree's values depend
# only on its structure, the points and the precision, so a value found here is the very one a new
# evaluation would compute. Bounded: when full, the half used longest ago is forgotten (clearing it all
# made every reference's shared subtrees, its costliest, be computed again).
_SUBTREES: dict[tuple[object, object, int], Any] = {}
SUBTREES_KEPT = 16384
# Structural keys of subtrees, interned as numbers that are never given out again (so a memory entry
# of a forgotten structure can never be met by another).
_STRUCTURES: dict[tuple[object, ...], int] = {}
STRUCTURES_KEPT = 65536
_numbers = itertools.count()


def _recalled(key: tuple[object, object, int]) -> Any:
    """The values kept for `key` (None if none), now the most recently used."""
    found = _SUBTREES.pop(key, None)
    if found is not None:
        _SUBTREES[key] = found  # to the end: a dict keeps its keys in the order they were set
    return found


def _remember(key: tuple[object, object, int], values: Any) -> Any:
    if len(_SUBTREES) >= SUBTREES_KEPT:
        for oldest in list(itertools.islice(_SUBTREES, max(1, SUBTREES_KEPT // 2))):
            del _SUBTREES[oldest]
    _SUBTREES[key] = values
    return values


class _FloatTree:
    """The tree in float64 at every sample point (numpy), as the judge's first look evaluates sympy's."""

    def __init__(
        self, reference: PreparedReference, symbols: Mapping[str, sympy.Symbol], keys: Mapping[int, int]
    ) -> None:
        self._columns = {name: reference.floats.columns[symbol] for name, symbol in symbols.items()}
        self._size = reference.sample.size
        self._keys = keys
        self._grid = (reference.token, _FLOATS)

    def value(self, node: Node) -> Floats:
        # One rule per node type, found by the type (an answer has dozens of nodes; a chain of
        # isinstance tests per node was a tenth of a check).
        kind = type(node)
        if kind is Name:
            return self._columns[node.name]  # type: ignore[union-attr]
        # A number's values too are kept: the same few numbers recur in every answer.
        key = (*self._grid, self._keys[id(node)])
        found = _recalled(key)
        if found is None:
            found = _remember(key, _FLOAT_RULES[kind](self, node))
        return found  # type: ignore[no-any-return]

    def _num(self, node: Num) -> Floats:
        return np.full(self._size, float(node.value))

    def _const(self, node: Const) -> Floats:
        return np.full(self._size, float(_NUMBER_SYMBOLS[node.which]))

    def _group(self, node: Group) -> Floats:
        return self.value(node.inner)

    def _neg(self, node: Neg) -> Floats:
        return -self.value(node.operand)

    def _sum(self, node: Sum) -> Floats:
        total = self.value(node.first)
        for sign, term in node.rest:
            total = total + self.value(term) if sign == "+" else total - self.value(term)
        return total

    def _product(self, node: Product) -> Floats:
        product = self.value(node.first)
        for operator, factor in node.rest:
            product = product * self.value(factor) if operator == "*" else product / self.value(factor)
        return product

    def _power(self, node: Power) -> Floats:
        if _is_e(node.base):
            return np.exp(self.value(node.exponent))
        exponent = constant_exponent(node.exponent)
        assert exponent is not None  # admitted
        powered: Floats = np.power(self.value(node.base), float(exponent))
        return powered

    def _call(self, node: Call) -> Floats:
        argument = self.value(node.arg)
        if node.func == "sqrt":
            return np.sqrt(argument)
        if node.func == "log10":
            return np.log10(argument)
        return floats.UNARY[_function(node.func)](argument)


_FLOAT_RULES: dict[type, Callable[[_FloatTree, Any], Floats]] = {
    Num: _FloatTree._num,
    Const: _FloatTree._const,
    Group: _FloatTree._group,
    Neg: _FloatTree._neg,
    Sum: _FloatTree._sum,
    Product: _FloatTree._product,
    Power: _FloatTree._power,
    Call: _FloatTree._call,
}


class _TreeValues:
    """The tree at a few points at `prec`, as numeric.Evaluator computes sympy's; raises _Declined at an
    intermediate value that is undefined, or nonzero and beyond 2^±100 (the module's second condition).
    Every step is point by point, so a point's values are the same whichever points it is evaluated with."""

    def __init__(
        self,
        columns: Mapping[sympy.Symbol, Column],
        size: int,
        symbols: Mapping[str, sympy.Symbol],
        prec: int,
        keys: Mapping[int, int],
        grid: tuple[object, object],
    ) -> None:
        self._columns = {name: _checked(columns[symbol]) for name, symbol in symbols.items()}
        self._size = size
        self._prec = prec
        self._sums = Evaluator({}, self._size, prec)  # its sums: cancellation to exact zero
        self._keys = keys
        self._grid = grid  # (reference token, the points): with prec, what the values depend on

    def value(self, node: Node) -> list[Mpf]:
        kind = type(node)
        while kind is Group:
            node = node.inner  # type: ignore[union-attr]
            kind = type(node)
        if kind is Name:
            return self._columns[node.name]  # type: ignore[union-attr]
        if kind is Num or kind is Const:
            # Made anew: kept like a subtree's, a number's values made this walk measure 2.5 times slower
            # (mpmath normalizing the sums over them), for a reason not found.
            return _checked(_VALUE_RULES[kind](self, node))
        key = (*self._grid, self._keys[id(node)])
        found = _recalled(key)
        if found is None:
            found = _remember(key, _checked(_VALUE_RULES[kind](self, node)))
        return found  # type: ignore[no-any-return]

    def _constant(self, value: Mpf) -> list[Mpf]:
        return [value] * self._size

    def _num(self, node: Num) -> Sequence[Mpf | None]:
        return self._constant(from_rational(node.value.numerator, node.value.denominator, self._prec))

    def _const(self, node: Const) -> Sequence[Mpf | None]:
        prec = self._prec
        return self._constant(libmp.mpf_pi(prec) if node.which == "pi" else libmp.mpf_e(prec))

    def _neg(self, node: Neg) -> Sequence[Mpf | None]:
        return [libmp.mpf_neg(v) for v in self.value(node.operand)]

    def _sum(self, node: Sum) -> Sequence[Mpf | None]:
        terms: list[Column] = [list(self.value(node.first))]
        for sign, term in node.rest:
            values = self.value(term)
            signed: Column = list(values) if sign == "+" else [libmp.mpf_neg(v) for v in values]
            terms.append(signed)
        return self._sums.add(terms)

    def _product(self, node: Product) -> Sequence[Mpf | None]:
        prec = self._prec
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

    def _power(self, node: Power) -> Sequence[Mpf | None]:
        prec = self._prec
        if _is_e(node.base):
            return [_unary(sympy.exp, x, prec) for x in self.value(node.exponent)]
        exponent = constant_exponent(node.exponent)
        assert exponent is not None  # admitted
        return [_power(b, exponent, prec) for b in self.value(node.base)]

    def _call(self, node: Call) -> Sequence[Mpf | None]:
        prec = self._prec
        arguments = self.value(node.arg)
        if node.func == "sqrt":
            return [_power(x, _HALF, prec) for x in arguments]
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


_HALF = Fraction(1, 2)
_VALUE_RULES: dict[type, Callable[[_TreeValues, Any], Sequence[Mpf | None]]] = {
    Num: _TreeValues._num,
    Const: _TreeValues._const,
    Neg: _TreeValues._neg,
    Sum: _TreeValues._sum,
    Product: _TreeValues._product,
    Power: _TreeValues._power,
    Call: _TreeValues._call,
}


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
    for value in values:
        # value[2] + value[3]: the binary magnitude of a nonzero value (numeric.magnitude_bits).
        if value is None or (value != ZERO and abs(value[2] + value[3]) > MAGNITUDE_BITS):
            raise _Declined
    return list(values)  # type: ignore[arg-type]


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
