"""An ambiguous grouping (the power `A e^-ωt`, the root `(2gh)^1/2`) is settled by dimension where
exactly one reading has the dimension the answer must have; it is refused where dimensions cannot
decide. A `/` followed by an unparenthesised product (`mv/qB`) is never settled: the contract refuses it
whatever the dimensions."""

from __future__ import annotations

import pytest

from physics.checking import SymbolDecl, preview, run_job
from physics.verdict import Outcome, Reason
from problems.kinds.symbolic import SymbolicJob

CHARGE = (
    SymbolDecl("m", "kg"),
    SymbolDecl("v", "m/s"),
    SymbolDecl("q", "C"),
    SymbolDecl("B", "T"),
)
PENDULUM = (SymbolDecl("m", "kg"), SymbolDecl("M", "kg"), SymbolDecl("g", "m/s^2"), SymbolDecl("L", "m"))
LENNARD_JONES = (SymbolDecl("U0", "J"), SymbolDecl("r0", "m"), SymbolDecl("r", "m"), SymbolDecl("m", "kg"))
MOMENTUM = (SymbolDecl("p", "kg*m/s"), SymbolDecl("m", "kg"))
FALL = (SymbolDecl("v", "m/s"), SymbolDecl("g", "m/s^2"))
DECAY = (
    SymbolDecl("A", "m"),
    SymbolDecl("omega", "1/s"),
    SymbolDecl("t", "s"),
    SymbolDecl("k", "1/m"),
    SymbolDecl("tau", "s"),
    SymbolDecl("b", "kg/s"),
    SymbolDecl("m", "kg"),
)
ROLL = (
    SymbolDecl("g", "m/s^2"),
    SymbolDecl("h", "m"),
    SymbolDecl("I", "kg*m^2"),
    SymbolDecl("m", "kg"),
    SymbolDecl("r", "m"),
)
SWING = (SymbolDecl("g", "m/s^2"), SymbolDecl("L", "m"), SymbolDecl("theta", "1"))
WAVE = (SymbolDecl("A", "m"), SymbolDecl("k", "1"), SymbolDecl("x", "m"))
DROP = (SymbolDecl("g", "m/s^2"), SymbolDecl("h", "m"), SymbolDecl("k", "N/m"), SymbolDecl("m", "kg"))
CIRCUIT = (SymbolDecl("V0", "V"), SymbolDecl("t", "s"), SymbolDecl("R", "ohm"), SymbolDecl("C", "F"))
PURE = (SymbolDecl("x", "1"), SymbolDecl("y", "1"))
PURE3 = (SymbolDecl("x", "1"), SymbolDecl("y", "1"), SymbolDecl("z", "1"))
UNDIMENSIONED_CHARGE = (SymbolDecl("m"), SymbolDecl("v"), SymbolDecl("q"), SymbolDecl("B"))
UNDIMENSIONED = (SymbolDecl("A"), SymbolDecl("omega"), SymbolDecl("t"))

