"""Tokens of a unit string, from a whitelist: names, integers, `* · ⋅ × / ^ ** ( ) - −`, superscripts.

Anything else is a ParseError at its position. Spaces only separate tokens: letters glued together
form one name (`Nm`), which the parser looks up or splits, so `N m` and `Nm` both reach it as names.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

from physics.errors import ParseError


class Kind(Enum):
    NAME = "name"
    INTEGER = "integer"
    SUPERSCRIPT = "superscript"  # a run such as `⁻²`, already read as its integer value
    TIMES = "times"
    DIVIDE = "divide"
    POWER = "power"
    LPAREN = "("
    RPAREN = ")"
    MINUS = "-"
    PLUS = "+"
    END = "end"


@dataclass(frozen=True)
class Token:
    kind: Kind
    text: str
    position: int
    value: int = 0  # for INTEGER and SUPERSCRIPT


_SINGLE = {
    "*": Kind.TIMES,
    "·": Kind.TIMES,  # middle dot
    "⋅": Kind.TIMES,  # dot operator
    "×": Kind.TIMES,
    "/": Kind.DIVIDE,
    "^": Kind.POWER,
    "(": Kind.LPAREN,
    ")": Kind.RPAREN,
    "-": Kind.MINUS,
    "−": Kind.MINUS,  # Unicode minus
    "+": Kind.PLUS,
}
_SUPERSCRIPT_DIGITS = {c: i for i, c in enumerate("⁰¹²³⁴⁵⁶⁷⁸⁹")}
_SUPERSCRIPT_SIGNS = {"⁻": -1, "⁺": 1}
_MAX_INTEGER_DIGITS = 6


def _is_name_char(char: str) -> bool:
    # `°` is not a letter but begins `°C`; `_` appears in pint names such as `electron_volt`.
    return char.isalpha() or char in "°_"


def tokenize(text: str) -> list[Token]:
    tokens: list[Token] = []
    i = 0
    n = len(text)
    while i < n:
        char = text[i]
        if char.isspace():
            i += 1
            continue
        start = i
        if _is_name_char(char):
            while i < n and _is_name_char(text[i]):
                i += 1
            if i < n and text[i] in "0123456789":
                raise ParseError(
                    f"Write powers of units with ^ (for example m^2 or s^-2), not {text[start : i + 1]!r}",
                    i,
                )
            tokens.append(Token(Kind.NAME, text[start:i], start))
        elif char in "0123456789":
            while i < n and text[i] in "0123456789":
                i += 1
            digits = text[start:i]
            if len(digits) > _MAX_INTEGER_DIGITS:
                raise ParseError("This number is too long for a unit string", start)
            tokens.append(Token(Kind.INTEGER, digits, start, int(digits)))
        elif char in _SUPERSCRIPT_DIGITS or char in _SUPERSCRIPT_SIGNS:
            sign = 1
            if char in _SUPERSCRIPT_SIGNS:
                sign = _SUPERSCRIPT_SIGNS[char]
                i += 1
            digits_start = i
            while i < n and text[i] in _SUPERSCRIPT_DIGITS and i - digits_start < _MAX_INTEGER_DIGITS:
                i += 1
            if i == digits_start:
                raise ParseError("A superscript sign must be followed by superscript digits", start)
            value = 0
            for digit in text[digits_start:i]:
                value = value * 10 + _SUPERSCRIPT_DIGITS[digit]
            tokens.append(Token(Kind.SUPERSCRIPT, text[start:i], start, sign * value))
        elif char == "*" and text.startswith("**", i):
            i += 2
            tokens.append(Token(Kind.POWER, "**", start))
        elif char in _SINGLE:
            i += 1
            tokens.append(Token(_SINGLE[char], char, start))
        else:
            hint = " (use a decimal point, not a comma, and one answer only)" if char == "," else ""
            raise ParseError(f"Unexpected character {char!r} in the units{hint}", start)
    tokens.append(Token(Kind.END, "", n))
    return tokens
