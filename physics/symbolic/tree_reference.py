"""A reference read from text, prepared from its parse tree: sympy builds it only when a check needs it.

Building a new reference's sympy tree is most of what preparing it costs (under names never seen, sympy
infers every new node's assumptions), yet a check mostly needs only its values: float64 at every sample
point, multiprecision at the precise points and at a point or two where a wrong answer is confirmed
wrong. The parse tree gives those as the answer's tree gives the answer's (physics.symbolic.quick), so a
reference is prepared from it when all of this holds, and else as before (`prepare_reference`):

- the tree has the shape quick.py admits, within which the builder refuses nothing (so the reference
  would have compiled) and sympy's tree is the same function;
- float64 vouches (physics.symbolic.bounded) that it is defined at every point of the domain's first
  batch and gives it there to within PRECISE_RELATIVE: sampling keeps every point of that batch (sympy's
  tree, the same function, is defined wherever this one certainly is), and the values in float64 are
  the ones sampling would have kept, to within PRECISE_RELATIVE;
- it varies over the points when it names a symbol (so sympy's tree has free symbols too: a reference
  that cancels to a constant, `m/m`, says so only once built);
- its dimension is consistent and every name's is declared (it is then sympy's tree's too).

Its multiprecision values come from the tree in quick.py's memory of subtrees at a reference's points,
which answers to it share; where the tree cannot give them (a value undefined or beyond 2^±100 on the
way) sympy builds the reference and evaluates it. Both give the values of the same function at the same
points to within far less than any tolerance: a verdict could differ only for an answer within
rounding of a tolerance, as in quick.py.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cached_property

import numpy as np
import sympy

from physics.dimensions import DIMENSIONLESS, Dimension
from physics.errors import AnswerError, SpecError
from physics.mathinput import InputLimits
from physics.mathinput.reader import build_tree, parse_tree
from physics.mathinput.tree import Call, Const, Group, Name, Neg, Node, Num, Power, Product, Sum
from physics.symbolic.bounded import Bounded, BoundedTree, Unsupported, constant_exponent
from physics.symbolic.compare import PREC, PRECISE_PREC
from physics.symbolic.domain import SymbolicContext
from physics.symbolic.floats import Floats
from physics.symbolic.numeric import Column
from physics.symbolic.quick import _PRECISE, EXTRA_BITS, _Declined, _Shape, _TreeValues
from physics.symbolic.reference import (
    PRECISE_POINTS,
    SAMPLE_SIZE,
    PreparedReference,
    _declared_dimensions,
    _reference_side,
    _typical_scale,
)
from physics.symbolic.sampling import (
    PRECISE_RELATIVE,
    _Batch,
    domain_seed,
    first_batch,
    whole_batch_sample,
)

# A reference that names a symbol varies over the sample by more than this (relatively): its float64
# values are within 2^-36 of the exact ones, so a wider spread is a real one.
_VARIES = 2.0**-30
_DIMENSIONS_KEPT = 1024  # subtrees' dimensions per domain


@dataclass(frozen=True)
class _TreeSource:
    """The reference's parse tree: its values at the reference's points, and sympy's tree on demand."""

    tree: Node
    names: Mapping[str, sympy.Symbol]  # what each name in the tree stands for
    symbols: Mapping[str, sympy.Symbol]  # the names the tree uses
    keys: Mapping[int, int]  # each node's structural key, by its id (quick._Shape's)
    context: SymbolicContext
    limits: InputLimits

    @property
    def has_symbols(self) -> bool:
        return bool(self.symbols)

    def build(self) -> sympy.Expr:
        return _reference_side(build_tree(self.tree, self.names, self.limits), self.context, ("expected",))

    def precise_values(self, reference: PreparedReference) -> Column | None:
        points = min(PRECISE_POINTS, reference.sample.size)
        grid = (reference.token, _PRECISE)  # quick.py's grid of the precise points, at its precision
        return self._values(reference.precise_columns, points, PRECISE_PREC + EXTRA_BITS, grid)

    def values_at(self, reference: PreparedReference, indexes: tuple[int, ...]) -> Column | None:
        columns = reference.sample.columns
        points = {symbol: [columns[symbol][i] for i in indexes] for symbol in self.symbols.values()}
        return self._values(points, len(indexes), PREC + EXTRA_BITS, (reference.token, indexes))

    def _values(
        self, columns: Mapping[sympy.Symbol, Column], size: int, prec: int, grid: tuple[object, object]
    ) -> Column | None:
        try:
            found = _TreeValues(columns, size, self.symbols, prec, self.keys, grid).value(self.tree)
        except (_Declined, ArithmeticError, ValueError):
            return None
        return list(found)


