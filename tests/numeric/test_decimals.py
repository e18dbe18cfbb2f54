"""The one reader of authors' numbers: what it accepts, what it refuses and what it says."""

from __future__ import annotations

from decimal import Decimal

import pytest

from physics.errors import SpecError
from physics.numeric import NotADecimal, as_decimal, read_decimal
from physics.numeric.decimals import MAX_DIGITS, MAX_EXPONENT, MAX_TEXT, is_number_text

D = Decimal

ACCEPTED = [
    # (value as given, exact decimal read)
    (4.5807, "4.5807"),  # a JSON float is the decimal its author wrote
    (0.1, "0.1"),
    (9.81, "9.81"),
    (6.02214076e23, "6.02214076e23"),
    (1.602176634e-19, "1.602176634e-19"),
    (6.674e-11, "6.674e-11"),
    (5.391e-44, "5.391e-44"),  # the Planck time
    ("6.62607015e-34", "6.62607015e-34"),
    ("  4.58  ", "4.58"),
    (".5", "0.5"),
    ("100.", "100"),
    ("-3", "-3"),
    ("+2E3", "2000"),
    (0, "0"),
    ("0e999999999999999999999", "0"),  # zero is zero, whatever power of ten
    (42, "42"),
    (10**MAX_EXPONENT, f"1e{MAX_EXPONENT}"),
    ("9.99e100", "9.99e100"),
    ("1e-100", "1e-100"),
    ("1." + "1" * (MAX_DIGITS - 1), "1." + "1" * (MAX_DIGITS - 1)),
    ("1" + "0" * 60, "1e60"),  # trailing zeros of an integer are not significant
    (D("2.50"), "2.50"),
]


@pytest.mark.parametrize(
    ("value", "read"), ACCEPTED, ids=[f"{type(c[0]).__name__}-{str(c[0])[:24]}" for c in ACCEPTED]
)
def test_accepted_numbers_are_read_exactly(value, read) -> None:
    assert read_decimal(value) == D(read)


SIZE = f"must be 0 or of size from 1e-{MAX_EXPONENT} to below 1e{MAX_EXPONENT + 1}"
REFUSED = [
    # (value, message): the message completes "<field> ..."
    (True, "must be a number, not true/false"),
    (None, "must be a number such as 9.81 or 6.022e23"),
    ([1], "must be a number such as 9.81 or 6.022e23"),
    ("abc", "must be a decimal number such as 9.81 or 6.022e23"),
    ("4_58", "must be a decimal number such as 9.81 or 6.022e23"),
    ("4,58", "must be a decimal number such as 9.81 or 6.022e23"),
    ("NaN", "must be a decimal number such as 9.81 or 6.022e23"),
    ("Infinity", "must be a decimal number such as 9.81 or 6.022e23"),
    ("pi/2", "must be a decimal number such as 9.81 or 6.022e23"),
    ("", "must be a decimal number such as 9.81 or 6.022e23"),
    (float("nan"), "must be a finite number"),
    (float("inf"), "must be a finite number"),
    (D("NaN"), "must be a finite number"),
    (D("sNaN"), "must be a finite number"),
    (D("-Infinity"), "must be a finite number"),
    (10 ** (MAX_EXPONENT + 1), SIZE),
    (-(10**4200), SIZE),
    (1e300, SIZE),
    (5e-324, SIZE),
    ("1e101", SIZE),
    ("1e-101", SIZE),
    ("1e999999999", SIZE),
    ("1e" + "9" * 150, SIZE),
    (D("1e999999999"), SIZE),
    ("1." + "1" * MAX_DIGITS, f"must have at most {MAX_DIGITS} significant digits"),
    ("1" * 61, f"must have at most {MAX_DIGITS} significant digits"),
    ("1" * (MAX_TEXT + 1), f"must be written in at most {MAX_TEXT} characters"),
    ("0." + "0" * 300 + "1", f"must be written in at most {MAX_TEXT} characters"),
]


@pytest.mark.parametrize(
    ("value", "message"), REFUSED, ids=[f"{type(c[0]).__name__}-{str(c[0])[:24]}" for c in REFUSED]
)
def test_refused_numbers_say_why(value, message) -> None:
    with pytest.raises(NotADecimal) as caught:
        read_decimal(value)
    assert caught.value.message == message
    assert isinstance(caught.value, ValueError)  # so pydantic reports it at the field's path


@pytest.mark.parametrize(
    ("path", "message"),
    [
        (("expected",), "expected must be a finite number"),
        (("tolerance", "rel"), "rel must be a finite number"),
    ],
)
def test_the_core_names_the_field_in_a_spec_error(path, message) -> None:
    with pytest.raises(SpecError) as caught:
        as_decimal(float("nan"), path)
    assert (caught.value.path, caught.value.message) == (path, message)


@pytest.mark.parametrize(
    ("text", "number"),
    [
        ("1e-3", True),
        (" .5 ", True),
        ("1" * 1000, True),
        ("pi/2", False),
        ("1_000", False),
        ("NaN", False),
        ("2 pi", False),
    ],
)
def test_number_text_is_told_from_expression_text(text, number) -> None:
    assert is_number_text(text) is number


@pytest.mark.parametrize(
    ("hostile", "message"),
    [
        (10**4000, SIZE),
        ("9" * 100_000, f"must be written in at most {MAX_TEXT} characters"),
        ("1e" + "9" * 100_000, f"must be written in at most {MAX_TEXT} characters"),
        ("1e" + "9" * 190, SIZE),
        (D("1e-999999999999999999"), SIZE),
    ],
    ids=["4000-digit-int", "100k-digits", "100k-digit-exponent", "190-digit-exponent", "decimal-tiny"],
)
def test_hostile_numbers_are_refused_by_their_size_before_any_arithmetic(hostile, message) -> None:
    # The int is compared with a power of ten, the text measured, the exponent counted: nothing here
    # reaches Decimal arithmetic (the per-test time limit would catch one that did).
    with pytest.raises(NotADecimal) as caught:
        read_decimal(hostile)
    assert caught.value.message == message
