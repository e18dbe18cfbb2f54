"""Hz for an angular frequency: correct by default (Hz and rad/s are both s⁻¹), said once and plainly; a
part with `angular_units: strict` counts a hertz as a cycle, 2π rad/s, and grades Hz for ω as the 2π
mistake. Against turns (rev/s, rpm) a hertz is a cycle in either mode."""

from __future__ import annotations

from decimal import Decimal

import pytest

from app.web.student_work import shown_feedback
from physics.errors import SpecError
from physics.numeric import NumericSpec, Tolerance, check_numeric
from physics.verdict import Outcome, Reason

D = Decimal
OK, NO = Outcome.CORRECT, Outcome.INCORRECT
OMEGA_SAYS = "An angular frequency ω is usually given in rad/s"
F_SAYS = "A frequency f is usually given in Hz"


def _omega(**extra: object) -> NumericSpec:
    return NumericSpec(D("4.5807"), "rad/s", **extra)  # type: ignore[arg-type]


def _frequency(**extra: object) -> NumericSpec:
    return NumericSpec(D("0.72904"), "Hz", **extra)  # type: ignore[arg-type]


STRICT = {"angular_units": "strict"}

GRADED = [
    # (answer, spec, outcome, reason, what the feedback says about the units: "" for nothing)
    ("4.58 Hz", _omega(), OK, Reason.EQUIVALENT, OMEGA_SAYS),  # s⁻¹ either way by default
    ("0.00458 kHz", _omega(), OK, Reason.EQUIVALENT, OMEGA_SAYS),
    ("0.729 Hz", _omega(), NO, Reason.CONSTANT_FACTOR, OMEGA_SAYS),  # f given for ω
    ("4.58 rad/s", _frequency(), NO, Reason.CONSTANT_FACTOR, F_SAYS),
    ("4.58 rad/s", _omega(), OK, Reason.EQUIVALENT, ""),
    ("4.58 1/s", _omega(), OK, Reason.EQUIVALENT, ""),
    # a turn is a cycle whatever the mode: 43.7 rpm is 0.729 Hz, not 2π times it
    ("43.7 rpm", _frequency(), OK, Reason.EQUIVALENT, ""),
    ("0.729 rev/s", _frequency(), OK, Reason.EQUIVALENT, ""),
    ("275 rpm", _frequency(), NO, Reason.CONSTANT_FACTOR, ""),  # 2π times too many turns
    ("0.729 Hz", NumericSpec(D("43.7"), "rpm"), OK, Reason.EQUIVALENT, ""),
    ("0.000729 kHz", NumericSpec(D("43.7"), "rpm"), OK, Reason.EQUIVALENT, ""),
    ("4.58 Hz", NumericSpec(D("43.7"), "rpm"), NO, Reason.CONSTANT_FACTOR, ""),  # ω in Hz for a rate
    # strict: a hertz is a cycle per second, 2π rad/s
    ("4.58 Hz", _omega(**STRICT), NO, Reason.CONSTANT_FACTOR, OMEGA_SAYS),  # the 2π mistake
    ("0.00458 kHz", _omega(**STRICT), NO, Reason.CONSTANT_FACTOR, OMEGA_SAYS),
    ("0.729 Hz", _omega(**STRICT), OK, Reason.EQUIVALENT, OMEGA_SAYS),  # 0.729 cycles/s is 4.58 rad/s
    ("4.58 rad/s", _frequency(**STRICT), OK, Reason.EQUIVALENT, F_SAYS),  # ω = 2πf, converted
    ("0.729 rad/s", _frequency(**STRICT), NO, Reason.CONSTANT_FACTOR, F_SAYS),
    ("0.729 rev/s", _frequency(**STRICT), OK, Reason.EQUIVALENT, ""),  # a revolution is a cycle
    ("43.7 rpm", _frequency(**STRICT), OK, Reason.EQUIVALENT, ""),
    ("4.58 rad/s", _omega(**STRICT), OK, Reason.EQUIVALENT, ""),
    ("4.58 1/s", _omega(**STRICT), OK, Reason.EQUIVALENT, ""),  # no cycles, no angles: s⁻¹
    ("0.729 1/s", _frequency(**STRICT), OK, Reason.EQUIVALENT, ""),
    ("0.729 Bq", _frequency(**STRICT), OK, Reason.EQUIVALENT, ""),
]


@pytest.mark.parametrize(
    ("answer", "spec", "outcome", "reason", "says"),
    GRADED,
    ids=[f"{c[0]} for {c[1].units}{' strict' if c[1].angular_units else ''}" for c in GRADED],
)
def test_hertz_and_radians_per_second(
    answer: str, spec: NumericSpec, outcome: Outcome, reason: Reason, says: str
) -> None:
    verdict = check_numeric(answer, spec)
    assert (verdict.outcome, verdict.reason) == (outcome, reason), verdict.feedback
    if says:
        assert says in verdict.feedback
    else:
        assert "usually given" not in verdict.feedback


def test_the_strict_hertz_is_graded_as_the_2pi_mistake() -> None:
    verdict = check_numeric("4.58 Hz", _omega(**STRICT))
    assert "off by a factor of 2π" in verdict.feedback


def test_hertz_for_omega_is_correct_once_on_the_page_and_in_the_feedback() -> None:
    verdict = check_numeric("4.58 Hz", _omega())
    assert verdict.feedback.count("Correct.") == 1
    assert verdict.feedback.endswith("Correct.")
    # the student page says its own "Correct." first, then the feedback
    page = f"Correct. {shown_feedback(verdict.outcome, verdict.feedback)}"
    assert page.count("Correct") == 1, page
    assert page.startswith(f"Correct. {OMEGA_SAYS}")


def test_significant_figures_apply_to_a_strict_hertz_in_its_own_units() -> None:
    spec = NumericSpec(D("4.58"), "rad/s", tolerance=Tolerance(sigfigs=3), angular_units="strict")
    assert check_numeric("0.729 Hz", spec).outcome is OK  # 4.58/2π = 0.7289… to 3 figures
    assert check_numeric("0.7289 Hz", spec).reason is Reason.SIGFIGS


def test_angular_units_other_than_strict_are_a_spec_error() -> None:
    with pytest.raises(SpecError) as raised:
        NumericSpec(D(1), "rad/s", angular_units="loose")
    assert raised.value.path == ("angular_units",)


@pytest.mark.parametrize(
    ("answer", "units", "example"),
    [
        ("π/6", "deg", "pi/6 rad"),  # not "pi/6 °", a thirtieth of a degree
        ("2π", "°", "2*pi rad"),
        ("pi/6", "rad", "pi/6 rad"),
        ("π/2", "rad/s", "pi/2 rad/s"),
        ("30", "deg", "30 °"),
    ],
)
def test_a_bare_angle_is_asked_for_units_that_fit_how_it_is_written(
    answer: str, units: str, example: str
) -> None:
    verdict = check_numeric(answer, NumericSpec(D("0.5236"), units))
    assert verdict.reason is Reason.MISSING_UNITS
    assert verdict.feedback == f"Your answer needs units, for example {example}."
