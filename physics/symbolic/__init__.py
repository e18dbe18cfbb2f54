"""Symbolic answers: equivalence on the physical domain, diagnosis of wrong answers, dimensions.

    prepare_reference(expected, context) -> PreparedReference    (once per reference; cacheable)
    judge_symbolic(answer, reference) -> Judgement               (about a millisecond per answer)

How equivalence is decided is documented in `physics.symbolic.judge`.
"""

from physics.dimensions import describe
from physics.symbolic.bench import bench_equivalence_cases
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension
from physics.symbolic.domain import KnownMistake, LimitCase, SymbolicContext, SymbolSpec, make_symbol
from physics.symbolic.judge import judge_symbolic
from physics.symbolic.proof import proves_equal
from physics.symbolic.reference import PreparedReference, prepare_reference

__all__ = [
    "DimensionMismatch",
    "KnownMistake",
    "LimitCase",
    "PreparedReference",
    "SymbolSpec",
    "SymbolicContext",
    "UnknownDimension",
    "bench_equivalence_cases",
    "describe",
    "expression_dimension",
    "judge_symbolic",
    "make_symbol",
    "prepare_reference",
    "proves_equal",
]
