"""Why a wrong answer is wrong: known mistakes, sign, constant factor, limits, and the order of reasons."""

from __future__ import annotations

import pytest
import sympy

from physics.symbolic import KnownMistake, LimitCase, judge_symbolic, prepare_reference
from physics.verdict import Reason
from tests.symbolic.support import M, context, cos, g, judge, m, pi, sin, sqrt, theta

s, c = sin(theta), cos(theta)
WEDGE = -m * g * s * c / (M + m * s**2)
RELATIVE = (M + m) * g * s / (M + m * s**2)
IMMOVABLE = LimitCase({M: sympy.oo}, "an immovable wedge (M → ∞)")
LIGHT_BLOCK = LimitCase({m: sympy.Integer(0)}, "a very light block (m → 0)")
FORGOT_WEDGE_MOVES = KnownMistake(-m * g * s * c / (M + m), "Did you let the wedge move?")
NEGATED_MISTAKE = KnownMistake(-RELATIVE, "Down the incline is the positive direction here.")
WRONG_DIMENSION_MISTAKE = KnownMistake(RELATIVE * m, "This is a force.")


def wedge_reference(expected=RELATIVE, mistakes=(), limits=(IMMOVABLE, LIGHT_BLOCK)):
    return prepare_reference(expected, context(expected, mistakes=mistakes, limits=limits))


def test_a_known_mistake_gets_its_feedback():
    reference = wedge_reference(WEDGE, mistakes=(FORGOT_WEDGE_MOVES,))
    answer = -g * m * sin(2 * theta) / (2 * (m + M))  # the mistake, written differently
    judgement = judge_symbolic(answer, reference)
    assert judgement == judgement.__class__(False, Reason.KNOWN_MISTAKE, "Did you let the wedge move?")


def test_a_known_mistake_comes_before_the_sign_error_it_also_is():
    judgement = judge_symbolic(-RELATIVE, wedge_reference(mistakes=(NEGATED_MISTAKE,)))
    assert judgement.reason is Reason.KNOWN_MISTAKE


def test_a_known_mistake_of_another_dimension_keeps_its_targeted_feedback():
    judgement = judge_symbolic(RELATIVE * m, wedge_reference(mistakes=(WRONG_DIMENSION_MISTAKE,)))
    assert (judgement.reason, judgement.feedback) == (Reason.KNOWN_MISTAKE, WRONG_DIMENSION_MISTAKE.feedback)


def test_a_wrong_dimension_that_is_no_known_mistake_says_so():
    judgement = judge_symbolic(RELATIVE * m * m, wedge_reference(mistakes=(WRONG_DIMENSION_MISTAKE,)))
    assert judgement.reason is Reason.WRONG_DIMENSION


def test_the_sign_comes_before_a_constant_factor_of_minus_one():
    assert judge_symbolic(-RELATIVE, wedge_reference()).reason is Reason.SIGN_ERROR


@pytest.mark.parametrize(
    "factor",
    [
        pytest.param(sympy.Integer(2), id="two"),
        pytest.param(sympy.Rational(1, 2), id="half"),
        pytest.param(-sympy.Integer(3), id="minus-three"),
        pytest.param(sqrt(2), id="root-two"),
        pytest.param(pi, id="pi"),
    ],
)
def test_a_constant_factor_is_reported_without_its_value(factor):
    judgement = judge_symbolic(factor * RELATIVE, wedge_reference())
    assert judgement.reason is Reason.CONSTANT_FACTOR
    assert str(factor) not in judgement.feedback.replace("2, π", "")


def test_a_zero_answer_is_a_wrong_value_not_a_factor():
    assert judge_symbolic(sympy.Integer(0) * g, wedge_reference()).reason is Reason.WRONG_VALUE


def test_a_wrong_limit_is_pointed_out():
    answer = (M + m) * g * s / (m + M * s**2)  # tends to g / sin(theta) for a heavy wedge
    judgement = judge_symbolic(answer, wedge_reference(limits=(IMMOVABLE,)))
    assert judgement.reason is Reason.WRONG_VALUE
    assert "fails a limiting case, an immovable wedge (M → ∞): check it there." in judgement.feedback


def test_a_wrong_answer_with_the_right_limit_gets_no_limit_hint():
    answer = g * s  # exactly the heavy-wedge limit, wrong otherwise
    judgement = judge_symbolic(answer, wedge_reference())
    assert judgement.reason is Reason.WRONG_VALUE
    assert "immovable" not in judgement.feedback


FLAT = LimitCase({theta: sympy.Integer(0)}, "a flat incline (θ → 0)")
LIMIT_HINTS = [
    ("breaks-heavy-wedge-only", RELATIVE * (1 + s * M / (M + m)), ["immovable"], ["flat"]),
    ("breaks-flat-incline-only", RELATIVE + g * c * m / (M + m), ["flat"], ["immovable"]),
    ("breaks-both", g * c, ["immovable", "flat"], []),
    ("breaks-neither", RELATIVE * (1 + s * m / (M + m)), [], ["limiting case"]),
]


@pytest.mark.parametrize(
    ("answer", "named", "not_named"), [h[1:] for h in LIMIT_HINTS], ids=[h[0] for h in LIMIT_HINTS]
)
def test_only_the_limits_an_answer_breaks_are_named(answer, named, not_named):
    judgement = judge_symbolic(answer, wedge_reference(limits=(IMMOVABLE, FLAT)))
    assert judgement.reason is Reason.WRONG_VALUE
    for word in named:
        assert word in judgement.feedback
    for word in not_named:
        assert word not in judgement.feedback


def test_a_limit_to_a_finite_angle_is_approached_from_inside_the_domain():
    expected = g * (s - sympy.Rational(1, 5) * c) + g / 5  # tends to 0 on a flat incline
    reference = prepare_reference(expected, context(expected, limits=(FLAT,)))
    assert "flat incline" in judge_symbolic(g * c, reference).feedback
    assert "flat incline" not in judge_symbolic(g * s * 2, reference).feedback


WRONG = [
    ("sign", -RELATIVE),
    ("factor", 2 * RELATIVE),
    ("value", g * c),
    ("dimension", RELATIVE * m),
    ("mistake", -RELATIVE),
]


@pytest.mark.parametrize("answer", [w[1] for w in WRONG], ids=[w[0] for w in WRONG])
def test_feedback_never_shows_the_reference(answer):
    reference = wedge_reference(mistakes=(KnownMistake(-RELATIVE, "Mind the direction."),))
    feedback = judge_symbolic(answer, reference).feedback
    for text in (str(RELATIVE), sympy.latex(RELATIVE), "M + m", "sin(theta)"):
        assert text not in feedback


def test_a_correct_answer_says_so():
    judgement = judge(RELATIVE, RELATIVE)
    assert (judgement.correct, judgement.reason, judgement.feedback) == (True, Reason.EQUIVALENT, "Correct.")


def test_several_failed_limits_are_named_in_one_sentence():
    judgement = judge_symbolic(g * c, wedge_reference(limits=(IMMOVABLE, FLAT)))
    assert judgement.feedback.count("limiting case") == 1
    assert (
        "fails 2 limiting cases; check it in each: an immovable wedge (M → ∞); a flat incline (θ → 0)."
        in judgement.feedback
    )
