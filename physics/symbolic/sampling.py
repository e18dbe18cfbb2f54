"""Random points of a symbolic question's domain, reproducible from a seed.

Each batch is a Latin hypercube (every symbol's range is cut into as many strata as there are points,
one point per stratum), so both halves of θ ∈ (0, π) are always visited; points that break a
constraint, or where the reference is undefined, are rejected and another batch is drawn.

Where the reference is defined is decided in float64 wherever float64 can vouch for it
(physics.symbolic.bounded), and in multiprecision at the other points: the same points are kept as by
multiprecision alone. The reference's multiprecision values are then computed only where float64 cannot
give them to within 2^-36 (PRECISE_RELATIVE); the reference computes the rest when a check needs them.
"""

from __future__ import annotations

import functools
import hashlib
import math
import random
import threading
from collections import OrderedDict
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy
from mpmath import libmp

from physics.errors import SpecError
from physics.symbolic.bounded import Bounded, BoundedEvaluator, Unsupported
from physics.symbolic.domain import SymbolicContext, SymbolSpec, symbol_assumptions
from physics.symbolic.floats import Floats, in_range
from physics.symbolic.numeric import (
    RND,
    Column,
    Evaluator,
    Mpf,
    as_mpf,
    evaluate_constant,
    from_int,
    is_negative,
    to_float,
)

# Unbounded positive values are drawn log-uniformly over two decades around 1: dimensions are checked
# apart, so the scale of a value carries no physics, and wider spreads only lose precision.
_LOG10_SPAN = 1.0
_EDGE = 1e-9  # keeps points strictly inside open ranges
_INTEGER_SPAN = 12
MAX_BATCHES = 100  # a constraint may keep only a few percent of the candidates
# float64 values this close to the multiprecision ones stand in for them (floats.AGREE is 1e-9).
PRECISE_RELATIVE = 2.0**-36

Axis = Callable[[float], Mpf]


@dataclass(frozen=True)
class DomainSample:
    symbols: tuple[sympy.Symbol, ...]
    columns: Mapping[sympy.Symbol, Column]
    size: int
    # The same points rounded to float64 (derived from `columns`, hence not compared).
    float_columns: Mapping[sympy.Symbol, Floats] = field(compare=False)
    # The `required` expressions at the points, in order: in float64 where float64 gives every value to
    # within PRECISE_RELATIVE of multiprecision (else None), in multiprecision otherwise (else None).
    required_floats: tuple[Floats | None, ...] = field(default=(), compare=False)
    required: tuple[Column | None, ...] = ()
    # Whether every float column is floats.in_range, when known (points shared by many references).
    float_columns_in_range: bool | None = field(default=None, compare=False)

    def point(self, index: int) -> dict[sympy.Symbol, Mpf]:
        return {s: self.columns[s][index] for s in self.symbols}  # type: ignore[misc]


def seed_for(*parts: object) -> int:
    """A seed that depends only on the reference side (not on Python's per-run string hashing)."""
    digest = hashlib.sha256(repr(parts).encode()).digest()
    return int.from_bytes(digest[:8], "big")


def domain_seed(context: SymbolicContext, constraints: Sequence[sympy.Basic]) -> int:
    """The seed of a domain: its symbols' specs in the order of their names, but not the names
    themselves (a domain renamed, `m` -> `m_2`, is drawn as the same points: `_first_batch`), and its
    constraints (printed by sympy: computed once per domain, it would be a tenth of preparing a
    reference)."""
    return _domain_seed(_shape(context), tuple(constraints))


def _shape(context: SymbolicContext) -> tuple[SymbolSpec, ...]:
    """The domain's symbols' specs without their names, in the order of the names (`sample_domain`'s
    order of the columns)."""
    return context.shape


@functools.lru_cache(maxsize=256)
def _domain_seed(shape: tuple[SymbolSpec, ...], constraints: tuple[sympy.Basic, ...]) -> int:
    return seed_for([repr(spec) for spec in shape], [sympy.srepr(c) for c in constraints])


