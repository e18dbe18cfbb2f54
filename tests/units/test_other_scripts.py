"""Units written in Russian or Chinese, or with a letter that looks Latin: refused naming the Latin symbols
to type, never read as them."""

from __future__ import annotations

from decimal import Decimal

import pytest

from physics.numeric import NumericSpec, check_numeric
from physics.units.other_scripts import latin_units
from physics.verdict import Outcome, Reason

LATIN = [
    # (units as typed, in Latin letters, or None: not units written in Russian)
    ("м/с²", "m/s²"),
    ("м/с^2", "m/s^2"),
    ("кг", "kg"),
    ("Н·м", "N·m"),
    ("км/ч", "km/h"),
    ("мм", "mm"),
    ("мкм", "µm"),
    ("мс", "ms"),  # the millisecond, as Russian writes it
    ("мин", "min"),
    ("кПа", "kPa"),
    ("米/秒²", "m/s²"),  # as Chinese textbooks write them
    ("千克", "kg"),
    ("公斤", "kg"),
    ("牛·米", "N·m"),
    ("千米/小时", "km/h"),
    ("m/s^2", None),  # no Cyrillic
    ("шт", None),  # no unit's symbol
]


@pytest.mark.parametrize(("typed", "latin"), LATIN, ids=[c[0] for c in LATIN])
def test_russian_unit_symbols_are_spelled_in_latin(typed: str, latin: str | None) -> None:
    assert latin_units(typed) == latin


REFUSED = [
    # (answer, expected, units, the refusal's message): was "Unknown unit 'м'" with no more
    (
        "4.58 м/с²",
        "4.58",
        "m/s^2",
        "Unknown unit 'м': units are written with SI's symbols in Latin letters; did you mean m/s²?",
    ),
    ("36 км/ч", "10", "m/s", "did you mean km/h?"),
    ("5 кН", "5000", "N", "did you mean kN?"),
    (
        "4.58 м/с",
        "4.58",
        "m/s^2",
        "did you mean m/s?",
    ),  # graded once typed in Latin: a speed, not an acceleration
    (
        "4.58 шт",
        "4.58",
        "m/s^2",
        "Unknown unit 'шт': units are written with SI's symbols in Latin letters, as in",
    ),
    # Chinese: was "Unknown unit '米'" with no more
    (
        "4.58 米/秒²",
        "4.58",
        "m/s^2",
        "Unknown unit '米': units are written with SI's symbols in Latin letters; did you mean m/s²?",
    ),
    ("4.58 千克", "4.58", "kg", "did you mean kg?"),
    (
        "4.58 メートル",
        "4.58",
        "m",
        "units are written with SI's symbols in Latin letters, as in m/s^2, kg or N",
    ),
    # a Cyrillic or Greek letter that looks Latin, named as in a symbolic answer: was no hint, or the
    # Russian one, which this is not
    ("2.01 ѕ", "2.01", "s", "did you mean s? Its ѕ is a Cyrillic letter that looks like the Latin s"),
    ("4.58 m/ѕ^2", "4.58", "m/s^2", "did you mean m/s^2? Its ѕ is a Cyrillic letter"),
    ("4.58 κm/h", "4.58", "km/h", "did you mean km/h? Its κ is a Greek letter that looks like the Latin k"),
    ("4.58 m/с²", "4.58", "m/s^2", "did you mean m/s²?"),  # Russian's с, the second, not the Latin c
]


@pytest.mark.parametrize(("answer", "expected", "units", "message"), REFUSED, ids=[c[0] for c in REFUSED])
def test_units_in_another_script_are_refused_naming_the_latin_symbols(
    answer: str, expected: str, units: str, message: str
) -> None:
    verdict = check_numeric(answer, NumericSpec(Decimal(expected), units))
    assert verdict.outcome is Outcome.INVALID  # no attempt used
    assert verdict.reason is Reason.UNKNOWN_UNIT
    assert verdict.error is not None
    assert message in verdict.error.message
