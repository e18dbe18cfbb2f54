"""A number joined to its units by `*` or `·` (as STACK and Maxima users type it) is the same decimal
literal as with a space: significant figures and plain-decimal parts take it."""

from __future__ import annotations

from decimal import Decimal

import pytest

from physics.numeric import NumericSpec, Tolerance, check_numeric
from physics.verdict import Outcome, Reason

D = Decimal


def _sigfigs(expected: str, units: str) -> NumericSpec:
    return NumericSpec(D(expected), units, tolerance=Tolerance(sigfigs=3))


JOINED = [
    # (answer, spec, what it reads as): each graded as the spaced literal is
    ("12.3*m/s", _sigfigs("12.3", "m/s"), "12.3 m/s"),
    ("12.3 * m/s", _sigfigs("12.3", "m/s"), "12.3 m/s"),
    ("12.3·m/s", _sigfigs("12.3", "m/s"), "12.3 m/s"),
    ("12.3⋅m/s", _sigfigs("12.3", "m/s"), "12.3 m/s"),
    ("-9.81*m/s^2", _sigfigs("-9.81", "m/s^2"), "-9.81 m/s^2"),
    ("25.0*g", _sigfigs("25.0", "g"), "25.0 g"),
    ("1.50e3*N", _sigfigs("1500", "N"), "1.50e3 N"),
    ("1.50×10^3*N", _sigfigs("1500", "N"), "1.50e3 N"),
    ("12.3*[m/s]", _sigfigs("12.3", "m/s"), "12.3 m/s"),
    (r"12.3 \cdot \mathrm{m/s}", _sigfigs("12.3", "m/s"), "12.3 m/s"),
    ("12.3*km/h", _sigfigs("3.42", "m/s"), "12.3 km/h"),
]


@pytest.mark.parametrize(("answer", "spec", "reading"), JOINED, ids=[c[0] for c in JOINED])
def test_a_number_joined_to_its_units_by_a_times_sign_passes_a_significant_figures_part(
    answer: str, spec: NumericSpec, reading: str
) -> None:
    verdict = check_numeric(answer, spec)
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback
    assert verdict.read_as is not None and verdict.read_as.text == reading


def test_significant_figures_are_counted_on_a_joined_literal() -> None:
    verdict = check_numeric("12.30*m/s", _sigfigs("12.3", "m/s"))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is Reason.SIGFIGS
    assert "yours shows 4" in verdict.feedback


@pytest.mark.parametrize("answer", ["9.81*m/s^2", "9.81·m/s^2", "9.81 * m/s^2"])
def test_a_plain_decimal_part_takes_a_literal_joined_to_its_units(answer: str) -> None:
    spec = NumericSpec(D("9.81"), "m/s^2", arithmetic=False)
    assert check_numeric(answer, spec).outcome is Outcome.CORRECT


STILL_ARITHMETIC = [
    # (answer): a `*` before a number, a constant or a function is arithmetic, as before
    "4.1*3 m/s",
    "12.3*1 m/s",
    "3.92*pi m/s",
    "24.6*sin(30°) m/s",
]


@pytest.mark.parametrize("answer", STILL_ARITHMETIC)
def test_a_times_sign_before_more_arithmetic_is_still_arithmetic(answer: str) -> None:
    verdict = check_numeric(answer, _sigfigs("12.3", "m/s"))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is Reason.SIGFIGS
    assert "not as arithmetic" in verdict.feedback