def _float(value: float, prec: int) -> Mpf:
    return as_mpf(libmp.mpf_pos(libmp.from_float(value), prec, RND))


def _log_uniform(u: float) -> float:
    return float(10 ** (_LOG10_SPAN * (2 * u - 1)))


def _bound(spec: SymbolSpec, which: int, prec: int) -> Mpf | None:
    bound = spec.low if which == 0 else spec.high
    if bound is None or bound in (sympy.oo, -sympy.oo):
        return None
    value = evaluate_constant(bound, prec)
    if value is None:
        path = ("symbols", spec.name, "range", which)
        raise SpecError(f"the range bound {bound} is not a real number", path)
    return value


def _integer_axis(spec: SymbolSpec, low: Mpf | None, high: Mpf | None) -> Axis:
    assumptions = symbol_assumptions(spec)
    if low is not None or high is not None:
        first = int(libmp.to_int(libmp.mpf_floor(low))) + 1 if low is not None else None
        last = int(libmp.to_int(libmp.mpf_ceil(high))) - 1 if high is not None else None
        if first is None:
            first = (last if last is not None else 0) - _INTEGER_SPAN
        if last is None:
            last = first + _INTEGER_SPAN
    elif assumptions.get("negative"):
        first, last = -_INTEGER_SPAN, -1
    elif assumptions.get("real"):
        first, last = -_INTEGER_SPAN, _INTEGER_SPAN
    else:
        first, last = 1, _INTEGER_SPAN
    values = [n for n in range(first, last + 1) if not (n == 0 and spec.nonzero)]
    if not values:
        raise SpecError(f"no integer lies in the range of {spec.name}", ("symbols", spec.name, "range"))
    return lambda u: from_int(values[min(int(u * len(values)), len(values) - 1)])


def axis_for(spec: SymbolSpec, prec: int) -> Axis:
    """Maps u in (0, 1) to a value of the symbol's domain."""
    low, high = _bound(spec, 0, prec), _bound(spec, 1, prec)
    if spec.negative and (high is None or not is_negative(high)):
        high = libmp.fzero
    if spec.integer:
        return _integer_axis(spec, low, high)
    if low is not None and high is not None:
        if libmp.mpf_le(high, low):
            raise SpecError(f"the range of {spec.name} is empty", ("symbols", spec.name, "range"))
        width = libmp.mpf_sub(high, low, prec, RND)
        return lambda u: libmp.mpf_add(low, libmp.mpf_mul(width, _float(u, prec), prec, RND), prec, RND)
    if low is not None:
        return lambda u: libmp.mpf_add(low, _float(_log_uniform(u), prec), prec, RND)
    if high is not None:
        return lambda u: libmp.mpf_sub(high, _float(_log_uniform(u), prec), prec, RND)
    if symbol_assumptions(spec).get("real"):
        # Either sign, magnitudes log-uniform as for positive symbols.
        def either_sign(u: float) -> Mpf:
            v = 2 * u - 1
            magnitude = _float(_log_uniform(abs(v)), prec)
            return libmp.mpf_neg(magnitude) if v < 0 else magnitude

        return either_sign
    return lambda u: _float(_log_uniform(u), prec)


def _latin_hypercube(rng: random.Random, dimensions: int, size: int) -> list[list[float]]:
    """`dimensions` rows of `size` values in (0, 1), one per stratum, each row independently shuffled."""
    rows = []
    for _ in range(dimensions):
        strata = list(range(size))
        rng.shuffle(strata)
        rows.append([min(max((k + rng.random()) / size, _EDGE), 1 - _EDGE) for k in strata])
    return rows


