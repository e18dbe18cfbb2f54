"""Everything about a reference answer that does not depend on the student: prepared once, cached.

The sample points, the reference's values there (and at two points with twice the precision), the
known mistakes' values, the limiting cases, and the dimension the answer must have. Values float64
gives exactly enough (physics.symbolic.bounded) are not computed in multiprecision until a check
needs them: most checks are decided from float64 and a few multiprecision points.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from decimal import Decimal
from fractions import Fraction
from functools import cached_property
from typing import Any, Protocol

import numpy as np
import sympy
from mpmath import libmp

from physics.dimensions import Dimension, describe
from physics.errors import SpecError
from physics.symbolic.compare import PREC, PRECISE_PREC, typical_scale
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension
from physics.symbolic.domain import LimitCase, SymbolicContext
from physics.symbolic.floats import FloatEvaluator, Floats, FloatSample, float_sample, in_range, rounded
from physics.symbolic.limits import PreparedLimit, prepare_limit
from physics.symbolic.numeric import ONE, Column, Evaluator, Mpf
from physics.symbolic.sampling import DomainSample, domain_seed, sample_domain

SAMPLE_SIZE = 24
PRECISE_POINTS = 2
# Grids whose reference-side subtrees a prepared reference keeps (`point_evaluator`, `float_evaluator`):
# the first met (the check points, float64, the usual suspect points); few, as a worker holds many
# references.
_MAX_GRIDS = 8
_FLOATS = "float64"  # the grid of `float_evaluator`: every sample point in float64


class _Grids:
    """A reference's subtrees evaluated on each grid (a tuple of sample indexes, or _FLOATS), kept from
    a grid's second use on: a reference met once evaluates nothing ahead of its answer."""

    def __init__(self) -> None:
        self._known: dict[object, dict[Any, Any] | None] = {}

    def known(self, grid: object) -> dict[Any, Any] | None:
        """The subtrees kept for this grid (to fill and start from); None at its first use."""
        kept = self._known
        if grid not in kept:
            if len(kept) < _MAX_GRIDS:
                kept[grid] = None
            return None
        found = kept[grid]
        if found is None:
            found = kept[grid] = {}
        return found


@dataclass(frozen=True)
class PreparedMistake:
    expr: sympy.Expr
    feedback: str
    values: Column


class ReferenceSource(Protocol):
    """A reference sympy has not built yet, valued from its parse tree (physics.symbolic.tree_reference):
    built only when a check needs sympy's tree."""

    @property
    def has_symbols(self) -> bool: ...

    def build(self) -> sympy.Expr:
        """sympy's tree of the reference, as compiling it would have read it."""
        ...

    def precise_values(self, reference: PreparedReference) -> Column | None:
        """`precise_values` from the tree; None where the tree cannot give them."""
        ...

    def values_at(self, reference: PreparedReference, indexes: tuple[int, ...]) -> Column | None:
        """`values_at` from the tree; None where the tree cannot give them."""
        ...


