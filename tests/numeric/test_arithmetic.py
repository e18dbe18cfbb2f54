"""Numeric answers written as arithmetic: read exactly, with units, and refused where a part asks for a
plain decimal or for significant figures; errors blame the part that is wrong."""

from __future__ import annotations

from decimal import Decimal

import pytest

from physics.numeric import NumericSpec, Tolerance, check_numeric
from physics.verdict import Outcome, Reason

D = Decimal

ARITHMETIC = [
    # (answer, expected, units, how it reads): each refused before, blamed on the units
    ("229/50", "4.58", None, "229/50"),
    ("6/2", "3", None, "6/2"),
    ("0.1+0.2", "0.3", None, "0.1 + 0.2"),
    ("2*pi", "6.28319", None, "2*pi"),
    ("2π", "6.28319", None, "2*pi"),
    ("sqrt(2)", "1.41421", None, "sqrt(2)"),
    ("√2", "1.41421", None, "sqrt(2)"),
    ("2^0.5", "1.41421", None, "2**0.5"),
    ("9.8*sin(30°)", "4.9", None, "9.8*sin(30*pi/180)"),
    ("9.8 sin 30°", "4.9", None, "9.8*sin(30*pi/180)"),
    ("pi/6 rad", "0.523599", "rad", "pi/6 rad"),
    ("1/2 m", "0.5", "m", "1/2 m"),
    ("3/4 J", "0.75", "J", "3/4 J"),
    ("½ kg", "0.5", "kg", "1/2 kg"),
    ("⅔ m", "0.666667", "m", "2/3 m"),
    ("⁵⁄₇ m", "0.714286", "m", "5/7 m"),  # raised over lowered digits: was "Unexpected '⁵'"
    ("2*9.8 m/s^2", "19.6", "m/s^2", "2*9.8 m/s^2"),
    ("2·9.8 m/s^2", "19.6", "m/s^2", "2*9.8 m/s^2"),  # a raised dot before a decimal: a product
    ("9.81*m/s^2", "9.81", "m/s^2", "9.81 m/s^2"),
    ("4.58·m/s^2", "4.58", "m/s^2", "4.58 m/s^2"),
    ("4.58 * m/s^2", "4.58", "m/s^2", "4.58 m/s^2"),
    ("0.5 kg * 9.8 m/s^2", "4.9", "N", "0.5*9.8 kg·m/s^2"),
    ("0.5 kg · 9.8 m/s^2", "4.9", "N", "0.5*9.8 kg·m/s^2"),
    ("229/50 km/h", "1.27222", "m/s", "229/50 km/h"),
    ("5 sec", "5", "s", "5 s"),  # `sec` with no argument is the second, not the secant
    ("sec(0) m", "1", "m", "sec(0) m"),
    ("2 x 3 m", "6", "m", "2*3 m"),
    ("2*%pi m", "6.28319", "m", "2*pi m"),  # Maxima's π, as STACK students type it
    ("2 %pi m", "6.28319", "m", "2*pi m"),
    ("2.5*e m", "6.79570", "m", "2.5*e m"),  # Euler's number, written with its *
    ("2.5e3 m", "2500", "m", None),
    ("3.0 × 10 - 3 s", "27", "s", "3.0*10 - 3 s"),  # spaced round: a subtraction, not ×10^-3
    ("-3/2 N", "-1.5", "N", "-3/2 N"),
    ("50%", "0.5", None, "50%"),
    ("2*5 Pint/min", "10", "pint/min", "2*5 pt/min"),  # a unit in capitals, not π (PI, Pi are asked about)
]


@pytest.mark.parametrize(
    ("answer", "expected", "units", "shown"),
    [c for c in ARITHMETIC if c[3] is not None],
    ids=[c[0] for c in ARITHMETIC if c[3] is not None],
)
def test_arithmetic_answer_is_read_exactly_with_its_units(
    answer: str, expected: str, units: str | None, shown: str
) -> None:
    verdict = check_numeric(answer, NumericSpec(D(expected), units, tolerance=Tolerance(rel=D("0.00001"))))
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback
    assert verdict.read_as is not None
    assert verdict.read_as.text == shown


def test_rational_arithmetic_is_exact() -> None:
    exact = NumericSpec(D("0.3"), None, tolerance=Tolerance(abs=D(0)))
    assert check_numeric("0.1+0.2", exact).outcome is Outcome.CORRECT
    assert check_numeric("229/50", NumericSpec(D("4.58"), None, tolerance=Tolerance(abs=D(0)))).score == 1.0


def test_irrational_arithmetic_is_accurate_far_beyond_any_tolerance() -> None:
    tight = NumericSpec(D("6.283185307179586476925286766559"), None, tolerance=Tolerance(rel=D("1e-28")))
    assert check_numeric("2π", tight).outcome is Outcome.CORRECT
    assert check_numeric("6.2831853", tight).outcome is Outcome.INCORRECT