def _holds(relation: sympy.Basic, evaluate: Evaluator, size: int) -> list[bool]:
    """Where a constraint holds; undefined counts as not holding."""
    if relation is sympy.true:
        return [True] * size
    if relation is sympy.false:
        return [False] * size
    if isinstance(relation, sympy.And | sympy.Or):
        parts = [_holds(arg, evaluate, size) for arg in relation.args]
        combine = all if isinstance(relation, sympy.And) else any
        return [combine(row) for row in zip(*parts, strict=True)]
    if isinstance(relation, sympy.Not):
        return [not ok for ok in _holds(relation.args[0], evaluate, size)]
    if isinstance(relation, sympy.Ne):
        return [True] * size  # excludes a set of measure zero
    if not isinstance(relation, sympy.Lt | sympy.Le | sympy.Gt | sympy.Ge):
        raise SpecError(f"a constraint must be an inequality, not {relation}", ("constraints",))
    difference = evaluate(relation.lhs - relation.rhs)
    wants_negative = isinstance(relation, sympy.Lt | sympy.Le)
    strict = isinstance(relation, sympy.Lt | sympy.Gt)
    out = []
    for d in difference:
        if d is None:
            out.append(False)
        elif d == libmp.fzero:
            out.append(not strict)
        else:
            out.append(is_negative(d) == wants_negative)
    return out


@dataclass(frozen=True)
class _Batch:
    """One Latin-hypercube batch of candidate points, with where the constraints hold."""

    columns: Mapping[sympy.Symbol, Column]
    allowed: tuple[bool, ...]
    floats: Mapping[sympy.Symbol, Floats]
    rng_state: Any  # the generator's state after drawing this batch, to draw the next ones
    # Subtrees of the references over this domain, bounded in float64 at these points: a new reference
    # over a known domain is mostly made of subtrees an earlier one had (sin θ, M + m sin²θ).
    bounded: dict[sympy.Basic, Bounded] = field(default_factory=dict, compare=False)
    # The same of references' parse trees, by their structure (physics.symbolic.tree_reference).
    tree_bounded: dict[int, Bounded] = field(default_factory=dict, compare=False)

    @functools.cached_property
    def floats_in_range(self) -> bool:
        """Every point in float64 floats.in_range (asked of each reference prepared over them)."""
        return all(in_range(column) for column in self.floats.values())


_BATCH_CACHE_SIZE = 256
_first_batches: OrderedDict[tuple[Any, ...], _Batch] = OrderedDict()
# The same batches by the domain's shape (`_shape`: the specs without the names), for a domain without
# constraints: one under new names (`m_2` for `m`, a course's own names) is drawn as the same points, so
# a new domain of a known shape costs no draw. Columns in the order of the names.
_first_draws: OrderedDict[tuple[Any, ...], _Batch] = OrderedDict()
_first_batches_lock = threading.Lock()


def _draw(
    symbols: tuple[sympy.Symbol, ...],
    axes: Sequence[Axis],
    constraints: Sequence[sympy.Basic],
    rng: random.Random,
    size: int,
    prec: int,
) -> _Batch:
    grid = _latin_hypercube(rng, len(symbols), size)
    columns: dict[sympy.Symbol, Column] = {
        s: [axis(u) for u in row] for s, axis, row in zip(symbols, axes, grid, strict=True)
    }
    evaluate = Evaluator(columns, size, prec)
    ok = [True] * size
    for relation in constraints:
        ok = [a and b for a, b in zip(ok, _holds(relation, evaluate, size), strict=True)]
    floats = {s: np.array([to_float(v) for v in column]) for s, column in columns.items()}  # type: ignore[arg-type]
    return _Batch(columns, tuple(ok), floats, rng.getstate())


