"""A unit spelling with several meanings (`lb`, `oz`, `Gal`, `mil`, `c`, `g`, `C`, `F`) is settled by the
dimension the answer must have, as the glued names `Kg` and `ms^-1` are; where no dimension settles it,
it is refused with every meaning and no attempt is used, except the gram, the coulomb and the farad,
which nearly everyone means by `g`, `C` and `F`: an answer no meaning of which fits is graded in them.
An author's units, where no dimension is expected, take pint's meaning."""

from __future__ import annotations

from decimal import Decimal

import pytest

from physics.dimensions import Dimension
from physics.errors import AmbiguousInput, UnknownUnit
from physics.numeric import NumericSpec, check_numeric
from physics.units import parse_units, read_units, unit_dimension
from physics.verdict import Outcome, Reason

D = Decimal
MASS = Dimension({"mass": 1})
LENGTH = Dimension({"length": 1})
SPEED = Dimension({"length": 1, "time": -1})
ACCELERATION = Dimension({"length": 1, "time": -2})
FORCE = Dimension({"mass": 1, "length": 1, "time": -2})
ENERGY = Dimension({"mass": 1, "length": 2, "time": -2})
VOLUME = Dimension({"length": 3})
CHARGE = Dimension({"current": 1, "time": 1})
ONE = Dimension()

SETTLED = [
    # (answer, spec units, expected value in them, reading taken, note): each graded correct
    ("50 lb", "N", "222.41", "50 lbf", "Read lb as lbf: the only reading that is a force"),
    ("50 lbs", "N", "222.41", "50 lbf", "Read lbs as lbf: the only reading that is a force"),
    ("50 lb", "kg", "22.680", "50 lb", None),
    ("10 ft·lb", "J", "13.558", "10 ft·lbf", "Read ft·lb as ft·lbf: the only reading that is an energy"),
    ("10 ft lb", "J", "13.558", "10 ft·lbf", "Read ft lb as ft·lbf: the only reading that is an energy"),
    ("10 lb ft", "N·m", "13.558", "10 lbf·ft", "Read lb ft as lbf·ft: the only reading that is an energy"),
    ("10 ft-lb", "J", "13.558", "10 ft·lbf", "Read ft-lb as ft·lbf: the only reading that is an energy"),
    (
        "30 lb/in^2",
        "kPa",
        "206.84",
        "30 lbf/in^2",
        "Read lb/in^2 as lbf/in^2: the only reading that is a pressure",
    ),
    ("2 Gal", "m/s^2", "0.02", "2 Gal", None),
    ("2 Gal", "L", "7.5708", "2 gal", "Read Gal as gal: the only reading that is a volume"),
    ("2 mil", "mm", "0.0508", "2 thou", "Read mil as thou: the only reading that is a length"),
    ("8 oz", "g", "226.80", "8 oz", None),
    ("8 oz", "mL", "236.59", "8 fl oz", "Read oz as fl oz: the only reading that is a volume"),
    ("8 oz", "N", "2.2241", "8 ozf", "Read oz as ozf: the only reading that is a force"),
    ("0.8 c", "m/s", "2.3983e8", "0.8 c", None),
    ("5 c", "C", "5", "5 C", "Read c as C: the only reading that is an electric charge"),
    # An acceleration in gees, as students say it; the gram wherever a mass is meant.
    ("0.467 g", "m/s^2", "4.5807", "0.467 g0", "Read g as g0: the only reading that is an acceleration"),
    ("0.467 g0", "m/s^2", "4.5807", "0.467 g0", None),
    ("0.467 g_0", "m/s^2", "4.5807", "0.467 g0", None),
    ("0.467 g_n", "m/s^2", "4.5807", "0.467 g0", None),
    ("0.467 gn", "m/s^2", "4.5807", "0.467 g0", None),
    ("0.467 gees", "m/s^2", "4.5807", "0.467 g0", None),
    # `gs` and `g's` as a plural: gees first, grams where a mass is meant; never the gram-second.
    ("0.467 gs", "m/s^2", "4.5807", "0.467 g0", None),
    ("0.467 g's", "m/s^2", "4.5807", "0.467 g0", None),
    ("0.467 G’s", "m/s^2", "4.5807", "0.467 g0", None),
    ("450 g's", "kg", "0.45", "450 g", "Read g's as g: the only reading that is a mass"),
    ("450 gs", "kg", "0.45", "450 g", "Read gs as g: the only reading that is a mass"),
    ("500 g", "kg", "0.5", "500 g", None),
    ("1 g/cm^3", "kg/m^3", "1000", "1 g/cm^3", None),
    # Degrees typed without the degree sign, where a temperature is expected.
    ("27 C", "K", "300.15", "27 °C", "Read C as °C: the only reading that is a temperature"),
    ("27 c", "K", "300.15", "27 °C", "Read c as °C: the only reading that is a temperature"),
    ("80.6 F", "°C", "27", "80.6 °F", "Read F as °F: the only reading that is a temperature"),
    ("5 C", "C", "5", "5 C", None),
    ("2 F", "F", "2", "2 F", None),
    ("4.2 J/C", "J/K", "4.2", "4.2 J/°C", "Read J/C as J/°C: the only reading that is a heat capacity"),
    ("4.2 J/C", "V", "4.2", "4.2 J/C", None),
]


