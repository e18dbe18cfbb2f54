"""The float64 first look only ever shortens the way to the verdict multiprecision would give."""

from __future__ import annotations

import sympy

from physics.dimensions import DIMENSIONLESS
from physics.symbolic import SymbolicContext, SymbolSpec, make_symbol
from physics.verdict import Reason
from tests.symbolic.support import context, g, judge, m

TINY = SymbolSpec("x", DIMENSIONLESS, low=sympy.Integer(0), high=sympy.Rational(1, 10**6))
x = make_symbol(TINY)


def test_a_difference_float64_cannot_see_is_still_rejected():
    for relative in (sympy.Rational(1, 10**13), sympy.Rational(1, 10**30)):
        assert not judge(m * g * (1 + relative), m * g).correct


def test_cancellation_in_float64_does_not_refute_a_correct_answer():
    # For x below 1e-6, float64 keeps only a few digits of 1 - cos(x), which equals 2 sin²(x/2) exactly.
    tiny = SymbolicContext({x: TINY})
    assert judge(1 - sympy.cos(x), 2 * sympy.sin(x / 2) ** 2, tiny).correct


def test_a_refutation_is_the_one_multiprecision_gives():
    judgement = judge(-m * g, m * g, context(m * g))
    assert (judgement.correct, judgement.reason) == (False, Reason.SIGN_ERROR)