SETTLED = [
    # (answer, reference, symbols, reading taken, what the answer must be)
    # e^(−ω)·t takes exp of a rate: only e^(−ωt) can be right, as physics writes it
    ("A e^-ωt", "A*exp(-omega*t)", DECAY, "A*e**(-omega*t)", "a length"),
    (
        "A e^-omegat cos(omega t)",
        "A*exp(-omega*t)*cos(omega*t)",
        DECAY,
        "A*e**(-omega*t)*cos(omega*t)",
        "a length",
    ),
    ("A e^-kA", "A*exp(-k*A)", DECAY, "A*e**(-k*A)", "a length"),
    ("A e^-t/τ", "A*exp(-t/tau)", DECAY, "A*e**(-t/tau)", "a length"),
    # with e^(−t) there is no length however τ cos(ωt) is grouped: no division is read one way
    ("A e^-t/τ cos(ωt)", "A*exp(-t/tau)*cos(omega*t)", DECAY, "A*e**(-t/tau)*cos(omega*t)", "a length"),
    # a root as students type it: (2gh)^1 halved is no speed
    ("(2gh)^1/2", "sqrt(2*g*h)", DROP, "(2*g*h)**(1/2)", "a speed"),
    ("2π (k/m)^-1/2", "2*pi*sqrt(m/k)", DROP, "2*pi*(k/m)**(-1/2)", "a time"),
    # a root or a function without brackets, a `/` typed on: √m/k would be no time, sin of x/L's x no angle
    ("2π√m/k", "2*pi*sqrt(m/k)", DROP, "2*pi*sqrt(m/k)", "a time"),
    ("2πsqrt m/k", "2*pi*sqrt(m/k)", DROP, "2*pi*sqrt(m/k)", "a time"),
    ("A sin kx/A", "A*sin(k*x/A)", WAVE, "A*sin(k*x/A)", "a length"),
    # a function's word glued on past its angle: sin(θ·m·g·L) has no dimension, sin(θ)·m·g·L is an energy
    ("sinθmgL", "m*g*L*sin(theta)", (*SWING, SymbolDecl("m", "kg")), "sin(theta)*m*g*L", "an energy"),
    (
        "μcosθmg",
        "mu*m*g*cos(theta)",
        (*SWING, SymbolDecl("m", "kg"), SymbolDecl("mu", "1")),
        "mu*cos(theta)*m*g",
        "a force",
    ),
    ("cos ωtA", "A*cos(omega*t)", DECAY, "cos(omega*t)*A", "a length"),
    # ln 2 typed glued, as a half-life is written: log(2/b) has no dimension to take the log of
    ("m ln2/b", "m*log(2)/b", DECAY, "m*log(2)/b", "a time"),
]


@pytest.mark.parametrize(
    ("answer", "reference", "symbols", "reading", "kind"), SETTLED, ids=[c[0] for c in SETTLED]
)
def test_the_only_reading_with_the_expected_dimension_is_graded_and_shown(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], reading: str, kind: str
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback
    assert verdict.read_as is not None
    assert verdict.read_as.text == reading
    assert verdict.read_as.note is not None
    # the note in the student's style: the page shows it as Markdown, where `*` is emphasis
    typed = reading.replace("**", "^").replace("*", "·")
    assert verdict.read_as.note.startswith(f"Read as {typed}: the only reading that is {kind}")
    assert verdict.feedback.startswith(f"Read as {typed}")


def test_preview_shows_a_glued_argument_ended_by_dimension() -> None:
    shown = preview(SymbolicJob("sinθmgL", "m*g*L*sin(theta)", (*SWING, SymbolDecl("m", "kg"))))
    assert shown.error is None
    assert shown.read_as is not None
    assert shown.read_as.text == "sin(theta)*m*g*L"
    assert shown.read_as.note == "Read as sin(theta)·m·g·L: the only reading that is an energy"


def test_a_settled_reading_that_is_wrong_is_graded_wrong() -> None:
    verdict = run_job(SymbolicJob("2A e^-ωt", "A*exp(-omega*t)", DECAY))
    assert verdict.outcome is Outcome.INCORRECT
    assert verdict.reason is Reason.CONSTANT_FACTOR
    assert verdict.read_as is not None and verdict.read_as.note is not None


def test_preview_shows_the_settled_reading_before_submission() -> None:
    shown = preview(SymbolicJob("A e^-ωt", "A*exp(-omega*t)", DECAY))
    assert shown.error is None
    assert shown.read_as is not None
    assert shown.read_as.text == "A*e**(-omega*t)"
    assert shown.read_as.note is not None


REFUSED = [
    # (answer, reference, symbols, why dimensions cannot decide)
    ("e^2x", "exp(2*x)", PURE, "Both readings are a pure number"),  # e²·x or e^(2x)
    ("A e^-2kA", "A*exp(-2*k*A)", DECAY, "Both readings are a length"),  # A·e^(−2)·k·A is one too
    ("e^x/2", "exp(x)/2", PURE, "Both readings are a pure number"),  # e^x/2 or e^(x/2)
    ("x^1/2", "sqrt(x)", PURE, "Both readings are a pure number"),  # x/2 or √x
    ("A e^-ωt^2", "A*exp(-omega*t)", DECAY, "Add parentheses"),  # neither exponent is a pure number
    # a function's or a root's bare argument with a `/` typed on: sin(x)/2 or sin(x/2)?
    ("sin x/2", "sin(x/2)", PURE, "Both readings are a pure number"),
    ("y sin x/2", "y*sin(x)/2", PURE, "Both readings are a pure number"),
    ("√x/y", "sqrt(x/y)", PURE, "Both readings are a pure number"),
    ("sqrt 2gh/3", "sqrt(2*g*h/3)", DROP, "Both readings are a speed"),
    ("√2gL(1 - cos θ)", "sqrt(2*g*L*(1 - cos(theta)))", SWING, "Both readings are a speed"),  # √(2gL)·(…)
    ("√2gh/(1+I/(mr²))", "sqrt(2*g*h/(1 + I/(m*r**2)))", ROLL, "Both readings are a speed"),
    # the question is sin's reach, e's exponent being settled (only ω·t is a pure number)
    (
        "A e^-ωt sin x/2",
        "A*exp(-omega*t)*sin(x/2)",
        (*DECAY, SymbolDecl("x", "1")),
        "Did you mean sin(x)/2 or sin(x/2)? Add parentheses. Both readings are a length",
    ),
]


