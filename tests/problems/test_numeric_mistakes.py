"""Numeric parts `of` a symbolic part recognise that part's known mistakes by their values at the
student's given values, within the part's tolerance."""

from __future__ import annotations

import copy
import pickle
from functools import cache
from typing import Any

import pytest

from physics.checking import run_job
from physics.verdict import Outcome, Reason
from problems.compiled import CompiledNumericPart, CompiledProblem, compile_problem
from problems.kinds.numeric import Evaluated
from problems.loader import parse_problem
from problems.selftest import verify_problem
from problems.variants import fixed_variant
from tests.bank import bank_documents
from tests.problems.documents import stated_value

AT_REST = "That is the period in a lift at rest: gravity is effectively g + A."
SAID_AGAIN = "The lift at rest, said a second time."
SWAPPED = "A sine and a cosine are swapped."

_LIFT: dict[str, Any] = {
    "id": "lift-cone-typed",
    "title": "A conical pendulum in an accelerating lift",
    "statement": "Here $L$ = {L}, $\\alpha$ = {alpha}, $A$ = {A}, $g$ = {g}.",
    "symbols": {
        "m": {"meaning": "mass of the bob", "dimension": "kg"},
        "L": {"meaning": "length of the string", "dimension": "m"},
        "alpha": {"meaning": "angle of the string", "dimension": "1", "range": [0, "pi/2"]},
        "A": {"meaning": "upward acceleration of the lift", "dimension": "m/s^2"},
        "g": {"meaning": "acceleration due to gravity", "dimension": "m/s^2"},
    },
    "given": {
        "m": {"min": 0.10, "max": 1.0, "unit": "kg", "sigfigs": 2},
        "L": {"min": 0.50, "max": 1.5, "unit": "m", "sigfigs": 2},
        "alpha": {"min": 20, "max": 40, "unit": "deg", "sigfigs": 3},
        "A": {"min": 1.0, "max": 3.0, "unit": "m/s^2", "sigfigs": 2},
        "g": {"min": 9.81, "max": 9.81, "unit": "m/s^2"},
    },
    "parts": [
        {
            "id": "period",
            "kind": "symbolic",
            "prompt": "Find the period.",
            "answer": "2*pi*sqrt(L*cos(alpha)/(g + A))",
            "symbols": ["L", "alpha", "A", "g"],
            "mistakes": [
                {"answer": "2*pi*sqrt(L*cos(alpha)/g)", "feedback": AT_REST},
                {"answer": "2*pi*sqrt(L*sin(alpha)/(g + A))", "feedback": SWAPPED},
                {"answer": "2*pi*sqrt(L/g)*sqrt(cos(alpha))", "feedback": SAID_AGAIN},
            ],
        },
        {
            "id": "tension",
            "kind": "symbolic",
            "prompt": "Find the tension.",
            "answer": "m*(g + A)/cos(alpha)",
            "symbols": ["m", "alpha", "A", "g"],
        },
        {"id": "period_numeric", "kind": "numeric", "prompt": "The period?", "of": "period", "units": "s"},
        {"id": "tension_numeric", "kind": "numeric", "prompt": "The tension?", "of": "tension", "units": "N"},
    ],
}

# L = 1.0 m, A = 2.0 m/s², g = 9.81 m/s²: the right period at α = 30° is 1.7015 s, the lift at rest's
# 1.8669 s, the swapped sine's 1.2928 s; at α = 44.5° the swapped sine gives 1.5307 s against the
# right 1.5441 s, 0.9 % apart, which a 1 % tolerance cannot tell apart.
AT = {"L": "1.0", "A": "2.0", "m": "0.50"}


def lift() -> dict[str, Any]:
    return copy.deepcopy(_LIFT)


@cache
def compiled() -> CompiledProblem:
    return compile_problem(parse_problem(lift()), use_model=False)


def graded(problem: CompiledProblem, part: str, answer: str, values: dict[str, str]) -> Any:
    """Graded as a worker grades it: the part's job, pickled across."""
    variant = fixed_variant(problem.document, values)
    return run_job(pickle.loads(pickle.dumps(problem.job(part, answer, variant))))


GRADING = [
    pytest.param("30", "1.70 s", Outcome.CORRECT, Reason.EQUIVALENT, "Correct", id="right-value"),
    pytest.param("30", "1.87 s", Outcome.INCORRECT, Reason.KNOWN_MISTAKE, AT_REST, id="declared-mistake"),
    pytest.param("30", "1867 ms", Outcome.INCORRECT, Reason.KNOWN_MISTAKE, AT_REST, id="mistake-in-ms"),
    pytest.param("30", "1.29 s", Outcome.INCORRECT, Reason.KNOWN_MISTAKE, SWAPPED, id="second-mistake"),
    pytest.param(
        "30",
        "1.87 m",
        Outcome.INCORRECT,
        Reason.WRONG_DIMENSION,
        "a time is expected",
        id="units-message-wins",
    ),
    pytest.param("30", "1.87", Outcome.INVALID, Reason.MISSING_UNITS, "needs units", id="missing-units-wins"),
    pytest.param("30", "3.40 s", Outcome.INCORRECT, Reason.CONSTANT_FACTOR, "factor", id="slips-still-found"),
    pytest.param(
        "44.5",
        "1.521 s",  # 1.5 % below the right value, 0.6 % below the swapped sine's
        Outcome.INCORRECT,
        Reason.WRONG_VALUE,
        "not within the accepted tolerance",
        id="mistake-within-tolerance-of-right-is-not-named",
    ),
]


