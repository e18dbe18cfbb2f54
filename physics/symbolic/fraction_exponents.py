"""A fraction typed on an exponent without brackets: `(R+h)^3/2` is (R+h)³/2 as typed (an exponent other
than 1 keeps its fraction outside, as `2mR^2/5` does), but where that can never be right, having another
dimension than the answer must have, and the fraction as the exponent, (R+h)^(3/2), has that dimension,
the student meant the exponent: the answer is refused (`invalid`, no attempt used) asking so, as a sum
without its brackets is (bracketed_sums.py), rather than graded wrong for a missing bracket. Never read
as the bracketed exponent: precedence says otherwise, and the student's text must say what they mean."""

from __future__ import annotations

import re
from collections.abc import Mapping

import sympy

from physics.dimensions import Dimension, describe
from physics.errors import AmbiguousInput, AnswerError
from physics.mathinput import InputLimits
from physics.mathinput.render import in_student_style
from physics.symbolic.dimensional import (
    named_dimension,
)
from physics.symbolic.reading import read_symbolic_answer

# `^3/2`, `**-1/3`: whole numbers either side of the slash, the divisor a number alone (`^3/2m` is a
# division by a product, refused as such before the answer is graded).
_GLUED_FRACTION = re.compile(r"(?:\^|\*\*)(-?\d+)/(\d+)(?![\w.(])")
# Exponents tried, each one parse: a few at most, on a wrong answer.
_MAX_EXPONENTS = 3


def fraction_exponent(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    dimensions: Mapping[str, Dimension],
    expected: Dimension,
) -> AmbiguousInput | None:
    """The question to ask of `text` whose exponent wants its fraction bracketed (`2π(R+h)^3/2/√(GM)` for
    a time), or None: the cheap test first (the text), then the answer as typed, which must lack the
    expected dimension."""
    glued = [found for found in _GLUED_FRACTION.finditer(text) if found.group(1).lstrip("-") != "1"]
    if not glued:  # `x^1/2`: settled by dimension where it can be, else asked, when read
        return None
    try:
        typed = read_symbolic_answer(text, names, limits, dimensions, expected)
    except AnswerError:
        return None
    if named_dimension(typed.expr, dimensions) in (expected, None):
        return None
    for found in glued[:_MAX_EXPONENTS]:
        top, bottom = found.group(1), found.group(2)
        try:
            other = read_symbolic_answer(
                f"{text[: found.start(1)]}({top}/{bottom}){text[found.end() :]}",
                names,
                limits,
                dimensions,
                expected,
            )
        except AnswerError:
            continue
        if named_dimension(other.expr, dimensions) == expected:
            meant = in_student_style(other.read_as.text)
            caret = text[found.start() : found.start(1)]
            return AmbiguousInput(
                f"Did you mean {meant}? As typed, {caret}{top}/{bottom} is the power {top}, then divided by "
                f"{bottom}, which is not {describe(expected)}, so it cannot be right: write the exponent in "
                f"brackets, {caret}({top}/{bottom}).",
                found.start(),
                [in_student_style(typed.read_as.text), meant],
            )
    return None
