"""Exact conversion between compatible units, with pint's factors as Fractions."""

from __future__ import annotations

from fractions import Fraction

import pytest

from physics.units import parse_units

F = Fraction

CONVERSIONS = [
    # (value, from, to, exact result)
    (F("16.49"), "km/h", "m/s", F(1649, 360)),
    (F(36), "km/h", "m/s", F(10)),
    (F(1), "kWh", "J", F(3_600_000)),
    (F(1), "eV", "J", F("1.602176634e-19")),
    (F(1), "N·m", "J", F(1)),
    (F(1), "MPa", "N/mm^2", F(1)),
    (F(1), "L", "m^3", F(1, 1000)),
    (F(1), "g/cm^3", "kg/m^3", F(1000)),
    (F(180), "°", "rev", F(1, 2)),
    (F(60), "rpm", "rev/s", F(1)),
    (F(1), "h", "s", F(3600)),
    (F(90), "min", "h", F(3, 2)),
    (F(1), "Å", "nm", F(1, 10)),
    (F(1), "mA·h", "C", F("3.6")),
    (F(1), "kΩ", "V/mA", F(1)),
]


@pytest.mark.parametrize(
    ("value", "source", "target", "expected"),
    CONVERSIONS,
    ids=[f"{c[0]} {c[1]} to {c[2]}" for c in CONVERSIONS],
)
def test_conversion_is_exact(value: Fraction, source: str, target: str, expected: Fraction) -> None:
    assert parse_units(source).convert(value, parse_units(target)) == expected


def test_km_per_hour_round_trips_exactly() -> None:
    kmh, ms = parse_units("km/h"), parse_units("m/s")
    assert ms.convert(kmh.convert(F("16.49"), ms), kmh) == F("16.49")


def test_to_si_and_back() -> None:
    units = parse_units("km/h")
    assert units.to_si(F(18)) == 5
    assert units.from_si(F(5)) == 18
