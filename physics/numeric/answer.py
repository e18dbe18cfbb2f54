"""A numeric answer as read: the number (a decimal literal or, where allowed, exact arithmetic), then
the units (if any) that follow it.

A plain literal followed by units (`4.58 m/s^2`, `1.2e3 N`, `45%`) is read first, exactly as before,
because only it shows significant figures. Anything else is read as arithmetic by
`physics.numeric.arithmetic` (`229/50 m/s^2`, `2π rad`, `0.5 kg * 9.8 m/s^2`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace
from fractions import Fraction

from physics.characters import fullwidth_as_ascii, may_be_wrapped, without_math_delimiters, without_zero_width
from physics.dimensions import Dimension
from physics.errors import AnswerError, LikelySlip, ParseError, TooLarge, UnknownUnit
from physics.mathinput.sentences import named_side
from physics.mathinput.vocabulary import FUNCTIONS
from physics.numeric.literal import NumberLiteral, read_number, side_by_side, units_start
from physics.units import ParsedUnits, UnitReading, read_units
from physics.units.other_scripts import other_script_units_hint
from physics.verdict import ReadAs
from physics.wording import ARROWS, DIRECTION_BY_SIGN, DIRECTION_WORDS, TRAILING_SEMICOLON

MAX_ANSWER_LENGTH = 200


@dataclass(frozen=True)
class NumericAnswer:
    value: Fraction  # exact for literals and rational arithmetic; irrational arithmetic to ~60 digits
    text: str  # the number part as read: `4.58e3`, `229/50`, `2*pi`
    latex: str
    end: int  # just past the number part
    units: ParsedUnits | None  # None when no units were written
    units_position: int | None  # where the units start in the answer
    units_text: str = ""  # the units as typed
    literal: NumberLiteral | None = None  # the number, when it is a plain decimal literal
    note: str | None = None  # how a reading was chosen (`5 ms^-1` read as m/s for a speed)

    @staticmethod
    def of_literal(
        number: NumberLiteral,
        units: ParsedUnits | None,
        units_position: int | None,
        units_text: str = "",
        note: str | None = None,
    ) -> NumericAnswer:
        return NumericAnswer(
            number.value,
            number.text,
            number.latex,
            number.end,
            units,
            units_position,
            units_text,
            number,
            note,
        )

    def read_as(self, units: ParsedUnits | None = None) -> ReadAs:
        """How the answer was understood; `units` stands in for units the answer left implicit."""
        shown = self.units if self.units is not None else units
        if shown is None or shown.is_dimensionless_number:
            return ReadAs(self.text, self.latex, self.note)
        if shown.text == "°":  # 30°, not 30 °
            return ReadAs(f"{self.text}°", f"{self.latex}{shown.latex}", self.note)
        return ReadAs(f"{self.text} {shown.text}", rf"{self.latex}\,{shown.latex}", self.note)


_RECIPROCAL = re.compile(r"1\s*/")  # `4.9e12 1/s` is a number and a unit, not two numbers
_UNCERTAINTY = re.compile(r"±|\+\s*/\s*[-−]|\+[-−](?=\s*[\d.])")
_STARTS_LITERAL = re.compile(r"\s*[-−+]?\s*\.?[0-9]")
_MATH_WORDS = frozenset({*FUNCTIONS, "pi", "π", "e"})  # words arithmetic reads before a number
_NOT_ARITHMETIC = re.compile(r"[\s\d.,*·⋅]*")  # after a literal: more digits or a times sign only


class _NumberFormError(Exception):
    """The decimal literal itself is malformed (`4.5.8`, `4,58`, `4.58×10^`); carries the AnswerError."""

    def __init__(self, error: AnswerError) -> None:
        super().__init__(error.message)
        self.error = error


def read_literal_answer(text: str, expected: Dimension | None = None) -> NumericAnswer:
    """Read `4.58 m/s^2`, `-1.2e3 N`, `45%`, `16.49 km/h`: a decimal literal and units."""
    return _read_literal(text, expected)[0]


def _read_literal(text: str, expected: Dimension | None) -> tuple[NumericAnswer, int]:
    """The answer, and where its number ended; _NumberFormError when the number itself is malformed."""
    try:
        number = read_number(text)
    except AnswerError as error:
        raise _NumberFormError(error) from None
    rest_start = units_start(text, number.end)
    unit_text = text[rest_start:].rstrip()
    if not unit_text:
        return NumericAnswer.of_literal(number, None, None), number.end
    unit_text, rest_start = unbracketed_units(unit_text, rest_start)
    reciprocal = _RECIPROCAL.match(unit_text)
    if unit_text.startswith("/"):  # `4.9e12 /s`: a unit of the form 1/…
        unit_text, rest_start = "1" + unit_text, rest_start - 1
    elif reciprocal is None and (
        unit_text[0] in "0123456789" or (unit_text[0] in ",." and unit_text[1:2].isdigit())
    ):
        raise side_by_side(text, number, rest_start)
    reading = read_units_at(unit_text, rest_start, expected)
    return NumericAnswer.of_literal(number, reading.units, rest_start, unit_text, reading.note), number.end


# An approximation said before the value, with or without a name before it: `≈ 4.58`, `a ≈ 4.58`,
# `approx. 4.58`, `about 4.58`.
_APPROXIMATELY = re.compile(
    r"\s*(?:[^\W\d]\w*\s*)?(≈|~|∼|approx\.?|approximately|about|around|roughly)\s*(?=[-−+.\d])", re.IGNORECASE
)


def _approximation(text: str) -> ParseError | None:
    """Why `≈ 4.58`, `a ≈ 4.58` or `approx 4.58` is refused, or None for other text."""
    approximately = _APPROXIMATELY.match(text)
    if approximately is None:
        return None
    return ParseError(
        f"Give the value without '{approximately.group(1)}': write the number itself", approximately.start(1)
    )


def _no_number_first(text: str, otherwise: AnswerError | None = None) -> AnswerError:
    """Why an answer that does not start with a number is refused: an equation (`a = 4.58 m/s^2`), a
    label (`a: 4.58 m/s^2`) or an approximation sign (`≈ 4.58`) is named, as students write them on
    paper; else `otherwise`."""
    equals = text.find("=")
    if equals >= 0:
        if not text[:equals].strip():  # `=9.81*sin(35°)`: a spreadsheet's formula
            return ParseError("Leave out the '=' at the start: type the value alone", equals)
        named = named_side(text, equals)
        if named is not None and text[:equals].strip() == named[0]:  # `T = 2.01 s`: shows the value to type
            return ParseError(f"Give the value alone, without '{named[0]} =': type only {named[1]}", equals)
        return ParseError(
            "Give the value alone, without a name and '=': write what comes after the '='", equals
        )
    colon = text.find(":")
    if colon >= 0:  # `a: 4.58 m/s^2`, Maxima's assignment; `Answer: 4.58 m/s^2`, a sentence's
        return ParseError("Give the value alone: write what comes after the ':'", colon)
    start = len(text) - len(text.lstrip())
    if text[start : start + 1] in tuple(ARROWS):  # `↓ 4.58 m/s^2`
        return ParseError(DIRECTION_BY_SIGN[0].upper() + DIRECTION_BY_SIGN[1:], start)
    return (
        _approximation(text)
        or _sentence(text)
        or otherwise
        or ParseError("The answer must start with a number, such as 2.5 or 229/50", 0)
    )


# Words before the value, as a sentence says it: `The period is 1.42 s`, `it takes 3.2 s`.
_SENTENCE = re.compile(r"\s*([^\W\d_]+(?:\s+[^\W\d_]+)+)\s+(?=[-−+]?\.?\d)")


def _sentence(text: str) -> ParseError | None:
    """Why `The period is 1.42 s` is refused, saying what to type; None where the words before the value
    may be arithmetic's (`pi sqrt 2 m`) or there are none."""
    sentence = _SENTENCE.match(text)
    if sentence is None or any(w.lower() in _MATH_WORDS for w in sentence.group(1).split()):
        return None
    value = text[sentence.end() :].strip().rstrip(".")
    return ParseError(f"Type only the value and its units ({value}), not a sentence", sentence.start(1))


