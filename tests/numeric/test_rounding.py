"""The one rounding rule: what grading accepts is what the instructor is shown, digit for digit."""

from __future__ import annotations

from decimal import ROUND_CEILING, ROUND_FLOOR, ROUND_HALF_EVEN, Decimal
from fractions import Fraction

import pytest

from physics.numeric import NumericSpec, Tolerance, check_numeric, round_sigfigs
from physics.verdict import Outcome

F = Fraction
D = Decimal

HALF_UP = [
    # (value, figures, shown): halves away from zero, trailing zeros shown
    (F("4.585"), 3, "4.59"),
    (F("-4.585"), 3, "-4.59"),
    (F("4.5849999"), 3, "4.58"),
    (F("9.995"), 3, "10.0"),
    (D("9.96"), 2, "10"),
    (F(1498), 3, "1.50E+3"),
    (F("0.00044995"), 4, "0.0004500"),
    (F(123456), 1, "1E+5"),
    (F(2, 3), 2, "0.67"),
    (F(1, 3), 40, "0." + "3" * 40),
    (F(0), 3, "0"),
    (D("2.5"), 3, "2.50"),
    (D("2.4999"), 2, "2.5"),
    (D("0.012345"), 3, "0.0123"),
    (D("12345"), 2, "1.2E+4"),
    (D("2.5"), 1, "3"),
    (D("-2.5"), 1, "-3"),
    (F(10) ** 400, 3, "1.00E+400"),
    (F(15, 10**401), 1, "2E-400"),
]


@pytest.mark.parametrize(("value", "figures", "shown"), HALF_UP, ids=[f"{c[0]}@{c[1]}"[:40] for c in HALF_UP])
def test_rounds_half_away_from_zero_showing_exactly_the_figures(value, figures, shown) -> None:
    rounded = round_sigfigs(value, figures)
    assert str(rounded) == shown
    assert len(rounded.as_tuple().digits) == figures or rounded == 0


DIRECTED = [
    # (value, figures, rounding, shown): the directions drawing given values uses
    (D("2.5"), 1, ROUND_HALF_EVEN, "2"),
    (D("3.5"), 1, ROUND_HALF_EVEN, "4"),
    (D("2.51"), 1, ROUND_HALF_EVEN, "3"),
    (D("2.01"), 1, ROUND_CEILING, "3"),
    (D("-2.01"), 1, ROUND_CEILING, "-2"),
    (D("2.99"), 1, ROUND_FLOOR, "2"),
    (D("-9.01"), 1, ROUND_FLOOR, "-1E+1"),
    (D("9.99"), 2, ROUND_CEILING, "10"),
]


@pytest.mark.parametrize(
    ("value", "figures", "rounding", "shown"), DIRECTED, ids=[f"{c[0]}@{c[1]}{c[2]}" for c in DIRECTED]
)
def test_other_directions_round_the_same_way_as_the_decimal_module(value, figures, rounding, shown) -> None:
    assert str(round_sigfigs(value, figures, rounding)) == shown
    # The decimal module's own quantize agrees wherever no carry into the next decade happens.
    if value.adjusted() == round_sigfigs(value, figures, rounding).adjusted():
        assert round_sigfigs(value, figures, rounding) == value.quantize(
            D(1).scaleb(value.adjusted() - figures + 1), rounding=rounding
        )


@pytest.mark.parametrize(("figures", "rounding"), [(0, "ROUND_HALF_UP"), (2, "ROUND_05UP"), (2, "up")])
def test_unknown_rounding_or_no_figures_is_refused(figures, rounding) -> None:
    with pytest.raises(ValueError):
        round_sigfigs(D("2.5"), figures, rounding)


@pytest.mark.parametrize("expected", ["4.585", "-4.585", "0.0004499500", "9.995", "1234.5"])
@pytest.mark.parametrize("figures", [1, 2, 3, 4])
def test_the_value_shown_to_n_figures_is_the_value_a_sigfigs_check_accepts(expected, figures) -> None:
    spec = NumericSpec(D(expected), tolerance=Tolerance(sigfigs=figures))
    shown = round_sigfigs(D(expected), figures)
    # `1.50E+3` is not how a student writes it, and 1500 may show 2 to 4 figures: write the mantissa.
    answer = f"{shown.scaleb(-shown.adjusted())}e{shown.adjusted()}"
    assert check_numeric(answer, spec).outcome is Outcome.CORRECT, answer
    # One unit more in the last place shown is wrong.
    last = D(1).scaleb(shown.adjusted() - figures + 1)
    off = shown + last if shown > 0 else shown - last
    off_answer = f"{off.scaleb(-off.adjusted())}e{off.adjusted()}"
    if len(off.as_tuple().digits) == figures:
        assert check_numeric(off_answer, spec).outcome is Outcome.INCORRECT, off_answer
