"""Numbers typed with a separator that is not read: a comma inside a number (`4,58`, `1,500`) and digits
grouped by spaces (`12 500`, SI's `0.123 45`). The contract makes both `invalid` (a comma may be a
decimal comma or a thousands separator, and a space may be a product), so nothing here reads such a
number as one: it only says what was seen and what to type instead, for both readers of numbers
(physics/numeric/literal.py and physics/mathinput/tokens.py). Imports nothing of the project but errors.
"""

from __future__ import annotations

import re

from physics.errors import LikelySlip, ParseError

_DIGITS = "0123456789"
# The spaces SI groups digits with (and a phone's no-break space): shown back as a plain space.
_SPACES = " \u00a0\u2009\u202f"
# Arabic script's thousands separator, as an Arabic or Persian keyboard types it: `٤٬٥٨٠`.
ARABIC_THOUSANDS = "٬"
_NUMBER = _DIGITS + ".," + ARABIC_THOUSANDS
_RAISED_DIGITS = "⁰¹²³⁴⁵⁶⁷⁸⁹"
_MINUS_SIGNS = "-−"
# A power typed on a number: `^2`, `**-2`, `^(1/2)`, `^{2}`, `²`, `⁻¹`.
_POWER = re.compile(r"(?:\^|\*\*)\s*[-−+]?(?:\d+(?:\.\d+)?|\([^()]*\)|\{[^{}]*\})|⁻?[⁰¹²³⁴⁵⁶⁷⁸⁹]+")


# A comma braced so that TeX sets no space after it: `4{,}58`, `1{,}500`.
LATEX_COMMA = "{,}"


def comma_in_number(text: str, at: int) -> LikelySlip:
    """Why the comma at `at`, between digits, is refused: a decimal comma (`4,58`: write 4.58), a
    thousands separator (`1,500,000`: write 1500000) or either (`1,500`: asked, naming both). A slip,
    so that no other reader (a numeric answer's arithmetic, its units) has the last word on it. A LaTeX
    comma (`4{,}58`, braced so that TeX sets no space after it) is read as typed commas are: it is a
    decimal comma in one document and a thousands separator in another (`1{,}500`)."""
    seen, start = _typed_number(text, at)
    if text.startswith(LATEX_COMMA, at):
        at += 1  # at the comma inside the braces
    spaced = [k for k, c in enumerate(seen) if c in _SPACES]
    if spaced:  # `1 500,5`: refused where the second number starts, as without the comma
        second = start + spaced[0] + 1
        return LikelySlip(side_by_side(text, start, second).message, second)
    whole, _, after = seen.partition(",")
    if "." in whole:  # `1.500,5`: points between thousands and a decimal comma, or no number at all
        groups = whole.split(".")
        if "," in after or not 1 <= len(groups[0]) <= 3 or any(len(g) != 3 for g in groups[1:]):
            return LikelySlip(f"{seen}: a comma is not read in a number; write it with one decimal point", at)
        return LikelySlip(
            f"{seen}: a comma is not read in a number, nor a point between thousands; write {''.join(groups)}.{after}",
            at,
        )
    if "," in after or "." in seen:  # `1,500,000`, `1,500.5`: thousands separators
        return LikelySlip(f"{seen}: a comma between thousands is not read; write {seen.replace(',', '')}", at)
    if len(after) == 3 and len(whole) <= 3 and whole[0] != "0":
        return LikelySlip(
            f"{seen}: a comma is not read in a number. Did you mean {whole}.{after} or {whole}{after}? Write "
            f"a decimal point for a decimal ({whole}.{after}), and the digits together for thousands "
            f"({whole}{after})",
            at,
        )
    return LikelySlip(f"{seen}: a decimal comma is not read; write {whole}.{after}", at)


def arabic_thousands(text: str, at: int) -> LikelySlip:
    """Why the Arabic thousands separator at `at`, between digits, is refused: the contract reads no
    separator in a number (a comma, a space), and this one is never a decimal one, so it is not asked
    about as `1,500` is: `٤٬٥٨٠` is 4580, to be typed so."""
    seen, _ = _typed_number(text, at)
    whole, _, fraction = seen.partition(".")
    groups = whole.split(ARABIC_THOUSANDS)
    grouped = (
        1 <= len(groups[0]) <= 3 and all(len(g) == 3 for g in groups[1:]) and ARABIC_THOUSANDS not in fraction
    )
    meant = (
        f"write {''.join(groups)}{'.' + fraction if fraction else ''}"
        if grouped
        else "write its digits together, with a point (or ٫) before any decimals"
    )
    return LikelySlip(
        f"{seen}: {ARABIC_THOUSANDS}, the Arabic thousands separator, is not read in a number; {meant}", at
    )


