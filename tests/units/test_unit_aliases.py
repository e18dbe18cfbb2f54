"""Units are never misread: aliases and plurals by a table, units beyond SI from pint, glued names that
another single unit fits refused or settled by the expected dimension, and the SI-only restriction."""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction

import pytest

from physics.dimensions import Dimension
from physics.errors import AmbiguousInput, SpecError, UnknownUnit
from physics.numeric import NumericSpec, check_numeric
from physics.units import parse_units, read_units
from physics.units.catalogue import ALIASES
from physics.verdict import Outcome, Reason

F = Fraction
D = Decimal
MASS = Dimension({"mass": 1})
LENGTH = Dimension({"length": 1})
TIME = Dimension({"time": 1})
SPEED = Dimension({"length": 1, "time": -1})
ACCELERATION = Dimension({"length": 1, "time": -2})
FORCE = Dimension({"mass": 1, "length": 1, "time": -2})
ENERGY = Dimension({"mass": 1, "length": 2, "time": -2})
POWER = Dimension({"mass": 1, "length": 2, "time": -3})
PRESSURE = Dimension({"mass": 1, "length": -1, "time": -2})
VOLUME = Dimension({"length": 3})
ONE = Dimension()

ALIAS_READINGS = [
    # (typed, canonical text): each alias and plural of the table, and the ones pint already has
    ("ohms", "Ω"),
    ("Ohms", "Ω"),
    ("rads", "rad"),
    ("degs", "°"),
    ("revs", "rev"),
    ("volts", "V"),
    ("amps", "A"),
    ("amp", "A"),
    ("newtons", "N"),
    ("joules", "J"),
    ("watts", "W"),
    ("secs", "s"),
    ("sec", "s"),
    ("hrs", "h"),
    ("hr", "h"),
    ("mins", "min"),
    ("days", "d"),
    ("yrs", "yr"),
    ("kph", "km/h"),
    ("kmh", "km/h"),
    ("kmph", "km/h"),
    ("kmps", "km/s"),  # was km·ps, a length times a time
    ("mps", "m/s"),
    ("gm", "g"),
    ("gms", "g"),
    ("kgs", "kg"),
    ("mcg", "µg"),
    ("lbs", "lb"),
    ("cc", "cm^3"),
    ("AU", "au"),
    ("N.m", "N·m"),
    ("kg.m/s^2", "kg·m/s^2"),
    ("ms-1", "m/s"),
    ("ms−1", "m/s"),  # Unicode minus
    ("ms-2", "m/s^2"),
    ("m s-1", "m/s"),
    ("m s-2", "m/s^2"),
    ("J kg-1 K-1", "J/(kg·K)"),
    ("kgm^2", "kg·m^2"),  # a power on a glued product belongs to its last unit
    # a power typed without its ^, as `s-2` is
    ("m/s2", "m/s^2"),
    ("cm3", "cm^3"),
    ("kg m2/s2", "kg·m^2/s^2"),
    ("kgm2", "kg·m^2"),
    ("ᶜ", "rad"),  # the raised c of British texts (1.2ᶜ), once folded to c, the speed of light
    ("ᶜ/s", "rad/s"),
]


@pytest.mark.parametrize(("typed", "canonical"), ALIAS_READINGS, ids=[c[0] for c in ALIAS_READINGS])
def test_alias_reads_as_the_unit_a_person_means(typed: str, canonical: str) -> None:
    assert parse_units(typed) == parse_units(canonical)
    assert parse_units(typed).text == canonical


@pytest.mark.parametrize("alias", sorted(ALIASES))
def test_every_alias_in_the_table_reads_as_a_single_known_unit_expression(alias: str) -> None:
    assert parse_units(alias) == parse_units(ALIASES[alias])


