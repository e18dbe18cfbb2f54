"""Numeric answers written as arithmetic: `229/50`, `2π`, `√2`, `9.8*sin(30°)`, `pi/6 rad`, `1/2 m`,
`2*9.8 m/s^2`, `9.81*m/s^2`, `0.5 kg * 9.8 m/s^2`.

The math reader (its whitelist tokenizer, parser and size limits) reads the number part, the unit
grammar the units. The number part ends at the first word outside brackets that is not arithmetic
(a function with its argument, `pi`, `π`, `e`, `x` between numbers) or at a `°` outside brackets; a
`*` or `·` between the number and its units is allowed. A number after units that follows a `*`
begins another quantity (`0.5 kg * 9.8 m/s^2`); the quantities multiply, units and all, but a whole
number after a unit and a `*` not spaced on both sides, at the end (`4.58 m/s*2`), is refused as a `^`
mistyped. In LaTeX, a `\\mathrm{…}` or `\\text{…}` holds units (`\\frac{229}{50}\\,\\mathrm{m/s^2}`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from fractions import Fraction

import sympy

from physics.dimensions import Dimension
from physics.errors import AnswerError, LikelySlip, ParseError, TooLarge, UnknownSymbol
from physics.mathinput import InputLimits, parse_math
from physics.mathinput.tokens import Kind, Token, tokenize
from physics.mathinput.vocabulary import DEGREE_WORD, FUNCTIONS, PI_SPELLINGS
from physics.mathinput.words import (
    capital_pi_hint,
    degree_function_argument,
    glued_angle_hint,
    other_names_hint,
    root_hint,
)
from physics.numeric.answer import (
    MAX_ANSWER_LENGTH,
    NumericAnswer,
    read_units_at,
    unbracketed_units,
)
from physics.symbolic.numeric import Evaluator
from physics.units import ParsedUnits
from physics.units.registry import lookup

LIMITS = InputLimits(max_length=MAX_ANSWER_LENGTH)
_PREC = 200  # bits (60 digits): far beyond any tolerance, for values such as 2π or √2
_MAX_VALUE_BITS = 1400  # |value| below 2^1400 (about 10^420), as for decimal literals
_ARGUMENT_STARTS = frozenset({Kind.LPAREN, Kind.NUM, Kind.WORD, Kind.SQRT, Kind.SUP, Kind.OP})
_SIMPLE = re.compile(r"-?[0-9.e]+")


@dataclass(frozen=True)
class _Quantity:
    start: int  # where its number part starts in the answer
    number_end: int  # just past the number part (before a `*` that precedes the units)
    units_start: int | None
    end: int


def _is_arithmetic_word(tokens: list[Token], i: int) -> bool:
    word = tokens[i].text
    if word in PI_SPELLINGS or word == "e":
        return True
    if word == "x":  # `2 x 3`: a times sign between numbers
        return i > 0 and tokens[i - 1].kind is Kind.NUM and tokens[i + 1].kind is Kind.NUM
    glued = _GLUED_NUMBER.fullmatch(word)
    if glued is not None:  # `ln2`, `sqrt2`, and `sin30` before its degree sign, as the math reader reads them
        following = tokens[i + 1]
        if glued.group(1) in ("ln", "sqrt"):
            return following.kind is not Kind.LPAREN
        return following.kind is Kind.POSTFIX and following.text == "°"
    if word in FUNCTIONS:
        # `sec` is also the second: a function only when an argument follows (`sec(x)`, `sin 30°`).
        following = tokens[i + 1]
        return following.kind in _ARGUMENT_STARTS and not (
            following.kind is Kind.OP and following.text != "^"
        )
    return False


# A function with its number glued on (`words._number_ending`).
_GLUED_NUMBER = re.compile(r"(ln|sqrt|sin|cos|tan|sec|csc|cot)(\d+)")

_ENDS_NUMBER = frozenset({Kind.NUM, Kind.RPAREN, Kind.WORD, Kind.POSTFIX})


def _slip_hint(tokens: list[Token], i: int, text: str) -> str:
    """What to type for a word in the number part that means a function or π under another spelling:
    `tg 30°` or MATLAB's `sind(30)`, `root(2)`, `SQRT(2)` or `Sin(30°)` in capitals, a spreadsheet's
    `PI()`; or ""."""
    word, following = tokens[i].text, tokens[i + 1]
    argued = following.kind in (Kind.LPAREN, Kind.NUM)
    if (argued or word[-1].isdigit()) and (
        hint := other_names_hint(word, degree_function_argument(tokens[i + 1 :], text))
    ):
        return hint.strip()
    if argued and (hint := root_hint(word, tokens[i + 1 :], text)):
        return hint.strip()
    if argued and word.lower() in FUNCTIONS and word not in FUNCTIONS:
        return f"Did you mean {word.lower()}? Function names are in small letters."
    if following.kind in (Kind.LPAREN, Kind.OP) and word.lower() == "pi" and word != "pi":  # not `Pint/min`
        return capital_pi_hint(word).strip()
    return ""


_TRIGONOMETRIC = frozenset({"sin", "cos", "tan", "sec", "csc", "cot"})


def _degrees_of_a_sine(tokens: list[Token], i: int) -> bool:
    """Whether the word at i is `deg` right after a sine's (cosine's, …) bracket, `sin(30)deg`: left in
    the number part, for the math reader to ask about (did you mean sin(30°)?), never a unit."""
    if tokens[i].text != DEGREE_WORD or i == 0 or tokens[i - 1].kind is not Kind.RPAREN:
        return False
    depth = 0
    for at in range(i - 1, -1, -1):
        depth += {Kind.RPAREN: 1, Kind.LPAREN: -1}.get(tokens[at].kind, 0)
        if depth == 0:
            return at > 0 and FUNCTIONS.get(tokens[at - 1].text) in _TRIGONOMETRIC
    return False


def _opens_units(tokens: list[Token], i: int) -> bool:
    """Whether the `[` at i opens units in square brackets after a number (`9.8 [m/s^2]`, `9.8*[m]`),
    not arithmetic (`2 [pi]`); elsewhere (`[m]`, `2+[m]`) the brackets are refused as before."""
    if tokens[i].text != "[" or i == 0:
        return False
    before, following = tokens[i - 1], tokens[i + 1]
    if not (before.kind in _ENDS_NUMBER or (before.kind is Kind.OP and before.text == "*")):
        return False
    if following.kind is Kind.POSTFIX:
        return following.text == "°"
    return following.kind is Kind.WORD and not _is_arithmetic_word(tokens, i + 1)


def _quantities(tokens: list[Token], text: str) -> list[_Quantity]:
    found: list[_Quantity] = []
    start = tokens[0].pos
    units_start: int | None = None
    number_end = len(text)
    depth = 0
    function_seen = False  # `sin 30°`: the ° is the argument's, not a unit
    for i, token in enumerate(tokens):
        if token.kind is Kind.END:
            break
        if units_start is None:
            if token.kind is Kind.LPAREN and not (depth == 0 and _opens_units(tokens, i)):
                depth += 1
            elif token.kind is Kind.RPAREN:
                depth -= 1
            elif (
                depth == 0
                and token.kind is Kind.WORD
                and not _is_arithmetic_word(tokens, i)
                and (hint := glued_angle_hint(token.text))
            ):
                raise LikelySlip(hint.strip(), token.pos)  # `9.8 sin30 m/s^2`: never a unit sin³⁰
            elif depth == 0 and token.kind is Kind.WORD and (hint := _slip_hint(tokens, i, text)):
                raise LikelySlip(hint, token.pos)  # `9.81 tg 30°`, `2*PI()`: never units t·g or P·I
            elif depth == 0 and (
                token.kind is Kind.LPAREN  # `[` opening units: the test above let it through
                or (
                    token.kind is Kind.WORD
                    and not _is_arithmetic_word(tokens, i)
                    and not _degrees_of_a_sine(tokens, i)
                )
                or (token.kind is Kind.POSTFIX and token.text == "°" and not function_seen)
            ):
                units_start = token.pos
                before = tokens[i - 1] if i > 0 else None
                times = before is not None and before.kind is Kind.OP and before.text == "*"
                number_end = before.pos if times and before is not None else token.pos
            elif token.kind is Kind.FUNC or (
                token.kind is Kind.WORD
                and (token.text in FUNCTIONS or _GLUED_NUMBER.fullmatch(token.text) is not None)
            ):
                function_seen = True  # a FUNC is a LaTeX function command, `\sin`
        elif token.kind is Kind.NUM and tokens[i - 1].kind is Kind.OP and tokens[i - 1].text == "*":
            if (slip := _power_typed_as_times(tokens, i, text, units_start)) is not None:
                raise slip
            found.append(_Quantity(start, number_end, units_start, tokens[i - 1].pos))
            start, units_start, number_end, function_seen = token.pos, None, len(text), False
    found.append(_Quantity(start, number_end, units_start, len(text)))
    return found


def _power_typed_as_times(tokens: list[Token], i: int, text: str, units_start: int) -> LikelySlip | None:
    """The refusal of `4.58 m/s*2` (or `m/s *2`): a whole number after a unit's letters and a `*`, ending
    the answer, is the `*` typed for `^` (shift-8 beside shift-6), never 4.58 m/s times 2; with the `*`
    spaced on both sides, `2 m * 3`, or after a power, `2.29 m/s^2*2`, it is the product typed."""
    times, unit, number = tokens[i - 1], tokens[i - 2], tokens[i]
    glued = unit.pos + len(unit.text) == times.pos or times.pos + 1 == number.pos
    if not (glued and unit.kind is Kind.WORD and number.text.isdigit() and tokens[i + 1].kind is Kind.END):
        return None
    meant = f"{text[units_start : times.pos].rstrip()}^{number.text}"
    return LikelySlip(
        f"Did you mean {meant}? Write a power with ^; for a product, put spaces round the * "
        f"({text[: times.pos].strip()} * {number.text})",
        times.pos,
    )


def _split(text: str) -> list[_Quantity]:
    """The quantities of `text` (a numeric answer's `\\mathrm{…}` or `\\text{…}` is units)."""
    tokens = tokenize(text, LIMITS, units_in_fonts=True)
    if tokens[0].kind is Kind.END:
        raise ParseError("The answer must start with a number, such as 2.5 or 229/50", 0)
    return _quantities(tokens, text)


def _value(expr: sympy.Expr, position: int) -> Fraction:
    if expr.is_Rational:
        return Fraction(int(expr.p), int(expr.q))
    found = Evaluator({}, 1, _PREC)(expr)[0]
    if found is None:
        raise ParseError("This arithmetic has no real value (or one too large to check)", position)
    sign, mantissa, exponent, bits = found
    if exponent + bits > _MAX_VALUE_BITS or exponent + bits < -_MAX_VALUE_BITS:
        raise TooLarge("The value of this arithmetic is too large or too small to check", position)
    value = Fraction(mantissa) * Fraction(2) ** exponent
    return -value if sign else value


@dataclass(frozen=True)
class _Read:
    value: Fraction
    text: str
    latex: str
    units: ParsedUnits | None
    units_text: str  # as typed, without the square brackets around them
    note: str | None


def _read_quantity(text: str, quantity: _Quantity, expected: Dimension | None) -> _Read:
    number_text = text[quantity.start : quantity.number_end]
    if not number_text.strip():
        raise ParseError("The answer must start with a number, such as 2.5 or 229/50", quantity.start)
    try:
        parsed = parse_math(number_text, {}, limits=LIMITS)
    except UnknownSymbol as error:
        # Only a word inside brackets reaches here: units belong after the number.
        where = quantity.start + (error.position or 0)
        hint = "write units after the number, as in sqrt(2) m" if lookup(error.symbol) else ""
        raise ParseError(
            f"Unexpected word {error.symbol!r} in the number" + (f": {hint}" if hint else ""), where
        ) from None
    except AnswerError as error:
        if error.position is not None:
            error.position += quantity.start
        raise
    units = note = None
    unit_text = ""
    if quantity.units_start is not None:
        unit_text, start = unbracketed_units(
            text[quantity.units_start : quantity.end].rstrip(), quantity.units_start
        )
        reading = read_units_at(unit_text, start, expected)
        units, note = reading.units, reading.note
    value = _value(parsed.expr, quantity.start)
    return _Read(value, parsed.read_as.text, parsed.read_as.latex, units, unit_text, note)


def number_part_end(text: str) -> int | None:
    """Where the number part of `text` read as arithmetic ends; None when the math reader cannot
    tokenize it (then it is not arithmetic at all), but its error for LaTeX that it refuses, or for a
    likely slip (`30^0` for 30°)."""
    try:
        return _split(text)[0].number_end
    except AnswerError as error:
        if "\\" in text or isinstance(error, LikelySlip):  # `9.8 sin(30^0) N`: asked about where it stands
            raise
        return None


def read_arithmetic_answer(text: str, expected: Dimension | None) -> NumericAnswer:
    """Read `text` as arithmetic and units (check `number_part_end` first: it must not be None)."""
    quantities = _split(text)
    single = len(quantities) == 1
    reads = [_read_quantity(text, q, expected if single else None) for q in quantities]
    value = Fraction(1)
    units: ParsedUnits | None = None
    for read in reads:
        value *= read.value
        if read.units is not None:
            units = read.units if units is None else units * read.units
    first, last = quantities[0], quantities[-1]
    if single:
        shown, latex = reads[0].text, reads[0].latex
    else:
        shown = "*".join(r.text if _SIMPLE.fullmatch(r.text) else f"({r.text})" for r in reads)
        latex = r" \cdot ".join(r.latex for r in reads)
    units_start = first.units_start
    units_text = text[units_start:].strip() if units_start is not None else ""
    return NumericAnswer(
        value=value,
        text=shown,
        latex=latex,
        end=first.number_end if single else last.end,
        units=units,
        units_position=units_start,
        units_text=reads[0].units_text if single else units_text,
        note=reads[0].note,
    )