def side_by_side(text: str, start: int, at: int, *, product: bool = False) -> ParseError:
    """Why the digits at `at`, after the number that starts at `start` and a space (`12 500`,
    `0.123 45`, `0 500`), are refused: two numbers side by side, saying how to write the one number
    meant (and, where `product` may be meant, as in a symbolic answer, how to write the product)."""
    end = at
    while end < len(text) and (
        text[end] in _NUMBER or (text[end] in _SPACES and text[end + 1 : end + 2] in tuple(_DIGITS))
    ):
        end += 1
    shown = " ".join(text[start:end].lstrip("+-−").rstrip(".,").split())
    first, _, rest = shown.partition(" ")
    second = rest.split(" ")[0]
    times = f"; for a product, write {first}*{second}" if product else ""
    together = shown.replace(" ", "")
    power = _POWER.match(text, end)
    if power is not None:  # `2 3^2`: the digits are no one number; shown with the power they carry
        raised = f"{shown}{power.group()}"
        if " " in rest:  # `1 500 000^2`
            return ParseError(f"{raised}: numbers side by side; write * between them for a product", at)
        grouped = first.isdecimal() and len(first) <= 3 and len(second) == 3 and second.isdecimal()
        one = f"; for one number, write {first}{second}{power.group()}" if grouped else ""  # `1 500^2`
        return ParseError(
            f"{raised}: two numbers side by side; for a product, write {first}*{rest}{power.group()}{one}", at
        )
    if not second or any(c not in _NUMBER for c in together):  # `4.5e3 12`: nor these
        return ParseError(f"{shown}: two numbers side by side; write one number{times}", at)
    exponent = shown.removeprefix(f"{first} 10 ")
    if shown == f"{first} 10" and first.replace(".", "", 1).isdecimal():
        found = calculator_exponent(text, end)
        if found is not None:  # `4.58 10 -3`: the display of a negative power, its × and ^ left out
            return calculator_exponent_slip(first, found[1], at, typed=text[start : found[2]])
    if exponent.isdecimal() and len(exponent) <= 2 and first.replace(".", "", 1).isdecimal():
        # `4.58 10 3`: a calculator's display with its × and ^ left out (no group of digits is two long)
        return ParseError(
            f"{shown}: numbers side by side. Did you mean {first}×10^{exponent}? For a power of ten, write "
            f"{first}×10^{exponent} or {first}e{exponent}",
            at,
        )
    if second == "10" and shown == f"{first} 10":  # `4.58 10`: a calculator's ×10 with its exponent left out
        return ParseError(
            f"{shown}: two numbers side by side; for a power of ten, write {first}×10^ and its exponent (as "
            f"in {first}×10^3), or {first}e10 for {first}×10^10{times}",
            at,
        )
    if first == "0":  # `0 500`: no group of digits starts with a lone 0
        return ParseError(f"{shown}: two numbers side by side. Did you mean 0.{second} or {second}?", at)
    if together.count(",") == 1 and "." not in together:  # `1 500,5`: the comma a decimal one
        together = together.replace(",", ".")
    together = together.replace(",", "")
    if together.count(".") > 1:
        return ParseError(
            f"{shown}: two numbers side by side; write one number, its digits together{times}", at
        )
    return ParseError(
        f"{shown}: two numbers side by side; for one number, write {together}{_scientific(together)}{times}",
        at,
    )


def calculator_exponent(text: str, after: int) -> tuple[int, str, int] | None:
    """`10-3`, `10 -3`, `10- 3` after the 10 ending at `after`: a calculator's negative exponent typed
    without its ^ (where the minus stands, the exponent's digits, where they end); None where no minus
    and digits follow, or where the minus is spaced on both sides (`10 - 3`, a subtraction)."""
    minus = after
    while minus < len(text) and text[minus].isspace():
        minus += 1
    if minus == len(text) or text[minus] not in _MINUS_SIGNS:
        return None
    digits = minus + 1
    while digits < len(text) and text[digits].isspace():
        digits += 1
    end = digits
    while end < len(text) and text[end] in _DIGITS:
        end += 1
    if end == digits or (minus > after and digits > minus + 1):
        return None
    return minus, text[digits:end], end