def test_wrong_arithmetic_is_graded_with_a_reason() -> None:
    verdict = check_numeric("229/5 m/s^2", NumericSpec(D("4.58"), "m/s^2"))
    assert verdict.outcome is Outcome.INCORRECT
    assert verdict.reason is Reason.CONSTANT_FACTOR
    verdict = check_numeric("229/50 m/s", NumericSpec(D("4.58"), "m/s^2"))
    assert verdict.reason is Reason.WRONG_DIMENSION


PLAIN_ONLY = NumericSpec(D("4.58"), "m/s^2", arithmetic=False)


@pytest.mark.parametrize("answer", ["229/50 m/s^2", "2*2.29 m/s^2", "√21 m/s^2", "4.58*1 m/s^2"])
def test_a_part_that_asks_for_a_plain_decimal_refuses_arithmetic(answer: str) -> None:
    verdict = check_numeric(answer, PLAIN_ONLY)
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is Reason.PARSE_ERROR
    assert "plain decimal number" in verdict.feedback


@pytest.mark.parametrize("answer", ["4.58 m/s^2", "4.58e0 m/s^2", "458e-2 m/s^2", "4.58 m·s⁻²"])
def test_a_part_that_asks_for_a_plain_decimal_takes_decimals(answer: str) -> None:
    assert check_numeric(answer, PLAIN_ONLY).outcome is Outcome.CORRECT


def test_significant_figures_apply_to_a_plain_decimal_only() -> None:
    spec = NumericSpec(D("4.58"), "m/s^2", tolerance=Tolerance(sigfigs=3))
    assert check_numeric("4.58 m/s^2", spec).outcome is Outcome.CORRECT
    verdict = check_numeric("229/50 m/s^2", spec)
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is Reason.SIGFIGS
    assert "decimal number with 3 significant figures" in verdict.feedback


