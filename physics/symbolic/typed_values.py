"""Values typed where a symbol is meant: a decimal for π (`2*3.14*sqrt(L/g)`, off by a constant factor;
so too for ln 2, √2, √3 and a fraction such as 5/7, `0.714 g sin θ`),
for e (`v0*2.718^(-b t/m)`, a wrong value) or for g (`9.8 m sin θ`, a wrong dimension), and units after
a symbolic answer (`m g sin θ N`).

The answer is graded as typed: a decimal is exactly the number it shows, and units are no symbols. But
where the symbol in the value's place would make it right, the feedback says so, instead of leaving
the student to guess what "off by a constant factor" or "the dimension of a mass" points at.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping

from physics.dimensions import Dimension
from physics.errors import AnswerError, UnknownSymbol
from physics.units import read_units
from physics.verdict import Reason

_DECIMAL = re.compile(r"(?<![\w.])(\d+\.\d+)(?![\w.])")
_PI_MULTIPLES = ((1, 4), (1, 2), (1, 1), (2, 1), (3, 1), (4, 1))  # π/4, π/2, π, 2π, 3π, 4π
_MIN_DIGITS = 3  # 3.14, 6.28, 1.57: a decimal of fewer significant digits is not meant as π
_CLOSE = 2e-3  # 3.14 is 5e-4 from π
_GRAVITY = (9.78, 9.832)  # g at the equator to g at the poles, in m/s^2: 9.8, 9.81, 9.807


def _as_pi(decimal: str) -> tuple[str, str] | None:
    """The multiple of π that `decimal` rounds, as text the reader takes (`(2*pi/1)`) and as shown
    (`2π`), or None."""
    if len(decimal.replace(".", "").lstrip("0")) < _MIN_DIGITS:
        return None
    value = float(decimal)
    for top, bottom in _PI_MULTIPLES:
        if abs(value / (math.pi * top / bottom) - 1) < _CLOSE:
            shown = ("" if top == 1 else str(top)) + "π" + ("" if bottom == 1 else f"/{bottom}")
            return f"({top}*pi/{bottom})", shown
    return None


# Other numbers a formula holds, typed as decimals from a calculator: (value, as the reader takes it, as
# shown, as the student should write it).
_NAMED_NUMBERS = (
    (math.log(2), "log(2)", "ln 2", "ln(2)"),
    (math.sqrt(2), "sqrt(2)", "√2", "sqrt(2)"),
    (math.sqrt(3), "sqrt(3)", "√3", "sqrt(3)"),
)


def _as_named_number(decimal: str) -> tuple[str, str] | None:
    """ln 2, √2 or √3 that `decimal` rounds (`0.693` for a half-life's ln 2), or None."""
    if len(decimal.replace(".", "").lstrip("0")) < _MIN_DIGITS:
        return None
    value = float(decimal)
    for exact, typed, shown, _ in _NAMED_NUMBERS:
        if abs(value / exact - 1) < _CLOSE:
            return f"({typed})", shown
    return None


_DENOMINATORS = range(3, 13)  # 1/3 to 11/12: the fractions a formula holds (5/7 of a rolling ball's g sin θ)


def _as_fraction(decimal: str) -> tuple[str, str] | None:
    """The fraction of small whole numbers that `decimal` rounds and is not (`0.714` for 5/7), or None."""
    if len(decimal.replace(".", "").lstrip("0")) < _MIN_DIGITS:
        return None
    value = float(decimal)
    for bottom in _DENOMINATORS:
        top = round(value * bottom)
        if top > 0 and math.gcd(top, bottom) == 1 and 0 < abs(value * bottom / top - 1) < _CLOSE:
            return f"({top}/{bottom})", f"{top}/{bottom}"
    return None


def _as_pi_or_named(decimal: str) -> tuple[str, str] | None:
    return _as_pi(decimal) or _as_named_number(decimal) or _as_fraction(decimal)


def _as_e(decimal: str) -> tuple[str, str] | None:
    digits = len(decimal.replace(".", "").lstrip("0"))
    return ("e", "e") if digits >= _MIN_DIGITS and abs(float(decimal) / math.e - 1) < _CLOSE else None


def _as_g(decimal: str) -> tuple[str, str] | None:
    return ("g", "g") if _GRAVITY[0] <= float(decimal) <= _GRAVITY[1] else None


# Angles in degrees as they are typed inside a function of an angle: `cos(90 - θ)` for cos(90° − θ).
_DEGREES = re.compile(r"(?<=[(\s])(30|45|60|90|120|135|150|180|270|360)(?=\s*[-+)])")


def _in_degrees(read_as_text: str, right_with: Callable[[str], bool]) -> str | None:
    """Feedback for a wrong answer that an angle typed in degrees without its sign (`cos(90 - θ)`, 90
    rad as typed) makes wrong, where the degree sign would make it right; else None."""
    if "(" not in read_as_text:
        return None
    found = list(_DEGREES.finditer(read_as_text))
    if not found:
        return None
    text = read_as_text
    for match in reversed(found):
        text = f"{text[: match.start()]}{match.group(1)}°{text[match.end() :]}"
    if not right_with(text):
        return None
    said = ", ".join(dict.fromkeys(f"{match.group(1)}° for {match.group(1)}" for match in found))
    return (
        f"Your answer would be right with {said}: an angle is in radians unless it has a degree sign, so "
        "write the ° (or the angle in radians, as pi/2 for 90°)."
    )


def typed_value_hint(
    read_as_text: str, reason: Reason, names: Mapping[str, object], right_with: Callable[[str], bool]
) -> str | None:
    """Feedback for a wrong answer whose decimals stand for π (off by a constant factor) or for a
    declared g (a wrong dimension), or whose angles were typed in degrees without the sign: when the
    answer with the symbols in their place is right (`right_with` grades a text), what to write
    instead; else None."""
    if reason is Reason.WRONG_VALUE and (degrees := _in_degrees(read_as_text, right_with)) is not None:
        return degrees
    if reason is Reason.CONSTANT_FACTOR:
        symbol_for = _as_pi_or_named
        advice = "a decimal is taken as exactly the number it shows, so write pi (or π) where you mean π"
    elif reason is Reason.WRONG_DIMENSION and "g" in names:
        symbol_for = _as_g
        advice = "write the symbol g, not its value"
    elif reason is Reason.WRONG_VALUE and "e" not in names:
        symbol_for = _as_e
        advice = (
            "a decimal is taken as exactly the number it shows, so write e^(…) or exp(…) where you mean e"
        )
    else:
        return None
    found = [(match, symbol_for(match.group(1))) for match in _DECIMAL.finditer(read_as_text)]
    swaps = [(match, symbol) for match, symbol in found if symbol is not None]
    if not swaps:
        return None
    text = read_as_text
    for match, (typed, _) in reversed(swaps):
        text = text[: match.start()] + typed + text[match.end() :]
    if not right_with(text):
        return None
    said = ", ".join(dict.fromkeys(f"{shown} for {match.group(1)}" for match, (_, shown) in swaps))
    named = [written for _, _, shown, written in _NAMED_NUMBERS if any(s[1] == shown for _, s in swaps)]
    named += [shown for _, (_, shown) in swaps if "/" in shown and "π" not in shown]  # the fractions
    if named and reason is Reason.CONSTANT_FACTOR:
        pi = " and pi (or π) where you mean π" if any("π" in s[1] for _, s in swaps) else ""
        advice = f"a decimal is taken as exactly the number it shows, so write {' and '.join(named)}{pi}"
    return f"Your answer would be right with {said}: {advice}."


def with_units_hint(error: AnswerError, answer: str, expected: Dimension | None) -> AnswerError:
    """An unknown symbol where the rest of the answer reads as units of the expected dimension
    (`m g sin θ N`, `… kg m/s^2` for a force, `… \\mathrm{kg\\,m/s^2}`): the refusal says that a symbolic
    answer is written without units. (`… T` for a force is not taken for the tesla: a T may be a tension.)"""
    if error.position is None or expected is None:
        return error
    if isinstance(error, UnknownSymbol):
        start = error.position
    else:  # `… \mathrm{rad/s}`: units in a LaTeX font command, refused inside its braces
        start = max(answer.rfind("\\mathrm{", 0, error.position), answer.rfind("\\text{", 0, error.position))
        if start < 0:
            return error
    units = shown = answer[start:].strip()
    if units.endswith(")") and answer[: error.position].rstrip().endswith("("):  # `m g h (J)`
        units = units[:-1].rstrip()
        shown = f"({units})"
    try:
        dimension = read_units(units).units.dimension
    except AnswerError:
        return error
    if dimension != expected:
        return error
    leave_out = f"A symbolic answer is written without units: leave out {shown}."
    if isinstance(error, UnknownSymbol):
        error.message += f" {leave_out}"
    else:  # the font command's own complaint (a name only) is beside the point
        error.message, error.position = leave_out, start
    return error