def _first_batch(
    context: SymbolicContext, constraints: Sequence[sympy.Basic], size: int, seed: int, prec: int
) -> _Batch | None:
    """The first batch drawn for this domain, if an earlier reference over the same symbols drew it."""
    key = _batch_key(context, constraints, size, seed, prec)
    with _first_batches_lock:
        found = _first_batches.get(key)
        if found is not None:
            _first_batches.move_to_end(key)
            return found
        drawn = None if constraints else _first_draws.get((_shape(context), size, seed, prec))
    if drawn is None:
        return None
    # The same points under this domain's names: the n-th column is the n-th name's in both.
    renamed = dict(zip(drawn.columns, sorted(context.symbols, key=lambda s: s.name), strict=True))
    batch = _Batch(
        {renamed[s]: column for s, column in drawn.columns.items()},
        drawn.allowed,
        {renamed[s]: floats for s, floats in drawn.floats.items()},
        drawn.rng_state,
    )
    _remember_first_batch(context, constraints, size, seed, prec, batch)
    return batch


def _remember_first_batch(
    context: SymbolicContext,
    constraints: Sequence[sympy.Basic],
    size: int,
    seed: int,
    prec: int,
    batch: _Batch,
) -> None:
    key = _batch_key(context, constraints, size, seed, prec)
    with _first_batches_lock:
        _first_batches[key] = batch
        while len(_first_batches) > _BATCH_CACHE_SIZE:
            _first_batches.popitem(last=False)
        if not constraints:
            _first_draws[(_shape(context), size, seed, prec)] = batch
            while len(_first_draws) > _BATCH_CACHE_SIZE:
                _first_draws.popitem(last=False)


def _batch_key(
    context: SymbolicContext, constraints: Sequence[sympy.Basic], size: int, seed: int, prec: int
) -> tuple[Any, ...]:
    # Symbols compare with their assumptions; specs with their ranges: equal keys, equal batches.
    symbols = tuple(sorted(context.symbols.items(), key=lambda item: item[0].name))
    return (symbols, tuple(constraints), size, seed, prec)


_BOUNDED_KEPT = 256  # subtrees per batch


def _bounded(exprs: Sequence[sympy.Basic], batch: _Batch, size: int) -> list[Bounded | None]:
    kept = batch.bounded
    if len(kept) > _BOUNDED_KEPT:
        kept.clear()
    evaluate = BoundedEvaluator(batch.floats, size, kept)
    found: list[Bounded | None] = []
    for expr in exprs:
        try:
            found.append(evaluate(expr))
        except Unsupported:
            found.append(None)
    return found


def _defined(
    batch: _Batch, required: Sequence[sympy.Basic], bounded: list[Bounded | None], prec: int
) -> list[bool]:
    """Where the constraints hold and every required expression is defined in multiprecision: vouched
    for by float64 where it can, evaluated in multiprecision at the other points."""
    ok = list(batch.allowed)
    vouched = np.ones(len(ok), dtype=bool)
    for found in bounded:
        vouched &= found.vouched if found is not None else False
    unsure = [i for i, allowed in enumerate(ok) if allowed and not vouched[i]]
    if unsure:
        columns = {s: [column[i] for i in unsure] for s, column in batch.columns.items()}
        evaluate = Evaluator(columns, len(unsure), prec)
        for expr in required:
            for index, value in zip(unsure, evaluate(expr), strict=True):
                if value is None:
                    ok[index] = False
    return ok


