"""check_numeric: verdict, reason and feedback for answers against specs, as a table."""

from __future__ import annotations

from decimal import Decimal

import pytest

from physics.numeric import NumericSpec, Tolerance, check_numeric
from physics.verdict import Outcome, Reason

D = Decimal
ACCEL = NumericSpec(D("4.5807"), "m/s^2")
SPEED = NumericSpec(D("4.58"), "m/s")
PURE = NumericSpec(D("0.45"))
OMEGA = NumericSpec(D("4.5807"), "rad/s")
ANGLE = NumericSpec(D("0.5"), "rad")
KELVIN = NumericSpec(D("298.15"), "K", tolerance=Tolerance(abs=D("0.01")))
SIGFIGS3 = NumericSpec(D("1498"), "N", tolerance=Tolerance(sigfigs=3))
BARE_OK = NumericSpec(D("4.5807"), "m/s^2", units_required=False)
NEGATIVE = NumericSpec(D("-2.45"), "m/s^2")

OK, NO, BAD = Outcome.CORRECT, Outcome.INCORRECT, Outcome.INVALID

VERDICTS = [
    # (id, answer, spec, outcome, reason)
    ("plain", "4.58 m/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("negative-expected", "-2.45 m/s^2", NEGATIVE, OK, Reason.EQUIVALENT),
    ("superscript-units", "4.58 m·s⁻²", ACCEL, OK, Reason.EQUIVALENT),
    ("slash-slash-units", "4.58 m/s/s", ACCEL, OK, Reason.EQUIVALENT),
    ("units-in-words", "4.58 metres per second squared", ACCEL, OK, Reason.EQUIVALENT),
    ("sentence-full-stop", "4.58 m/s^2.", ACCEL, OK, Reason.EQUIVALENT),
    ("radians-per-second", "4.58 radians per second", OMEGA, OK, Reason.EQUIVALENT),
    ("per-alone-is-a-rate", "4.58 per second", NumericSpec(D("4.58"), "1/s"), OK, Reason.EQUIVALENT),
    ("per-without-a-unit", "4.58 m per", ACCEL, BAD, Reason.PARSE_ERROR),
    ("reciprocal-units", "4.58 1/s", NumericSpec(D("4.58"), "1/s"), OK, Reason.EQUIVALENT),
    (
        "fahrenheit-to-kelvin",
        "80.33 °F",
        NumericSpec(D("300"), "K", tolerance=Tolerance(abs=D("0.01"))),
        OK,
        Reason.EQUIVALENT,
    ),
    (
        "fahrenheit-to-celsius",
        "-40 °F",
        NumericSpec(D("-40"), "°C", tolerance=Tolerance(abs=D("0.001"))),
        OK,
        Reason.EQUIVALENT,
    ),
    ("reciprocal-units-spaced", "4.58 1 / s", NumericSpec(D("4.58"), "s^-1"), OK, Reason.EQUIVALENT),
    ("leading-slash-units", "4.58 /s", NumericSpec(D("4.58"), "1/s"), OK, Reason.EQUIVALENT),
    ("number-then-number-over-unit", "4.58 12/s", NumericSpec(D("4.58"), "1/s"), BAD, Reason.PARSE_ERROR),
    ("glued-units", "4.58m/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("mixed-number", "1 ½ m", NumericSpec(D("1.52"), "m"), BAD, Reason.PARSE_ERROR),  # never 1·½ m
    ("divided-twice", "4.58 m/s^-2", ACCEL, BAD, Reason.AMBIGUOUS),  # m·s² as typed: asked about
    ("glued-degrees", "9.8 sin30° m/s^2", NumericSpec(D("4.9"), "m/s^2"), OK, Reason.EQUIVALENT),
    ("glued-ln-2", "2ln2 s", NumericSpec(D("1.386"), "s"), OK, Reason.EQUIVALENT),
    ("divided-twice-where-meant", "4.58 m/s^-2", NumericSpec(D("4.58"), "m*s^2"), OK, Reason.EQUIVALENT),
    ("fullwidth-units", "4.58 ｍ／ｓ＾２", ACCEL, OK, Reason.EQUIVALENT),  # East Asian input methods
    ("fullwidth-number", "４．５８ m/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("fullwidth-brackets", "4.58 ［m/s^2］", ACCEL, OK, Reason.EQUIVALENT),
    ("arabic-digits", "٤٫٥٨ m/s^2", ACCEL, OK, Reason.EQUIVALENT),  # an Arabic keyboard's digits and point
    ("persian-digits", "۴٫۵۸ m/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("math-italic-units", "4.58 𝑚/𝑠^2", ACCEL, OK, Reason.EQUIVALENT),  # copied from Word
    ("math-bold-digits", "𝟒.𝟓𝟖 m/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("invisible-times-units", "4.58 m\u2062s^-2", ACCEL, OK, Reason.EQUIVALENT),
    ("zero-width-space", "4.58 m/s²\u200b", ACCEL, OK, Reason.EQUIVALENT),  # from a web page
    ("zero-width-in-number", "4.5\u200b8 m/s^2", ACCEL, OK, Reason.EQUIVALENT),  # shows as 4.58
    ("right-to-left-mark", "\u200f4.58 m/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("byte-order-mark", "\ufeff4.58 m/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("bullet-operator-units", "4.58 m∙s^-2", ACCEL, OK, Reason.EQUIVALENT),
    ("bullet-units", "4.58 m•s^-2", ACCEL, OK, Reason.EQUIVALENT),  # option-8 on a Mac
    ("bullet-times-ten", "458•10^-2 m/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("asterisk-operator", "458 ∗ 10^-2 m/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("degree-as-power-o", "28.65^o", ANGLE, OK, Reason.EQUIVALENT),  # plain text for 28.65°
    ("degree-as-power-o-braced", "28.65^{o}", ANGLE, OK, Reason.EQUIVALENT),
    ("degree-as-power-o-celsius", "25^oC", KELVIN, OK, Reason.EQUIVALENT),
    ("degree-as-power-zero", "28.65^0", ANGLE, BAD, Reason.PARSE_ERROR),  # 28.65° or 1? asked
    ("degree-as-superscript-zero", "28.65⁰", ANGLE, BAD, Reason.PARSE_ERROR),
    ("degree-as-power-zero-in-sin", "9.8 sin(30^0) N", NumericSpec(D("4.9"), "N"), BAD, Reason.PARSE_ERROR),
    ("caret-then-superscript", "4.58 m/s^²", ACCEL, OK, Reason.EQUIVALENT),
    ("caret-then-superscript-minus", "4.58 m·s^⁻²", ACCEL, OK, Reason.EQUIVALENT),
    ("latex-dollars", "$4.58\\,\\mathrm{m/s^2}$", ACCEL, OK, Reason.EQUIVALENT),  # copied from a document
    ("latex-parentheses", "\\(4.58 \\text{ m/s}^2\\)", ACCEL, OK, Reason.EQUIVALENT),
    ("prefixed-units", "4580 mm/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("scientific", "4.58e0 m/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("times-ten", "458×10^-2 m/s^2", ACCEL, OK, Reason.EQUIVALENT),
    ("km/h-vs-m/s", "16.49 km/h", SPEED, OK, Reason.EQUIVALENT),
    ("km/h-too-far", "16.7 km/h", SPEED, NO, Reason.WRONG_VALUE),
    ("percent", "45%", PURE, OK, Reason.EQUIVALENT),
    ("percent-spaced", "45 %", PURE, OK, Reason.EQUIVALENT),
    ("pure", "0.45", PURE, OK, Reason.EQUIVALENT),
    ("degrees-for-radians", "28.65°", ANGLE, OK, Reason.EQUIVALENT),
    ("deg-for-radians", "28.65 deg", ANGLE, OK, Reason.EQUIVALENT),
    ("ordinal-sign-for-degrees", "28.65º", ANGLE, OK, Reason.EQUIVALENT),  # º: option-0 on a Mac
    ("ring-above-for-degrees", "28.65˚", ANGLE, OK, Reason.EQUIVALENT),
    ("ordinal-sign-celsius", "25 ºC", KELVIN, OK, Reason.EQUIVALENT),
    ("rev-for-radians", "0.0796 rev", ANGLE, OK, Reason.EQUIVALENT),
    ("celsius-for-kelvin", "25 °C", KELVIN, OK, Reason.EQUIVALENT),
    ("kelvin", "298.15 K", KELVIN, OK, Reason.EQUIVALENT),
    ("bare-number-read-in-units", "4.58", BARE_OK, OK, Reason.EQUIVALENT),
    ("bare-number-units-still-checked", "4.58 m/s", BARE_OK, NO, Reason.WRONG_DIMENSION),
    ("sigfigs-right", "1.50e3 N", SIGFIGS3, OK, Reason.EQUIVALENT),
    ("sigfigs-ambiguous-zeros", "1500 N", SIGFIGS3, OK, Reason.EQUIVALENT),
    ("sigfigs-in-other-units", "1.50 kN", SIGFIGS3, OK, Reason.EQUIVALENT),
    ("sigfigs-too-few", "1.5e3 N", SIGFIGS3, BAD, Reason.SIGFIGS),
    ("sigfigs-too-many", "1498 N", SIGFIGS3, BAD, Reason.SIGFIGS),
    ("sigfigs-wrong-value", "1.49e3 N", SIGFIGS3, NO, Reason.WRONG_VALUE),
    ("sigfigs-sign", "-1.50e3 N", SIGFIGS3, NO, Reason.SIGN_ERROR),
    ("sigfigs-power-of-ten", "1.50 N", SIGFIGS3, NO, Reason.CONSTANT_FACTOR),
    ("wrong-dimension", "4.58 m/s", ACCEL, NO, Reason.WRONG_DIMENSION),
    ("wrong-dimension-pure-unit", "4.58 rad", ACCEL, NO, Reason.WRONG_DIMENSION),
    ("sign-error", "-4.58 m/s^2", ACCEL, NO, Reason.SIGN_ERROR),
    ("sign-error-unicode-minus", "−4.58 m/s^2", ACCEL, NO, Reason.SIGN_ERROR),
    ("sign-error-of-negative", "2.45 m/s^2", NEGATIVE, NO, Reason.SIGN_ERROR),
    ("power-of-ten-up", "45.8 m/s^2", ACCEL, NO, Reason.CONSTANT_FACTOR),
    ("power-of-ten-down", "0.458 m/s^2", ACCEL, NO, Reason.CONSTANT_FACTOR),
    ("prefix-slip", "4.58 mm/s^2", ACCEL, NO, Reason.CONSTANT_FACTOR),
    ("power-of-ten-far", "4.58e9 m/s^2", ACCEL, NO, Reason.CONSTANT_FACTOR),
    ("factor-two", "9.16 m/s^2", ACCEL, NO, Reason.CONSTANT_FACTOR),
    ("factor-half", "2.29 m/s^2", ACCEL, NO, Reason.CONSTANT_FACTOR),
    ("factor-two-pi", "28.78 rad/s", OMEGA, NO, Reason.CONSTANT_FACTOR),
    ("factor-one-over-two-pi", "0.729 rad/s", OMEGA, NO, Reason.CONSTANT_FACTOR),
    ("speed-in-km/h-labelled-m/s", "16.49 m/s", SPEED, NO, Reason.CONSTANT_FACTOR),
    ("degrees-labelled-radians", "28.65 rad", ANGLE, NO, Reason.CONSTANT_FACTOR),
    ("wrong-value", "3.3 m/s^2", ACCEL, NO, Reason.WRONG_VALUE),
    ("zero", "0 m/s^2", ACCEL, NO, Reason.WRONG_VALUE),
    ("missing-units", "4.58", ACCEL, BAD, Reason.MISSING_UNITS),
    ("missing-units-percent", "45%", SPEED, BAD, Reason.MISSING_UNITS),
    ("unexpected-units", "0.45 m", PURE, BAD, Reason.UNEXPECTED_UNITS),
    ("unexpected-angle-units", "0.45 rad", PURE, BAD, Reason.UNEXPECTED_UNITS),
    ("unknown-unit", "4.58 smoots", ACCEL, BAD, Reason.UNKNOWN_UNIT),
    ("unknown-unit-case", "4.58 M/S^2", SPEED, BAD, Reason.UNKNOWN_UNIT),  # not a speed in small letters
    ("caps-lock-units", "4.58 M/S^2", ACCEL, OK, Reason.EQUIVALENT),  # in small letters, an acceleration
    ("decimal-comma", "4,58 m/s^2", ACCEL, BAD, Reason.PARSE_ERROR),  # the contract: never read as 4.58
    ("thousands-or-decimal-comma", "4,580 m/s^2", ACCEL, BAD, Reason.PARSE_ERROR),
    ("two-numbers", "12 50 m/s^2", ACCEL, BAD, Reason.PARSE_ERROR),
    ("empty", "", ACCEL, BAD, Reason.PARSE_ERROR),
    ("words", "about four", ACCEL, BAD, Reason.PARSE_ERROR),
    ("ambiguous-units", "4.58 J/kg K/s", ACCEL, BAD, Reason.AMBIGUOUS),
    ("ambiguous-glued-units", "4.58 Nms", ACCEL, BAD, Reason.AMBIGUOUS),
    ("huge-exponent", "1e999999 m/s^2", ACCEL, BAD, Reason.TOO_LARGE),
    ("too-long", "4" * 201, ACCEL, BAD, Reason.TOO_LARGE),
    ("too-many-digits", "4." + "5" * 40 + " m/s^2", ACCEL, BAD, Reason.TOO_LARGE),
    # deg after an inverse sine's bracket is the answer's unit, as typed (a sine's is asked about)
    ("deg-after-an-inverse-sine", "asin(0.5) deg", NumericSpec(D("30"), "deg"), NO, Reason.CONSTANT_FACTOR),
    ("sines-degree-sign-outside", "9.8*sin(30)° m/s^2", ACCEL, BAD, Reason.PARSE_ERROR),
]


@pytest.mark.parametrize(
    ("answer", "spec", "outcome", "reason"), [c[1:] for c in VERDICTS], ids=[c[0] for c in VERDICTS]
)
def test_verdict(answer: str, spec: NumericSpec, outcome: Outcome, reason: Reason) -> None:
    verdict = check_numeric(answer, spec)
    assert (verdict.outcome, verdict.reason) == (outcome, reason)


@pytest.mark.parametrize(
    ("answer", "spec", "outcome", "reason"), [c[1:] for c in VERDICTS], ids=[c[0] for c in VERDICTS]
)
def test_feedback_never_reveals_the_expected_value(
    answer: str, spec: NumericSpec, outcome: Outcome, reason: Reason
) -> None:
    feedback = check_numeric(answer, spec).feedback
    assert feedback
    typed = answer.replace(",", ".")  # `4,58` is refused saying to write 4.58, its own digits
    for shown in {str(spec.expected), str(spec.expected.normalize()), "4.58", "298", "1498", "1.50"}:
        if shown not in typed:
            assert shown not in feedback


@pytest.mark.parametrize(
    ("answer", "spec", "outcome", "reason"),
    [c[1:] for c in VERDICTS if c[3] is BAD],
    ids=[c[0] for c in VERDICTS if c[3] is BAD],
)
def test_invalid_verdict_uses_no_attempt_and_says_where(
    answer: str, spec: NumericSpec, outcome: Outcome, reason: Reason
) -> None:
    verdict = check_numeric(answer, spec)
    assert verdict.score == 0.0
    assert verdict.error is not None
    assert verdict.error.message == verdict.feedback
    assert verdict.error.position is not None
    assert 0 <= verdict.error.position <= len(answer)


def test_scores_of_graded_verdicts() -> None:
    assert check_numeric("4.58 m/s^2", ACCEL).score == 1.0
    assert check_numeric("3.3 m/s^2", ACCEL).score == 0.0


WORDING = [
    # (answer, spec, words the feedback must contain)
    ("4.58 m/s", ACCEL, "Your answer has the units of a speed; an acceleration is expected."),
    ("4.58 N", ACCEL, "Your answer has the units of a force; an acceleration is expected."),
    ("4.58 J", NumericSpec(D(1), "N·m/s"), "an energy; a power is expected"),
    ("4.58 kg m^2/s^4", ACCEL, "a quantity in kg·m²/s⁴; an acceleration is expected"),
    ("45.8 m/s^2", ACCEL, "unit prefixes / powers of ten"),
    ("2.5 Kg", NumericSpec(D("2.5"), "kg"), "Read Kg as kg: the only reading that is a mass. Correct."),
    ("-4.58 m/s^2", ACCEL, "sign"),
    ("9.16 m/s^2", ACCEL, "factor"),
    ("28.78 rad/s", OMEGA, "angular frequency"),
    ("4.58", ACCEL, "needs units"),
    ("0.45 m", PURE, "remove the units"),
    ("4.58 KM/s^2", ACCEL, "Read KM/s^2 as km/s^2: the only reading that is an acceleration"),
    # caps lock on: units unknown as typed (M) that in small letters are the dimension asked
    ("4.58 M/S^2", ACCEL, "Read M/S^2 as m/s^2: units are case-sensitive, and in small letters these are an"),
    ("9.8 KG M/S^2", NumericSpec(D("9.8"), "N"), "Read KG M/S^2 as kg·m/s^2: units are case-sensitive"),
    ("101325 PA", NumericSpec(D("101325"), "Pa"), "PA is the petaampere, a current"),  # one name: asked
    ("1.5e3 N", SIGFIGS3, "3 significant figures (yours shows 2)"),
    ("1234000 N", SIGFIGS3, "3 significant figures (yours shows 4 to 7)"),
    ("12 50 m/s^2", ACCEL, "12 50: two numbers side by side; for one number, write 1250"),
    ("4,580 m/s^2", ACCEL, "Did you mean 4.580 or 4580?"),
    ("4,58 m/s^2", ACCEL, "4,58: a decimal comma is not read; write 4.58"),
    ("a = 4.58 m/s^2", ACCEL, "Give the value alone, without 'a =': type only 4.58 m/s^2"),
    ("a(t) = 4.58 m/s^2", ACCEL, "Give the value alone, without a name and '='"),
    ("≈ 4.58 m/s^2", ACCEL, "Give the value without '≈'"),
    ("a ≈ 4.58 m/s^2", ACCEL, "Give the value without '≈'"),  # once "must start with a number"
    ("approx. 4.58 m/s^2", ACCEL, "Give the value without 'approx.'"),
    ("About -4.58 m/s^2", ACCEL, "Give the value without 'About'"),
    ("4.58 ft/s^2", ACCEL, "Your number would be right in other units than the ones you wrote"),
    ("15.03 m/s^2", NumericSpec(D("15.03"), "ft/s^2"), "0.3048 m per ft"),
    ("2.08 lb", NumericSpec(D("2.08"), "kg"), "0.4536 kg per lb"),
    ("100 lbf", NumericSpec(D("100"), "N"), "would be right in other units"),
    ("9.8*sin(28) m/s^2", NumericSpec(D("4.6007"), "m/s^2"), "right with its angles in degrees"),
    ("9.8 cos 62 m/s^2", NumericSpec(D("4.6007"), "m/s^2"), "unless it has a degree sign, as in cos(62°)."),
    ("9.8sin(28) m/s^2", NumericSpec(D("4.6007"), "m/s^2"), "right with its angles in degrees"),  # glued
    ("2π√0.5/20 s", NumericSpec(D("0.9935"), "s"), "Did you mean sqrt(0.5)/20 or sqrt(0.5/20)?"),
    ("4.58 ± 0.05 m/s^2", ACCEL, "Give one value, without its uncertainty (± …)"),
    # a / and a negative power, which together multiply: once graded a wrong dimension (m·s²)
    ("4.58 m/s^-2", ACCEL, "Did you mean m/s^2? As typed, m/s^-2 is m·s^2: a / and a negative power each"),
    ("4.58 m/s⁻²", ACCEL, "Did you mean m/s^2? As typed, m/s⁻² is m·s^2"),
    (
        "4.2 J/kg^-1 K^-1",
        NumericSpec(D("4.2"), "J/(kg*K)"),
        "Did you mean J/(kg·K)? As typed, J/kg^-1 K^-1 is",
    ),
    # a direction said after the value: no unit, and the refusal says how to give it
    (
        "4.58 m/s^2 downward",
        ACCEL,
        "Unknown unit 'downward': a direction is not read here; give it by the sign",
    ),
    ("4.58 m/s^2 (down)", ACCEL, "Unknown unit 'down': a direction is not read here"),
    # an arrow for the direction, before or after the value: once "Unexpected character '↓' in the units"
    # or "The answer must start with a number"
    (
        "4.58 m/s^2 ↓",
        ACCEL,
        "Unexpected character '↓' in the units: a direction is not read here; give it by",
    ),
    ("↓ 4.58 m/s^2", ACCEL, "A direction is not read here; give it by the sign of the value"),
    # a sentence: once "The answer must start with a number"; words arithmetic reads are no sentence
    (
        "The period is 1.42 s.",
        NumericSpec(D("1.42"), "s"),
        "Type only the value and its units (1.42 s), not a",
    ),
    ("it takes about 1.42 s", NumericSpec(D("1.42"), "s"), "Type only the value and its units (1.42 s)"),
    ("pi sqrt 2 m", NumericSpec(D("4.4429"), "m"), "Correct"),
    # how near the value is, said after it: no unit (was "Unknown unit 'approx'" alone)
    (
        "4.58 m/s^2 approx",
        ACCEL,
        "Unknown unit 'approx': give the value and its units alone, and leave out approx",
    ),
    ("4.58 m/s^2 exactly", ACCEL, "leave out exactly"),
    # a prime or a double prime: minutes and seconds of arc, or feet and inches; named, not guessed
    ("30′", NumericSpec(D("0.5"), "deg"), "a prime is not read as a unit; for minutes of arc write arcmin"),
    (
        '12"',
        NumericSpec(D("12"), "in"),
        "a double prime is not read as a unit; for seconds of arc write arcsec",
    ),
    # a function of an angle with its number glued on and no degree sign: once "The power 30 is too
    # large for a unit" (a unit sin to the power 30)
    (
        "9.8 sin30 m/s^2",
        NumericSpec(D("4.9"), "m/s^2"),
        "Did you mean sin(30°)? Write the degree sign for degrees",
    ),
    # a calculator's key for the power of ten, once an unknown unit EXP
    ("2.5 EXP -3 m/s^2", ACCEL, "Did you mean 2.5E-3? A calculator's EXP key is a power of ten"),
    ("2.5EE-3 m/s^2", ACCEL, "Did you mean 2.5E-3? A calculator's EE key is a power of ten: write 2.5E-3 or"),
    # a sentence's `in`: the inch times m/s² as typed, once graded a quantity in m²/s²
    ("4.58 in m/s^2", ACCEL, "'in' here is the inch, so these units are in·m/s^2: write the units alone"),
    ("(4.58 ± 0.05) m/s^2", ACCEL, "without its uncertainty (± …)"),
    ("4.58 +/- 0.05 m/s^2", ACCEL, "without its uncertainty (+/- …)"),
    ("4.58+-0.05 m/s^2", ACCEL, "without its uncertainty (+- …)"),
    ("4.58 m/s^2 ± 1%", ACCEL, "without its uncertainty (± …)"),
    # a mixed number: `1 ½ m` was 1·½ m, graded wrong; `1½ m` named an unexpected character in the units
    ("1 ½ m", NumericSpec(D("1.5"), "m"), "Write a mixed number as one fraction or a decimal (3/2 or 1.5)"),
    ("1½ m", NumericSpec(D("1.5"), "m"), "Write a mixed number as one fraction or a decimal (3/2 or 1.5)"),
    (
        "2 3/4 in",
        NumericSpec(D("2.75"), "in"),
        "Write a mixed number as one fraction or a decimal (11/4 or 2.75)",
    ),
]


@pytest.mark.parametrize(("answer", "spec", "words"), WORDING, ids=[c[0] for c in WORDING])
def test_feedback_wording(answer: str, spec: NumericSpec, words: str) -> None:
    assert words in check_numeric(answer, spec).feedback


@pytest.mark.parametrize("answer", ["9.8*sin(30) m/s^2", "9.8*sin(28°)*2 m/s^2", "9.2 m/s^2"])
def test_degrees_are_suggested_only_where_they_make_the_answer_right(answer: str) -> None:
    verdict = check_numeric(answer, NumericSpec(D("4.6007"), "m/s^2"))
    assert verdict.outcome is NO
    assert "degrees" not in verdict.feedback


POSITIONS = [
    # (answer, position of the error)
    ("4.58", 4),  # missing units: just after the number
    ("  4.58  ", 6),
    ("0.45 m", 5),  # unexpected units: where they start
    ("4.58 m/smoot", 7),
    ("4.58 KG/s^2", 5),
    ("4,580 m/s^2", 1),
    ("12 50 m/s^2", 3),
    ("a = 4.58 m/s^2", 2),  # the '='
    ("(4.58 ± 0.05) m/s^2", 6),  # the uncertainty's sign
    ("\u200b4.58\u200b", 6),  # where typed, zero-width characters and all
    ("\u200f4.58 m/smoot", 8),
    ("\u200b0.45 m", 6),  # unexpected units
    ("9.8 in m/s^2", 4),  # the word in, which reads as the inch
    ("9.8 m/s^-2", 8),  # the minus that divides again
]


@pytest.mark.parametrize(("answer", "position"), POSITIONS, ids=[c[0] for c in POSITIONS])
def test_error_position_points_into_the_answer(answer: str, position: int) -> None:
    spec = PURE if answer.lstrip("\u200b").startswith("0.45") else ACCEL
    verdict = check_numeric(answer, spec)
    assert verdict.error is not None
    assert verdict.error.position == position


READ_AS = [
    ("4.58 m/s^2", ACCEL, "4.58 m/s^2", r"4.58\,\mathrm{m}/\mathrm{s}^{2}"),
    ("4.58 m s^-2", ACCEL, "4.58 m/s^2", r"4.58\,\mathrm{m}/\mathrm{s}^{2}"),
    ("4.58", BARE_OK, "4.58 m/s^2", r"4.58\,\mathrm{m}/\mathrm{s}^{2}"),
    ("16.49 km/h", SPEED, "16.49 km/h", r"16.49\,\mathrm{km}/\mathrm{h}"),
    ("45%", PURE, "45%", r"45\,\%"),
    ("4.58 m/s", ACCEL, "4.58 m/s", r"4.58\,\mathrm{m}/\mathrm{s}"),
    ("1.5e3 N", SIGFIGS3, "1.5e3 N", r"1.5 \times 10^{3}\,\mathrm{N}"),
]


@pytest.mark.parametrize(("answer", "spec", "text", "latex"), READ_AS, ids=[c[0] for c in READ_AS])
def test_read_as_shows_number_and_units_as_understood(
    answer: str, spec: NumericSpec, text: str, latex: str
) -> None:
    read_as = check_numeric(answer, spec).read_as
    assert read_as is not None
    assert (read_as.text, read_as.latex) == (text, latex)


def test_unparseable_answer_has_no_read_as() -> None:
    assert check_numeric("4,580", ACCEL).read_as is None


def test_spec_units_of_one_mean_a_pure_number() -> None:
    spec = NumericSpec(D("0.45"), "1")
    assert check_numeric("0.45", spec).outcome is OK
    assert check_numeric("0.45 m", spec).reason is Reason.UNEXPECTED_UNITS


def test_answer_exactly_at_one_percent_of_a_converted_expected_value() -> None:
    # 4.58 m/s is 16.488 km/h; 1 % below is 16.32312 km/h, accepted; a hair lower is not.
    spec = NumericSpec(D("16.488"), "km/h")
    assert check_numeric("4.5342 m/s", spec).outcome is OK  # 16.32312 km/h: on the bound
    assert check_numeric("4.53419 m/s", spec).outcome is NO


HOSTILE = [
    "1e999999",
    "1" * 10_000,
    "9" * 199,
    "1e-400 m/s^2",
    "1e400 m/s^2",
    "1e400 Gm/ys^2",
    "4.58 " + "m/" * 97,
    "4.58 " + "(" * 195,
    "4.58 " + "kgm" * 65,
    "−" * 200,
    "4.58 m/s^2" + "\u202e" * 100,
]


@pytest.mark.timeout(10)  # hostile input must fail fast; a hang fails here
@pytest.mark.parametrize("answer", HOSTILE, ids=[f"hostile-{i}" for i in range(len(HOSTILE))])
def test_hostile_answer_gets_a_verdict_quickly(answer: str) -> None:
    verdict = check_numeric(answer, ACCEL)
    assert verdict.outcome in (OK, NO, BAD)