@pytest.mark.parametrize(("alpha", "answer", "outcome", "reason", "feedback"), GRADING)
def test_numeric_answer_at_a_mistakes_value_is_that_mistake(
    alpha: str, answer: str, outcome: Outcome, reason: Reason, feedback: str
) -> None:
    verdict = graded(compiled(), "period_numeric", answer, {**AT, "alpha": alpha})
    assert (verdict.outcome, verdict.reason) == (outcome, reason), verdict.feedback
    assert feedback in verdict.feedback


def test_when_two_mistakes_match_the_first_declared_wins() -> None:
    verdict = graded(compiled(), "period_numeric", "1.87 s", {**AT, "alpha": "30"})
    assert verdict.feedback == AT_REST and SAID_AGAIN not in verdict.feedback


def test_numeric_part_carries_the_symbolic_parts_mistakes_in_their_order() -> None:
    part = compiled().part("period_numeric")
    assert isinstance(part, CompiledNumericPart) and isinstance(part.value, Evaluated)
    assert [m.feedback for m in part.value.mistakes] == [AT_REST, SWAPPED, SAID_AGAIN]


@pytest.mark.parametrize(
    ("alpha", "named"),
    [
        pytest.param("30", [AT_REST, SWAPPED, SAID_AGAIN], id="all-apart-from-the-right-value"),
        pytest.param("45", [AT_REST, SAID_AGAIN], id="equal-to-the-right-value-skipped"),
        pytest.param("44.5", [AT_REST, SAID_AGAIN], id="within-tolerance-of-the-right-value-skipped"),
    ],
)
def test_a_mistake_the_tolerance_takes_for_the_right_value_is_left_out(alpha: str, named: list[str]) -> None:
    part = compiled().part("period_numeric")
    assert isinstance(part, CompiledNumericPart)
    spec = part.spec(fixed_variant(compiled().document, {**AT, "alpha": alpha}))
    assert [m.feedback for m in spec.mistakes] == named


def test_a_mistake_of_another_dimension_is_not_carried() -> None:
    data = lift()
    data["parts"][0]["mistakes"].append({"answer": "L*cos(alpha)", "feedback": "That is a length."})
    part = compile_problem(parse_problem(data), use_model=False).part("period_numeric")
    assert isinstance(part, CompiledNumericPart) and isinstance(part.value, Evaluated)
    assert [m.feedback for m in part.value.mistakes] == [AT_REST, SWAPPED, SAID_AGAIN]


@pytest.mark.parametrize(
    ("problem", "part"),
    [
        pytest.param(compiled, "tension_numeric", id="of-a-symbolic-part-without-mistakes"),
        pytest.param(
            lambda: compile_problem(parse_problem(stated_value()), use_model=False),
            "a_value",
            id="stated-value",
        ),
    ],
)
def test_numeric_parts_without_mistakes_have_none_to_name(problem: Any, part: str) -> None:
    compiled_part = problem().part(part)
    assert isinstance(compiled_part, CompiledNumericPart)
    assert compiled_part.spec(fixed_variant(problem().document, AT)).mistakes == ()


def test_self_test_grades_each_numeric_mistake_as_that_mistake() -> None:
    data = lift()
    del data["parts"][0]["mistakes"][2]  # the symbolic self-test wants each mistake's own feedback
    report = verify_problem(parse_problem(data), variants=3, use_model=False)
    assert report.ok, report.summary()
    checks = [r.check for r in report.problems[0].results if r.part == "period_numeric"]
    assert {"variant 0 mistake 1", "variant 2 mistake 2"} <= set(checks)


# The built-in bank's declared mistakes, now named in its numeric parts: m = 0.50 kg, L = 0.80 m and
# ω = 6.0 rad/s give a tension of 14.4 N (m g = 4.905 N) and cos θ = 0.3406 (ω²L/g = 2.936).
BANK = [
    pytest.param("tension_numeric", "4.91 N", "balances the weight", id="conical-pendulum-tension"),
    pytest.param("cone_cosine_numeric", "2.94", "The radius of the circle is", id="conical-pendulum-cosine"),
]


@pytest.mark.parametrize(("part", "answer", "feedback"), BANK)
def test_bank_numeric_part_names_its_symbolic_parts_declared_mistake(
    part: str, answer: str, feedback: str
) -> None:
    problem = compile_problem(bank_documents()["conical-pendulum"], use_model=False)
    verdict = graded(problem, part, answer, {"m": "0.50", "L": "0.80", "omega": "6.0"})
    assert (verdict.outcome, verdict.reason) == (Outcome.INCORRECT, Reason.KNOWN_MISTAKE), verdict.feedback
    assert feedback in verdict.feedback


def test_a_numeric_part_of_a_model_quantity_names_the_engines_mistakes() -> None:
    # No symbolic part asks for the common velocity: its mistakes are the engine's. m1 = 1.0 kg,
    # m2 = 2.0 kg, u = 3.0 m/s: the common velocity is 1.0 m/s, and 2.0 m/s with the masses swapped.
    problem = compile_problem(bank_documents()["collision-scenarios"])
    values = {"m1": "1.0", "m2": "2.0", "u": "3.0"}
    verdict = graded(problem, "common_velocity_numeric", "2.0 m/s", values)
    assert (verdict.outcome, verdict.reason) == (Outcome.INCORRECT, Reason.KNOWN_MISTAKE), verdict.feedback
    assert "masses are swapped" in verdict.feedback
    assert graded(problem, "common_velocity_numeric", "1.0 m/s", values).outcome is Outcome.CORRECT
