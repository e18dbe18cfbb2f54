"""Answers to the bank's problems typed as students of different habits type them (calculators, LaTeX,
Wolfram, phone keyboards, Word), each read as the student meant it or refused saying what to type."""

from __future__ import annotations

from functools import cache

import pytest

from physics.checking import check_answer
from physics.verdict import Outcome
from problems.compiled import CompiledProblem, compile_problem
from problems.errors import ProblemInvalid
from problems.variants import Variant, fixed_variant
from tests.bank import bank_documents

# The seed document's skier: 35°, μ = 0.13, so a = 4.58 m/s²; other problems take their midpoints.
VALUES = {"skier-friction": {"alpha": 35, "mu": "0.13"}}


@cache
def compiled(problem_id: str) -> CompiledProblem:
    """The hand-typed answers where they suffice (fast); the engine's where a part has only a derived one."""
    try:
        return compile_problem(bank_documents()[problem_id], use_model=False)
    except ProblemInvalid:
        return compile_problem(bank_documents()[problem_id])


def _variant(problem_id: str, part_id: str) -> Variant | None:
    if not part_id.endswith("_numeric"):
        return None
    return fixed_variant(bank_documents()[problem_id], VALUES.get(problem_id, {}))


CORRECT = [
    # (problem, part, typed): each read as the student meant it, and right
    ("moving-wedge", "wedge_acceleration", "-mg sinθ cosθ/(M+m sin²θ)"),
    ("moving-wedge", "wedge_acceleration", "−m·g·sin(θ)·cos(θ)/(M+m·sin(θ)^2)"),
    ("moving-wedge", "wedge_acceleration", "-(m g sin(2θ))/(2(M + m sin^2(θ)))"),
    ("moving-wedge", "wedge_acceleration", r"-\frac{mg\sin\theta\cos\theta}{M+m\sin^2\theta}"),
    ("moving-wedge", "normal_force", "M m g cos(θ) / (M + m sin(θ)²)"),
    ("moving-wedge", "block_relative_acceleration", "(M+m)g sinθ/(M+msin^2θ)"),
    ("yo-yo", "acceleration", "g/(1+(k/r)²)"),
    ("yo-yo", "tension", "mgk²/(r²+k²)"),
    ("simple-pendulum", "period", "2×π×√(L÷g)"),
    ("simple-pendulum", "period", "2π(L/g)^.5"),
    ("simple-pendulum", "period", "2πL^½g^-½"),
    ("simple-pendulum", "period", "2π sqrt[L/g]"),
    ("simple-pendulum", "period", "2 π √ (L/g)"),
    ("simple-pendulum", "period", "2πsqrt L/g"),  # settled by dimension
    ("simple-pendulum", "period", "2π√(L/g)\u200b"),  # a zero-width space copied from a page
    ("simple-pendulum", "angular_frequency", "(g/L)^1/2"),
    ("simple-pendulum", "tension_at_bottom", "m(g+v²/L)"),
    ("simple-pendulum", "tension_at_bottom", "m(g+vˆ2/L)"),  # a Mac's option-i circumflex for ^
    ("lennard-jones", "oscillation_frequency", "12 sqrt(U_0/m)/r_0"),
    ("lennard-jones", "spring_constant", "72U0/r0²"),
    ("lennard-jones", "equilibrium_separation", "r₀"),
    ("ballistic-pendulum", "bullet_speed", "((m+M)/m)√(2gL(1−cos θ))"),
    ("ballistic-pendulum", "bullet_speed", "(1+M/m)sqrt(2*g*L*(1-cos(theta)))"),
    ("mass-spring", "period", "2π√m/k"),  # settled by dimension
    ("rolling-incline", "acceleration_sphere", "5/7 g sin θ"),
    ("rolling-incline", "acceleration_hoop", "½ g sin θ"),
    ("conical-pendulum", "cone_angle", "cos^-1(g/(ω^2 L))"),
    ("skier-friction", "acceleration", "gsinα-μgcosα"),
    ("skier-friction", "acceleration", "g[sin α - μ cos α]"),
    ("skier-friction", "acceleration", r"g (\sin\alpha - \mu \cos\alpha)"),
    ("yo-yo-lagrangian", "kinetic_energy", "½m(1+k²/r²)ḋ²"),
    ("yo-yo-lagrangian", "kinetic_energy", "1/2 m d’^2 (1 + k^2/r^2)"),  # a phone's curly apostrophe
    ("yo-yo-lagrangian", "newton_vertical", "mg − T = m·a"),
    ("skier-friction", "acceleration_numeric", "9.81 × (sin 35° − 0.13 cos 35°) m/s²"),
    ("skier-friction", "acceleration_numeric", "4.58 m s⁻²"),
    ("skier-friction", "acceleration_numeric", "4.58 meters per second squared"),
    # a product of quantities typed with the `*` spaced, or after a power, is read as typed
    ("skier-friction", "acceleration_numeric", "2.29 m/s^2 * 2"),
    ("skier-friction", "acceleration_numeric", "2.29 m/s^2*2"),
]


