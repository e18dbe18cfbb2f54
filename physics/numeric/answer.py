"""A numeric answer as read: the number, then the units (if any) that follow it."""

from __future__ import annotations

import re
from dataclasses import dataclass
from fractions import Fraction

from physics.errors import AnswerError, ParseError, TooLarge
from physics.numeric.literal import NumberLiteral, read_number
from physics.units import ParsedUnits, parse_units
from physics.verdict import ReadAs

MAX_ANSWER_LENGTH = 200


@dataclass(frozen=True)
class NumericAnswer:
    number: NumberLiteral
    units: ParsedUnits | None  # None when no units were written
    units_position: int | None  # where the units start in the answer
    units_text: str = ""  # the units as typed

    @property
    def value(self) -> Fraction:
        """The number's exact value, in the written units."""
        return self.number.value

    def read_as(self, units: ParsedUnits | None = None) -> ReadAs:
        """How the answer was understood; `units` stands in for units the answer left implicit."""
        shown = self.units if self.units is not None else units
        if shown is None or shown.is_dimensionless_number:
            return ReadAs(self.number.text, self.number.latex)
        if shown.text == "°":  # 30°, not 30 °
            return ReadAs(f"{self.number.text}°", f"{self.number.latex}{shown.latex}")
        return ReadAs(f"{self.number.text} {shown.text}", rf"{self.number.latex}\,{shown.latex}")


_RECIPROCAL = re.compile(r"1\s*/")  # `4.9e12 1/s` is a number and a unit, not two numbers


def read_numeric_answer(text: str) -> NumericAnswer:
    """Read `4.58 m/s^2`, `-1.2e3 N`, `45%`, `16.49 km/h`; AnswerError with a position if it cannot be."""
    if len(text) > MAX_ANSWER_LENGTH:
        raise TooLarge(f"An answer may be at most {MAX_ANSWER_LENGTH} characters", MAX_ANSWER_LENGTH)
    number = read_number(text)
    rest_start = number.end
    while rest_start < len(text) and text[rest_start].isspace():
        rest_start += 1
    unit_text = text[rest_start:].rstrip()
    if not unit_text:
        return NumericAnswer(number, None, None)
    reciprocal = _RECIPROCAL.match(unit_text)
    if unit_text.startswith("/"):  # `4.9e12 /s`: a unit of the form 1/…
        unit_text, rest_start = "1" + unit_text, rest_start - 1
    elif reciprocal is None and (
        unit_text[0] in "0123456789" or (unit_text[0] in ",." and unit_text[1:2].isdigit())
    ):
        raise ParseError(
            "Two numbers side by side: write one number without spaces or separators (12500, not 12 500)",
            rest_start,
        )
    try:
        units = parse_units(unit_text)
    except AnswerError as error:
        if error.position is not None:
            error.position += rest_start
        raise
    return NumericAnswer(number, units, rest_start, unit_text)