@dataclass(frozen=True)
class PreparedReference:
    built: sympy.Expr | None  # the reference as sympy's tree; None until `expected` builds it (`source`)
    context: SymbolicContext
    sample: DomainSample
    scale: Mpf  # typical |reference|: the absolute floor of comparisons
    dimension: Dimension | None  # what the answer must have; None when unknown
    dims: Mapping[sympy.Symbol, Dimension]  # the symbols whose dimension is declared
    mistake_exprs: tuple[tuple[sympy.Expr, str], ...]  # (expression, feedback), over the context's symbols
    limit_cases: tuple[LimitCase, ...]
    source: ReferenceSource | None = field(default=None, compare=False)

    @cached_property
    def expected(self) -> sympy.Expr:
        """The reference as sympy's tree (built on first use for a reference read from its parse tree)."""
        if self.built is not None:
            return self.built
        assert self.source is not None
        return self.source.build()

    @cached_property
    def has_symbols(self) -> bool:
        """Whether the reference depends on a symbol (between plain numbers every ratio is constant)."""
        if self.source is not None:
            return self.source.has_symbols
        return bool(self.expected.free_symbols)

    @cached_property
    def values(self) -> Column:
        """The reference at every sample point (all defined), in multiprecision: computed on first use
        unless sampling had to compute them."""
        known = self.sample.required[0]
        if known is not None:
            return known
        return Evaluator(self.sample.columns, self.sample.size, PREC)(self.expected)

    def values_at(self, indexes: tuple[int, ...]) -> Column:
        """The reference at a few sample points, in multiprecision (the same numbers as `values`)."""
        if "values" in self.__dict__ or self.sample.required[0] is not None:
            return [self.values[i] for i in indexes]
        known = self._point_values
        missing = tuple(i for i in indexes if i not in known)
        if missing:
            found = None if self.source is None else self.source.values_at(self, missing)
            if found is None:
                columns = {s: [self.sample.columns[s][i] for i in missing] for s in self.sample.symbols}
                found = Evaluator(columns, len(missing), PREC)(self.expected)
            known.update(zip(missing, found, strict=True))
        return [known[i] for i in indexes]

    @cached_property
    def _point_values(self) -> dict[int, Mpf | None]:
        """The points `values_at` computed, kept: a prepared reference meets many wrong answers."""
        return {}

    def point_evaluator(self, indexes: tuple[int, ...], targets: tuple[sympy.Expr, ...] = ()) -> Evaluator:
        """An evaluator at PREC at these sample points that starts from the subtrees of the reference and
        of `targets` (reference-side expressions: its negation, a known mistake) there, evaluated once
        per point set and kept from its second use: an answer is then evaluated only where it differs."""
        columns = {s: [self.sample.columns[s][i] for i in indexes] for s in self.sample.symbols}
        known: dict[sympy.Basic, Column] | None = self._grids.known(indexes)
        if known is None:
            return Evaluator(columns, len(indexes), PREC)
        missing = [target for target in (self.expected, *targets) if target not in known]
        if missing:
            evaluator = Evaluator(columns, len(indexes), PREC, known)
            for target in missing:
                evaluator(target)
            known.update(evaluator.known)
        return Evaluator(columns, len(indexes), PREC, known)

    def float_evaluator(self) -> FloatEvaluator:
        """A float64 evaluator over the whole sample that starts from the reference's subtrees (kept
        from the second use on)."""
        columns, size = self.floats.columns, self.sample.size
        known: dict[sympy.Basic, Floats] | None = self._grids.known(_FLOATS)
        if known is None:
            return FloatEvaluator(columns, size)
        if self.expected not in known:
            evaluator = FloatEvaluator(columns, size, known)
            evaluator(self.expected)
            known.update(evaluator.known)
        return FloatEvaluator(columns, size, known)

    @cached_property
    def _grids(self) -> _Grids:
        return _Grids()

    @cached_property
    def token(self) -> object:
        """This reference's own identity in memories of values at its points (physics.symbolic.quick),
        which hold it: never reused by another reference, as an id() could be."""
        return object()

    def __getstate__(self) -> dict[str, object]:
        # Pickled with a compiled part: not what is kept for answers (rebuilt on first use), nor the
        # parse tree of a reference read from text (built by sympy now).
        state = {
            name: value
            for name, value in self.__dict__.items()
            if name not in ("_grids", "_judgements", "token")
        }
        if self.source is not None:
            state.update(built=self.expected, source=None, has_symbols=self.has_symbols)
        return state

    @cached_property
    def precise_columns(self) -> Mapping[sympy.Symbol, Column]:
        """The first PRECISE_POINTS sample points..."""
        size = min(PRECISE_POINTS, self.sample.size)
        return {s: list(self.sample.columns[s][:size]) for s in self.sample.symbols}

    @cached_property
    def _precise_subtrees(self) -> Mapping[sympy.Basic, Column]:
        evaluator = Evaluator(self.precise_columns, min(PRECISE_POINTS, self.sample.size), PRECISE_PREC)
        evaluator(self.expected)
        return dict(evaluator.known)

    @cached_property
    def precise_values(self) -> Column:
        """...and the reference there at PRECISE_PREC (or more, from the parse tree of a reference read
        from text)."""
        found = None if self.source is None else self.source.precise_values(self)
        return self._precise_subtrees[self.expected] if found is None else found

    def precise_evaluator(self) -> Evaluator:
        """An evaluator at the precise points that starts from the reference's subtrees (an answer
        shares many: sin(theta), M + m sin(theta)^2), so only what differs is computed."""
        size = min(PRECISE_POINTS, self.sample.size)
        return Evaluator(self.precise_columns, size, PRECISE_PREC, self._precise_subtrees)

    @cached_property
    def mistakes(self) -> tuple[PreparedMistake, ...]:
        """The known mistakes' values, computed on first use: only a wrong answer needs them."""
        evaluate = Evaluator(self.sample.columns, self.sample.size, PREC)
        return tuple(PreparedMistake(expr, feedback, evaluate(expr)) for expr, feedback in self.mistake_exprs)

    @cached_property
    def limits(self) -> tuple[PreparedLimit, ...]:
        """The limiting cases, computed on first use (at 400 bits: only a wrong answer needs them)."""
        return tuple(prepare_limit(case, self.expected, self.sample, self.scale) for case in self.limit_cases)

    @cached_property
    def floats(self) -> FloatSample:
        """The sample and the reference's values in float64, for the first look at an answer."""
        known = self.sample.required_floats[0]
        if known is not None:
            return float_sample(self.sample.float_columns, known, False, self.sample.float_columns_in_range)
        return float_sample(self.sample.float_columns, *rounded(self.values))

    @cached_property
    def float_mistakes(self) -> tuple[Floats | None, ...]:
        """The known mistakes in float64 at every point (None where float64 cannot stand in)."""
        evaluate = FloatEvaluator(self.floats.columns, self.sample.size)
        found: list[Floats | None] = []
        for expr, _ in self.mistake_exprs:
            values = evaluate(expr) if self.floats.usable else None
            found.append(values if values is not None and in_range(values) else None)
        return tuple(found)

    def complete(self) -> PreparedReference:
        """Everything computed now (before the reference is persisted or sent to another process)."""
        self.values  # noqa: B018
        self.precise_values  # noqa: B018
        self.mistakes  # noqa: B018
        self.limits  # noqa: B018
        self.floats  # noqa: B018
        self.float_mistakes  # noqa: B018
        return self


