"""Units in square brackets around all of them (`4.58 [m/s^2]`), as physics texts print them: read as
the units inside, with errors placed inside the brackets; brackets elsewhere are refused as before."""

from __future__ import annotations

from decimal import Decimal

import pytest

from physics.numeric import NumericSpec, Tolerance, check_numeric
from physics.verdict import Outcome, Reason

D = Decimal
CLOSE = Tolerance(rel=D("0.00001"))

SAME_AS_WITHOUT = [
    # (answer with brackets, the same answer without them, expected value, expected units)
    ("4.58 [m/s^2]", "4.58 m/s^2", "4.58", "m/s^2"),
    ("4.58[m/s^2]", "4.58 m/s^2", "4.58", "m/s^2"),
    ("4.58 [ m/s^2 ]", "4.58 m/s^2", "4.58", "m/s^2"),
    ("1.5e3 [N]", "1.5e3 N", "1500", "N"),
    ("16.5 [km/h]", "16.5 km/h", "4.58333", "m/s"),
    ("4.58 [m/s]", "4.58 m/s", "4.58", "m/s^2"),  # wrong dimension, said the same way
    ("4.60 [m/s^2]", "4.60 m/s^2", "4.58", "m/s^2"),  # wrong value
    ("30 [°]", "30°", "30", "°"),
    ("5 [Kg]", "5 Kg", "5", "kg"),  # a glued name settled by dimension, with its note
    ("5 [ms^-1]", "5 ms^-1", "5", "m/s"),
    ("229/50 [m/s^2]", "229/50 m/s^2", "4.58", "m/s^2"),
    ("2*pi [rad]", "2*pi rad", "6.28319", "rad"),
    ("9.81*[m/s^2]", "9.81*m/s^2", "9.81", "m/s^2"),
    ("0.5 [kg] * 9.8 [m/s^2]", "0.5 kg * 9.8 m/s^2", "4.9", "N"),
    ("4.58\\,[\\mathrm{m/s^2}]", "4.58\\,\\mathrm{m/s^2}", "4.58", "m/s^2"),
]


@pytest.mark.parametrize(
    ("bracketed", "plain", "expected", "units"), SAME_AS_WITHOUT, ids=[c[0] for c in SAME_AS_WITHOUT]
)
def test_units_in_square_brackets_are_graded_as_the_units_inside(
    bracketed: str, plain: str, expected: str, units: str
) -> None:
    spec = NumericSpec(D(expected), units, tolerance=CLOSE)
    with_brackets, without = check_numeric(bracketed, spec), check_numeric(plain, spec)
    assert with_brackets.outcome is not Outcome.INVALID, with_brackets.feedback
    assert with_brackets == without


ARITHMETIC_IN_BRACKETS = [
    # (answer, value): a bracket holding arithmetic after a number is a factor, as before
    ("2 [pi]", "6.28319"),
    ("2 [pi + 1]", "8.28319"),
    ("[2] [sqrt(2)]", "2.82843"),
]


@pytest.mark.parametrize(
    ("answer", "value"), ARITHMETIC_IN_BRACKETS, ids=[c[0] for c in ARITHMETIC_IN_BRACKETS]
)
def test_square_brackets_holding_arithmetic_are_not_units(answer: str, value: str) -> None:
    verdict = check_numeric(answer, NumericSpec(D(value), "1", tolerance=CLOSE))
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback


REFUSED = [
    # (answer, reason, position, words): errors inside the brackets point inside them
    ("4.58 [m/smoot]", Reason.UNKNOWN_UNIT, 8, "Unknown unit 'smoot'"),
    ("4.58 [ m/smoot ]", Reason.UNKNOWN_UNIT, 9, "Unknown unit 'smoot'"),
    ("229/50 [m/smoot]", Reason.UNKNOWN_UNIT, 10, "Unknown unit 'smoot'"),
    ("4.58 [m/s^2 foo]", Reason.UNKNOWN_UNIT, 12, "Unknown unit 'foo'"),
    ("4.58 [m/s^2", Reason.PARSE_ERROR, 5, "never closed"),
    ("229/50 [m/s^2", Reason.PARSE_ERROR, 7, "never closed"),
    ("4.58 [m]/s", Reason.PARSE_ERROR, 7, "around all of the units"),
    ("4.58 [m/s^2]]", Reason.PARSE_ERROR, 11, "around all of the units"),
    # refused as before
    ("4.58 m/[s^2]", Reason.PARSE_ERROR, 7, "Unexpected character '['"),
    ("4.58 []", Reason.PARSE_ERROR, 5, "Empty brackets"),
    ("[m/s^2]", Reason.PARSE_ERROR, 1, "Unexpected word 'm'"),
    ("2+[m/s^2]", Reason.PARSE_ERROR, 3, "Unexpected word 'm'"),
]


@pytest.mark.parametrize(("answer", "reason", "position", "words"), REFUSED, ids=[c[0] for c in REFUSED])
def test_bracketed_units_that_cannot_be_read_are_refused_where_the_fault_is(
    answer: str, reason: Reason, position: int, words: str
) -> None:
    verdict = check_numeric(answer, NumericSpec(D("4.58"), "m/s^2"))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is reason
    assert verdict.error is not None
    assert verdict.error.position == position
    assert words in verdict.feedback


# (answer, expected value, expected units, outcome, what the verdict says): units said again in
# brackets after them, or a remark in brackets, as an answer is copied from Wolfram|Alpha or a chatbot
REMARKS = [
    ("4.58 m/s^2 (meters per second squared)", "4.58", "m/s^2", "correct", "Correct."),  # was 4.58 m/m
    ("4.58 m/s^2 (m/s/s)", "4.58", "m/s^2", "correct", "Correct."),
    ("12 J (joules)", "12", "J", "correct", "Correct."),
    (
        "4.58 m/s^2 (approx)",
        "4.58",
        "m/s^2",
        "invalid",
        "Give the value and its units alone: leave out (approx)",
    ),
    ("4.58 m/s^2 (3 s.f.)", "4.58", "m/s^2", "invalid", "leave out (3 s.f.)"),
    ("4.58 m/s^2 (down)", "4.58", "m/s^2", "invalid", "a direction is not read here"),
    ("4.58 kg (m/s)", "4.58", "N*s", "correct", "Correct."),  # other units: a product, as before
    ("4186 J/(kg K)", "4186", "J/(kg*K)", "correct", "Correct."),
    # a chatbot's answer, in bold or boxed
    ("**4.58 m/s²**", "4.58", "m/s^2", "correct", "Correct."),
    (r"\[\boxed{4.58 \text{ m/s}^2}\]", "4.58", "m/s^2", "correct", "Correct."),
]


@pytest.mark.parametrize(
    ("answer", "expected", "units", "outcome", "says"), REMARKS, ids=[c[0] for c in REMARKS]
)
def test_units_said_again_in_brackets_are_read_once_and_a_remark_is_refused(
    answer: str, expected: str, units: str, outcome: str, says: str
) -> None:
    verdict = check_numeric(answer, NumericSpec(D(expected), units))
    assert verdict.outcome.value == outcome
    assert says in verdict.feedback