@dataclass(frozen=True)
class TreeDomain:
    """What the references over one set of declared symbols share, found once for the set."""

    names: Mapping[str, sympy.Symbol]  # what a reference or an answer may use
    context: SymbolicContext  # over those symbols, without constraints, mistakes or limiting cases
    dims: Mapping[sympy.Symbol, Dimension]
    # Subtrees' dimensions by their structural key (quick._Shape's), as the references' trees share them.
    dimensions: dict[int, Dimension] = field(default_factory=dict, compare=False)

    @cached_property
    def sample_batch(self) -> tuple[tuple[sympy.Symbol, ...], _Batch]:
        """The domain's symbols in the order of their names, and the first batch of its points (SpecError
        where its ranges hold none)."""
        seed = domain_seed(self.context, ())
        symbols = tuple(sorted(self.context.symbols, key=lambda s: s.name))
        return symbols, first_batch(self.context, SAMPLE_SIZE, seed, PREC)


def tree_domain(names: Mapping[str, sympy.Symbol], context: SymbolicContext) -> TreeDomain:
    return TreeDomain(names, context, _declared_dimensions(context))


def prepared_from_text(text: str, domain: TreeDomain, limits: InputLimits) -> PreparedReference | None:
    """The reference `text` over the domain prepared from its parse tree; None where the module's
    conditions do not all hold (then `prepare_reference` of its sympy tree prepares it, or says why it
    cannot)."""
    context, dims = domain.context, domain.dims
    if context.constraints or context.mistakes or context.limits:
        return None
    try:
        tree, names = parse_tree(text, domain.names, limits=limits)
        shape = _Shape(limits.max_exponent, names)
        shape.check(tree)
    except (AnswerError, _Declined, RecursionError):
        return None
    symbols = {name: names[name] for name in shape.names}
    keys = shape.keys
    try:
        dimension = _Dimensions(symbols, dims, keys, domain.dimensions)(tree)
    except _Declined:
        return None
    if context.expected_dimension is not None and dimension != context.expected_dimension:
        return None

    def values(columns: Mapping[sympy.Symbol, Floats], size: int, known: dict[int, Bounded]) -> Floats | None:
        try:
            found = BoundedTree(
                {name: columns[s] for name, s in symbols.items()}, size, _key_of(keys), known
            )(tree)
        except Unsupported:
            return None
        if not found.precise(PRECISE_RELATIVE).all():
            return None
        if symbols and np.ptp(found.values) <= _VARIES * np.max(np.abs(found.values)):
            return None
        return found.values

    try:
        symbols_in_order, batch = domain.sample_batch
    except SpecError:
        return None
    sample = whole_batch_sample(batch, symbols_in_order, SAMPLE_SIZE, values)
    if sample is None:
        return None
    return PreparedReference(
        built=None,
        context=context,
        sample=sample,
        scale=_typical_scale(sample),
        dimension=dimension,
        dims=dims,
        mistake_exprs=(),
        limit_cases=(),
        source=_TreeSource(tree, names, symbols, keys, context, limits),
    )


def _key_of(keys: Mapping[int, int]) -> Callable[[Node], int]:
    return lambda node: keys[id(node)]


class _Dimensions:
    """The tree's dimension where it is consistent and every name's is declared; else _Declined.
    Subtrees' dimensions are kept by their structure in `known` (one per domain: the same names)."""

    def __init__(
        self,
        symbols: Mapping[str, sympy.Symbol],
        dims: Mapping[sympy.Symbol, Dimension],
        keys: Mapping[int, int],
        known: dict[int, Dimension],
    ) -> None:
        self._symbols = symbols
        self._dims = dims
        self._keys = keys
        self._known = known

    def __call__(self, node: Node) -> Dimension:
        if isinstance(node, Name | Num | Const | Group):
            return self._dimension(node)
        key = self._keys[id(node)]
        found = self._known.get(key)
        if found is None:
            if len(self._known) >= _DIMENSIONS_KEPT:
                self._known.clear()
            found = self._known[key] = self._dimension(node)
        return found

    def _dimension(self, node: Node) -> Dimension:
        if isinstance(node, Name):
            found = self._dims.get(self._symbols[node.name])
            if found is None:
                raise _Declined
            return found
        if isinstance(node, Num | Const):
            return DIMENSIONLESS
        if isinstance(node, Group):
            return self(node.inner)
        if isinstance(node, Neg):
            return self(node.operand)
        if isinstance(node, Sum):
            first = self(node.first)
            if any(self(term) != first for _, term in node.rest):
                raise _Declined
            return first
        if isinstance(node, Product):
            result = self(node.first)
            for operator, factor in node.rest:
                other = self(factor)
                if not other.is_dimensionless:  # most factors are pure numbers: nothing to combine
                    result = result * other if operator == "*" else result / other
            return result
        if isinstance(node, Power):
            if isinstance(node.base, Const) and node.base.which == "e":
                return self._dimensionless(node.exponent)
            exponent = constant_exponent(node.exponent)
            if exponent is None:
                raise _Declined
            return self(node.base) ** exponent
        if isinstance(node, Call):
            if node.func == "abs":
                return self(node.arg)
            if node.func == "sqrt":
                return self(node.arg) ** Fraction(1, 2)
            return self._dimensionless(node.arg)
        raise _Declined

    def _dimensionless(self, node: Node) -> Dimension:
        if not self(node).is_dimensionless:
            raise _Declined
        return DIMENSIONLESS