def exact_numbers(expr: sympy.Basic) -> sympy.Basic:
    """Floats become the decimals they print as (API: decimals are exact; 0.1 is 1/10)."""
    floats = expr.atoms(sympy.Float)
    if not floats:
        return expr
    table = {}
    for number in floats:
        text = repr(float(number)) if number._prec <= 53 else str(number)
        fraction = Fraction(Decimal(text))
        table[number] = sympy.Rational(fraction.numerator, fraction.denominator)
    return expr.xreplace(table)


def over_context(expr: sympy.Basic, context: SymbolicContext) -> bool:
    """True when `expr` is arithmetic and functions of exact numbers and the context's own symbols: what
    exact_numbers and rename_symbols would return unchanged, found in one walk (a fifth of their time;
    anything else, a Float or a foreign symbol or another kind of node, is for them to handle)."""
    symbols = context.symbols
    stack = [expr]
    while stack:
        node = stack.pop()
        if node.is_Symbol:
            if node not in symbols:
                return False
        elif node.is_Float or not (
            node.is_Number
            or node.is_NumberSymbol
            or node.is_Add
            or node.is_Mul
            or node.is_Pow
            or isinstance(node, sympy.Function)
        ):
            return False
        stack.extend(node.args)
    return True


def rename_symbols(expr: sympy.Basic, context: SymbolicContext) -> sympy.Basic:
    """The same expression over the context's symbols, matched by name (assumptions may differ).

    Raises KeyError with the first unknown name.
    """
    foreign = {s for s in expr.free_symbols if s not in context.symbols}
    if not foreign:
        return expr
    return expr.xreplace({s: context.by_name[s.name] for s in foreign})


