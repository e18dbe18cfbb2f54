"""Units students of physics courses type, beyond the SI core: each reads as pint defines it (dimension
and exact factor), and a unit pint does not know is refused by its name."""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction

import pytest

from physics.dimensions import Dimension
from physics.errors import ParseError, SpecError, UnknownUnit
from physics.numeric import NumericSpec, check_numeric
from physics.units import parse_units, read_units, unit_dimension
from physics.verdict import Outcome, Reason

F = Fraction
D = Decimal
ONE = Dimension()
MASS = Dimension({"mass": 1})
LENGTH = Dimension({"length": 1})
AREA = Dimension({"length": 2})
VOLUME = Dimension({"length": 3})
TIME = Dimension({"time": 1})
RATE = Dimension({"time": -1})
SPEED = Dimension({"length": 1, "time": -1})
FORCE = Dimension({"mass": 1, "length": 1, "time": -2})
ENERGY = Dimension({"mass": 1, "length": 2, "time": -2})
PRESSURE = Dimension({"mass": 1, "length": -1, "time": -2})
AMOUNT = Dimension({"amount": 1})
CHARGE = Dimension({"current": 1, "time": 1})
RESISTANCE = Dimension({"mass": 1, "length": 2, "time": -3, "current": -2})
DOSE = Dimension({"length": 2, "time": -2})

INCH = F("0.0254")
US_GALLON = 231 * INCH**3
POUND = F("0.45359237")
POUND_FORCE = F("4.4482216152605")
C = F(299792458)
EV = F("1.602176634e-19")

SPELLINGS = [
    # (typed, dimension, exact value in coherent SI units): pint's definitions
    ("sr", ONE, F(1)),
    ("W/sr", Dimension({"mass": 1, "length": 2, "time": -3}), F(1)),
    ("micromol", AMOUNT, F(1, 10**6)),
    ("nanomol", AMOUNT, F(1, 10**9)),
    ("millimol", AMOUNT, F(1, 10**3)),
    ("micromoles", AMOUNT, F(1, 10**6)),
    ("microN", FORCE, F(1, 10**6)),  # WeBWorK's spelling
    ("millisec", TIME, F(1, 1000)),
    ("millibar", PRESSURE, F(100)),
    ("kiloohm", RESISTANCE, F(1000)),
    ("kilohm", RESISTANCE, F(1000)),  # the SI brochure's elided forms
    ("megohm", RESISTANCE, F(10**6)),
    ("cup", VOLUME, US_GALLON / 16),
    ("cups", VOLUME, US_GALLON / 16),
    ("pt", VOLUME, US_GALLON / 8),
    ("pint", VOLUME, US_GALLON / 8),
    ("pints", VOLUME, US_GALLON / 8),
    ("qt", VOLUME, US_GALLON / 4),
    ("quart", VOLUME, US_GALLON / 4),
    ("quarts", VOLUME, US_GALLON / 4),
    ("fl oz", VOLUME, US_GALLON / 128),
    ("floz", VOLUME, US_GALLON / 128),
    ("oz", MASS, POUND / 16),
    ("ozf", FORCE, POUND_FORCE / 16),
    ("Ci", RATE, F(37 * 10**9)),
    ("mCi", RATE, F(37 * 10**6)),
    ("µCi", RATE, F(37 * 10**3)),
    ("nmi", LENGTH, F(1852)),
    ("sq m", AREA, F(1)),
    ("sq ft", AREA, (12 * INCH) ** 2),
    ("sq. in", AREA, INCH**2),
    ("sqft", AREA, (12 * INCH) ** 2),
    ("square metres", AREA, F(1)),
    ("cu m", VOLUME, F(1)),
    ("cubic centimetres", VOLUME, F(1, 10**6)),
    ("cu ft", VOLUME, (12 * INCH) ** 3),
    ("cps", RATE, F(1)),
    ("c", SPEED, C),
    ("MeV/c^2", MASS, 10**6 * EV / C**2),
    ("GeV/c", Dimension({"mass": 1, "length": 1, "time": -1}), 10**9 * EV / C),
    ("tonne", MASS, F(1000)),
    ("tonnes", MASS, F(1000)),
    ("Gal", Dimension({"length": 1, "time": -2}), F(1, 100)),
    ("mGal", Dimension({"length": 1, "time": -2}), F(1, 10**5)),
    ("thou", LENGTH, INCH / 1000),
    ("Ah", CHARGE, F(3600)),
    ("mAh", CHARGE, F(18, 5)),
    ("kgf", FORCE, F("9.80665")),
    ("kip", FORCE, 1000 * POUND_FORCE),
    ("ksi", PRESSURE, 1000 * POUND_FORCE / INCH**2),
    ("ha", AREA, F(10**4)),
    ("micron", LENGTH, F(1, 10**6)),
    ("rem", DOSE, F(1, 100)),
    ("mrem", DOSE, F(1, 10**5)),
    ("Cal", ENERGY, F(4184)),  # the dietary calorie
    ("kilos", MASS, F(1)),
    ("lbm", MASS, POUND),
    ("kDa", MASS, parse_units("Da").scale * 1000),
    ("kpc", LENGTH, parse_units("pc").scale * 1000),
    ("Myr", TIME, F(31557600 * 10**6)),
    ("N-m", ENERGY, F(1)),
    ("kW-h", ENERGY, F(3_600_000)),
    # the long tail, by pint's own names
    ("furlongs/fortnight", SPEED, F("201.1684") / (14 * 86400)),  # pint's survey furlong
    ("barn", AREA, F(1, 10**28)),
    ("stone", MASS, 14 * POUND),
    ("weeks", TIME, F(7 * 86400)),
    ("electron_mass", MASS, F("9.1093837139e-31")),
]