@pytest.mark.parametrize(("answer", "reference", "symbols", "words"), REFUSED, ids=[c[0] for c in REFUSED])
def test_a_grouping_that_dimensions_cannot_settle_is_refused_with_both_readings(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], words: str
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is Reason.AMBIGUOUS
    assert words in verdict.feedback
    assert "Did you mean" in verdict.feedback


SPRING = (SymbolDecl("k", "N/m"), SymbolDecl("m", "kg"))
BOX = (SymbolDecl("n", "1"), SymbolDecl("hbar", "J*s"), SymbolDecl("m", "kg"), SymbolDecl("L", "m"))
FIELD = (SymbolDecl("q", "C"), SymbolDecl("epsilon_0", "C^2/(N*m^2)"), SymbolDecl("r", "m"))
FREQUENCY = "sqrt(k/m)/(2*pi)"
UNDIMENSIONED_P = (SymbolDecl("p"), SymbolDecl("m", "kg"), SymbolDecl("x", "1"))
DECAY_XYZ = (*DECAY, SymbolDecl("x", "1"), SymbolDecl("y", "1"), SymbolDecl("z", "1"))

DIVISIONS = [
    # (answer, reference, symbols, the readings asked about): a `/` followed by an unparenthesised
    # juxtaposed product, which the contract refuses whatever the dimensions; each was graded, read as
    # its only reading with the expected dimension, or as (a/b)·c because a space ended the divisor
    ("mv/qB", "m*v/(q*B)", CHARGE, ("(m·v/q)·B", "m·v/(q·B)")),
    ("m v/q B", "m*v/(q*B)", CHARGE, ("(m·v/q)·B", "m·v/(q·B)")),
    ("m v/q B", "m*v/(q*B)", UNDIMENSIONED_CHARGE, ("(m·v/q)·B", "m·v/(q·B)")),
    ("p^2/2m", "p^2/(2*m)", MOMENTUM, ("(p^2/2)·m", "p^2/(2·m)")),
    ("p^2/2m", "p^2/(2*m)", (SymbolDecl("p"), SymbolDecl("m", "kg")), ("(p^2/2)·m", "p^2/(2·m)")),
    ("v^2/2g", "v^2/(2*g)", FALL, ("(v^2/2)·g", "v^2/(2·g)")),
    ("mv/qB", "m*v*B", CHARGE, ("(m·v/q)·B", "m·v/(q·B)")),  # neither reading fits: refused as before
    (
        "(m+M)/m sqrt(2gL)",
        "(m+M)/m*sqrt(2*g*L)",
        PENDULUM,
        ("((m + M)/m)·sqrt(2·g·L)", "(m + M)/(m·sqrt(2·g·L))"),
    ),
    ("12/r0 sqrt(U0/m)", "12/r0*sqrt(U0/m)", LENNARD_JONES, ("(12/r0)·sqrt(U0/m)", "12/(r0·sqrt(U0/m))")),
    ("x/yz", "x*z/y", PURE3, ("(x/y)·z", "x/(y·z)")),
    ("x/y z", "x*z/y", PURE3, ("(x/y)·z", "x/(y·z)")),
    ("x / y z", "x*z/y", PURE3, ("(x/y)·z", "x/(y·z)")),
    ("x/y (z)", "x*z/y", PURE3, ("(x/y)·z", "x/(y·z)")),
    (
        "12 U0/r ((r0/r)^12 - (r0/r)^6)",
        "12*U0/r*((r0/r)^12 - (r0/r)^6)",
        LENNARD_JONES,
        ("(12·U0/r)·((r0/r)^12 - (r0/r)^6)", "12·U0/(r·((r0/r)^12 - (r0/r)^6))"),
    ),
    ("mv/qB + mv/2qB", "3*m*v/(2*q*B)", CHARGE, ("(m·v/q)·B", "m·v/(q·B)")),
    # inside e's exponent, a root's or a function's argument: the same construct, refused there too
    ("A e^-bt/2m cos(ωt)", "A*exp(-b*t/(2*m))*cos(omega*t)", DECAY, ("(b·t/2)·m", "b·t/(2·m)")),
    ("V0 e^-t/RC", "V0*exp(-t/(R*C))", CIRCUIT, ("(t/R)·C", "t/(R·C)")),
    ("√2gh/(1+I/mr²)", "sqrt(2*g*h/(1 + I/(m*r**2)))", ROLL, ("(I/m)·r^2", "I/(m·r^2)")),
    # beside another grouping the dimensions cannot settle (p, or every symbol, has no dimension; more
    # groupings than the budget): the division is asked about, not the other grouping
    # (the other grouping shown as typed, not as the reading tried to find the division)
    ("e^2x p^2/2m", "exp(2*x)*p^2/(2*m)", UNDIMENSIONED_P, ("(e^2x·p^2/2)·m", "e^2x·p^2/(2·m)")),
    (
        "e^2x p^2/2m",
        "exp(2*x)*p^2/(2*m)",
        (SymbolDecl("p"), SymbolDecl("m"), SymbolDecl("x")),
        ("(e^2x·p^2/2)·m", "e^2x·p^2/(2·m)"),
    ),
    ("sin x/2 p^2/2m", "sin(x/2)*p^2/(2*m)", UNDIMENSIONED_P, ("(sin x/2·p^2/2)·m", "sin x/2·p^2/(2·m)")),
    ("√x/2 p^2/2m", "sqrt(x/2)*p^2/(2*m)", UNDIMENSIONED_P, ("(√x/2·p^2/2)·m", "√x/2·p^2/(2·m)")),
    (
        "p^2/2m sin x/2",
        "sin(x/2)*p^2/(2*m)",
        UNDIMENSIONED_P,
        ("(p^2/2)·m·sin x/2", "p^2/(2·m)·sin x/2", "p^2/(2·m·sin x/2)"),
    ),
    (" + ".join(["A e^-ωt"] * 3 + ["A x/y z"]), "3*A*exp(-omega*t)", DECAY_XYZ, ("(A·x/y)·z", "A·x/(y·z)")),
    (" + ".join(["A e^-ωt"] * 4 + ["A x/y z"]), "4*A*exp(-omega*t)", DECAY_XYZ, ("(A·x/y)·z", "A·x/(y·z)")),
    (" + ".join(["A e^-ωt"] + ["A x/y z"] * 3), "A*exp(-omega*t)", DECAY_XYZ, ("(A·x/y)·z", "A·x/(y·z)")),
    # a divisor followed by several factors: a reading for each place it may end
    (
        "1/2π sqrt(k/m)",
        FREQUENCY,
        SPRING,
        ("(1/2)·pi·sqrt(k/m)", "1/(2·pi)·sqrt(k/m)", "1/(2·pi·sqrt(k/m))"),
    ),
    (
        "n^2 π^2 ħ^2/2m L^2",
        "n^2*pi^2*hbar^2/(2*m*L^2)",
        BOX,
        ("(n^2·pi^2·hbar^2/2)·m·L^2", "n^2·pi^2·hbar^2/(2·m)·L^2", "n^2·pi^2·hbar^2/(2·m·L^2)"),
    ),
    (
        "q/4π ε₀ r²",
        "q/(4*pi*epsilon_0*r^2)",
        FIELD,
        (
            "(q/4)·pi·epsilon_0·r^2",
            "q/(4·pi)·epsilon_0·r^2",
            "q/(4·pi·epsilon_0)·r^2",
            "q/(4·pi·epsilon_0·r^2)",
        ),
    ),
]