BEYOND_SI = [
    # (typed, dimension, exact value in SI units): factors from pint's definitions
    ("ft", LENGTH, F("0.3048")),
    ("feet", LENGTH, F("0.3048")),
    ("in", LENGTH, F("0.0254")),
    ("inches", LENGTH, F("0.0254")),
    ("mi", LENGTH, F("1609.344")),
    ("yd", LENGTH, F("0.9144")),
    ("mph", SPEED, F("0.44704")),
    ("knot", SPEED, F(1852, 3600)),
    ("kn", SPEED, F(1852, 3600)),
    ("lb", MASS, F("0.45359237")),
    ("lbf", FORCE, F("4.4482216152605")),
    ("slug", MASS, F("4.4482216152605") / F("0.3048")),
    ("psi", PRESSURE, F("4.4482216152605") / F("0.0254") ** 2),
    ("atm", PRESSURE, F(101325)),
    ("bar", PRESSURE, F(100000)),
    ("mbar", PRESSURE, F(100)),
    ("torr", PRESSURE, F(101325, 760)),
    ("mmHg", PRESSURE, F("133.322387415")),
    ("cal", ENERGY, F("4.184")),
    ("kcal", ENERGY, F(4184)),
    ("Btu", ENERGY, F("1055.056")),
    ("hp", POWER, F("745.69987158227022")),
    ("kWh", ENERGY, F(3_600_000)),
    ("dyn", FORCE, F(1, 10**5)),
    ("erg", ENERGY, F(1, 10**7)),
    ("gauss", Dimension({"mass": 1, "time": -2, "current": -1}), F(1, 10**4)),
    ("G", Dimension({"mass": 1, "time": -2, "current": -1}), F(1, 10**4)),
    ("au", LENGTH, F(149597870700)),
    ("ly", LENGTH, F(9460730472580800)),
    ("yr", TIME, F(31557600)),
    ("day", TIME, F(86400)),
    ("d", TIME, F(86400)),
    ("kat", Dimension({"amount": 1, "time": -1}), F(1)),
    ("katal", Dimension({"amount": 1, "time": -1}), F(1)),
    ("gal", VOLUME, F("0.003785411784")),
]


@pytest.mark.parametrize(("typed", "dimension", "scale"), BEYOND_SI, ids=[c[0] for c in BEYOND_SI])
def test_unit_beyond_si_has_its_exact_factor(typed: str, dimension: Dimension, scale: Fraction) -> None:
    units = parse_units(typed)
    assert units.dimension == dimension
    assert units.scale == scale


def test_parsec_is_about_3_086e16_metres() -> None:
    assert abs(float(parse_units("pc").scale) / 3.0857e16 - 1) < 1e-4


NOT_SPLIT = [
    # (answer, spec units, expected value): each once read as a product of units and graded wrong
    ("2 ohms", "ohm", "2"),
    ("3 rads", "rad", "3"),
    ("2 gm", "g", "2"),
    ("5 mps", "m/s", "5"),
    ("2 kmh", "km/h", "2"),
    ("2 kph", "m/s", "0.5556"),
    ("2 mcg", "µg", "2"),
    ("1 gal", "L", "3.785411784"),
    ("2 Kg", "kg", "2"),
    ("2 Km", "km", "2"),
    ("5 ms^-1", "m/s", "5"),
    ("5 ms⁻¹", "m/s", "5"),
    ("5 ms-1", "m/s", "5"),
    ("9.8 ms^-2", "m/s^2", "9.8"),
    ("3 lbs", "kg", "1.36077711"),
    ("10 ft", "m", "3.048"),
    ("60 mph", "m/s", "26.8224"),
    ("1 atm", "kPa", "101.325"),
    ("2 kcal", "J", "8368"),
]


@pytest.mark.parametrize(("answer", "units", "expected"), NOT_SPLIT, ids=[c[0] for c in NOT_SPLIT])
def test_glued_unit_is_read_as_the_single_unit_it_spells(answer: str, units: str, expected: str) -> None:
    verdict = check_numeric(answer, NumericSpec(D(expected), units))
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback


def test_instructor_units_gal_is_the_gallon() -> None:
    assert parse_units("gal").text == "gal"
    verdict = check_numeric("3.785 L", NumericSpec(D(1), "gal"))
    assert verdict.outcome is Outcome.CORRECT


