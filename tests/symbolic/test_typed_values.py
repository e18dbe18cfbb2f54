"""Values typed where a symbol is meant are graded as typed, and the feedback says which symbol would
make the answer right: a decimal for π (off by a constant factor), for e (a wrong value), 9.8 for a
declared g (a wrong dimension), 90 for 90° (a wrong value). Units after a symbolic answer, of the dimension the answer must have, are refused with
the advice to leave them out."""

from __future__ import annotations

import pytest

from physics.checking import SymbolDecl, run_job
from physics.symbolic.judge import FACTOR_FEEDBACK
from physics.verdict import Outcome, Reason
from problems.kinds.symbolic import SymbolicJob

PENDULUM = (SymbolDecl("L", "m"), SymbolDecl("g", "m/s^2"))
PERIOD = "2*pi*sqrt(L/g)"
SLOPE = (SymbolDecl("m", "kg"), SymbolDecl("g", "m/s^2"), SymbolDecl("theta", "1", range=("0", "pi/2")))
WEIGHT_ALONG = "m*g*sin(theta)"
DRAG = (SymbolDecl("v0", "m/s"), SymbolDecl("b", "kg/s"), SymbolDecl("t", "s"), SymbolDecl("m", "kg"))
SLOWING = "v0*exp(-b*t/m)"

HINTED = [
    # (answer, reference, symbols, reason, the hint's swaps, or None: no hint)
    ("2*3.14*sqrt(L/g)", PERIOD, PENDULUM, Reason.CONSTANT_FACTOR, "π for 3.14"),
    ("2·3.1416·√(L/g)", PERIOD, PENDULUM, Reason.CONSTANT_FACTOR, "π for 3.1416"),
    ("6.28 sqrt(L/g)", PERIOD, PENDULUM, Reason.CONSTANT_FACTOR, "2π for 6.28"),
    ("4*1.571*sqrt(L/g)", PERIOD, PENDULUM, Reason.CONSTANT_FACTOR, "π/2 for 1.571"),
    ("3.14 sqrt(L/g)", PERIOD, PENDULUM, Reason.CONSTANT_FACTOR, None),  # the 2 is missing too
    ("2*3.1*sqrt(L/g)", PERIOD, PENDULUM, Reason.CONSTANT_FACTOR, None),  # too few digits for π
    ("6 sqrt(L/g)", PERIOD, PENDULUM, Reason.CONSTANT_FACTOR, None),
    ("9.8 m sin θ", WEIGHT_ALONG, SLOPE, Reason.WRONG_DIMENSION, "g for 9.8"),
    ("9.81*m*sin(theta)", WEIGHT_ALONG, SLOPE, Reason.WRONG_DIMENSION, "g for 9.81"),
    ("2π sqrt(L/9.8)", PERIOD, PENDULUM, Reason.WRONG_DIMENSION, "g for 9.8"),
    ("2*9.8 m sin θ", WEIGHT_ALONG, SLOPE, Reason.WRONG_DIMENSION, None),  # wrong with g too
    ("9.8 sin θ", WEIGHT_ALONG, SLOPE, Reason.WRONG_DIMENSION, None),
    ("v0 * 2.718^(-b t/m)", SLOWING, DRAG, Reason.WRONG_VALUE, "e for 2.718"),
    ("v0 2.72^(-b t/m)", SLOWING, DRAG, Reason.WRONG_VALUE, "e for 2.72"),
    ("v0 2.7^(-b t/m)", SLOWING, DRAG, Reason.WRONG_VALUE, None),  # too few digits for e
    ("v0 2.718^(-2 b t/m)", SLOWING, DRAG, Reason.WRONG_VALUE, None),  # wrong with e too
]
ADVICE = {
    Reason.WRONG_DIMENSION: ("Your expression has the dimension of", "write the symbol g, not its value"),
    Reason.WRONG_VALUE: ("Your answer is not equivalent", "write e^(…) or exp(…) where you mean e"),
}


@pytest.mark.parametrize(
    ("answer", "reference", "symbols", "reason", "swaps"), HINTED, ids=[c[0] for c in HINTED]
)
def test_a_value_typed_for_a_symbol_is_named_when_the_symbol_would_make_it_right(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], reason: Reason, swaps: str | None
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert verdict.outcome is Outcome.INCORRECT  # graded as typed: a decimal is exact
    assert verdict.reason is reason
    hint = f"Your answer would be right with {swaps}: "
    if swaps is None:
        assert "would be right with" not in verdict.feedback
        if reason is Reason.CONSTANT_FACTOR:
            assert verdict.feedback == FACTOR_FEEDBACK
    elif reason is Reason.CONSTANT_FACTOR:
        assert verdict.feedback.startswith(hint)  # in place of the bare "off by a constant factor"
        assert "write pi (or π)" in verdict.feedback
    else:
        start, advice = ADVICE[reason]
        assert verdict.feedback.startswith(start)  # then the hint
        assert hint in verdict.feedback and advice in verdict.feedback