@pytest.mark.parametrize(
    ("answer", "reference", "symbols", "readings"),
    DIVISIONS,
    ids=[c[0] for c in DIVISIONS],
)
def test_a_division_before_an_unbracketed_product_is_refused_whatever_the_dimensions(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], readings: tuple[str, ...]
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert (verdict.outcome, verdict.reason, verdict.read_as) == (Outcome.INVALID, Reason.AMBIGUOUS, None)
    assert verdict.error is not None
    asked = f"{', '.join(readings[:-1])} or {readings[-1]}" if len(readings) > 2 else " or ".join(readings)
    assert verdict.error.message == f"Did you mean {asked}? Add parentheses."
    assert answer[verdict.error.position] == "/"


def test_preview_refuses_a_division_before_an_unbracketed_product() -> None:
    shown = preview(SymbolicJob("p^2/2m", "p^2/(2*m)", MOMENTUM))
    assert shown.read_as is None
    assert shown.error is not None
    assert shown.error.message == "Did you mean (p^2/2)·m or p^2/(2·m)? Add parentheses."


COEFFICIENTS = [
    # (answer, reference, symbols): an integer fraction opening a term, spaced from what follows
    ("1/2 m v^2", "m*v^2/2", CHARGE),
    ("1/2 p^2/m", "p^2/(2*m)", MOMENTUM),
    ("m v^2 + 1/2 m v^2", "3*m*v^2/2", CHARGE),
]


