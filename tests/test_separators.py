"""A comma inside a number and digits grouped by spaces are `invalid` wherever numbers are read (API.md:
"a comma inside a number (`4,58`) or two numbers side by side (`12 500`) is `invalid`"), each refusal
saying what was seen and what to type instead, at the right place."""

from __future__ import annotations

from decimal import Decimal

import pytest

from physics.errors import ParseError
from physics.numeric import NumericSpec, check_numeric
from physics.verdict import Outcome, Reason
from tests.mathinput.support import read

REFUSED = [
    # (typed number, position in it, the message's start): the contract's own examples first
    ("4,58", 1, "4,58: a decimal comma is not read; write 4.58"),
    ("12 500", 3, "12 500: two numbers side by side; for one number, write 12500 (or 12.5e3)"),
    ("0,500", 1, "0,500: a decimal comma is not read; write 0.500"),
    ("1,500", 1, "1,500: a comma is not read in a number. Did you mean 1.500 or 1500?"),
    ("1,500,000", 1, "1,500,000: a comma between thousands is not read; write 1500000"),
    ("1.500,5", 5, "1.500,5: a comma is not read in a number, nor a point between thousands; write 1500.5"),
    ("1 500", 2, "1 500: two numbers side by side; for one number, write 1500 (or 1.5e3)"),
    ("1\u2009500", 2, "1 500: two numbers side by side"),  # a thin space
    ("1\u202f500", 2, "1 500: two numbers side by side"),  # a narrow no-break space
    ("12 345", 3, "12 345: two numbers side by side; for one number, write 12345"),
    ("1 500.5", 2, "1 500.5: two numbers side by side; for one number, write 1500.5"),
    ("0.123 45", 6, "0.123 45: two numbers side by side; for one number, write 0.12345"),
    ("4.580 7", 6, "4.580 7: two numbers side by side; for one number, write 4.5807"),
    ("1 500,5", 2, "1 500,5: two numbers side by side; for one number, write 1500.5"),
    ("0 500", 2, "0 500: two numbers side by side. Did you mean 0.500 or 500?"),
    # a calculator's display, 4.58 and its exponent 10, or ×10 with its exponent left out: never 4.5810
    (
        "4.58 10",
        5,
        "4.58 10: two numbers side by side; for a power of ten, write 4.58×10^ and its exponent (as in "
        "4.58×10^3), or 4.58e10 for 4.58×10^10",
    ),
    # a number with a power after another: the power shown with it (was "2 3: …", the ^2 dropped)
    ("2 3^2", 2, "2 3^2: two numbers side by side; for a product, write 2*3^2"),
    ("2 3²", 2, "2 3²: two numbers side by side; for a product, write 2*3²"),
    ("4.5 2^(1/2)", 4, "4.5 2^(1/2): two numbers side by side; for a product, write 4.5*2^(1/2)"),
    (
        "1 500^2",
        2,
        "1 500^2: two numbers side by side; for a product, write 1*500^2; for one number, write 1500^2",
    ),
    # Arabic script's thousands separator is never a decimal one: not asked about, as 1,500 is
    ("٤٬٥٨٠", 1, "4٬580: ٬, the Arabic thousands separator, is not read in a number; write 4580"),
    (
        "١٬٥٠٠٬٠٠٠٫٥",
        1,
        "1٬500٬000.5: ٬, the Arabic thousands separator, is not read in a number; write 1500000.5",
    ),
    (
        "۴٬۵۸",
        1,
        "4٬58: ٬, the Arabic thousands separator, is not read in a number; write its digits together",
    ),
    # LaTeX's braced comma is a decimal one (LaTeX groups thousands with a thin space, \,)
    ("4{,}58", 2, "4,58: a decimal comma is not read; write 4.58"),
    ("1{,}500", 2, "1,500: a comma is not read in a number. Did you mean 1.500 or 1500?"),
]
IDS = [c[0] for c in REFUSED]


@pytest.mark.parametrize(("number", "position", "message"), REFUSED, ids=IDS)
def test_a_numeric_answer_with_a_separator_is_invalid_saying_what_to_type(
    number: str, position: int, message: str
) -> None:
    verdict = check_numeric(f"{number} N", NumericSpec(Decimal("4.58"), "N"))
    assert (verdict.outcome, verdict.reason) == (Outcome.INVALID, Reason.PARSE_ERROR)
    assert verdict.error is not None
    assert verdict.error.position == position
    assert verdict.error.message.startswith(message)


@pytest.mark.parametrize(("number", "position", "message"), REFUSED, ids=IDS)
def test_a_symbolic_answer_with_a_separator_is_refused_saying_what_to_type(
    number: str, position: int, message: str
) -> None:
    with pytest.raises(ParseError) as caught:
        read(f"{number} m g", "m", "g")
    assert caught.value.position == position
    assert caught.value.message.startswith(message)


@pytest.mark.parametrize(
    ("answer", "message"),
    [("12 500/2", "12 500: two numbers side by side"), ("1 1/2", "Write a mixed number")],
)
def test_digits_grouped_before_a_division_are_no_mixed_number(answer: str, message: str) -> None:
    with pytest.raises(ParseError) as caught:
        read(f"{answer} m", "m")
    assert caught.value.message.startswith(message)


def test_two_numbers_side_by_side_in_a_symbolic_answer_may_also_be_a_product() -> None:
    with pytest.raises(ParseError) as caught:
        read("12 500 m g", "m", "g")
    assert caught.value.message.endswith("; for a product, write 12*500")