def sample_domain(
    context: SymbolicContext,
    constraints: Sequence[sympy.Basic],
    required: Sequence[sympy.Basic],
    size: int,
    seed: int,
    prec: int,
) -> DomainSample:
    """`size` points satisfying every constraint, where every `required` expression is defined.

    The points depend on the domain and the seed only, so references over the same symbols (and the
    same seed) share them: the first batch, constraints evaluated, is kept and reused (LRU), and only
    the `required` expressions are evaluated for a new reference.

    Raises SpecError when the domain looks empty (fewer than half the points found).
    """
    symbols = tuple(sorted(context.symbols, key=lambda s: s.name))
    rng = random.Random(seed)  # noqa: S311 - reproducible sampling, not secrecy
    kept: dict[sympy.Symbol, Column] = {s: [] for s in symbols}
    kept_floats: dict[sympy.Symbol, list[Floats]] = {s: [] for s in symbols}
    kept_values: list[list[Floats]] = [[] for _ in required]
    precise = [True] * len(required)
    found = 0
    first = _first_batch(context, constraints, size, seed, prec)
    axes: list[Axis] | None = None
    for batch_number in range(MAX_BATCHES):
        if batch_number == 0 and first is not None:
            batch = first
        else:
            if axes is None:
                axes = [axis_for(context.symbols[s], prec) for s in symbols]
            if batch_number == 1 and first is not None:
                rng.setstate(first.rng_state)  # the draws the first batch took, so later ones are the same
            batch = _draw(symbols, axes, constraints, rng, size, prec)
            if batch_number == 0:
                _remember_first_batch(context, constraints, size, seed, prec, batch)
        bounded = _bounded(required, batch, size)
        ok = _defined(batch, required, bounded, prec)
        indexes = [i for i in range(size) if ok[i]][: size - found]
        whole = len(indexes) == size  # the usual case: every point of the batch kept, in order
        for s in symbols:
            kept[s].extend(batch.columns[s] if whole else [batch.columns[s][i] for i in indexes])
            kept_floats[s].append(batch.floats[s] if whole else batch.floats[s][indexes])
        for k, b in enumerate(bounded):
            if b is None or not b.precise(PRECISE_RELATIVE)[indexes].all():
                precise[k] = False
            else:
                kept_values[k].append(b.values[indexes])
        found += len(indexes)
        if found == size:
            break
    if found < math.ceil(size / 2):
        raise SpecError(
            "could not find enough points where the symbols' ranges and constraints hold "
            "and the reference is defined",
            ("constraints",) if constraints else ("expected",),
        )
    evaluate = Evaluator(kept, found, prec)
    return DomainSample(
        symbols,
        kept,
        found,
        {s: np.concatenate(kept_floats[s]) for s in symbols},
        tuple(
            np.concatenate(values) if ok else None for values, ok in zip(kept_values, precise, strict=True)
        ),
        tuple(None if ok else evaluate(expr) for expr, ok in zip(required, precise, strict=True)),
    )


def first_batch(context: SymbolicContext, size: int, seed: int, prec: int) -> _Batch:
    """The first batch `sample_domain` draws for a domain without constraints, drawn (and remembered)
    as it draws it."""
    batch = _first_batch(context, (), size, seed, prec)
    if batch is None:
        symbols = tuple(sorted(context.symbols, key=lambda s: s.name))
        axes = [axis_for(context.symbols[s], prec) for s in symbols]
        batch = _draw(symbols, axes, (), random.Random(seed), size, prec)  # noqa: S311 - as sample_domain
        _remember_first_batch(context, (), size, seed, prec, batch)
    return batch


def whole_batch_sample(
    batch: _Batch,
    symbols: tuple[sympy.Symbol, ...],
    size: int,
    values: Callable[[Mapping[sympy.Symbol, Floats], int, dict[int, Bounded]], Floats | None],
) -> DomainSample | None:
    """The sample `sample_domain` draws for a domain without constraints whose `first_batch` this is,
    when the one required expression is defined at every point of the batch and `values` (of the
    batch's points in float64, their number, and the bounded values of parse trees' subtrees there, to
    fill and start from) gives it there in float64 to within PRECISE_RELATIVE; None when `values`
    cannot vouch for that (sample_domain then decides).

    `values` vouches for a reference not yet built by sympy (physics.symbolic.tree_reference): the
    points are those sample_domain keeps of its first batch, all of them. `symbols`: the domain's, in
    the order of their names."""
    if len(batch.tree_bounded) > _BOUNDED_KEPT:
        batch.tree_bounded.clear()
    found = values(batch.floats, size, batch.tree_bounded)
    if found is None:
        return None
    return DomainSample(
        symbols,
        {s: list(batch.columns[s]) for s in symbols},
        size,
        {s: batch.floats[s].copy() for s in symbols},
        (found,),
        (None,),
        batch.floats_in_range,
    )