def unbracketed_units(unit_text: str, start: int) -> tuple[str, int]:
    """Units in square brackets, as physics texts print them (`4.58 [m/s^2]`): the text inside and
    where it starts in the answer; other unit text as it is. A bracket that does not enclose all the
    units (`[m/s^2`, `[m]/s`) is refused here, where the message can say what is wrong; empty
    brackets are left to the math reader, which names them."""
    if not unit_text.startswith("["):
        return unit_text, start
    closing = unit_text.find("]")
    if closing < 0:
        raise ParseError("Unbalanced bracket: this '[' is never closed.", start)
    if closing != len(unit_text) - 1:
        raise ParseError(
            "Square brackets go around all of the units, as in [m/s^2], or are left out", start + closing
        )
    inside = unit_text[1:closing]
    units = inside.strip()
    if not units:
        return unit_text, start
    return units, start + 1 + inside.index(units[0])


def read_units_at(unit_text: str, start: int, expected: Dimension | None) -> UnitReading:
    """`read_units`, with any error's position moved to where the units start in the answer."""
    if unit_text.endswith(")") and (remark := _REMARK.search(unit_text)) is not None and remark.start() > 0:
        restated = _restated(unit_text, remark, start, expected)
        if restated is not None:
            return restated
    try:
        return read_units(unit_text, expected)
    except AnswerError as error:
        if error.position is not None:
            error.position += start
        if isinstance(error, UnknownUnit) and (hint := other_script_units_hint(unit_text, expected)):
            error.message += (
                hint  # `4.58 м/с²`, `4.58 米/秒²`: SI's units as a Russian or Chinese school writes them
            )
        raise