CHOSEN_BY_DIMENSION = [
    # (units typed, expected dimension, reading taken)
    ("ms^-1", SPEED, "m/s"),
    ("ms^-2", ACCELERATION, "m/s^2"),
    ("Kg", MASS, "kg"),
    ("Km", LENGTH, "km"),
    ("KM", LENGTH, "km"),
    ("KJ", ENERGY, "kJ"),
    ("Kg m/s^2", FORCE, "kg·m/s^2"),
    # the letters spell several units in other cases (ks, kS; Pa, pA, PA): only one is the dimension
    ("Ks", TIME, "ks"),
    ("KS", TIME, "ks"),
    ("pa", PRESSURE, "Pa"),
    ("KPA", PRESSURE, "kPa"),
    # an alias with a negative power: per radian, or rad·s⁻¹ (once graded as a pure number)
    ("rads^-1", Dimension({"time": -1}), "rad/s"),
    # a unit's name in capitals (a sentence's start, a phone): once split, A·m·ps and Pa·s·ca·l·s
    ("Amps", Dimension({"current": 1}), "A"),
    ("Pascals", PRESSURE, "Pa"),
    # an alias of a rate with a power, said "metres per second squared" (once (m/s)², graded m²/s²)
    ("mps2", ACCELERATION, "m/s^2"),
    ("mps^2", ACCELERATION, "m/s^2"),
    ("mps²", ACCELERATION, "m/s^2"),
    ("kph2", Dimension({"length": 1, "time": -2}), "km/h^2"),
    ("mps^2", Dimension({"length": 2, "time": -2}), "m^2/s^2"),  # the square of a speed, where one is asked
    # a short name typed in capitals spells a glued product too: NM was asked about as nm alone
    ("NM", ENERGY, "N·m"),
    ("NM", LENGTH, "nm"),
]


@pytest.mark.parametrize(
    ("typed", "dimension", "reading"), CHOSEN_BY_DIMENSION, ids=[c[0] for c in CHOSEN_BY_DIMENSION]
)
def test_the_only_reading_with_the_expected_dimension_is_taken_and_said(
    typed: str, dimension: Dimension, reading: str
) -> None:
    read = read_units(typed, dimension)
    assert read.units.text == reading
    assert read.note is not None
    assert f"Read {typed} as {reading}" in read.note


def test_a_rate_alias_with_a_power_that_fits_nowhere_is_graded_per_second_squared() -> None:
    assert read_units("mps^2", SPEED).units.text == "m/s^2"
    assert read_units("mps2").units.text == "m/s^2"  # an instructor's, where no dimension is expected


def test_a_literal_reading_with_the_expected_dimension_needs_no_note() -> None:
    assert read_units("ms^-1", Dimension({"time": -1})) == read_units("ms^-1")
    assert read_units("ms^-1").note is None
    assert read_units("ms^-1").units.text == "1/ms"


def test_chosen_reading_is_shown_in_read_as_and_feedback() -> None:
    verdict = check_numeric("5 ms^-1", NumericSpec(D(5), "m/s"))
    assert verdict.outcome is Outcome.CORRECT
    assert verdict.read_as is not None
    assert verdict.read_as.text == "5 m/s"
    assert verdict.read_as.note == "Read ms^-1 as m/s: the only reading that is a speed"
    assert verdict.feedback.startswith("Read ms^-1 as m/s")


NO_SAFE_READING = [
    # (units, error, the readings or spelling the message offers)
    ("Kg", AmbiguousInput, ("K·g", "kg")),
    ("Km", AmbiguousInput, ("K·m", "km")),
    ("KG", AmbiguousInput, ("K·G", "kg")),
    ("kms", AmbiguousInput, ("km·s", "km")),
    ("KM", UnknownUnit, ("km",)),
]


@pytest.mark.parametrize(("typed", "error", "offered"), NO_SAFE_READING, ids=[c[0] for c in NO_SAFE_READING])
def test_glued_name_with_no_safe_reading_is_refused_with_the_candidates(
    typed: str, error: type[Exception], offered: tuple[str, ...]
) -> None:
    with pytest.raises(error) as caught:
        parse_units(typed)
    for reading in offered:
        assert reading in str(caught.value)
    if isinstance(caught.value, AmbiguousInput):
        assert set(caught.value.readings) == set(offered)


def test_refused_reading_uses_no_attempt() -> None:
    # A pressure is expected: neither K·g nor kg is one, so nothing settles it.
    verdict = check_numeric("2 Kg", NumericSpec(D(2), "Pa"))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is Reason.AMBIGUOUS
    assert verdict.error is not None and verdict.error.position == 2


def test_instructor_units_with_no_safe_reading_are_a_spec_error() -> None:
    with pytest.raises(SpecError):
        NumericSpec(D(1), "Kg")


def test_newton_metre_stays_a_newton_metre() -> None:
    # The case rule applies to a kelvin-led split only: `Nm` is never read as a nanometre; where a
    # length is expected it is asked about (CASE_SLIPS below), not read either way.
    assert parse_units("Nm").text == "N·m"
    assert read_units("Nm", ENERGY).units.text == "N·m"
    with pytest.raises(AmbiguousInput, match="Did you mean nm"):
        read_units("Nm", LENGTH)


