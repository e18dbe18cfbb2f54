"""Tokens of a unit string, from a whitelist: names, integers, `* · ⋅ × . / ^ ** ( ) - −`, superscripts.

Anything else is a ParseError at its position. Spaces only separate tokens: letters glued together
form one name (`Nm`), which the parser looks up or splits, so `N m` and `Nm` both reach it as names.
A name with a negative integer glued to it is a power, as textbooks print it (`m s-2` is m·s⁻²), and
`N.m` and `N-m` are N·m. Units said in words read as written: `per` divides (`per second` alone is 1/s),
`squared` and `cubed` raise the unit before them (`metres per second squared` is m/s²), `sq`, `square`,
`cu` and `cubic` the unit after them (`sq ft`, `cubic centimetres`), or before them where none follows
(`m/s sq`); `fl oz` is the fluid ounce, and a degree word before a temperature scale one unit (`deg C`,
`degrees Fahrenheit` are °C, °F).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace
from enum import Enum

from physics.errors import AnswerError, LikelySlip, ParseError
from physics.units.catalogue import ALIASES, SPELLINGS_WITH_DIGITS
from physics.units.latex import plain_units
from physics.wording import ARROWS, DIRECTION_BY_SIGN


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
    ".": Kind.TIMES,  # `N.m`, `kg.m/s^2`
    "∙": Kind.TIMES,  # the bullet operator and bullet a word processor's symbol menu gives
    "•": Kind.TIMES,
    "∗": Kind.TIMES,
    "/": Kind.DIVIDE,
    "⁄": Kind.DIVIDE,  # the fraction slash and division slash, as the math reader takes them
    "∕": Kind.DIVIDE,
    "÷": Kind.DIVIDE,
    "^": Kind.POWER,
    "(": Kind.LPAREN,
    ")": Kind.RPAREN,
    "-": Kind.MINUS,
    "−": Kind.MINUS,  # Unicode minus
    "–": Kind.MINUS,  # the en dash a word processor makes of a minus (`m s–2`)
    "‐": Kind.MINUS,  # the hyphen and the non-breaking hyphen of a word processor
    "‑": Kind.MINUS,
    "+": Kind.PLUS,
}
# Words that are operators, as a student says a unit: no unit has these names.
_WORD_POWERS = {"squared": 2, "cubed": 3}
_LEADING_POWERS = {"sq": 2, "square": 2, "cu": 3, "cubic": 3}  # `sq ft`, `cubic metres`


def _word_tokens(word: str, position: int, first: bool) -> list[Token] | None:
    """The tokens a word standing for an operator stands for (`per`, `squared`, `cubed`), or None;
    a `per` that comes first is `1/` (`4.58 per second`, a rate)."""
    lowered = word.lower()
    if lowered == "per":
        divide = Token(Kind.DIVIDE, word, position)
        return [Token(Kind.INTEGER, "1", position, 1), divide] if first else [divide]
    if lowered in _WORD_POWERS:
        power = _WORD_POWERS[lowered]
        return [Token(Kind.POWER, word, position), Token(Kind.INTEGER, str(power), position, power)]
    return None


_SUPERSCRIPT_DIGITS = {c: i for i, c in enumerate("⁰¹²³⁴⁵⁶⁷⁸⁹")}
_SUPERSCRIPT_SIGNS = {"⁻": -1, "⁺": 1}
_PLAIN_DIGITS = {c: i for i, c in enumerate("0123456789")}
_MAX_INTEGER_DIGITS = 6


def _is_name_char(char: str) -> bool:
    # `°` is not a letter but begins `°C`; `_` appears in pint names such as `electron_volt`; `℃` and
    # `℉` are one character each for °C and °F (catalogue.ALIASES).
    return char.isalpha() or char in "°_℃℉"


_MINUS_SIGNS = "-−–‐‑"  # the minus, and the dashes a word processor makes of one
_AS_HYPHEN = str.maketrans(dict.fromkeys(_MINUS_SIGNS[1:], "-"))


def _glued_negative_power(text: str, i: int) -> int | None:
    """The end of a `-2` glued to the name ending at i (`s-2`, `s–2`), or None."""
    if i + 1 < len(text) and text[i] in _MINUS_SIGNS and text[i + 1] in "0123456789":
        end = i + 1
        while end < len(text) and text[end] in "0123456789":
            end += 1
        return end
    return None


# A degree sign typed as a power of the number before the units: `30^o`, `30 ^{o}`, `30^°`, `25^oC`.
_DEGREE_AS_POWER = re.compile(r"\s*\^\s*(?:[o°]|\{\s*[o°]\s*\})(?=[CFK]?(?![\w°]))")
# A degree sign typed as a zero: `30^0`, `30⁰` (30 to the power 0 is 1, which no one writes so).
_DEGREE_AS_ZERO = re.compile(r"\s*(?:\^\s*(?:0|\{\s*0\s*\})|⁰)(?![\d.⁰-⁹])")


def _degree_sign_typed_as_power(text: str) -> str:
    """The units with a leading `^o` as the degree sign, padded with spaces so positions stay as typed;
    ParseError for a leading `^0`, asking whether a degree was meant."""
    zero = _DEGREE_AS_ZERO.match(text)
    if zero is not None:
        raise LikelySlip(
            "Did you mean degrees? A power 0 makes the number 1: for degrees write ° or deg, as in 30°",
            zero.start() + len(zero.group()) - len(zero.group().lstrip()),
        )
    power = _DEGREE_AS_POWER.match(text)
    if power is None:
        return text
    return " " * (power.end() - 1) + "°" + text[power.end() :]


def tokenize(text: str) -> list[Token]:
    """The tokens of a unit string; LaTeX (`\\mathrm{m/s^2}`) is read as the plain units it shows, with
    positions into what was typed."""
    if "^" in text or "⁰" in text:
        text = _degree_sign_typed_as_power(text)
    if "\\" not in text and "{" not in text and "}" not in text:
        return _tokenize(text)
    plain, where = plain_units(text)
    try:
        tokens = _tokenize(plain)
    except AnswerError as error:
        if error.position is not None:
            error.position = where[error.position]
        raise
    return [replace(token, position=where[token.position]) for token in tokens]


# A plural written with an apostrophe, as pilots and riders say an acceleration: `5 g's`, `3 G's`.
_APOSTROPHE_PLURALS = {"g": "gs", "G": "gs"}


def _apostrophe_plural_end(text: str, word: str, i: int) -> int | None:
    """The end of `'s` after a word of _APOSTROPHE_PLURALS ending at i, else None."""
    if word not in _APOSTROPHE_PLURALS or text[i : i + 2] not in ("'s", "’s"):
        return None
    end = i + 2
    return None if end < len(text) and _is_name_char(text[end]) else end


def _after_word(text: str, i: int) -> int:
    """Past the full stop of an abbreviation (`sq.`, `fl.`) and spaces after the word ending at i."""
    if i < len(text) and text[i] == ".":
        i += 1
    while i < len(text) and text[i].isspace():
        i += 1
    return i


def _fluid_ounce_end(text: str, word: str, i: int) -> int | None:
    """The end of `fl oz` (`fl. oz`) when the word `fl` ends at i, else None."""
    if word != "fl":
        return None
    j = _after_word(text, i)
    if text.startswith("oz", j) and not (j + 2 < len(text) and _is_name_char(text[j + 2])):
        return j + 2
    return None


# A temperature said with its degree apart (`deg C`, `degrees Celsius`, `° C`, `deg. F`): one unit, never
# an angle times a coulomb (or a farad), which converts to nonsense with a temperature's dimension.
_DEGREE_WORDS = frozenset({"°", "deg", "degs", "degree", "degrees", "Deg", "Degree", "Degrees"})
_TEMPERATURE_WORDS = {
    **dict.fromkeys(("C", "c", "Celsius", "celsius", "Centigrade", "centigrade"), "°C"),
    **dict.fromkeys(("F", "f", "Fahrenheit", "fahrenheit"), "°F"),
    **dict.fromkeys(("K", "Kelvin", "kelvin"), "K"),
}


def _temperature(text: str, word: str, i: int) -> tuple[str, int] | None:
    """The temperature unit and its end when a degree word ending at i is followed by a temperature
    scale (`deg C`), else None."""
    if word not in _DEGREE_WORDS:
        return None
    j = _after_word(text, i)
    end = j
    while end < len(text) and _is_name_char(text[end]):
        end += 1
    unit = _TEMPERATURE_WORDS.get(text[j:end])
    return None if unit is None else (unit, end)


def _tokenize(text: str) -> list[Token]:
    tokens: list[Token] = []
    i = 0
    n = len(text)
    leading: tuple[int, Token] | None = None  # `sq`, `cubic`: the power waiting for the next unit
    while i < n:
        char = text[i]
        if char.isspace():
            i += 1
            continue
        start = i
        if leading is not None and not _is_name_char(char):
            _raise_the_unit_before(tokens, leading)
            leading = None
        if _is_name_char(char):
            while i < n and _is_name_char(text[i]):
                i += 1
            word = text[start:i]
            if word.lower() in _LEADING_POWERS and leading is None:
                power = _LEADING_POWERS[word.lower()]
                leading = (power, Token(Kind.POWER, word, start))
                i = _after_word(text, i)
                continue
            plural_end = _apostrophe_plural_end(text, word, i)
            if plural_end is not None:
                tokens.append(Token(Kind.NAME, _APOSTROPHE_PLURALS[word], start))
                i = plural_end
                _raise_by(tokens, leading)
                leading = None
                continue
            temperature = _temperature(text, word, i)
            if temperature is not None:
                tokens.append(Token(Kind.NAME, temperature[0], start))
                i = temperature[1]
                _raise_by(tokens, leading)
                leading = None
                continue
            fluid_ounce_end = _fluid_ounce_end(text, word, i)
            if fluid_ounce_end is not None:
                tokens.append(Token(Kind.NAME, "floz", start))
                i = fluid_ounce_end
                _raise_by(tokens, leading)
                leading = None
                continue
            # `m/s2`, `cm3`: a power typed without its ^, as students write it (and as `s-2` is read),
            # unless the digits belong to the unit's spelling (`g0`, `g_0`: standard gravity)
            digits_end = i
            while digits_end < n and text[digits_end] in "0123456789":
                digits_end += 1
            if digits_end > i and text[start:digits_end] in SPELLINGS_WITH_DIGITS:
                tokens.append(Token(Kind.NAME, text[start:digits_end], start))
                i = digits_end
                _raise_by(tokens, leading)
                leading = None
                continue
            glued_power = i < n and text[i] in "0123456789"
            power_end = _glued_negative_power(text, i)
            spelled = text[start:power_end].translate(_AS_HYPHEN) if power_end is not None else ""
            if power_end is not None and spelled in ALIASES:  # `ms-1`, `ms–1`
                tokens.append(Token(Kind.NAME, spelled, start))
                i = power_end
                continue
            words = _word_tokens(text[start:i], start, first=not tokens)
            if words is not None:
                tokens.extend(words)
                if glued_power:
                    tokens.append(Token(Kind.POWER, "^", i))
                continue
            tokens.append(Token(Kind.NAME, text[start:i], start))
            if power_end is not None or glued_power:
                if leading is not None:
                    raise ParseError(f"Give {leading[1].text!r} or a power, not both", i)
                tokens.append(Token(Kind.POWER, "^", i))
            _raise_by(tokens, leading)
            leading = None
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
            # `s⁻2`: the sign from a phone's palette, the digits from its keyboard
            digit_values = _SUPERSCRIPT_DIGITS if text[i : i + 1] not in _PLAIN_DIGITS else _PLAIN_DIGITS
            while i < n and text[i] in digit_values and i - digits_start < _MAX_INTEGER_DIGITS:
                i += 1
            if i == digits_start:
                raise ParseError("A superscript sign must be followed by superscript digits", start)
            value = 0
            for digit in text[digits_start:i]:
                value = value * 10 + digit_values[digit]
            if (
                tokens
                and tokens[-1].kind is Kind.POWER
                and tokens[-1].position + len(tokens[-1].text) == start
            ):
                tokens.pop()  # `s^²`: the caret, then the superscript from a palette, is the one power
            elif (
                len(tokens) >= 2
                and tokens[-1].kind is Kind.MINUS
                and tokens[-1].position + 1 == start
                and tokens[-2].kind in (Kind.POWER, Kind.NAME)
                and tokens[-2].position + len(tokens[-2].text) == tokens[-1].position
            ):
                # `s^-²`, `s-²`: the caret or the unit and the minus typed, the digit from a palette
                del tokens[-1 if tokens[-2].kind is Kind.NAME else -2 :]
                sign = -sign
            tokens.append(Token(Kind.SUPERSCRIPT, text[start:i], start, sign * value))
        elif char == "*" and text.startswith("**", i):
            i += 2
            tokens.append(Token(Kind.POWER, "**", start))
        elif char == "." and not text[i + 1 :].strip():
            i += 1  # the full stop of a sentence: `4.58 m/s^2.`
        elif char == "." and text[i + 1 : i + 2].isdigit():
            _refuse_second_quantity(text, tokens, i)
            raise ParseError("A unit string holds whole numbers only: powers as in m^2 or s^-2", start)
        elif char in _MINUS_SIGNS and 0 < i < n - 1 and _is_name_char(text[i - 1]) and text[i + 1].isalpha():
            i += 1  # `N-m`, `ft-lb`, `kW-h`: a hyphen between units joins them, as engineers write it
            tokens.append(Token(Kind.TIMES, char, start))
        elif char in _SINGLE:
            i += 1
            tokens.append(Token(_SINGLE[char], char, start))
        else:
            hint = _CHARACTER_HINTS.get(char, "")
            raise ParseError(f"Unexpected character {char!r} in the units{hint}", start)
    if leading is not None:
        _raise_the_unit_before(tokens, leading)
    tokens.append(Token(Kind.END, "", n))
    return tokens


# Why a character that is no unit was typed, and what to type instead.
_CHARACTER_HINTS = {
    ",": " (use a decimal point, not a comma, and one answer only)",
    **dict.fromkeys(
        "′'",
        ": a prime is not read as a unit; for minutes of arc write arcmin (or the angle in degrees, as "
        "0.5°), for feet ft",
    ),
    **dict.fromkeys(
        '″"',
        ": a double prime is not read as a unit; for seconds of arc write arcsec, for inches in",
    ),
    **dict.fromkeys(ARROWS, f": {DIRECTION_BY_SIGN}"),
}


def _raise_by(tokens: list[Token], leading: tuple[int, Token] | None) -> None:
    """Put the power of a leading `sq` or `cubic` after the unit just read (`sq ft` is ft^2)."""
    if leading is not None:
        power, word = leading
        tokens.append(word)
        tokens.append(Token(Kind.INTEGER, str(power), word.position, power))


def _raise_the_unit_before(tokens: list[Token], leading: tuple[int, Token]) -> None:
    """`m/s sq`, `m/sec sq.`: a `sq` with no unit after it raises the unit before it, as `squared` does
    (a phone's short form); with no unit before it either, it is refused."""
    if not tokens or tokens[-1].kind is not Kind.NAME:
        raise ParseError(f"{leading[1].text!r} needs a unit after it, as in sq m", leading[1].position)
    _raise_by(tokens, leading)


def second_quantity(number: str, unit: str, position: int) -> ParseError:
    """The refusal of `5 ft 10 in`, `2 h 30 min`: a second number with its own unit after the first."""
    return ParseError(
        f"A second number with its own unit ({number} {unit}): write the answer as one number in one unit, "
        "as 70 in for 5 ft 10 in",
        position,
    )


_DECIMAL_THEN_UNIT = re.compile(r"\.(\d+)\s*([^\W\d]+)")


def _refuse_second_quantity(text: str, tokens: list[Token], point: int) -> None:
    """`5 ft 10.5 in`: a decimal with its own unit after a unit is a second quantity, refused as `5 ft 10
    in` is; not a unit string's stray decimal, which the caller refuses."""
    if len(tokens) < 2 or tokens[-1].kind is not Kind.INTEGER or tokens[-2].kind is not Kind.NAME:
        return
    found = _DECIMAL_THEN_UNIT.match(text, point)
    if found is not None:
        raise second_quantity(f"{tokens[-1].text}.{found.group(1)}", found.group(2), tokens[-1].position)