# Words in brackets after the units, as an answer is copied from a calculator, Wolfram|Alpha or a
# chatbot: `4.58 m/s^2 (meters per second squared)`, `4.58 m/s^2 (approx)`.
_REMARK = re.compile(r"\s*\(([^()]*)\)\s*$")
_SAID_AS_DIRECTION = re.compile(r"\s*(up|down|left|right|north|south|east|west)\w*\s*", re.IGNORECASE)


def _restated(
    unit_text: str, remark: re.Match[str], start: int, expected: Dimension | None
) -> UnitReading | None:
    """The units before a remark in brackets that says them again (a product with them would square
    them, and the divisor of `m/s^2 (m/s^2)` would cancel them); None where the units before it do not
    read, or it reads as no units or other units (`_said_after_the_value` refuses a remark)."""
    try:
        before = read_units(unit_text[: remark.start()], expected)
        said = read_units(remark.group(1), before.units.dimension)
    except AnswerError:
        return None
    return before if said.units.dimension == before.units.dimension else None


def read_numeric_answer(
    text: str, expected: Dimension | None = None, *, arithmetic: bool = True
) -> NumericAnswer:
    """Read a numeric answer; AnswerError with a position if it cannot be.

    `expected`: the dimension the units should have, to choose between readings of glued unit names.
    `arithmetic`: whether the number may be an expression (`229/50`); if not, a plain decimal is required.
    """
    if len(text) > MAX_ANSWER_LENGTH:
        raise TooLarge(f"An answer may be at most {MAX_ANSWER_LENGTH} characters", MAX_ANSWER_LENGTH)
    if may_be_wrapped(text):
        text = without_math_delimiters(text)  # `$4.58\,\mathrm{m/s^2}$` copied from a document
    visible = without_zero_width(text)
    if visible is not None:  # read what the student sees; positions stay those of the typed text
        try:
            answer = read_numeric_answer(visible.text, expected, arithmetic=arithmetic)
        except AnswerError as error:
            if error.position is not None:
                error.position = visible.typed_position(error.position)
            raise
        return replace(
            answer,
            end=visible.typed_position(answer.end),
            units_position=None
            if answer.units_position is None
            else visible.typed_position(answer.units_position),
        )
    text = fullwidth_as_ascii(text)
    if text.rstrip().endswith(";"):  # `4.58 m/s^2;`: a command's end, as STACK refuses it
        raise ParseError(TRAILING_SEMICOLON, len(text.rstrip()) - 1)
    uncertainty = _UNCERTAINTY.search(text)
    if uncertainty is not None:  # a lab result as written in a report: `(4.58 ± 0.05) m/s^2`
        raise ParseError(
            f"Give one value, without its uncertainty ({uncertainty.group().strip()} …): only the value "
            "is graded here",
            uncertainty.start(),
        )
    try:
        return _read_value(text, expected, arithmetic)
    except AnswerError:
        said_after = _said_after_the_value(text, expected, arithmetic)
        if said_after is None:
            raise
        raise said_after from None


def _read_value(text: str, expected: Dimension | None, arithmetic: bool) -> NumericAnswer:
    """`read_numeric_answer` of a text already plain (no delimiters, fullwidth forms or uncertainty)."""
    # Imported here: arithmetic pulls in the math reader and sympy, which plain literals never need.
    from physics.numeric.arithmetic import number_part_end, read_arithmetic_answer

    try:
        return read_literal_answer(text, expected)
    except _NumberFormError as malformed:
        if isinstance(malformed.error, LikelySlip):  # `3.0 x 10-3`: never the arithmetic 30 − 3
            raise malformed.error from None
        # No literal starts the answer (`pi/6`, `√2`): only arithmetic can read it. A literal that
        # starts but is malformed (`4.5.8`, `4,58`) keeps its own, specific, message.
        literal_error = malformed.error if _STARTS_LITERAL.match(text) else None
    except AnswerError as error:
        literal_error = error
    try:
        ends = number_part_end(text)
    except LikelySlip:  # `9.8 sin(30^0) N`: a degree typed as a power 0, asked about where it stands
        raise
    except AnswerError as latex_error:  # LaTeX that the math reader refuses, where and why
        raise (literal_error or _no_number_first(text, latex_error)) from None
    if ends is None:
        if literal_error is None:
            raise _no_number_first(text) from None
        raise literal_error
    if not _STARTS_LITERAL.match(text) and (approximately := _approximation(text)) is not None:
        raise approximately  # `approx 4.58`: never a unit or a symbol `approx`
    if not _STARTS_LITERAL.match(text) and (sentence := _sentence(text)) is not None:
        raise sentence  # `The period is 1.42 s`: never units or symbols `The period is`
    try:
        answer = read_arithmetic_answer(text, expected)
    except AnswerError:
        # Arithmetic that is no more than the literal (`12 500 m`, `4.5.8`) is best blamed by the literal.
        if literal_error is not None and not _beyond_literal(text, ends):
            raise literal_error from None
        raise
    if not arithmetic:
        raise ParseError(
            f"Write a plain decimal number (such as 4.58), not arithmetic such as {answer.text}: "
            "work the value out first",
            0,
        )
    return answer