def _reference_side(expr: sympy.Basic, context: SymbolicContext, path: tuple[str | int, ...]) -> sympy.Expr:
    if not isinstance(expr, sympy.Expr):
        raise SpecError(f"{expr} is not an expression", path)
    if over_context(expr, context):  # a read reference: nothing to make exact or rename (one walk)
        return expr
    try:
        renamed = rename_symbols(exact_numbers(expr), context)
    except KeyError as missing:
        raise SpecError(f"{missing.args[0]} is not a declared symbol", path) from None
    return renamed


def _declared_dimensions(context: SymbolicContext) -> dict[sympy.Symbol, Dimension]:
    return {s: spec.dimension for s, spec in context.symbols.items() if spec.dimension is not None}


def _reference_dimension(
    expected: sympy.Expr, context: SymbolicContext, dims: Mapping[sympy.Symbol, Dimension]
) -> Dimension | None:
    try:
        computed = expression_dimension(expected, dims)
    except UnknownDimension:
        return context.expected_dimension
    except DimensionMismatch as error:
        raise SpecError(f"the reference {error.message}", ("expected",)) from None
    if context.expected_dimension is not None and computed != context.expected_dimension:
        raise SpecError(
            f"the reference has the dimension of {describe(computed)}, "
            f"but {describe(context.expected_dimension)} is expected",
            ("expected",),
        )
    return computed


def prepare_reference(expected: sympy.Expr, context: SymbolicContext) -> PreparedReference:
    """Sample the domain and evaluate the reference side; raises SpecError when it is unusable."""
    reference = _reference_side(expected, context, ("expected",))
    constraints = tuple(
        _reference_side_relation(c, context, ("constraints", i)) for i, c in enumerate(context.constraints)
    )
    # The points depend on the domain only (not on the reference): references over the same symbols
    # share them, so a new reference costs one evaluation at points already drawn (sampling.py).
    seed = domain_seed(context, constraints)
    sample = sample_domain(context, constraints, (reference,), SAMPLE_SIZE, seed, PREC)
    dims = _declared_dimensions(context)
    mistakes = tuple(
        (_reference_side(mistake.expr, context, ("mistakes", index)), mistake.feedback)
        for index, mistake in enumerate(context.mistakes)
    )
    limits = tuple(_renamed_limit(case, context, index) for index, case in enumerate(context.limits))
    return PreparedReference(
        built=reference,
        context=context,
        sample=sample,
        scale=_typical_scale(sample),
        dimension=_reference_dimension(reference, context, dims),
        dims=dims,
        mistake_exprs=mistakes,
        limit_cases=limits,
    )


def _typical_scale(sample: DomainSample) -> Mpf:
    """typical_scale of the reference's values, from float64 when sampling found them exactly enough
    (the scale is only a floor for tolerances: a relative 2^-36 in it changes nothing)."""
    floats = sample.required_floats[0]
    if floats is None:
        values = sample.required[0]
        assert values is not None  # sampling computes one or the other
        return typical_scale(values)
    magnitudes = np.sort(np.abs(floats))
    median = float(magnitudes[len(magnitudes) // 2])
    return ONE if median == 0 else libmp.from_float(median)


def _reference_side_relation(
    relation: sympy.Basic, context: SymbolicContext, path: tuple[str | int, ...]
) -> sympy.Basic:
    try:
        return rename_symbols(exact_numbers(relation), context)
    except KeyError as missing:
        raise SpecError(f"{missing.args[0]} is not a declared symbol", path) from None


def _renamed_limit(case: LimitCase, context: SymbolicContext, index: int) -> LimitCase:
    substitutions: dict[sympy.Symbol, sympy.Expr] = {}
    for symbol, value in case.substitutions.items():
        if symbol.name not in context.by_name:
            raise SpecError(
                f"the limit names {symbol.name}, which is not a declared symbol", ("limits", index)
            )
        substitutions[context.by_name[symbol.name]] = _reference_side(value, context, ("limits", index))
    return LimitCase(substitutions, case.description)