CASE_SLIPS = [
    # (answer, spec units, value, the reading offered): a unit that is not the expected dimension, but
    # is in another case; once graded wrong_dimension (an attempt used for a capital letter)
    ("101325 PA", "Pa", "101325", "Pa", 7),  # the petaampere
    ("4.58 Ms^-2", "m/s^2", "4.58", "m/s^2", 5),  # per megasecond squared
    ("4.58 m/S^2", "m/s^2", "4.58", "m/s^2", 7),  # the siemens
    ("5 S", "s", "5", "s", 2),
    ("5 G", "g", "5", "g", 2),  # the gauss
    ("10 nm", "N m", "10", "N·m", 3),  # a torque typed with a small n: the nanometre
    ("5 MS", "ms", "5", "ms", 2),  # the megasiemens: ms and Ms are both times, both offered
]


@pytest.mark.parametrize(
    ("answer", "units", "value", "offered", "position"), CASE_SLIPS, ids=[c[0] for c in CASE_SLIPS]
)
def test_a_unit_in_the_wrong_case_is_refused_asking_for_the_case_that_fits(
    answer: str, units: str, value: str, offered: str, position: int
) -> None:
    verdict = check_numeric(answer, NumericSpec(D(value), units))
    assert verdict.outcome is Outcome.INVALID, verdict.feedback
    assert verdict.reason is Reason.AMBIGUOUS
    assert verdict.error is not None
    assert "case-sensitive" in verdict.error.message
    assert f"Did you mean {offered}" in verdict.error.message or f" or {offered}?" in verdict.error.message
    assert verdict.error.position == position


CASE_KEPT = [
    # (answer, spec units, value, reason): a reading with the expected dimension is graded as typed,
    # whatever another case would make of it
    ("3 Mm", "mm", "3", Reason.CONSTANT_FACTOR),  # the megametre is a length
    ("3 MA", "mA", "3", Reason.CONSTANT_FACTOR),  # the megaampere is a current
    ("5 Ms", "ms", "5", Reason.CONSTANT_FACTOR),
    ("2 J", "W", "2", Reason.WRONG_DIMENSION),  # no other case of J is a unit
    ("5 N", "kg", "5", Reason.WRONG_DIMENSION),  # a weight for a mass: a real mistake, graded
]


@pytest.mark.parametrize(("answer", "units", "value", "reason"), CASE_KEPT, ids=[c[0] for c in CASE_KEPT])
def test_a_unit_is_graded_as_typed_where_no_other_case_is_asked_about(
    answer: str, units: str, value: str, reason: Reason
) -> None:
    verdict = check_numeric(answer, NumericSpec(D(value), units))
    assert verdict.outcome is Outcome.INCORRECT, verdict.feedback
    assert verdict.reason is reason


SI_ONLY = [
    # (answer, accepted under "units_system": "SI")
    ("4.58 m/s", True),
    ("16.5 km/h", True),
    ("0.3 km/min", True),  # the minute is accepted for use with the SI
    ("10.2 ft/s", False),
    ("10.2 mph", False),
    ("10.2 kn", False),
]


@pytest.mark.parametrize(("answer", "accepted"), SI_ONLY, ids=[c[0] for c in SI_ONLY])
def test_si_only_part_refuses_non_si_units_with_a_clear_message(answer: str, accepted: bool) -> None:
    verdict = check_numeric(answer, NumericSpec(D("4.58"), "m/s", units_system="SI"))
    if accepted:
        assert verdict.outcome is not Outcome.INVALID
    else:
        assert verdict.outcome is Outcome.INVALID
        assert verdict.reason is Reason.UNKNOWN_UNIT
        assert "must be in SI units" in verdict.feedback
        assert "m/s" in verdict.feedback


def test_without_the_restriction_non_si_units_are_converted() -> None:
    verdict = check_numeric("10.2 mph", NumericSpec(D("4.56"), "m/s"))
    assert verdict.outcome is Outcome.CORRECT


def test_si_only_spec_in_non_si_units_is_a_spec_error() -> None:
    with pytest.raises(SpecError):
        NumericSpec(D(1), "ft", units_system="SI")
    with pytest.raises(SpecError):
        NumericSpec(D(1), "m", units_system="imperial")