POWERS_OF_TEN_APART = [
    # (typed, position, message): a calculator's display, its × left out, is two numbers side by side too
    ("4.58 10^3", 5, "4.58 10^3: two numbers side by side; for a power of ten, write 4.58×10^3"),
    ("4.58 10⁻³", 5, "4.58 10⁻³: two numbers side by side; for a power of ten, write 4.58×10⁻³"),
    ("4.580\u200910^-3", 6, "4.580 10^-3: two numbers side by side; for a power of ten, write 4.580×10^-3"),
    # its ^ left out too: was "for one number, write 4.58103"
    (
        "4.58 10 3",
        5,
        "4.58 10 3: numbers side by side. Did you mean 4.58×10^3? For a power of ten, write 4.58×10^3 or 4.58e3",
    ),
    # its ^ left out, with a minus: was "Did you mean ×10^-3?" (numeric), "4.58 10: …" (symbolic)
    (
        "4.58 10 -3",
        5,
        "4.58 10 -3: numbers side by side. Did you mean 4.58×10^-3? For a power of ten, write 4.58×10^-3 or "
        "4.58e-3",
    ),
    (
        "4.58 10−3",
        5,
        "4.58 10−3: numbers side by side. Did you mean 4.58×10^-3? For a power of ten, write 4.58×10^-3 or 4.58e-3",
    ),
    (
        "6 10 23",
        2,
        "6 10 23: numbers side by side. Did you mean 6×10^23? For a power of ten, write 6×10^23 or 6e23",
    ),
]


@pytest.mark.parametrize(
    ("number", "position", "message"), POWERS_OF_TEN_APART, ids=[c[0] for c in POWERS_OF_TEN_APART]
)
def test_a_power_of_ten_apart_from_its_number_is_refused_saying_where_the_times_sign_goes(
    number: str, position: int, message: str
) -> None:
    verdict = check_numeric(f"{number} N", NumericSpec(Decimal("4.58"), "N"))
    assert (verdict.outcome, verdict.reason) == (Outcome.INVALID, Reason.PARSE_ERROR)
    assert verdict.error is not None
    assert (verdict.error.position, verdict.error.message) == (position, message)
    with pytest.raises(ParseError) as caught:
        read(f"{number} m", "m")
    assert (caught.value.position, caught.value.message) == (position, message)


@pytest.mark.parametrize("answer", ["2*4,58 N", "4,58*2 N", "(4,58) N"])
def test_a_decimal_comma_in_arithmetic_is_refused_at_the_comma(answer: str) -> None:
    verdict = check_numeric(answer, NumericSpec(Decimal("9.16"), "N"))
    assert verdict.error is not None
    assert verdict.error.message.startswith("4,58: a decimal comma is not read; write 4.58")
    assert answer[verdict.error.position] == ","


NUMBERS_AFTER_A_POWER = [
    # (answer, position, message): the exponent and a number typed after it, side by side
    (
        "x^2 3",
        4,
        "x^2 3: the number after a power is a separate factor, not part of the exponent: for the product, "
        "write 3 x^2; for the power, write x^(23)",
    ),
    (
        "m g x^-2 3",
        9,
        "x^-2 3: the number after a power is a separate factor, not part of the exponent: for the product, write 3 x^-2; for the power, write x^(-23)",
    ),
    (
        "x**2 3",
        5,
        "x^2 3: the number after a power is a separate factor, not part of the exponent: for the product, write 3 x^2; for the power, write x^(23)",
    ),
    (
        "x^2 1/2",
        4,
        "x^2 1/2: the number after a power is a separate factor, not part of the exponent: for the product, write 1/2 x^2",
    ),
    (
        "(m+g)^2 3.5",
        8,
        "(m+g)^2 3.5: the number after a power is a separate factor, not part of the exponent: for the product, write 3.5 (m+g)^2",
    ),
    (
        "2^2 3",
        4,
        "2^2 3: the number after a power is a separate factor, not part of the exponent: for the product, write 3*2^2; for the power, write 2^(23)",
    ),
    # a power of ten after a power: the exponent times it, or a factor; was "2 10: two numbers side by side"
    (
        "x^2 10^3",
        4,
        "x^2 10^3: the number after a power is a separate factor, not part of the exponent: for the product, write 10^3 x^2; for the power, write x^(2·10^3)",
    ),
    (
        "x^-2 10^3",
        5,
        "x^-2 10^3: the number after a power is a separate factor, not part of the exponent: for the product, write 10^3 x^-2; for the power, write x^(-2·10^3)",
    ),
    (
        "x^2 10³",
        4,
        "x^2 10³: the number after a power is a separate factor, not part of the exponent: for the product, write 10³ x^2; for the power, write x^(2·10³)",
    ),
]


@pytest.mark.parametrize(
    ("answer", "position", "message"), NUMBERS_AFTER_A_POWER, ids=[c[0] for c in NUMBERS_AFTER_A_POWER]
)
def test_a_number_after_a_power_is_refused_saying_how_to_write_the_product_or_the_power(
    answer: str, position: int, message: str
) -> None:
    with pytest.raises(ParseError) as caught:
        read(answer, "x", "m", "g")
    assert (caught.value.position, caught.value.message) == (position, message)


def test_a_number_after_a_power_of_a_number_is_refused_in_a_numeric_answer_too() -> None:
    verdict = check_numeric("9.8*2^2 3 N", NumericSpec(Decimal("117.6"), "N"))
    assert (verdict.outcome, verdict.reason) == (Outcome.INVALID, Reason.PARSE_ERROR)
    assert verdict.error is not None
    assert verdict.error.message.endswith("for the product, write 3*2^2; for the power, write 2^(23)")
