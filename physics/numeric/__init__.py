"""Numeric answers with units: reading them exactly and comparing them with a tolerance.

check_numeric(answer, spec) -> Verdict
NumericSpec(expected, units=None, units_required=True, tolerance=DEFAULT_TOLERANCE, mistakes=())
Tolerance(rel=None, abs=None, sigfigs=None)
read_decimal(value) -> Decimal        an author's number (the one reader, with its limits)
round_sigfigs(value, n) -> Decimal    the one rounding rule (half-up), for grading and display alike
"""

from __future__ import annotations

from physics.numeric.answer import NumericAnswer, read_numeric_answer
from physics.numeric.check import check_numeric
from physics.numeric.decimals import NotADecimal, as_decimal, read_decimal
from physics.numeric.literal import NumberLiteral, read_number
from physics.numeric.rounding import round_sigfigs
from physics.numeric.spec import MistakenValue, NumericSpec
from physics.numeric.tolerance import DEFAULT_TOLERANCE, Tolerance

__all__ = [
    "DEFAULT_TOLERANCE",
    "MistakenValue",
    "NotADecimal",
    "NumberLiteral",
    "NumericAnswer",
    "NumericSpec",
    "Tolerance",
    "as_decimal",
    "check_numeric",
    "read_decimal",
    "read_number",
    "read_numeric_answer",
    "round_sigfigs",
]