@pytest.mark.parametrize(("answer", "reference", "symbols"), COEFFICIENTS, ids=[c[0] for c in COEFFICIENTS])
def test_an_integer_fraction_starting_a_term_is_a_coefficient(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...]
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback
    assert verdict.read_as is not None and verdict.read_as.note is None


def test_a_division_followed_by_too_many_factors_is_refused_with_two_readings() -> None:
    # Each place the divisor may end is a reading; past a few, they are not all listed
    verdict = run_job(SymbolicJob("1/2π k m m k sqrt(k/m)/(k m)^2", FREQUENCY, SPRING))
    assert verdict.reason is Reason.AMBIGUOUS
    assert verdict.feedback == (
        "Did you mean (1/2)·pi·k·m·m·k·sqrt(k/m) or 1/(2·pi·k·m·m·k·sqrt(k/m))? Add parentheses."
    )


def test_a_divisions_readings_do_not_count_against_the_budget_of_settled_groupings() -> None:
    # e^(−t)/τ cos(ωt), the grammar's reading of the first power, reads its division both ways before the
    # other two powers are settled: three groupings, within the budget, and only e^(−t/τ) fits
    answer = "A e^-t/τ cos(ωt) + A e^-ωt + A e^-ωt"
    verdict = run_job(SymbolicJob(answer, "A*exp(-t/tau)*cos(omega*t) + 2*A*exp(-omega*t)", DECAY))
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback
    assert verdict.read_as is not None
    assert verdict.read_as.text == "A*e**(-t/tau)*cos(omega*t) + A*e**(-omega*t) + A*e**(-omega*t)"


def test_more_ambiguous_groupings_than_the_budget_are_refused() -> None:
    answer = " + ".join(["A e^-ωt"] * 4)  # each settled alone
    verdict = run_job(SymbolicJob(answer, "4*A*exp(-omega*t)", DECAY))
    assert verdict.reason is Reason.AMBIGUOUS


UNCHANGED = [
    # (answer, reference, symbols, reading): nothing glued to an unbracketed exponent of e, and no
    # exponent of 1 with a glued /n
    ("A e^(-ω)t", "A*exp(-omega)*t", UNDIMENSIONED, "A*e**(-omega)*t"),  # the student's brackets
    ("A e^-ω t", "A*exp(-omega)*t", UNDIMENSIONED, "A*e**(-omega)*t"),  # a space ends the exponent
    ("x^2y", "x**2*y", PURE, "x**2*y"),  # only e's exponent takes the word
    ("e^x y", "exp(x)*y", PURE, "e**x*y"),
    ("e^x /2", "exp(x)/2", PURE, "e**x/2"),
    ("x^2/3", "x^2/3", PURE, "x**2/3"),  # only an exponent of 1 takes the fraction: 2mR^2/5 stays
    ("x^1 /2", "x/2", PURE, "x**1/2"),
    ("e^x/ 2", "exp(x)/2", PURE, "e**x/2"),
]


