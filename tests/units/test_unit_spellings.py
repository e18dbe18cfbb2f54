"""Every unit spelling the contract names reads as the right unit: dimension and exact SI factor."""

from __future__ import annotations

from fractions import Fraction

import pytest

from physics.dimensions import Dimension
from physics.units import parse_units

MASS = Dimension({"mass": 1})
LENGTH = Dimension({"length": 1})
TIME = Dimension({"time": 1})
ONE = Dimension()
FORCE = Dimension({"mass": 1, "length": 1, "time": -2})
ENERGY = Dimension({"mass": 1, "length": 2, "time": -2})
POWER = Dimension({"mass": 1, "length": 2, "time": -3})
PRESSURE = Dimension({"mass": 1, "length": -1, "time": -2})
SPEED = Dimension({"length": 1, "time": -1})
RATE = Dimension({"time": -1})
VOLTAGE = Dimension({"mass": 1, "length": 2, "time": -3, "current": -1})
RESISTANCE = Dimension({"mass": 1, "length": 2, "time": -3, "current": -2})

F = Fraction

EXACT_SPELLINGS = [
    # (text, dimension, value of one unit in coherent SI units)
    ("g", MASS, F(1, 1000)),
    ("kg", MASS, F(1)),
    ("mg", MASS, F(1, 10**6)),
    ("m", LENGTH, F(1)),
    ("km", LENGTH, F(1000)),
    ("cm", LENGTH, F(1, 100)),
    ("mm", LENGTH, F(1, 1000)),
    ("nm", LENGTH, F(1, 10**9)),
    ("µm", LENGTH, F(1, 10**6)),  # micro sign U+00B5
    ("μm", LENGTH, F(1, 10**6)),  # Greek mu U+03BC
    ("um", LENGTH, F(1, 10**6)),
    ("Å", LENGTH, F(1, 10**10)),
    ("s", TIME, F(1)),
    ("ms", TIME, F(1, 1000)),
    ("µs", TIME, F(1, 10**6)),
    ("min", TIME, F(60)),
    ("h", TIME, F(3600)),
    ("N", FORCE, F(1)),
    ("kN", FORCE, F(1000)),
    ("Nm", ENERGY, F(1)),
    ("metres per second", SPEED, F(1)),
    ("km per h", SPEED, F(5, 18)),
    ("radians per second", RATE, F(1)),
    ("m per s squared", Dimension({"length": 1, "time": -2}), F(1)),
    ("kg m per s squared", FORCE, F(1)),
    ("cm cubed", Dimension({"length": 3}), F(1, 10**6)),
    ("J per kg K", Dimension({"length": 2, "time": -2, "temperature": -1}), F(1)),
    ("N m", ENERGY, F(1)),
    ("N·m", ENERGY, F(1)),
    ("J", ENERGY, F(1)),
    ("kJ", ENERGY, F(1000)),
    ("kWh", ENERGY, F(3_600_000)),
    ("eV", ENERGY, F("1.602176634e-19")),
    ("MeV", ENERGY, F("1.602176634e-13")),
    ("W", POWER, F(1)),
    ("MW", POWER, F(10**6)),
    ("Pa", PRESSURE, F(1)),
    ("MPa", PRESSURE, F(10**6)),
    ("kPa", PRESSURE, F(1000)),
    ("L", Dimension({"length": 3}), F(1, 1000)),
    ("mL", Dimension({"length": 3}), F(1, 10**6)),
    ("km/h", SPEED, F(5, 18)),
    ("Hz", RATE, F(1)),
    ("kHz", RATE, F(1000)),
    ("rad", ONE, F(1)),
    ("K", Dimension({"temperature": 1}), F(1)),
    ("°C", Dimension({"temperature": 1}), F(1)),
    ("C", Dimension({"current": 1, "time": 1}), F(1)),
    ("V", VOLTAGE, F(1)),
    ("Ω", RESISTANCE, F(1)),
    ("Ω", RESISTANCE, F(1)),  # ohm sign U+2126
    ("ohm", RESISTANCE, F(1)),
    ("kΩ", RESISTANCE, F(1000)),
    ("A", Dimension({"current": 1}), F(1)),
    ("mA", Dimension({"current": 1}), F(1, 1000)),
    ("mol", Dimension({"amount": 1}), F(1)),
    ("cd", Dimension({"luminosity": 1}), F(1)),
    ("meters", LENGTH, F(1)),
    ("kilometres", LENGTH, F(1000)),
    ("seconds", TIME, F(1)),
    ("newtons", FORCE, F(1)),
]


@pytest.mark.parametrize(("text", "dimension", "scale"), EXACT_SPELLINGS, ids=[c[0] for c in EXACT_SPELLINGS])
def test_spelling_reads_as_unit_with_exact_si_factor(
    text: str, dimension: Dimension, scale: Fraction
) -> None:
    units = parse_units(text)
    assert units.dimension == dimension
    assert units.scale == scale


ANGLE_RATIOS = [
    # (text, other, exact ratio text/other): pint's π cancels, so these are exact
    ("°", "deg", F(1)),
    ("rev", "°", F(360)),
    ("rev", "deg", F(360)),
    ("rpm", "rev/min", F(1)),
    ("rpm", "rev/s", F(1, 60)),
    ("degrees", "°", F(1)),
]


@pytest.mark.parametrize(
    ("text", "other", "ratio"), ANGLE_RATIOS, ids=[f"{a}-per-{b}" for a, b, _ in ANGLE_RATIOS]
)
def test_angle_units_relate_exactly(text: str, other: str, ratio: Fraction) -> None:
    assert parse_units(text).scale / parse_units(other).scale == ratio


@pytest.mark.parametrize("text", ["°", "deg", "rev"])
def test_angles_are_dimensionless(text: str) -> None:
    assert parse_units(text).dimension == ONE


def test_degree_is_pi_over_180_radians_to_many_places() -> None:
    assert abs(float(parse_units("°").scale) - 0.017453292519943295) < 1e-18


def test_rpm_is_a_rate() -> None:
    assert parse_units("rpm").dimension == RATE
    assert abs(float(parse_units("rpm").scale) - 0.10471975511965977) < 1e-15


CASE_MATTERS = [
    # (text, dimension): the prefix or unit letter's case changes the meaning
    ("ms", TIME),  # millisecond
    ("Ms", TIME),  # megasecond
    ("mN", FORCE),  # millinewton
    ("Nm", ENERGY),  # newton-metre
    ("nm", LENGTH),  # nanometre
    ("mPa", PRESSURE),
    ("MPa", PRESSURE),
]


@pytest.mark.parametrize(("text", "dimension"), CASE_MATTERS, ids=[c[0] for c in CASE_MATTERS])
def test_letter_case_selects_the_unit(text: str, dimension: Dimension) -> None:
    assert parse_units(text).dimension == dimension


def test_milli_and_mega_differ_by_a_factor_of_a_billion() -> None:
    assert parse_units("Ms").scale / parse_units("ms").scale == 10**9
    assert parse_units("MPa").scale / parse_units("mPa").scale == 10**9
