"""Equation parts, tried as students would: the asked equation written any way people write it (sides
swapped, terms moved, multiplied through) is accepted; a force missing or extra, a sign, the wrong
component, a true equation that is not the one asked are refused, each said. Hand-written tables over
four equations, ad hoc (`POST /v1/check` bodies), and the bank's wedge and yo-yo, whose models give the
unknowns' values."""

from __future__ import annotations

from functools import cache

import pytest
from pydantic import TypeAdapter

from physics.checking import preview, run_job
from physics.verdict import Outcome, Reason, Verdict
from problems.compiled import compile_problem
from problems.kinds import CheckIn
from tests.bank import bank_documents

_KG = {"dimension": "kg"}
EQUATIONS = {
    # Newton's second law along a rough incline, down the slope positive
    "incline": {
        "expected": "m*a = m*g*sin(theta) - mu*N",
        "unknowns": {"a": "the block's acceleration down the slope", "N": "the normal force on the block"},
        "symbols": {"m": _KG, "g": {"dimension": "m/s^2"}, "mu": {}, "theta": {"range": ["0", "pi/2"]}},
    },
    # across the same incline: nothing accelerates
    "normal": {
        "expected": "N = m*g*cos(theta)",
        "unknowns": {"N": "the normal force on the block"},
        "symbols": {"m": _KG, "g": {"dimension": "m/s^2"}, "theta": {"range": ["0", "pi/2"]}},
    },
    # the hanging mass of an Atwood machine, down positive
    "atwood": {
        "expected": "m2*a = m2*g - T",
        "unknowns": {"a": "the acceleration of m2, downwards", "T": "the tension in the string"},
        "symbols": {"m1": _KG, "m2": _KG, "g": {"dimension": "m/s^2"}},
    },
    # rolling without slipping (v = ω R) and energy conserved from rest through a drop h
    "energy": {
        "expected": "m*g*h = 1/2*m*v^2 + 1/2*I*w^2",
        "unknowns": {"v": "the speed of the centre", "w": "the angular speed"},
        "symbols": {
            "m": _KG,
            "g": {"dimension": "m/s^2"},
            "h": {"dimension": "m"},
            "I": {"dimension": "kg*m^2"},
        },
    },
}


def check(equation: str, answer: str) -> Verdict:
    return run_job(
        TypeAdapter(CheckIn)
        .validate_python({"kind": "equation", "answer": answer, **EQUATIONS[equation]})
        .job()
    )


RIGHT = [
    ("incline", "m a = m g sin θ - μ N"),
    ("incline", "m*a = m*g*sin(theta) - mu*N"),
    ("incline", "m g sin θ - μ N = m a"),
    ("incline", "m a + μ N = m g sin θ"),
    ("incline", "m a + μ N - m g sin θ = 0"),
    ("incline", "0 = m g sin θ - μ N - m a"),
    ("incline", "a = g sin θ - μ N/m"),
    ("incline", "2 m a = 2 m g sin θ - 2 μ N"),
    ("incline", r"ma = mg\sin\theta - \mu N"),
    ("incline", "m a = m g sin(θ) - mu N"),
    ("incline", "-m a = μ N - m g sin θ"),
    ("incline", "m (a - g sin θ) = -μ N"),
    ("normal", "N = m g cos θ"),
    ("normal", "m g cos θ = N"),
    ("normal", "N - m g cos θ = 0"),
    ("normal", "N/m = g cos θ"),
    ("normal", r"N = mg\cos\theta"),
    ("normal", "N = m g cos(θ)"),
    ("atwood", "m2 a = m2 g - T"),
    ("atwood", "T = m2 g - m2 a"),
    ("atwood", "T = m2 (g - a)"),
    ("atwood", "m2 g - T = m2 a"),
    ("atwood", "m_2 a = m_2 g - T"),
    ("atwood", "a = g - T/m2"),
    ("atwood", "T + m2 a - m2 g = 0"),
    ("energy", "m g h = 1/2 m v^2 + 1/2 I w^2"),
    ("energy", "1/2 m v^2 + 1/2 I w^2 = m g h"),
    ("energy", "2 m g h = m v^2 + I w^2"),
    ("energy", "m g h - 1/2 m v^2 - 1/2 I w^2 = 0"),
    ("energy", r"mgh = \frac{1}{2}mv^2 + \frac{1}{2}I\omega^2".replace(r"\omega", "w")),
    ("energy", "g h = v^2/2 + I w^2/(2 m)"),
    ("energy", "m g h = (m v^2 + I w^2)/2"),
]

WRONG = [
    ("incline", "m a = m g sin θ", "missing"),  # friction left out
    ("incline", "m a = m g sin θ + μ N", "sign"),
    ("incline", "m a = m g cos θ - μ N", "component"),
    ("incline", "m a = m g sin θ - μ N + N", "does not belong"),  # an extra force
    ("incline", "m a = m g sin θ - μ N - m g", "does not belong"),
    ("incline", "m a = -μ N", "missing"),
    ("incline", "m a = m g - μ N", None),
    ("incline", "m a = m g sin θ - N", None),
    ("incline", "a = g sin θ - μ N", None),
    ("incline", "m a = m g sin θ - μ m g", None),
    ("incline", "m g sin θ = μ N", None),
    ("incline", "m a = m g sin θ μ N", None),
    ("normal", "N = m g", None),
    ("normal", "N = m g sin θ", "component"),
    ("normal", "N = -m g cos θ", "sign"),
    ("normal", "N = m g cos θ + m g sin θ", "does not belong"),
    ("normal", "N = 0", None),
    ("normal", "N + m g cos θ = 0", "sign"),
    ("atwood", "m2 a = m2 g + T", "sign"),
    ("atwood", "m2 a = m2 g", "missing"),
    ("atwood", "m2 a = T", "missing"),
    ("atwood", "(m1 + m2) a = m2 g - T", None),
    ("atwood", "m2 a = m2 g - T - m1 g", "does not belong"),
    ("atwood", "m1 a = m1 g - T", None),
    ("atwood", "T = m2 g", None),
    ("atwood", "m2 a = m1 g - T", None),
    ("energy", "m g h = 1/2 m v^2", "missing"),
    ("energy", "m g h = 1/2 I w^2", "missing"),
    ("energy", "m g h = m v^2 + I w^2", None),
    ("energy", "m g h = 1/2 m v^2 - 1/2 I w^2", "sign"),
    ("energy", "g h = 1/2 v^2 + 1/2 I w^2", None),
    ("energy", "m g h = 1/2 m v + 1/2 I w^2", None),
]