@pytest.mark.parametrize(
    ("answer", "reference", "symbols", "reading"), UNCHANGED, ids=[c[0] for c in UNCHANGED]
)
def test_an_exponent_set_apart_or_not_a_roots_is_no_ambiguity(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], reading: str
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert verdict.read_as is not None, verdict.feedback
    assert (verdict.read_as.text, verdict.read_as.note) == (reading, None)


def test_the_refusal_of_an_exponent_names_both_readings_at_its_caret() -> None:
    verdict = run_job(SymbolicJob("e^2x", "exp(2*x)", PURE))
    assert verdict.error is not None
    assert verdict.error.position == 1
    assert verdict.feedback.startswith("Did you mean e^2·x or e^(2·x)? Add parentheses.")


ATWOOD = (SymbolDecl("m1", "kg"), SymbolDecl("m2", "kg"), SymbolDecl("g", "m/s^2"))
UNBRACKETED_SUMS = [
    # (answer, reference, symbols, the reading asked about): as typed the answer adds unlike quantities
    # and was graded wrong_dimension, an attempt used for a missing bracket
    ("mg/m+M", "m*g/(m + M)", PENDULUM, "m·g/(m + M)"),
    ("mg / m+M", "m*g/(m + M)", PENDULUM, "m·g/(m + M)"),
    ("m g/m + M", "m*g/(m + M)", PENDULUM, "m·g/(m + M)"),  # spaced as most type it
    ("m g / m + M", "m*g/(m + M)", PENDULUM, "m·g/(m + M)"),
    ("2 m g/m + M", "2*m*g/(m + M)", PENDULUM, "2·m·g/(m + M)"),
    ("g(m2-m1)/m1+m2", "g*(m2 - m1)/(m1 + m2)", ATWOOD, "g·(m2 - m1)/(m1 + m2)"),
    ("m+M/m", "(m + M)/m", PENDULUM, "(m + M)/m"),
    ("m + 2(M)/m", "(m + 2*M)/m", PENDULUM, "(m + 2·M)/m"),  # a bracket that is not all the numerator
]


@pytest.mark.parametrize(
    ("answer", "reference", "symbols", "meant"), UNBRACKETED_SUMS, ids=[c[0] for c in UNBRACKETED_SUMS]
)
def test_a_sum_whose_brackets_are_left_out_beside_a_division_is_asked_about(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], meant: str
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is Reason.AMBIGUOUS
    assert verdict.error is not None
    assert verdict.error.position == answer.index("/")
    assert verdict.error.message.startswith(f"Did you mean {meant}? As typed,")
    assert "put the sum in brackets" in verdict.error.message


KEPT_AS_TYPED = [
    # (answer, reference, symbols, reason): a sum that adds like quantities, or whose bracketing does not
    # have the dimension either, is graded as typed
    ("mg/m+g", "m*g/(m + M)", PENDULUM, Reason.WRONG_VALUE),
    ("mg/m+M g", "m*g/(m + M)", PENDULUM, Reason.WRONG_DIMENSION),
    # a bracket around the divisor or the whole numerator says where it ends: read as typed, not asked
    ("m g/(m) + M", "m*g/(m + M)", PENDULUM, Reason.WRONG_DIMENSION),
    ("m g/(m)+M", "m*g/(m + M)", PENDULUM, Reason.WRONG_DIMENSION),
    ("(m g/(m) + M)", "m*g/(m + M)", PENDULUM, Reason.WRONG_DIMENSION),
    ("M + (m g)/m", "m*g/(m + M)", PENDULUM, Reason.WRONG_DIMENSION),
    ("m + (M)/m", "(m + M)/m", PENDULUM, Reason.WRONG_DIMENSION),
]


@pytest.mark.parametrize(
    ("answer", "reference", "symbols", "reason"), KEPT_AS_TYPED, ids=[c[0] for c in KEPT_AS_TYPED]
)
def test_a_sum_beside_a_division_is_graded_as_typed_where_brackets_would_not_fit(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], reason: Reason
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert verdict.outcome is Outcome.INCORRECT
    assert verdict.reason is reason


def test_preview_asks_about_a_sum_whose_brackets_are_left_out_before_submission() -> None:
    shown = preview(SymbolicJob("mg/m+M", "m*g/(m + M)", PENDULUM))
    assert shown.read_as is None
    assert shown.error is not None
    assert shown.error.position == 2
    assert shown.error.message.startswith("Did you mean m·g/(m + M)?")


