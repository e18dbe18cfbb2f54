"""Reading the number at the start of a numeric answer, exactly, with its significant figures.

Accepted: an optional sign (`-`, `−`, `+`), a decimal literal (`4.58`, `.5`, `1500`, `100.`), an
optional power of ten (`e3`, `E-3`, `×10^3`, `x 10^3`, `*10**3`, `·10⁻³`, `10^3` alone, Mathematica's `*^3`) and an optional `%` (or `percent`).
Size limits are checked on the raw characters before any arithmetic, so `1e999999` costs nothing.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction

from physics import separators
from physics.errors import LikelySlip, ParseError, TooLarge

MAX_DIGITS = 40
MAX_EXPONENT = 400

_DIGITS = "0123456789"
# Digit-group separators other than the comma: programming's `1_500`, and the Swiss `1'500`.
_DIGIT_SEPARATORS = "_'’"
_MINUS_SIGNS = "-−"
_TIMES_SIGNS = "×xX*·⋅"
_SUPERSCRIPT_DIGITS = {c: i for i, c in enumerate("⁰¹²³⁴⁵⁶⁷⁸⁹")}
_SUPERSCRIPT_SIGNS = "⁻⁺"


@dataclass(frozen=True)
class NumberLiteral:
    """A number as the student wrote it: exact value, and the digits that fix its significant figures."""

    negative: bool
    integer_digits: str  # before the decimal point ("" for `.5`)
    fraction_digits: str  # after it
    has_point: bool
    exponent: int | None  # the power of ten, when written
    percent: bool
    position: int  # where the number starts in the answer
    end: int  # just past the number (and its `%`)

    @property
    def value(self) -> Fraction:
        mantissa = Fraction(
            int(self.integer_digits + self.fraction_digits or "0"), 10 ** len(self.fraction_digits)
        )
        result = mantissa * Fraction(10) ** (self.exponent or 0)
        if self.percent:
            result /= 100
        return -result if self.negative else result

    @property
    def sigfig_range(self) -> tuple[int, int]:
        """The significant figures shown, as (fewest, most): trailing zeros of `1500` may or may not count."""
        digits = (self.integer_digits + self.fraction_digits).lstrip("0")
        if not digits:  # zero: the places shown after the point, at least one
            shown = max(1, len(self.fraction_digits))
            return shown, shown
        if self.has_point:
            return len(digits), len(digits)
        return len(digits.rstrip("0")), len(digits)

    def _mantissa_text(self) -> str:
        text = (self.integer_digits or "0") + ("." + self.fraction_digits if self.has_point else "")
        return ("-" if self.negative else "") + text

    @property
    def text(self) -> str:
        """Plain text: `4.58e3`, `-0.5`, `45%`."""
        exponent = f"e{self.exponent}" if self.exponent is not None else ""
        return self._mantissa_text() + exponent + ("%" if self.percent else "")

    @property
    def latex(self) -> str:
        """LaTeX: `4.58 \\times 10^{3}`, `45\\,\\%`."""
        text = self._mantissa_text()
        if self.exponent is not None:
            text += rf" \times 10^{{{self.exponent}}}"
        return text + (r"\,\%" if self.percent else "")


# LaTeX, as equation editors paste a number: `4.58 \\times 10^{3}`, `4.58\\,\\mathrm{m}`, `45\\,\\%`.
_LATEX_SPACES = ("\\,", "\\;", "\\:", "\\!", "\\ ", "~")
_LATEX_TIMES = ("\\times", "\\cdot")


def skip_spaces(text: str, i: int) -> int:
    while i < len(text):
        if text[i].isspace():
            i += 1
        elif text.startswith(_LATEX_SPACES, i) and "\\" in text:
            i += 1 if text[i] == "~" else 2
        else:
            break
    return i


def _times_sign_end(text: str, j: int) -> int | None:
    """The end of a times sign at j (`×`, `*`, `\\times`, `\\cdot`), or None."""
    if j < len(text) and text[j] in _TIMES_SIGNS:
        return j + 1
    for command in _LATEX_TIMES:
        if text.startswith(command, j) and not text[j + len(command) : j + len(command) + 1].isalpha():
            return j + len(command)
    return None


# Signs that may join a number to its units (`12.3*m/s`, `12.3·m/s`): `x` is left out, being a letter.
_JOINING_SIGNS = "*·⋅×"


def units_start(text: str, i: int) -> int:
    """Where the units after the number ending at i start: past spaces, and past a times sign that joins
    the number to its units (`12.3*m/s`, `12.3 · m/s`, `12.3\\cdot\\mathrm{m/s}`), as STACK and Maxima
    write a quantity. A sign before a number (`4*3 m`) or before nothing is left for arithmetic."""
    j = skip_spaces(text, i)
    times_end = _times_sign_end(text, j)
    if times_end is None or (text[j] in _TIMES_SIGNS and text[j] not in _JOINING_SIGNS):
        return j
    k = skip_spaces(text, times_end)
    if k == len(text) or text[k] in _DIGITS + ".,":
        return j
    return k


def _run(text: str, i: int, alphabet: str | dict[str, int]) -> int:
    while i < len(text) and text[i] in alphabet:
        i += 1
    return i


def _exponent_value(digits: str, sign: int, position: int) -> int:
    significant = digits.lstrip("0")
    if len(significant) > len(str(MAX_EXPONENT)) or int(significant or "0") > MAX_EXPONENT:
        raise TooLarge(f"The power of ten is too large (at most {MAX_EXPONENT} either way)", position)
    return sign * int(significant or "0")


def _signed_exponent(text: str, i: int) -> tuple[int, int] | None:
    """An ASCII exponent `3`, `-3`, `−3`, `+3`, `(-3)` at i: (value, end), or None if there is none."""
    parenthesised = i < len(text) and text[i] in "({"  # `^(-3)`, or LaTeX's `^{-3}`
    j = i + 1 if parenthesised else i
    sign = 1
    if j < len(text) and text[j] in _MINUS_SIGNS + "+":
        sign = -1 if text[j] in _MINUS_SIGNS else 1
        j += 1
    end = _run(text, j, _DIGITS)
    if end == j:
        return None
    if parenthesised:
        if end >= len(text) or text[end] != {"(": ")", "{": "}"}[text[i]]:
            return None
        return _exponent_value(text[j:end], sign, j), end + 1
    return _exponent_value(text[j:end], sign, j), end


def _superscript_exponent(text: str, i: int) -> tuple[int, int] | None:
    sign = 1
    j = i
    if j < len(text) and text[j] in _SUPERSCRIPT_SIGNS:
        sign = -1 if text[j] == "⁻" else 1
        j += 1
    end = _run(text, j, _SUPERSCRIPT_DIGITS)
    if end == j:
        return None
    digits = "".join(str(_SUPERSCRIPT_DIGITS[c]) for c in text[j:end])
    return _exponent_value(digits, sign, j), end


def _power_of_ten(text: str, i: int) -> tuple[int, int] | None:
    """`^3`, `**3`, `^(-3)` or `⁻³` right after a `10`: (exponent, end), or None."""
    if text.startswith("**", i):
        return _signed_exponent(text, i + 2)
    if i < len(text) and text[i] == "^":
        return _signed_exponent(text, i + 1)
    return _superscript_exponent(text, i)


# The exponent marks of calculators' displays: a TI's small capital E, and the decimal exponent symbol.
_CALCULATOR_EXPONENTS = "ᴇ⏨"


def _scientific(text: str, i: int, start: int) -> tuple[int, int] | None:
    """A power of ten after the mantissa from `start` to i: (exponent, end), or None if none is written."""
    if "E" in text or "x" in text:  # `2.5 EXP -3`, `2.5EE-3`: a calculator's key for the power of ten
        _refuse_calculator_key(text, text[start:i], skip_spaces(text, i))
    if i < len(text) and text[i] in _CALCULATOR_EXPONENTS:  # `4.58ᴇ3`: a TI calculator's small capital E
        return _signed_exponent(text, i + 1)
    if text.startswith("*^", i):  # `4.58*^3`: Mathematica's power of ten, as its output is copied
        return _signed_exponent(text, i + 2)
    if i < len(text) and text[i] in "eE":
        found = _signed_exponent(text, i + 1)
        if found is None and (i + 1 == len(text) or text[i + 1].isspace()):
            # `2.5e m`: a power of ten with its digits left out, or 2.5 times e? (`2.5eV` is a unit)
            mantissa = text[start:i]
            raise LikelySlip(
                f"Did you mean a power of ten, as in {mantissa}{text[i]}3, or {mantissa} times Euler's number e "
                f"(write {mantissa}*e)?",
                i,
            )
        return found
    j = skip_spaces(text, i)
    if j > i and j < len(text) and text[j] in "eE":
        _refuse_spaced_exponent(text, text[start:i], j)
    times_end = _times_sign_end(text, j)
    if times_end is None and j > i and text.startswith("10", j):  # `4.58 10^3`: two numbers, never one
        found = _power_of_ten(text, j + 2)
        if found is None:
            _refuse_calculator_exponent(text, text[start:i], j + 2, apart_from=start)  # `4.58 10-3`
            return None
        raise separators.power_of_ten_apart(text, start, j, found[1])
    if times_end is not None:
        k = skip_spaces(text, times_end)
        if text.startswith("10", k):
            after = k + 2
            if after < len(text) and text[after] in _DIGITS + ".,":
                return None  # `4 × 100`: not a power of ten; the unit reader will refuse it
            found = _power_of_ten(text, after)
            if found is None:
                _refuse_calculator_exponent(text, text[start:i], after)
                _refuse_two_powers_of_ten(text, text[start:i], after)
                digits = skip_spaces(text, after)
                exponent = text[digits : _run(text, digits, _DIGITS)]
                if digits > after and 0 < len(exponent) <= 2:  # `1.2 x 10 4`: its ^ left out
                    meant = f"{text[start:i]}×10^{exponent}"
                    raise LikelySlip(
                        f"Did you mean {meant}? Write the power of ten with ^, as {meant}", after
                    )
                raise ParseError("Write a power of ten with its exponent, for example 2.5×10^3", after)
            return found
    return None


_INCHES_AFTER_FEET = re.compile(r"['’′]\s*(\d+(?:\.\d+)?)\s*(?:[\"”″]|'')")
_PRIMES = "'’′"


def _refuse_feet_and_inches(text: str, feet: str, at: int) -> None:
    """ParseError for `5'10"`, `5′ 11″`, a height in feet and inches: not the Swiss thousands separator
    `1'500`."""
    found = _INCHES_AFTER_FEET.match(text, at)
    if found is not None and feet and len(found.group(1)) <= MAX_DIGITS:
        inches = Decimal(feet) * 12 + Decimal(found.group(1))  # exact: `5' 10.5"` is 70.5 in
        raise ParseError(
            f"Feet and inches ({text[: found.end()].strip()}): write one number in one unit, as {inches} in",
            at,
        )


def _refuse_calculator_exponent(
    text: str, mantissa: str, after: int, *, apart_from: int | None = None
) -> None:
    """Refuses `3.0 x 10-3`, a calculator's exponent typed after `×10` (ending at `after`) without its `^`:
    as arithmetic it would be 3.0·10 − 3 = 27, which no one means by it, so it is refused whatever the
    arithmetic reader makes of it, asking "Did you mean 3.0×10^-3?". A minus spaced on both sides,
    `3 × 10 - 3`, is arithmetic. `apart_from`: where the mantissa starts, when its × is left out too
    (`4.58 10 -3`, refused as numbers side by side, as `4.58 10 3` is)."""
    found = separators.calculator_exponent(text, after)
    if found is None:
        return
    minus, exponent, end = found
    if apart_from is None:
        raise separators.calculator_exponent_slip(mantissa, exponent, minus)
    raise separators.calculator_exponent_slip(mantissa, exponent, after - 2, typed=text[apart_from:end])


_SPACED_EXPONENT = re.compile(r"[eE][-−+]?\d+(?![\w.])")


def _refuse_spaced_exponent(text: str, mantissa: str, at: int) -> None:
    """LikelySlip for `1.6 E-19 C`: a power of ten typed apart from its number, which the units would read
    as a unit E to the power −19."""
    found = _SPACED_EXPONENT.match(text, at)
    if found is not None:
        typed = found.group().replace("−", "-")
        raise LikelySlip(
            f"Did you mean {mantissa}{typed}? Write a power of ten without a space before its {typed[0]}",
            at,
        )


# A calculator's key for the power of ten, as its label reads, and the exponent typed after it.
_CALCULATOR_KEY = re.compile(r"(EXP|Exp|exp|EE)\s*([-−+]?\d+)(?![\w.])")


def _refuse_calculator_key(text: str, mantissa: str, at: int) -> None:
    """LikelySlip for `2.5 EXP -3 m`, `2.5EE-3 m`: a power of ten as a calculator's key labels it, which
    the units would read as a unit EXP."""
    found = _CALCULATOR_KEY.match(text, at)
    if found is not None:
        key, exponent = found.group(1), found.group(2).replace("−", "-")
        raise LikelySlip(
            f"Did you mean {mantissa}E{exponent}? A calculator's {key} key is a power of ten: write "
            f"{mantissa}E{exponent} or {mantissa}×10^{exponent}",
            at,
        )


def _refuse_two_powers_of_ten(text: str, mantissa: str, after: int) -> None:
    """LikelySlip if `e3` (or `E-3`) follows the `×10` ending at `after`: `3.0×10e8` marks the power of
    ten twice, and is 3.0×10^9 as typed, where 3.0×10^8 is what is meant most often."""
    if after >= len(text) or text[after] not in "eE":
        return
    exponent = _signed_exponent(text, after + 1)
    if exponent is None:
        return
    typed = text[after + 1 : exponent[1]]
    raise TwoPowersOfTen(mantissa, text[after], typed, after)


class TwoPowersOfTen(LikelySlip):
    """`3.0×10e8`: ×10 and e both mark a power of ten. Read as typed it is 3.0×10^9, which few who type
    it mean: refused, saying how to write each reading."""

    def __init__(self, mantissa: str, letter: str, exponent: str, position: int) -> None:
        super().__init__(
            f"Did you mean {mantissa}×10^{exponent} or {mantissa}{letter}{exponent}? ×10 and {letter} each mark a "
            f"power of ten: write one of them, not both",
            position,
        )


def side_by_side(text: str, number: NumberLiteral, at: int) -> ParseError:
    """Why digits after a number and a space (`12 500`, `0.123 45`, `0 500`, `4 .58`) are refused: two
    numbers, saying what was seen and how to write the one number meant."""
    fraction_end = _run(text, at + 1, _DIGITS)
    if (
        text[at] == "."
        and fraction_end > at + 1
        and not (number.has_point or number.percent)
        and number.exponent is None
    ):
        meant = f"{text[number.position : number.end].strip()}.{text[at + 1 : fraction_end]}"
        return ParseError(f"Did you mean {meant}? Type a decimal number without a space: write {meant}", at)
    if number.exponent is not None or number.percent or text[at] not in _DIGITS:
        typed = text[number.position : number.end].strip()
        after = text[at : _run(text, at, _DIGITS)] or text[at]
        return ParseError(f"Read as {typed} and then {after}, two numbers side by side: write one number", at)
    return separators.side_by_side(text, number.position, at)


def _refuse_raised_point(text: str, integer_digits: str, at: int) -> None:
    """LikelySlip for `4·58`: a raised dot between whole numbers is a decimal point in British print and
    a product elsewhere, so asked, naming both. A power of ten (`2·10^3`) or a decimal after the dot
    (`2·9.8`) says it is a product."""
    if not text.startswith("·", at):
        return
    end = _run(text, at + 1, _DIGITS)
    after = text[at + 1 : end]
    if (
        not after
        or text[end : end + 1] in (".", ",")
        or (after == "10" and _power_of_ten(text, end) is not None)
    ):
        return
    raise LikelySlip(
        f"Did you mean {integer_digits}.{after} or {integer_digits}×{after}? A raised dot between digits is a "
        f"decimal point in British print and a product elsewhere: write {integer_digits}.{after} for the "
        f"decimal, or {integer_digits}*{after} for the product",
        at,
    )


def read_number(text: str, start: int = 0) -> NumberLiteral:
    """The number at the start of `text` (after spaces), or ParseError / TooLarge with a position."""
    i = skip_spaces(text, start)
    position = i
    negative = False
    if i < len(text) and text[i] in _MINUS_SIGNS + "+":
        negative = text[i] in _MINUS_SIGNS
        i = skip_spaces(text, i + 1)
    integer_end = _run(text, i, _DIGITS)
    integer_digits = text[i:integer_end]
    has_point = integer_end < len(text) and text[integer_end] == "."
    fraction_start = integer_end + 1 if has_point else integer_end
    fraction_end = _run(text, fraction_start, _DIGITS)
    fraction_digits = text[fraction_start:fraction_end]
    if not integer_digits and not fraction_digits:
        raise ParseError("The answer must start with a number, such as 2.5 or -0.5", i)
    if len(integer_digits) + len(fraction_digits) > MAX_DIGITS:
        raise TooLarge(f"A number may have at most {MAX_DIGITS} digits", i)
    i = fraction_end
    if i < len(text) and text[i] in _PRIMES and not has_point:  # `5′ 11″`, `5' 10.5"`
        _refuse_feet_and_inches(text, integer_digits, i)
    if i + 1 < len(text) and text[i] == "," and text[i + 1] in _DIGITS:
        raise separators.comma_in_number(text, i)
    if text.startswith(separators.LATEX_COMMA, i) and i + 3 < len(text) and text[i + 3] in _DIGITS:
        raise separators.comma_in_number(text, i)
    if i + 1 < len(text) and text[i] == separators.ARABIC_THOUSANDS and text[i + 1] in _DIGITS:
        raise separators.arabic_thousands(text, i)
    if i + 1 < len(text) and text[i] in _DIGIT_SEPARATORS and text[i + 1] in _DIGITS:
        _refuse_feet_and_inches(text, integer_digits, i)
        raise ParseError(f"Write a number without separators: 1500, not 1{text[i]}500", i)
    if i < len(text) and text[i] == "." and i + 1 < len(text) and text[i + 1] in _DIGITS:
        raise ParseError("A number has at most one decimal point", i)
    if not has_point and integer_digits:
        _refuse_raised_point(text, integer_digits, i)
    exponent: int | None = None
    if not has_point and integer_digits == "10" and not negative:
        # A bare power of ten, `10^3`, is 1×10^3.
        bare = _power_of_ten(text, i)
        if bare is not None:
            return _finish(text, "1", "", False, bare[0], bare[1], negative, position)
    found = _scientific(text, i, position)
    if found is not None:
        exponent, i = found
    return _finish(text, integer_digits, fraction_digits, has_point, exponent, i, negative, position)


_PERCENT_WORDS = re.compile(r"per\s?cent\b", re.IGNORECASE)  # `45 percent`, `45 per cent`


def _percent_end(text: str, j: int) -> int | None:
    """The end of a percent sign (`%`, `\\%`) or word at j, else None."""
    if text.startswith("%", j):
        return j + 1
    if text.startswith("\\%", j):
        return j + 2
    word = _PERCENT_WORDS.match(text, j)
    return None if word is None else word.end()


def _finish(
    text: str,
    integer_digits: str,
    fraction_digits: str,
    has_point: bool,
    exponent: int | None,
    i: int,
    negative: bool,
    position: int,
) -> NumberLiteral:
    j = skip_spaces(text, i)
    percent_end = _percent_end(text, j)
    percent = percent_end is not None
    if percent_end is not None:
        i = percent_end
    return NumberLiteral(
        negative=negative,
        integer_digits=integer_digits,
        fraction_digits=fraction_digits,
        has_point=has_point,
        exponent=exponent,
        percent=percent,
        position=position,
        end=i,
    )