@pytest.mark.parametrize(
    ("answer", "units", "expected", "reading", "note"), SETTLED, ids=[f"{c[0]} for {c[1]}" for c in SETTLED]
)
def test_the_meaning_with_the_expected_dimension_is_taken_and_said(
    answer: str, units: str, expected: str, reading: str, note: str | None
) -> None:
    verdict = check_numeric(answer, NumericSpec(D(expected), units))
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback
    assert verdict.read_as is not None
    assert verdict.read_as.text == reading
    assert verdict.read_as.note == note
    if note is not None:
        assert verdict.feedback.startswith(note)


REFUSED = [
    # (answer, spec units, meanings named): no meaning has the dimension the answer must have
    ("50 lb", "m/s", ["lb", "lbf"]),
    ("2 Gal", "s", ["Gal", "gal"]),
    ("2 mil", "s", ["mil", "thou"]),
    ("8 oz", "J", ["oz", "fl oz", "ozf"]),
    ("3 c", "m", ["c", "C"]),
]


@pytest.mark.parametrize(
    ("answer", "units", "meanings"), REFUSED, ids=[c[0] + " for " + c[1] for c in REFUSED]
)
def test_a_spelling_no_meaning_of_which_fits_is_refused_with_every_meaning(
    answer: str, units: str, meanings: list[str]
) -> None:
    verdict = check_numeric(answer, NumericSpec(D(1), units))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is Reason.AMBIGUOUS
    assert verdict.score == 0
    assert verdict.error is not None and verdict.error.position == answer.index(" ") + 1
    for meaning in meanings:
        assert meaning in verdict.feedback


TWO_ANGLES = [
    # (answer, spec units): `Grad` is the degree in German and the gradian elsewhere; never read as a
    # gigaradian (G·rad), a gram-radian (g·rad) or a gram-radian-second, whatever is expected
    ("30 Grad", "deg"),
    ("30 grad", "deg"),
    ("30 grads", "deg"),
    ("30 Grads", "rad"),
    ("2 Grad/s", "rad/s"),
    ("30 grad", "g*rad"),
]


@pytest.mark.parametrize(("answer", "units"), TWO_ANGLES, ids=[c[0] + " for " + c[1] for c in TWO_ANGLES])
def test_grad_is_refused_as_the_degree_or_the_gradian(answer: str, units: str) -> None:
    verdict = check_numeric(answer, NumericSpec(D(30), units))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is Reason.AMBIGUOUS
    assert verdict.error is not None and verdict.error.position == answer.index(" ") + 1
    assert "degrees (°) or gradians" in verdict.feedback
    assert "write ° or deg" in verdict.feedback


GRADED_AS_FIRST = [
    # (answer, spec units, the dimension named): no meaning fits, and the first is what nearly everyone
    # means, so the answer is graded (a wrong dimension, an attempt used) rather than refused
    ("5 g", "J", "a mass"),
    ("5 gs", "J", "an acceleration"),
    ("5 C", "J", "an electric charge"),
    ("5 F", "C", "a capacitance"),
]


@pytest.mark.parametrize(
    ("answer", "units", "named"), GRADED_AS_FIRST, ids=[c[0] + " for " + c[1] for c in GRADED_AS_FIRST]
)
def test_a_gram_coulomb_or_farad_that_fits_nothing_is_graded_as_typed(
    answer: str, units: str, named: str
) -> None:
    verdict = check_numeric(answer, NumericSpec(D(1), units))
    assert verdict.outcome is Outcome.INCORRECT
    assert verdict.reason is Reason.WRONG_DIMENSION
    assert f"units of {named}" in verdict.feedback


def test_the_refusal_carries_the_readings() -> None:
    with pytest.raises(AmbiguousInput) as refused:
        read_units("lb", SPEED)
    assert refused.value.readings == ("lb", "lbf")


@pytest.mark.parametrize(
    ("units", "dimension"),
    [
        ("lb", MASS),
        ("lbs", MASS),
        ("oz", MASS),
        ("Gal", ACCELERATION),
        ("mil", ONE),
        ("c", SPEED),
        ("g", MASS),
        ("C", CHARGE),
        ("g0", ACCELERATION),
        ("gs", ACCELERATION),
    ],
)
def test_without_an_expected_dimension_a_spelling_means_what_pint_defines(
    units: str, dimension: Dimension
) -> None:
    assert parse_units(units).dimension == dimension
    assert unit_dimension(units) == dimension  # an author's symbol declaration


def test_pounds_per_square_inch_where_a_pressure_is_expected_are_the_psi() -> None:
    reading = read_units("lb/in^2", Dimension({"mass": 1, "length": -1, "time": -2}))
    assert reading.units.scale == parse_units("psi").scale


def test_the_speed_of_light_is_never_a_piece_of_a_glued_name() -> None:
    # `mc` is the millicoulomb or the megacoulomb in the wrong case, never a metre times c
    with pytest.raises(UnknownUnit, match="case-sensitive"):
        read_units("mc", CHARGE)
    assert parse_units("MeV/c^2").dimension == MASS
