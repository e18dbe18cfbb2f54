"""What a symbolic question is about: its symbols (with their domain), constraints, mistakes, limits.

A symbol is positive and real unless its spec says otherwise (API.md, `POST /v1/check`); a `range`
is an open interval and replaces the positive default. Equivalence is decided on this domain only.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy

from physics.dimensions import Dimension
from physics.errors import SpecError


@dataclass(frozen=True)
class SymbolSpec:
    name: str
    dimension: Dimension | None = None
    real: bool = False
    nonzero: bool = False
    negative: bool = False
    integer: bool = False
    low: sympy.Expr | None = None  # open range (low, high); None: unbounded on that side
    high: sympy.Expr | None = None

    @property
    def has_range(self) -> bool:
        return self.low is not None or self.high is not None


@dataclass(frozen=True)
class KnownMistake:
    expr: sympy.Expr
    feedback: str


@dataclass(frozen=True)
class LimitCase:
    substitutions: Mapping[sympy.Symbol, sympy.Expr]  # a value may be sympy.oo, -sympy.oo, 0 or any number
    description: str  # e.g. "an immovable wedge (M → ∞)"


@dataclass(frozen=True)
class SymbolicContext:
    symbols: Mapping[sympy.Symbol, SymbolSpec]
    constraints: tuple[sympy.Basic, ...] = ()
    mistakes: tuple[KnownMistake, ...] = ()
    limits: tuple[LimitCase, ...] = ()
    expected_dimension: Dimension | None = None  # when the problem knows it; else computed from symbols
    by_name: Mapping[str, sympy.Symbol] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "by_name", {symbol.name: symbol for symbol in self.symbols})

    @functools.cached_property
    def shape(self) -> tuple[SymbolSpec, ...]:
        """The symbols' specs without their names, in the order of the names: what the domain's sample
        points depend on (physics.symbolic.sampling), asked three times per new reference."""
        ordered = sorted(self.symbols.items(), key=lambda item: item[0].name)
        return tuple(SymbolSpec(**{**vars(spec), "name": ""}) for _, spec in ordered)


def _bound_sign(bound: sympy.Expr | None, path: tuple[str | int, ...]) -> int | None:
    """-1, 0 or 1 for a finite bound's sign; None for an absent or infinite bound or an unknown sign."""
    if bound is None or bound in (sympy.oo, -sympy.oo):
        return None
    if not bound.is_number or bound.is_extended_real is False:
        raise SpecError("a range bound must be a real number such as 0 or pi/2", path)
    if bound.is_zero:
        return 0
    if bound.is_positive:
        return 1
    if bound.is_negative:
        return -1
    return None


def symbol_assumptions(spec: SymbolSpec) -> dict[str, bool]:
    """The strongest assumptions the spec makes sound, for sympy's simplifications."""
    path = ("symbols", spec.name, "range")
    low_sign = _bound_sign(spec.low, (*path, 0))
    high_sign = _bound_sign(spec.high, (*path, 1))
    low_nonnegative = low_sign is not None and low_sign >= 0
    assumptions: dict[str, bool] = {}
    if spec.negative or (high_sign is not None and high_sign <= 0):
        assumptions["negative"] = True
    elif spec.has_range:
        # An open interval that starts at or above zero holds only positive numbers: (0, pi/2) -> positive.
        assumptions["positive" if low_nonnegative else "real"] = True
        if spec.nonzero and not low_nonnegative:
            assumptions["nonzero"] = True
    elif spec.real:
        assumptions["real"] = True
        if spec.nonzero:
            assumptions["nonzero"] = True
    else:
        assumptions["positive"] = True
    if spec.integer:
        assumptions["integer"] = True
    return assumptions


@functools.lru_cache(maxsize=1024)
def make_symbol(spec: SymbolSpec) -> sympy.Symbol:
    """A sympy Symbol named as the spec, with the assumptions its domain allows (cached: sympy's
    assumption handling is a tenth of reading a new reference)."""
    return sympy.Symbol(spec.name, **symbol_assumptions(spec))