CHARGED = (SymbolDecl("e", "C"), SymbolDecl("V0", "V"), SymbolDecl("t", "s"), SymbolDecl("tau", "s"))
RESTITUTION = (SymbolDecl("e", "1"), SymbolDecl("h", "m"), SymbolDecl("t", "s"), SymbolDecl("tau", "s"))


@pytest.mark.parametrize("answer", ["V0 e^(-t/τ)", "V0/e^(t/τ)", "V0 e**(-t/tau)"])
def test_a_power_of_a_declared_charge_e_is_refused_saying_how_to_write_eulers_number(answer: str) -> None:
    # it was graded wrong_dimension: "raises an electric charge to a power that is not a fixed number"
    verdict = run_job(SymbolicJob(answer, "V0*exp(-t/tau)", CHARGED))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.error is not None
    assert verdict.error.position == answer.index("e")
    assert verdict.error.message.startswith("Here e is the problem's symbol e, an electric charge")
    assert "for Euler's number write exp(…)" in verdict.error.message


def test_a_power_of_a_dimensionless_declared_e_is_graded_as_typed() -> None:
    verdict = run_job(SymbolicJob("h e^(-t/τ)", "h*exp(-t/tau)", RESTITUTION))
    assert verdict.outcome is Outcome.INCORRECT  # e^(−t/τ) of a coefficient of restitution: an answer


def test_preview_asks_about_a_power_of_a_declared_charge_e() -> None:
    shown = preview(SymbolicJob("V0 e^(-t/τ)", "V0*exp(-t/tau)", CHARGED))
    assert shown.read_as is None
    assert shown.error is not None and shown.error.message.startswith("Here e is the problem's symbol e")


ORBIT = (SymbolDecl("G", "m^3/(kg*s^2)"), SymbolDecl("M", "kg"), SymbolDecl("R", "m"), SymbolDecl("h", "m"))
FRACTION_EXPONENTS = [
    # (answer, reference, symbols, the reading asked about): as typed the fraction divides the power, which
    # has no dimension the answer could have, and was graded wrong_dimension, an attempt used for a bracket
    ("2π(R+h)^3/2/√(GM)", "2*pi*sqrt((R + h)^3/(G*M))", ORBIT, "2·pi·(R + h)^(3/2)/sqrt(G·M)"),
    ("2*pi*(R+h)**3/2/sqrt(G*M)", "2*pi*sqrt((R + h)^3/(G*M))", ORBIT, "2·pi·(R + h)^(3/2)/sqrt(G·M)"),
    ("2π/((G M)^(1/2) (R+h)^-3/2)", "2*pi*sqrt((R + h)^3/(G*M))", ORBIT, "2·pi/((G·M)^(1/2)·(R + h)^(-3/2))"),
]


@pytest.mark.parametrize(
    ("answer", "reference", "symbols", "meant"), FRACTION_EXPONENTS, ids=[c[0] for c in FRACTION_EXPONENTS]
)
def test_an_exponents_fraction_typed_without_brackets_is_asked_about_where_only_it_fits(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], meant: str
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert (verdict.outcome, verdict.reason) == (Outcome.INVALID, Reason.AMBIGUOUS)
    assert verdict.error is not None
    assert verdict.error.message.startswith(f"Did you mean {meant}? As typed,")
    assert "write the exponent in brackets" in verdict.error.message
    assert preview(SymbolicJob(answer, reference, symbols)).error == verdict.error


@pytest.mark.parametrize(
    ("answer", "reference", "reason"),
    [
        ("2m R^2/5", "2*m*R^2/5", Reason.EQUIVALENT),  # the fraction outside has the dimension: as typed
        ("2m R^2/5", "2*m*R^2/3", Reason.CONSTANT_FACTOR),
        ("2π(R+h)^3/2/(G M)", "2*pi*sqrt((R + h)^3/(G*M))", Reason.WRONG_DIMENSION),  # neither fits
    ],
)
def test_an_exponents_fraction_is_graded_as_typed_where_the_bracketed_exponent_does_not_fit(
    answer: str, reference: str, reason: Reason
) -> None:
    symbols = (*ORBIT, SymbolDecl("m", "kg"))
    assert run_job(SymbolicJob(answer, reference, symbols)).reason is reason