@pytest.mark.parametrize(("problem_id", "part_id", "typed"), CORRECT, ids=[c[2] for c in CORRECT])
def test_a_students_answer_is_read_as_meant(problem_id: str, part_id: str, typed: str) -> None:
    variant = _variant(problem_id, part_id)
    verdict = check_answer(typed, compiled(problem_id).question(part_id, variant))
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback


REFUSED = [
    # (problem, part, typed, the refusal's words): each once read otherwise or refused unhelpfully
    ("simple-pendulum", "period", "T = 2π√(L/g)", "without 'T =': type only 2π√(L/g)."),
    # words, a left side, then the answer: was "without '=' (nor the name before it)"
    ("simple-pendulum", "period", "the period T = 2π√(L/g)", "without 'the period T =': type only 2π√(L/g)."),
    (
        "simple-pendulum",
        "period_numeric",
        "the period T = 2.01 s",
        "without 'the period T =': type only 2.01 s",
    ),
    ("yo-yo-lagrangian", "lagrangian", "L = 1/2 m(1+k²/r²)d'² + mgd", "without 'L =': type only 1/2 m"),
    ("skier-friction", "friction_coefficient", "μ = tan α", "without 'μ =': type only tan α."),
    ("simple-pendulum", "period_numeric", "T=2.01s", "Give the value alone, without 'T =': type only 2.01s"),
    (
        "simple-pendulum",
        "period",
        "2.π.√(L/g)",
        "Write a product with * or a space, not '.'",
    ),  # was "Unexpected"
    ("simple-pendulum", "period", "2π√(ℓ/g)", "did you mean L?"),  # `\ell`'s script l: was no hint
    ("skier-friction", "acceleration_numeric", "9.81*sind(35) m/s^2", "Did you mean sin(35°)?"),
    ("skier-friction", "acceleration", "g (sind(α) - μ cosd(α))", "Did you mean sin(α)?"),
    ("skier-friction", "acceleration_numeric", "4.58 10 -3 m/s^2", "Did you mean 4.58×10^-3?"),
    ("skier-friction", "acceleration", "3.0×10-3 g", "Did you mean 3.0×10^-3?"),  # was graded 3.0·10 − 3g
    # were graded as g·sin α·10 − 3 and 9.81·sin 35°·10 − 3
    ("skier-friction", "acceleration", "g sin α 10 -3", "Did you mean g sin α×10^-3?"),
    (
        "skier-friction",
        "acceleration_numeric",
        "9.81 sin 35° 10 -3 m/s^2",
        "Did you mean 9.81 sin 35°×10^-3?",
    ),
    # a positive power likewise: was told "for one number, write 103"
    ("skier-friction", "acceleration", "g sin α 10 3", "Did you mean g sin α×10^3?"),
    (
        "skier-friction",
        "acceleration_numeric",
        "9.81 sin 35° 10 3 m/s^2",
        "Did you mean 9.81 sin 35°×10^3?",
    ),
    ("skier-friction", "acceleration_numeric", "2 3^2 m/s^2", "2 3^2: two numbers side by side"),
    (
        "moving-wedge",
        "normal_force",
        "MmgCos(θ)/(M+mSin²(θ))",
        "Did you mean Mmg cos(…)?",
    ),  # a phone's capital
    ("conical-pendulum", "tension", "mω2L", "Did you mean m omega^2 L? Write a power with ^."),
    # graded wrong_dimension as (R+h)³/2, an attempt used for a bracket
    ("satellite-orbit", "period", "2π(R+h)^3/2/√(GM)", "Did you mean 2·pi·(R + h)^(3/2)/sqrt(G·M)?"),
    # graded as √(gR)·tan θ: both readings are speeds, so it is asked
    ("banked-curve", "design_speed", "√gRtanθ", "Did you mean sqrt(g·R)·tan(theta) or sqrt(g·R·tan(theta))?"),
    # a spreadsheet's formula: was told to leave out "a name" that is not there
    (
        "skier-friction",
        "acceleration_numeric",
        "=9.81*(sin(35°)-0.13*cos(35°)) m/s^2",
        "Leave out the '=' at",
    ),
    ("simple-pendulum", "period", "=2*pi*sqrt(L/g)", "Leave out the '=' at the start"),
    ("skier-friction", "acceleration_numeric", "4.58 m/s^2 downhill", "a direction is not read here"),
    ("skier-friction", "acceleration_numeric", "4.58 m/s^2 downwards", "a direction is not read here"),
    # a direction said in a phrase: was "Unknown unit 'to'", or a second number with its own unit
    (
        "skier-friction",
        "acceleration_numeric",
        "4.58 m/s^2 to the right",
        "'to the right': a direction is not read",
    ),
    (
        "skier-friction",
        "acceleration_numeric",
        "4.58 m/s^2 to the left",
        "'to the left': a direction is not read",
    ),
    ("skier-friction", "acceleration_numeric", "4.58 m/s^2 at 30°", "'at 30°': a direction is not read here"),
    # a square root's name spelled out, or BASIC's square: was "Unknown function" with no hint
    ("simple-pendulum", "period", "2π root(L/g)", "Did you mean sqrt(L/g)?"),
    ("simple-pendulum", "period", "2π squareroot(L/g)", "Did you mean sqrt(L/g)?"),
    ("simple-pendulum", "period", "2πroot(L/g)", "Did you mean π sqrt(L/g)?"),  # glued: was no hint
    (
        "simple-pendulum",
        "period",
        "2π sqr(L/g)",
        "Did you mean the square root, sqrt(L/g), or the square, (L/g)^2?",
    ),
    ("simple-pendulum", "period_numeric", "2*pi*sqroot(0.5/9.81) s", "Did you mean sqrt(0.5/9.81)?"),
    # an equation or a remark after the value: was "Unexpected character '=' in the units", "Unexpected
    # word 'no' in the number", "Unknown symbol "small""
    ("skier-friction", "acceleration_numeric", "4.58 m/s^2 = a", "without '= a': type only 4.58 m/s^2"),
    ("skier-friction", "acceleration_numeric", "4.58 m/s^2 ≈ 0.47g", "type only 4.58 m/s^2"),
    # the working, then the value with units: was told to type the working, which has no units
    (
        "simple-pendulum",
        "period_numeric",
        "2π√(1/9.81) = 2.01 s",
        "without '2π√(1/9.81) =': type only 2.01 s",
    ),
    ("skier-friction", "acceleration_numeric", "4 .58 m/s^2", "Did you mean 4.58?"),  # was "4 and then ."
    ("simple-pendulum", "period_numeric", "2.01 (no units)", "Give the value alone: leave out (no units)"),
    ("simple-pendulum", "period", "2π√(L/g) (small angles)", "and type only 2π√(L/g)."),
    # a textbook's power with a space before its minus: was a bare "Unexpected '-' in the units"
    ("skier-friction", "acceleration_numeric", "4.58 m s -2", "Did you mean m s^-2? Write a power with ^"),
    # the `*` typed for `^`: was graded as 4.58·2 m/s, wrong_dimension with an attempt used
    ("skier-friction", "acceleration_numeric", "4.58 m/s*2", "Did you mean m/s^2? Write a power with ^"),
    ("skier-friction", "acceleration_numeric", "4.58 m/s *2", "Did you mean m/s^2? Write a power with ^"),
]


@pytest.mark.parametrize(("problem_id", "part_id", "typed", "words"), REFUSED, ids=[c[2] for c in REFUSED])
def test_a_students_answer_that_cannot_be_read_says_what_to_type(
    problem_id: str, part_id: str, typed: str, words: str
) -> None:
    variant = _variant(problem_id, part_id)
    verdict = check_answer(typed, compiled(problem_id).question(part_id, variant))
    assert verdict.outcome is Outcome.INVALID
    assert words in verdict.feedback