_EQUATION_SIGN = re.compile("[=≈]")
# A direction said in a phrase after a value: `to the right`, `towards the left`, `at 30°` (`above the
# horizontal` and such after it); a single word, `downwards`, the units' reader refuses itself.
_DIRECTION_PHRASE = re.compile(
    r"\s((?:to|towards?)\s+(?:the\s+)?([^\W\d_]+)|at\s+[-−+]?[\d.]+\s*(?:°|º|deg\w*)(?:\s+[^\W\d_]+)*)\s*$",
    re.IGNORECASE,
)


def _direction_phrase(text: str, expected: Dimension | None, arithmetic: bool) -> ParseError | None:
    """The refusal of a direction said in a phrase after a value that reads, `12.5 m/s to the right`,
    `4 N at 30°`, as a single direction word is refused; None for other text."""
    phrase = _DIRECTION_PHRASE.search(text)
    if phrase is None or (phrase.group(2) is not None and phrase.group(2).lower() not in DIRECTION_WORDS):
        return None
    value = text[: phrase.start()].strip()
    if not value or _reads(value, expected, arithmetic) is None:
        return None
    return ParseError(f"{phrase.group(1)!r}: {DIRECTION_BY_SIGN}. Type only {value}", phrase.start(1))


def _said_after_the_value(text: str, expected: Dimension | None, arithmetic: bool) -> ParseError | None:
    """The refusal of what is said after a value that reads, in place of the reader's own: an equation (`4.58 m/s^2 =
    a`, `… ≈ 0.47g`) or a remark in brackets (`0.0612 (no units)`), showing the value to type; None
    for other text. Only ever on the refusal path: it reads the value again without what follows."""
    if (direction := _direction_phrase(text, expected, arithmetic)) is not None:
        return direction
    sign = _EQUATION_SIGN.search(text)
    if (
        sign is not None
        and (value := text[: sign.start()].strip())
        and (left := _reads(value, expected, arithmetic)) is not None
    ):
        at = sign.start()
        result = text[sign.end() :].strip()
        # `2π√(1/9.81) = 2.01 s`: the working without units, then the answer with them
        if (
            left.units is None
            and left.literal is None
            and (right := _reads(result, expected, arithmetic)) is not None
            and right.units is not None
        ):
            return ParseError(f"Give the value alone, without '{value} {text[at]}': type only {result}", at)
        named = named_side(text, at)
        without = f"{text[at]} {named[0]}" if named is not None and named[1] == value else text[at:].strip()
        return ParseError(f"Give the value alone, without '{without}': type only {value}", at)
    remark = _REMARK.search(text)
    # `(down)`: the units' own refusal says to give a direction by the sign
    if (
        remark is None
        or not any(c.isalpha() for c in remark.group(1))
        or _SAID_AS_DIRECTION.fullmatch(remark.group(1))
    ):
        return None
    value = text[: remark.start()].strip()
    answer = _reads(value, expected, arithmetic) if value else None
    if answer is None:
        return None
    alone = "the value and its units" if answer.units is not None else "the value"
    return ParseError(
        f"Give {alone} alone: leave out ({remark.group(1).strip()}), and type only {value}",
        remark.start(1) - 1,
    )


def _reads(value: str, expected: Dimension | None, arithmetic: bool) -> NumericAnswer | None:
    try:
        return _read_value(value, expected, arithmetic)
    except AnswerError:
        return None


def _beyond_literal(text: str, ends: int) -> bool:
    """Whether the arithmetic number part holds more than a decimal literal does (an operator, a word)."""
    try:
        number = read_number(text)
    except AnswerError:
        return False  # a malformed literal (`4.5.8`): its own message is the specific one
    return _NOT_ARITHMETIC.fullmatch(text[number.end : ends]) is None