@pytest.mark.parametrize(("typed", "dimension", "scale"), SPELLINGS, ids=[c[0] for c in SPELLINGS])
def test_a_unit_students_type_reads_as_pint_defines_it(
    typed: str, dimension: Dimension, scale: Fraction
) -> None:
    units = parse_units(typed)
    assert units.dimension == dimension
    assert abs(units.scale / scale - 1) < F(1, 10**6)


ANSWERS = [
    # (answer, spec units, expected value in them): graded as students type them
    ("0.12 sr", "sr", "0.12"),
    ("5.0 micromol", "mol", "5.0e-6"),
    ("2 cups", "mL", "473.18"),
    ("1 pt", "L", "0.47318"),
    ("1 quart", "L", "0.94635"),
    ("12 fl oz", "mL", "354.88"),
    ("1.5 Ci", "Bq", "5.55e10"),
    ("3 nmi", "km", "5.556"),
    ("25 sq m", "m^2", "25"),
    ("440 cps", "Hz", "440"),
    ("938.3 MeV/c^2", "kg", "1.6726e-27"),
    ("0.6 c", "m/s", "1.7988e8"),
    # A temperature with its degree said apart: one unit, never an angle times a coulomb (which had a
    # temperature's dimension and was graded wrong)
    ("26.85 deg C", "K", "300"),
    ("26.85 deg. C", "K", "300"),
    ("26.85 degrees C", "K", "300"),
    ("26.85 degree Celsius", "K", "300"),
    ("26.85 degrees centigrade", "K", "300"),
    ("26.85 ° C", "K", "300"),
    ("26.85 Deg c", "K", "300"),
    ("80.33 deg F", "K", "300"),
    ("80.33 degrees Fahrenheit", "K", "300"),
    ("300 degrees K", "K", "300"),
    ("26.85 ℃", "K", "300"),  # the one-character signs
    ("80.33 ℉", "K", "300"),
    ("26.85 oC", "K", "300"),  # the degree typed as a letter o
    ("4186 J/(kg deg C)", "J/(kg*K)", "4186"),
    # A prefix said as a word apart from its unit: never `kilo` (the kilogram) times a newton
    ("1.5 kilo newtons", "N", "1500"),
    ("1.5 kilo-newtons", "N", "1500"),
    ("1.5 kilo N", "N", "1500"),
    ("3000 micro seconds", "s", "0.003"),
    ("3 milli-seconds", "s", "0.003"),
    ("5 kilo", "kg", "5"),  # alone, still the kilogram
    # before a unit's symbol, the prefix's symbol: once `micro` unknown, `kilo m` the kilogram-metre
    ("30 micro s", "µs", "30"),
    ("30 micro-s", "µs", "30"),
    ("5 kilo m", "km", "5"),
    ("2 kilo g", "kg", "2"),
    ("3 mega Pa", "MPa", "3"),
    ("30 mu s", "µs", "30"),  # the Greek letter's name: once m·u·s, metre by atomic mass unit
    ("30 µ s", "µs", "30"),
    # a word processor's dashes for a minus or a hyphen: once refused as unexpected characters
    ("4.58 m s–2", "m/s^2", "4.58"),
    ("4.58 m s‑2", "m/s^2", "4.58"),
    ("4.58 ms–1", "m/s", "4.58"),
    ("2 N–m", "N*m", "2"),
    ("4.58 m.s-²", "m/s^2", "4.58"),  # the minus typed, the ² from a palette
    ("25 C°", "K", "298.15"),  # the degree sign after the scale: once a coulomb times a degree
    # as a phone types them: once km·h (graded a wrong dimension), refused, and an unexpected character
    ("45 kmhr", "m/s", "12.5"),
    ("4.58 m/s sq", "m/s^2", "4.58"),
    ("4.58 m/sec sq.", "m/s^2", "4.58"),
    ("4.58 m/s²\ufe0f", "m/s^2", "4.58"),  # the emoji keyboard's variation selector after ²
    ("4.58 m/sˆ2", "m/s^2", "4.58"),  # a Mac's option-i circumflex for the caret: was a unit `sˆ`
    ("4.58 ms⁻2", "m/s^2", "4.58"),  # the minus from a palette, the digit typed: was refused
    ("12.5 m s⁻1", "m/s", "12.5"),
    # a unit's name spelled out, singular or plural, capitalised, British or American
    ("45 kilojoule", "kJ", "45"),
    ("2.4 kiloJoules", "kJ", "2.4"),
    ("3 Newtons", "N", "3"),
    ("5 metres per second", "m/s", "5"),
    ("5 meters per second", "m/s", "5"),
]


