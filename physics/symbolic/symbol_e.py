"""`e^(-t/τ)` where the problem declares a symbol e with a dimension (the elementary charge): as typed, the
charge raised to a power, which no answer can be, where the student meant Euler's number. Refused
(`invalid`, no attempt used) saying that e is the problem's symbol here and how to write Euler's
number, rather than graded wrong. A dimensionless e (a coefficient of restitution) to a power is an
answer like any other (`e^(2n) h`), and graded as typed."""

from __future__ import annotations

import re
from collections.abc import Mapping

import sympy

from physics.dimensions import Dimension, describe
from physics.errors import AmbiguousInput, AnswerError
from physics.mathinput import InputLimits, parse_math
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension

# An e typed as a word of its own, raised: `e^`, `e**`, `e⁻²`.
_RAISED_E = re.compile(r"(?<![\w\\])e\s*(?:\^|\*\*|[⁻⁺⁰¹²³⁴⁵⁶⁷⁸⁹])")


def symbol_e_raised(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    dimensions: Mapping[str, Dimension],
) -> AmbiguousInput | None:
    """The refusal of `text` whose declared, dimensioned e is raised to a power that is no fixed number,
    or None. For an answer graded wrong_dimension: the cheap tests first."""
    dimension = dimensions.get("e")
    if "e" not in names or dimension is None or dimension.is_dimensionless:
        return None
    raised = _RAISED_E.search(text)
    if raised is None:
        return None
    try:
        literal = parse_math(text, names, limits=limits)
        known = {s: dimensions[s.name] for s in literal.expr.free_symbols if s.name in dimensions}
        expression_dimension(literal.expr, known)
    except DimensionMismatch as mismatch:
        if mismatch.kind != "power" or mismatch.dims != (dimension,):
            return None
    except (AnswerError, UnknownDimension):
        return None
    else:
        return None
    return AmbiguousInput(
        f"Here e is the problem's symbol e, {describe(dimension)}, and a power of it cannot be right: for "
        "Euler's number write exp(…), as in exp(-t/tau).",
        raised.start(),
        ["e (the problem's symbol)", "exp(…)"],
    )
