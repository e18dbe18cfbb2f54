"""Numeric answers with units: reading them exactly and comparing them with a tolerance.

check_numeric(answer, spec) -> Verdict
NumericSpec(expected, units=None, units_required=True, tolerance=DEFAULT_TOLERANCE)
Tolerance(rel=None, abs=None, sigfigs=None)
"""

from __future__ import annotations

from physics.numeric.answer import NumericAnswer, read_numeric_answer
from physics.numeric.check import check_numeric
from physics.numeric.literal import NumberLiteral, read_number
from physics.numeric.spec import NumericSpec
from physics.numeric.tolerance import DEFAULT_TOLERANCE, Tolerance, round_sigfigs

__all__ = [
    "DEFAULT_TOLERANCE",
    "NumberLiteral",
    "NumericAnswer",
    "NumericSpec",
    "Tolerance",
    "check_numeric",
    "read_number",
    "read_numeric_answer",
    "round_sigfigs",
]