@pytest.mark.parametrize(("answer", "units", "expected"), ANSWERS, ids=[c[0] for c in ANSWERS])
def test_an_answer_in_those_units_is_graded(answer: str, units: str, expected: str) -> None:
    verdict = check_numeric(answer, NumericSpec(D(expected), units))
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback


@pytest.mark.parametrize("units", ["sr", "W/sr", "cd·sr", "lm/sr"])
def test_an_instructor_may_state_units_in_steradians(units: str) -> None:
    unit_dimension(units)
    NumericSpec(D(1), units, units_system="SI")  # the steradian is SI


@pytest.mark.parametrize("answer", ["4.58 smoot", "4.58 m/blorb", "4.58 kilofurlong"])
def test_a_unit_pint_does_not_know_is_refused_by_name(answer: str) -> None:
    verdict = check_numeric(answer, NumericSpec(D("4.58"), "m"))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is Reason.UNKNOWN_UNIT
    name = answer.split("/")[-1].split()[-1]
    assert f"Unknown unit {name!r}" in verdict.feedback


@pytest.mark.parametrize("typed", ["gr", "dB", "decade", "t", "cp", "th", "square_degree"])
def test_pint_spellings_that_would_mislead_are_not_taken(typed: str) -> None:
    # `gr` is pint's grain (a gram to a student), `dB` and `decade` are logarithmic, `t` is a tesla in
    # lower case, `cp` a centipoise, `th` nothing anyone types; angles stay the catalogue's
    with pytest.raises(UnknownUnit):
        parse_units(typed)


@pytest.mark.parametrize("typed", ["sq", "sq/s", "(m) sq"])
def test_a_square_said_with_no_unit_after_or_before_it_is_refused(typed: str) -> None:
    with pytest.raises(ParseError, match="needs a unit after it"):
        parse_units(typed)