def test_each_table_has_thirty_right_and_thirty_wrong_equations() -> None:
    assert len(RIGHT) >= 30 and len(WRONG) >= 30


@pytest.mark.parametrize(("equation", "answer"), RIGHT)
def test_the_asked_equation_written_any_way_is_accepted(equation: str, answer: str) -> None:
    verdict = check(equation, answer)
    assert verdict.outcome is Outcome.CORRECT, verdict


@pytest.mark.parametrize(("equation", "answer", "said"), WRONG)
def test_a_wrong_equation_is_refused_with_what_differs(equation: str, answer: str, said: str | None) -> None:
    verdict = check(equation, answer)
    assert verdict.outcome is Outcome.INCORRECT, verdict
    if said is not None:
        assert said in verdict.feedback.lower(), verdict.feedback


@pytest.mark.parametrize(
    ("answer", "message"),
    [
        ("m a", "'='"),
        ("m a = m g = 0", "one '='"),
        ("= m g", "left side"),
        ("m a =", "right side"),
        ("m a = q", "q"),
    ],
)
def test_what_is_not_one_readable_equation_is_invalid(answer: str, message: str) -> None:
    verdict = check("incline", answer)
    assert verdict.outcome is Outcome.INVALID and message in verdict.feedback, verdict


def test_an_error_on_the_right_side_points_into_the_whole_answer() -> None:
    verdict = check("incline", "m a = m g sin θ - μ Q")
    assert verdict.error is not None and verdict.error.position == len("m a = m g sin θ - μ ")


def test_the_preview_reads_both_sides() -> None:
    body = TypeAdapter(CheckIn).validate_python(
        {"kind": "equation", "answer": "m a = m g", **EQUATIONS["incline"]}
    )
    read = preview(body.job())
    assert read.read_as is not None and read.read_as.text == "m*a = m*g"


@cache
def _compiled(problem: str):
    return compile_problem(bank_documents()[problem])


@pytest.mark.parametrize(
    ("part", "answer", "said"),
    [
        ("newton_vertical", "m k^2 a/r = T r", "holds, but it is not the one asked"),  # the rotation law
        ("rotation", "m a = m g - T", "holds, but it is not the one asked"),
        ("rotation", "m k^2 a = T r", "angular acceleration is $a/r$"),  # the author's mistake
        ("newton_vertical", "m a = m g + T", "sign"),
        # solved for the tension first, and its value written in: told to keep the unknown asked for
        ("newton_vertical", "m a = m g - m g k^2/(k^2 + r^2)", "$T$ (the tension in the string) replaced by"),
        ("rotation", "m k^2 a/r = m g k^2 r/(k^2 + r^2)", "$T$ (the tension in the string) replaced by"),
        ("newton_vertical", "m g r^2/(k^2 + r^2) = m g - T", "replaced by its value: write $a$ itself"),
        # a side's dimension, from the problem's symbols and the unknowns' values
        (
            "newton_vertical",
            "a = m g - T",
            "differ in dimension: the left is an acceleration, the right a force",
        ),
        (
            "newton_vertical",
            "m a = m g - T/m",
            "The right side of your equation adds an acceleration to a force",
        ),
    ],
)
def test_a_bank_equation_tells_a_true_equation_that_is_not_the_one_asked(
    part: str, answer: str, said: str
) -> None:
    verdict = run_job(_compiled("yo-yo-lagrangian").part(part).job(answer))
    assert verdict.outcome is Outcome.INCORRECT and said in verdict.feedback, verdict


@pytest.mark.slow
def test_the_wedge_part_refuses_the_fixed_incline_law_with_the_authors_words() -> None:
    part = _compiled("moving-wedge-lagrangian").part("newton_block_along_incline")
    verdict = run_job(part.job("m a = m g sin θ"))
    assert verdict.reason is Reason.KNOWN_MISTAKE and "fixed incline" in verdict.feedback
    other = run_job(part.job("N - m g cos θ = m A sin θ"))  # true: the block across the incline
    assert "not the one asked" in other.feedback
    assert run_job(part.job("m a + m A cos θ = m g sin θ")).outcome is Outcome.CORRECT


def test_an_asked_equation_without_an_unknown_is_refused_at_expected() -> None:
    from physics.errors import SpecError

    body = {**EQUATIONS["normal"], "expected": "m*g = 2*m*g/2"}
    with pytest.raises(SpecError) as caught:
        TypeAdapter(CheckIn).validate_python({"kind": "equation", "answer": "N = 0", **body}).job().question()
    assert caught.value.path[:1] == ("expected",)