HALF_LIFE = (SymbolDecl("m", "kg"), SymbolDecl("b", "kg/s"))
NAMED_NUMBERS = [
    # (answer, reference, symbols, the hint's swaps and advice, or None): a calculator's decimal for ln 2
    # or √2, once "off by a constant factor" alone
    (
        "0.693 m/b",
        "m*log(2)/b",
        HALF_LIFE,
        "ln 2 for 0.693: a decimal is taken as exactly the number it shows, so write ln(2).",
    ),
    (
        "1.414 sqrt(g L)",
        "sqrt(2*g*L)",
        PENDULUM,
        "√2 for 1.414: a decimal is taken as exactly the number it shows, so write sqrt(2).",
    ),
    (
        "6.28*1.414 sqrt(L/g)",
        "2*pi*sqrt(2*L/g)",
        PENDULUM,
        "2π for 6.28, √2 for 1.414: a decimal is taken as exactly the number it shows, so write sqrt(2) and pi (or π) where you mean π.",
    ),
    ("0.69 m/b", "m*log(2)/b", HALF_LIFE, None),  # too few digits to stand for ln 2
    # a fraction of small whole numbers, rounded: a rolling ball's 5/7 g sin θ
    (
        "0.714 g sin(theta)",
        "5*g*sin(theta)/7",
        SLOPE,
        "5/7 for 0.714: a decimal is taken as exactly the number it shows, so write 5/7.",
    ),
    (
        "0.333 m g",
        "m*g/3",
        SLOPE,
        "1/3 for 0.333: a decimal is taken as exactly the number it shows, so write 1/3.",
    ),
    ("0.333 m g", "m*g/2", SLOPE, None),  # a third is not what makes it right
    ("0.71 g sin(theta)", "5*g*sin(theta)/7", SLOPE, None),  # too few digits to stand for 5/7
]


@pytest.mark.parametrize(
    ("answer", "reference", "symbols", "hint"), NAMED_NUMBERS, ids=[c[0] for c in NAMED_NUMBERS]
)
def test_a_decimal_for_ln_2_a_root_or_a_fraction_is_named_when_it_would_make_the_answer_right(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], hint: str | None
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert verdict.reason is Reason.CONSTANT_FACTOR
    if hint is None:
        assert verdict.feedback == FACTOR_FEEDBACK
    else:
        assert verdict.feedback == f"Your answer would be right with {hint}"


IN_DEGREES = [
    # (answer, the hint's swaps, or None): an angle typed in degrees without its sign is 90 rad as typed
    ("m g cos(90 - θ)", "90° for 90"),
    ("m g cos(90-θ)", "90° for 90"),
    ("-m g sin(180 + θ)", "180° for 180"),
    ("m g cos(90 + θ)", None),  # wrong with the degree sign too
]


@pytest.mark.parametrize(("answer", "swaps"), IN_DEGREES, ids=[c[0] for c in IN_DEGREES])
def test_an_angle_typed_in_degrees_without_its_sign_is_named_when_the_sign_would_make_it_right(
    answer: str, swaps: str | None
) -> None:
    verdict = run_job(SymbolicJob(answer, WEIGHT_ALONG, SLOPE))
    assert verdict.outcome is Outcome.INCORRECT  # graded as typed: 90 is 90 radians
    assert verdict.reason is Reason.WRONG_VALUE
    if swaps is None:
        assert "would be right with" not in verdict.feedback
    else:
        assert f"Your answer would be right with {swaps}: an angle is in radians unless it has a" in (
            verdict.feedback
        )


def test_the_symbols_themselves_are_correct() -> None:
    assert run_job(SymbolicJob("2π√(L/g)", PERIOD, PENDULUM)).outcome is Outcome.CORRECT
    assert run_job(SymbolicJob("m g sin θ", WEIGHT_ALONG, SLOPE)).outcome is Outcome.CORRECT


UNITS = [
    # (answer, the units the refusal says to leave out, or None: no such advice)
    ("m g sin θ N", "N"),
    ("m*g*sin(theta) newtons", "newtons"),
    ("m g sin θ kg m/s^2", "kg m/s^2"),
    ("m g sin θ (N)", "(N)"),  # in brackets, as a table's heading gives them
    ("m g sin θ (kg m/s^2)", "(kg m/s^2)"),
    ("m g sin θ T", None),  # a tesla is no force: a T may be a tension
    ("m g sin θ J", None),  # an energy
]


@pytest.mark.parametrize(("answer", "units"), UNITS, ids=[c[0] for c in UNITS])
def test_units_after_a_symbolic_answer_are_refused_with_the_advice_to_leave_them_out(
    answer: str, units: str | None
) -> None:
    verdict = run_job(SymbolicJob(answer, WEIGHT_ALONG, SLOPE))
    assert verdict.outcome is Outcome.INVALID  # no attempt used
    assert verdict.reason is Reason.UNKNOWN_SYMBOL
    advice = "A symbolic answer is written without units: leave out"
    if units is None:
        assert advice not in verdict.feedback
    else:
        assert f"{advice} {units}." in verdict.feedback


LATEX_UNITS = [
    # (answer, the refusal's message): units in a LaTeX font command, once "\mathrm{…} may only hold a name"
    (
        r"mg\sin\theta\,\mathrm{kg\,m/s^2}",
        r"A symbolic answer is written without units: leave out \mathrm{kg\,m/s^2}.",
    ),
    (
        r"mg\sin\theta\ \text{kg m/s^2}",
        r"A symbolic answer is written without units: leave out \text{kg m/s^2}.",
    ),
    (r"mg\sin\theta\ \mathrm{J/m^2}", r"\mathrm{…} may only hold a name here"),  # no force: as before
]


@pytest.mark.parametrize(("answer", "message"), LATEX_UNITS, ids=[c[0] for c in LATEX_UNITS])
def test_latex_units_after_a_symbolic_answer_are_refused_with_the_advice_to_leave_them_out(
    answer: str, message: str
) -> None:
    verdict = run_job(SymbolicJob(answer, WEIGHT_ALONG, SLOPE))
    assert verdict.outcome is Outcome.INVALID  # no attempt used
    assert verdict.reason is Reason.PARSE_ERROR
    assert verdict.error is not None
    assert message in verdict.error.message