def test_units_beyond_si_are_refused_where_the_part_asks_for_si() -> None:
    verdict = check_numeric("1.5 Ci", NumericSpec(D("5.55e10"), "Bq", units_system="SI"))
    assert verdict.reason is Reason.UNKNOWN_UNIT
    with pytest.raises(SpecError):
        NumericSpec(D(1), "Ci", units_system="SI")


@pytest.mark.parametrize("answer", ["45 percent", "45 per cent", "45 %"])
def test_percent_in_words_is_a_percentage(answer: str) -> None:
    verdict = check_numeric(answer, NumericSpec(D("0.45")))
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback
    assert verdict.read_as is not None and verdict.read_as.text == "45%"


@pytest.mark.parametrize(("typed", "reading"), [("Kilos", "kg"), ("KILOS", "kg"), ("Kgs", "kg")])
def test_an_alias_in_the_wrong_case_is_settled_by_dimension(typed: str, reading: str) -> None:
    read = read_units(typed, MASS)
    assert read.units.text == reading
    assert read.note == f"Read {typed} as {reading}: the only reading that is a mass"


@pytest.mark.parametrize(
    ("answer", "expected", "units", "reason", "says"),
    [
        ("30o", "30", "deg", Reason.UNKNOWN_UNIT, "for degrees write ° or deg"),
        ("30 O", "30", "deg", Reason.UNKNOWN_UNIT, "for degrees write ° or deg"),
        # degrees shortened as decigrams: was graded, "the units of a mass"
        ("35 dg", "35", "deg", Reason.PARSE_ERROR, "Did you mean degrees? dg is the decigram"),
        # a prefix's symbol glued to a unit's name: was a bare "Unknown unit 'kJoules'"
        ("2.4 kJoules", "2.4", "kJ", Reason.UNKNOWN_UNIT, "did you mean kJ? Write the symbols together, kJ"),
        (
            "25 mSeconds",
            "25",
            "ms",
            Reason.UNKNOWN_UNIT,
            "did you mean ms? Write the symbols together, ms, or",
        ),
        ("5 ft 10 in", "1.778", "m", Reason.PARSE_ERROR, "second number with its own unit (10 in)"),
        ("2 h 30 min", "9000", "s", Reason.PARSE_ERROR, "second number with its own unit (30 min)"),
        # a decimal second number: was "A unit string holds whole numbers only"
        ("5 ft 10.5 in", "1.791", "m", Reason.PARSE_ERROR, "second number with its own unit (10.5 in)"),
        ("2 h 30.5 min", "9030", "s", Reason.PARSE_ERROR, "second number with its own unit (30.5 min)"),
        # true primes, and a space after the feet: were "Unexpected character '′' in the units"
        (
            "5′ 11″",
            "1.803",
            "m",
            Reason.PARSE_ERROR,
            "Feet and inches (5′ 11″): write one number in one unit, as 71 in",
        ),
        ("5′11″", "1.803", "m", Reason.PARSE_ERROR, "Feet and inches (5′11″): write one number in one unit"),
        ("5' 10.5\"", "1.791", "m", Reason.PARSE_ERROR, "write one number in one unit, as 70.5 in"),
        ("5′ 11''", "1.803", "m", Reason.PARSE_ERROR, "write one number in one unit, as 71 in"),
        (
            "5'10\"",
            "1.778",
            "m",
            Reason.PARSE_ERROR,
            "Feet and inches (5'10\"): write one number in one unit, as 70 in",
        ),
        (
            "5’11”",
            "1.803",
            "m",
            Reason.PARSE_ERROR,
            "Feet and inches (5’11”): write one number in one unit, as 71 in",
        ),
    ],
)
def test_an_answer_in_a_habit_of_everyday_units_is_refused_saying_how_to_write_it(
    answer: str, expected: str, units: str, reason: Reason, says: str
) -> None:
    verdict = check_numeric(answer, NumericSpec(D(expected), units))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is reason
    assert says in verdict.feedback