def calculator_exponent_slip(
    mantissa: str, exponent: str, at: int, *, typed: str | None = None, negative: bool = True
) -> LikelySlip:
    """Why `3.0 x 10-3` (or, `typed` as it stands, `4.58 10 -3`, its × left out too) is refused: a
    calculator's display of mantissa×10^-exponent, which as arithmetic would be 3.0·10 − 3; asked as
    `4.58 10 3` is. Not `negative`: `g sin α 10 3`, the display of a positive power after symbols."""
    sign = "-" if negative else ""
    meant = f"{mantissa}×10^{sign}{exponent}"
    # `g sin α 10 -3`: a mantissa of symbols has no `e` form
    scientific = f", or {mantissa}e{sign}{exponent}" if mantissa.replace(".", "", 1).isdecimal() else ""
    if not negative:
        return LikelySlip(
            f"10 {exponent}: numbers side by side. Did you mean {meant}? Write the power of ten with ^ "
            f"({meant}{scientific}); for a product, write {mantissa}*10*{exponent}",
            at,
        )
    if typed is not None:
        shown = " ".join(typed.split())
        return LikelySlip(
            f"{shown}: numbers side by side. Did you mean {meant}? For a power of ten, write {meant} or "
            f"{mantissa}e-{exponent}",
            at,
        )
    return LikelySlip(
        f"Did you mean {meant}? Write the power of ten with ^ ({meant}{scientific}); for a "
        f"subtraction, put spaces round the minus (10 - {exponent})",
        at,
    )


def number_after_a_power(base: str, exponent: str, number: str, at: int) -> ParseError:
    """Why `x^2 3`, a number typed after a power (`base` ^ `exponent`), is refused: as typed, two numbers
    side by side, the exponent and the number; saying how to write the product, or the power meant."""
    power = f"{base}^{exponent}"
    times = "*" if base[-1:] in _DIGITS else " "  # `2^2 3`: 3*2^2, never the numbers 3 2^2 side by side
    whole_exponent = exponent.lstrip("+-").isdecimal()
    if whole_exponent and any(c in number for c in "^" + _RAISED_DIGITS):  # `x^2 10^3`: times a power
        meant = f"; for the power, write {base}^({exponent}·{number})"
    elif whole_exponent and number.isdecimal():  # `x^2 3`: the digits of one exponent
        meant = f"; for the power, write {base}^({exponent}{number})"
    else:
        meant = ""
    return ParseError(
        f"{power} {number}: the number after a power is a separate factor, not part of the exponent: for "
        f"the product, write {number}{times}{power}{meant}",
        at,
    )


def power_of_ten_apart(text: str, start: int, ten: int, end: int) -> LikelySlip:
    """Why `4.58 10^3`, a calculator's display with its × left out, is refused: two numbers side by
    side (the number from `start`, the power of ten from `ten` to `end`), saying where the × goes."""
    mantissa, power = text[start:ten].strip(), text[ten:end].strip()
    return LikelySlip(
        f"{mantissa} {power}: two numbers side by side; for a power of ten, write {mantissa}×{power}", ten
    )


def _typed_number(text: str, at: int) -> tuple[str, int]:
    """The digits, points, commas and spaces between digits around `at`, as typed, and where they start."""

    def inside(k: int) -> bool:
        if text[k] in _NUMBER or LATEX_COMMA in (text[k : k + 3], text[k - 2 : k + 1]):
            return True
        return (
            text[k] in _SPACES and 0 < k < len(text) - 1 and text[k - 1] in _DIGITS and text[k + 1] in _DIGITS
        )

    start = at
    while start > 0 and inside(start - 1):
        start -= 1
    end = at
    while end < len(text) and inside(end):
        end += 1
    seen = (
        text[start:end].replace(LATEX_COMMA, ",").rstrip(".,")
    )  # a full stop ending the answer is no decimal point
    return seen.lstrip(".,"), start + len(seen) - len(seen.lstrip(".,"))


def _scientific(whole: str) -> str:
    """` (or 12.5e3)` for a whole number of thousands or more, in the engineering notation physics uses."""
    if "." in whole or len(whole) < 4 or whole[0] == "0":
        return ""
    power = (len(whole) - 1) // 3 * 3
    head, tail = whole[:-power], whole[-power:].rstrip("0")
    return f" (or {head}.{tail}e{power})" if tail else f" (or {head}e{power})"
