"""°C alone is an absolute temperature (offset 273.15 K); inside a compound unit it is a difference."""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction

import pytest

from physics.numeric import NumericSpec, check_numeric
from physics.units import IncompatibleUnits, parse_units

F = Fraction

CONVERSIONS = [
    # (value, from, to, exact result)
    (F(25), "°C", "K", F("298.15")),
    (F(0), "°C", "K", F("273.15")),
    (F("-273.15"), "°C", "K", F(0)),
    (F("298.15"), "K", "°C", F(25)),
    (F(0), "K", "°C", F("-273.15")),
    (F(25), "°C", "°C", F(25)),
    (F(25), "°C", "mK", F(298150)),
    (F(1), "J/(kg·°C)", "J/(kg·K)", F(1)),  # a difference: no offset
    (F(4186), "J/kg °C", "kJ/(kg·K)", F("4.186")),
    (F(3), "°C/s", "K/s", F(3)),
    (F(2), "°C^2", "K^2", F(2)),
]


@pytest.mark.parametrize(
    ("value", "source", "target", "expected"),
    CONVERSIONS,
    ids=[f"{c[0]} {c[1]} to {c[2]}" for c in CONVERSIONS],
)
def test_temperature_conversion_is_exact(
    value: Fraction, source: str, target: str, expected: Fraction
) -> None:
    assert parse_units(source).convert(value, parse_units(target)) == expected


def test_lone_celsius_has_an_offset_and_compound_celsius_has_none() -> None:
    assert parse_units("°C").offset == F("273.15")
    assert parse_units("J/(kg·°C)").offset == 0
    assert parse_units("K").offset == 0


def test_celsius_has_the_dimension_of_kelvin() -> None:
    assert parse_units("°C").dimension == parse_units("K").dimension


def test_converting_between_dimensions_is_refused() -> None:
    with pytest.raises(IncompatibleUnits):
        parse_units("°C").convert(F(1), parse_units("m"))


# (answer, expected, the part's units, outcome, what the feedback says)
TEMPERATURE_OR_CHANGE = [
    ("10 °C", "10", "K", "invalid", "Is 10 °C a temperature (283.15 K) or a change of temperature (10 K)?"),
    ("18 °F", "10", "K", "invalid", "a change of temperature (10 K)?"),
    ("10 K", "10", "°C", "invalid", "Is 10 K a temperature (-263.15 °C) or a change of temperature (10 °C)?"),
    ("10 °C", "283.15", "K", "correct", "Correct."),  # the temperature is right: no question
    ("12 °C", "10", "K", "incorrect", "not within the accepted tolerance"),  # neither reading is right
    ("10 °C", "10", "°C", "correct", "Correct."),  # the part's own units: nothing to convert
]


@pytest.mark.parametrize(("answer", "expected", "units", "outcome", "says"), TEMPERATURE_OR_CHANGE)
def test_a_temperature_right_only_as_a_change_is_asked_about(
    answer: str, expected: str, units: str, outcome: str, says: str
) -> None:
    verdict = check_numeric(answer, NumericSpec(Decimal(expected), units))
    assert verdict.outcome.value == outcome
    assert says in verdict.feedback
