"""Authors' numbers as exact decimals: a reference value, a tolerance, a given value, a range bound.

One reader, with one set of limits and one style of message, for problem documents, `POST /v1/check`
and the numeric core. A JSON or YAML float is read by its shortest repr (4.5807 stays 4.5807), which
is what the author wrote. The limits hold the work bounded before any arithmetic (a 5,000-digit
integer is compared, not converted; number text is measured before it is parsed) and are generous
for physics: 6.022e23, 1.602e-19, 6.674e-11 and the Planck time are far inside. Given values are also
turned into floats (a student's view, domain sampling), hence exponents well inside a double's.

A refusal is `NotADecimal` (a ValueError, so pydantic reports it at the field's path); its message
completes a sentence whose subject is the field: "must be a finite number".
"""

from __future__ import annotations

import math
import re
from decimal import Decimal

from physics.errors import SpecError

MAX_EXPONENT = 100  # 0, or 1e-100 ≤ |x| < 1e101
MAX_DIGITS = 40  # significant digits
MAX_TEXT = 200  # characters of number text (room for 1e-100 written out in full)

_NUMBER_TEXT = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
NUMBER_EXAMPLE = "such as 9.81 or 6.022e23"


class NotADecimal(ValueError):
    """Why a value is not an author's decimal; `message` follows the field's name."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


def is_number_text(text: str) -> bool:
    """Text that is a plain decimal (`1e-3`, `.5`), as opposed to an expression (`pi/2`, `1_000`, `NaN`)."""
    return _NUMBER_TEXT.fullmatch(text.strip()) is not None


def read_decimal(value: object) -> Decimal:
    """`value` (a number, or number text) as an exact Decimal within the limits; NotADecimal if not."""
    if isinstance(value, bool):
        raise NotADecimal("must be a number, not true/false")
    if isinstance(value, int):
        # Compared before converting: a 5,000-digit integer is refused without building a Decimal of it.
        if abs(value) >= 10 ** (MAX_EXPONENT + 1):
            raise NotADecimal(_SIZE)
        return _within_limits(Decimal(value))
    if isinstance(value, float):
        if not math.isfinite(value):
            raise NotADecimal("must be a finite number")
        return _within_limits(Decimal(repr(value)))
    if isinstance(value, str):
        text = value.strip()
        if len(text) > MAX_TEXT:
            raise NotADecimal(f"must be written in at most {MAX_TEXT} characters")
        if not _NUMBER_TEXT.fullmatch(text):
            # Decimal() alone would also take "4_58" (as 458), "NaN" and "Infinity".
            raise NotADecimal(f"must be a decimal number {NUMBER_EXAMPLE}")
        mantissa, _, exponent = text.lower().partition("e")
        if len(exponent.lstrip("+-").lstrip("0")) > len(str(MAX_EXPONENT)) + 1:
            # An exponent libmpdec cannot hold (`1e` and 30 nines) would raise InvalidOperation.
            return _zero_or_out_of_range(mantissa)
        return _within_limits(Decimal(text))
    if isinstance(value, Decimal):
        if not value.is_finite():
            raise NotADecimal("must be a finite number")
        return _within_limits(value)
    raise NotADecimal(f"must be a number {NUMBER_EXAMPLE}")


def as_decimal(value: object, path: tuple[str | int, ...]) -> Decimal:
    """`read_decimal` for the numeric core: a refusal is a SpecError at `path`, named by its last key."""
    try:
        return read_decimal(value)
    except NotADecimal as error:
        raise SpecError(f"{path[-1]} {error.message}", path) from None


_SIZE = f"must be 0 or of size from 1e-{MAX_EXPONENT} to below 1e{MAX_EXPONENT + 1}"


def _zero_or_out_of_range(mantissa: str) -> Decimal:
    if Decimal(mantissa) == 0:
        return Decimal(0)
    raise NotADecimal(_SIZE)


def _within_limits(value: Decimal) -> Decimal:
    if value and not -MAX_EXPONENT <= value.adjusted() <= MAX_EXPONENT:
        raise NotADecimal(_SIZE)
    # Not normalize(): it rounds to the context's 28 digits first.
    if len("".join(map(str, value.as_tuple().digits)).strip("0")) > MAX_DIGITS:
        raise NotADecimal(f"must have at most {MAX_DIGITS} significant digits")
    return value