BLAME = [
    # (answer, units, reason, position, words): the message names the part that is wrong
    ("229/50 m/s^2 foo", "m/s^2", Reason.UNKNOWN_UNIT, 13, "Unknown unit 'foo'"),
    ("229/50+ m/s^2", "m/s^2", Reason.PARSE_ERROR, 6, "Nothing after '+'"),
    ("sqrt(2 m/s^2", "m/s^2", Reason.PARSE_ERROR, 7, "write units after the number"),
    ("2*(3 m/s^2", "m/s^2", Reason.PARSE_ERROR, 5, "write units after the number"),
    ("1/0 m/s^2", "m/s^2", Reason.PARSE_ERROR, 0, "divides by zero"),
    ("sqrt(-1) m/s^2", "m/s^2", Reason.PARSE_ERROR, 0, "no real value"),
    ("12 50 m/s^2", "m/s^2", Reason.PARSE_ERROR, 3, "side by side"),
    ("4.5.8 m/s^2", "m/s^2", Reason.PARSE_ERROR, 3, "one decimal point"),
    ("4,580 m/s^2", "m/s^2", Reason.PARSE_ERROR, 1, "decimal point"),
    ("m/s^2", "m/s^2", Reason.PARSE_ERROR, 0, "must start with a number"),
    ("pi", "m/s^2", Reason.MISSING_UNITS, 2, "needs units"),
    ("4.58 x 10-3 m/s^2", "m/s^2", Reason.PARSE_ERROR, 9, "Did you mean 4.58×10^-3?"),  # not 45.8 − 3
    ("2*4.58×10e8 m/s^2", "m/s^2", Reason.PARSE_ERROR, 9, "Did you mean 4.58×10^8 or 4.58e8?"),  # not ×10^9
    # a function under its European or Russian name: never the units t·g (was "A second number …")
    ("9.81 tg 30° m/s^2", "m/s^2", Reason.PARSE_ERROR, 5, "Did you mean tan? Write tan for tg"),
    ("9.81*tg(30°) m/s^2", "m/s^2", Reason.PARSE_ERROR, 5, "Did you mean tan?"),
    ("9.81 tg30° m/s^2", "m/s^2", Reason.PARSE_ERROR, 5, "Did you mean tan?"),
    ("tg(30°)*9.81 m/s^2", "m/s^2", Reason.PARSE_ERROR, 0, "Did you mean tan?"),
    ("9.81 ctg(30°) m/s^2", "m/s^2", Reason.PARSE_ERROR, 5, "Did you mean cot? Write cot for ctg"),
    ("9.81*arctg(0.5) m/s^2", "m/s^2", Reason.PARSE_ERROR, 5, "Did you mean atan?"),
    ("10*lg(2) m/s^2", "m/s^2", Reason.PARSE_ERROR, 3, "Did you mean log10? Write log10 for lg"),
    ("—4.58 m/s^2", "m/s^2", Reason.PARSE_ERROR, 0, "— is a dash"),
    (
        '"4.58 m/s^2"',
        "m/s^2",
        Reason.PARSE_ERROR,
        0,
        "Leave out the quotation marks",
    ),  # was "must start with"
    # a label before the value, Maxima's assignment or a sentence's: was "must start with a number"
    ("a: 4.58 m/s^2", "m/s^2", Reason.PARSE_ERROR, 1, "Give the value alone: write what comes after the ':'"),
    ("Answer: 4.58 m/s^2", "m/s^2", Reason.PARSE_ERROR, 6, "write what comes after the ':'"),
    ("np.sqrt(21) m/s^2", "m/s^2", Reason.PARSE_ERROR, 2, "Leave out np."),  # was "must start with a number"
    ("sqrt(2*9.8.*1) m/s^2", "m/s^2", Reason.PARSE_ERROR, 10, "Did you mean *? .* is MATLAB's element-wise"),
    # a function or π in capitals, as caps lock, a phone or a spreadsheet types them: never units
    ("2*PI()*sqrt(2) m/s^2", "m/s^2", Reason.PARSE_ERROR, 2, "If you mean the number π, type pi or π"),
    ("2*Pi*sqrt(2) m/s^2", "m/s^2", Reason.PARSE_ERROR, 2, "type pi or π (in small letters)"),
    ("2*pi()*sqrt(2) m/s^2", "m/s^2", Reason.PARSE_ERROR, 4, "π is a number, not a function"),
    (
        "SQRT(21) m/s^2",
        "m/s^2",
        Reason.PARSE_ERROR,
        0,
        "Did you mean sqrt? Function names are in small letters.",
    ),
    ("9.8*Sin(30°) m/s^2", "m/s^2", Reason.PARSE_ERROR, 4, "Did you mean sin?"),
    (
        "9.8 SIN 30° m/s^2",
        "m/s^2",
        Reason.PARSE_ERROR,
        4,
        "Did you mean sin?",
    ),  # was "must start with a number"
    (
        "9.8*sind(30) m/s^2",
        "m/s^2",
        Reason.PARSE_ERROR,
        4,
        "Did you mean sin(30°)? sind is MATLAB's sin of an angle in degrees, which is not read here: write "
        "sin(30°), with the degree sign.",
    ),
    ("9.8 cosd 60 m/s^2", "m/s^2", Reason.PARSE_ERROR, 4, "write cos(60°)"),
    ("9.8 tand(45°) m/s^2", "m/s^2", Reason.PARSE_ERROR, 4, "write tan(45°)"),
    # a degree sign or deg after a sine's bracket: not a unit, nor sin(30 rad) in degrees, as they read
    ("9.8*sin(30)° m/s^2", "m/s^2", Reason.PARSE_ERROR, 11, "Did you mean sin(30°)?"),
    ("9.8 sin(30)deg m/s^2", "m/s^2", Reason.PARSE_ERROR, 11, "Did you mean sin(30°)?"),
    ("9.8 cos(60) deg m/s^2", "m/s^2", Reason.PARSE_ERROR, 12, "Did you mean cos(60°)?"),
]


@pytest.mark.parametrize(("answer", "units", "reason", "position", "words"), BLAME, ids=[c[0] for c in BLAME])
def test_refused_arithmetic_blames_the_right_part(
    answer: str, units: str, reason: Reason, position: int, words: str
) -> None:
    verdict = check_numeric(answer, NumericSpec(D("4.58"), units))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is reason
    assert verdict.error is not None
    assert verdict.error.position == position
    assert words in verdict.feedback


HOSTILE = [
    # (answer, reason): size limits apply to arithmetic before anything is computed
    ("9^9^9 m", Reason.TOO_LARGE),
    ("(1+1)^(10^6) m", Reason.TOO_LARGE),
    ("factorial(100000) m", Reason.TOO_LARGE),
    ("e^1000 m", Reason.TOO_LARGE),
    ("10^(10^10) m", Reason.TOO_LARGE),
    ("1" * 41 + "/3 m", Reason.TOO_LARGE),
    ("(" * 60 + "1" + ")" * 60 + " m", Reason.TOO_LARGE),
    ("1+" * 120 + "1 m", Reason.TOO_LARGE),
]


@pytest.mark.parametrize(("answer", "reason"), HOSTILE, ids=[c[0][:24] for c in HOSTILE])
def test_hostile_arithmetic_is_refused_by_the_size_limits(answer: str, reason: Reason) -> None:
    verdict = check_numeric(answer, NumericSpec(D(1), "m"))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is reason


@pytest.mark.parametrize(
    "answer", ["__import__('os') m", "eval(1) m", "2; import os", "lambda: 1", "2 m # x"]
)
def test_code_in_a_numeric_answer_is_never_run(answer: str) -> None:
    verdict = check_numeric(answer, NumericSpec(D(2), "m"))
    assert verdict.outcome is Outcome.INVALID
