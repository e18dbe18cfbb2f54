"""`describe` names a dimension for feedback, falling back to its SI form."""

from __future__ import annotations

from fractions import Fraction

import pytest

from physics.dimensions import Dimension, describe, si_form
from physics.units import unit_dimension

NAMED = [
    # (unit string, phrase)
    ("N", "a force"),
    ("m/s^2", "an acceleration"),
    ("m/s", "a speed"),
    ("km/h", "a speed"),
    ("J", "an energy"),
    ("N m", "an energy"),
    ("kg", "a mass"),
    ("m", "a length"),
    ("s", "a time"),
    ("W", "a power"),
    ("Pa", "a pressure"),
    ("kg m/s", "a momentum"),
    ("N s", "a momentum"),
    ("1/s", "an angular frequency or rate"),
    ("rad/s", "an angular frequency or rate"),
    ("Hz", "an angular frequency or rate"),
    ("N/m", "a spring constant"),
    ("1", "a pure number"),
    ("rad", "a pure number"),
    ("kg m^2", "a moment of inertia"),
    ("kg/m^3", "a density"),
    ("C", "an electric charge"),
    ("V", "a voltage"),
    ("K", "a temperature"),
    ("J/(kg K)", "a specific heat capacity"),
]


@pytest.mark.parametrize(("units", "phrase"), NAMED, ids=[c[0] for c in NAMED])
def test_common_dimension_has_a_name(units: str, phrase: str) -> None:
    assert describe(unit_dimension(units)) == phrase


FALLBACK = [
    (Dimension({"mass": 1, "length": 2, "time": -4}), "a quantity in kg·m²/s⁴"),
    (Dimension({"time": -3}), "a quantity in 1/s³"),
    (Dimension({"mass": 1, "length": -1, "time": -3}), "a quantity in kg/(m·s³)"),
    (Dimension({"length": Fraction(1, 2)}), "a quantity in m^(1/2)"),
    (Dimension({"length": 4}), "a quantity in m⁴"),
]


@pytest.mark.parametrize(("dimension", "phrase"), FALLBACK, ids=[p for _, p in FALLBACK])
def test_unnamed_dimension_falls_back_to_si_form(dimension: Dimension, phrase: str) -> None:
    assert describe(dimension) == phrase


def test_si_form_of_a_pure_number_is_one() -> None:
    assert si_form(Dimension()) == "1"
