"""The float64 first look only ever shortens the way to the verdict multiprecision would give."""

from __future__ import annotations

import math
import random

import numpy as np
import pytest
import sympy

from physics.dimensions import DIMENSIONLESS
from physics.symbolic import SymbolicContext, SymbolSpec, make_symbol
from physics.symbolic.floats import AGREE, agrees, float_sample, in_range
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


# Values at and around every edge of in_range and agrees: non-finite, zero, the safe magnitudes, the
# agreement tolerance, float64's extremes.
EDGES = [
    0.0, -0.0, 1.0, -1.0, math.nan, math.inf, -math.inf, 1e-100, -1e-100, 1.0000000000000001e-100,
    1e100, 9.999999999999999e99, 1e-101, 1e101, 5e-324, 1.7976931348623157e308, 1 + 1e-9, 1 + 2e-9,
    1 - 1e-9, 0.5, 2.0, 1e-9, 3.0000000015,
]  # fmt: skip


def _numpy_in_range(values):
    if not np.isfinite(values).all():
        return False
    magnitudes = np.abs(values)
    nonzero = magnitudes[magnitudes != 0]
    return bool(((nonzero > 1e-100) & (nonzero < 1e100)).all())


def _numpy_agrees(answer, target, scale):
    if not (np.isfinite(answer).all() and np.isfinite(target).all()):
        return False
    with np.errstate(all="ignore"):
        allowed = AGREE * (np.maximum(np.abs(answer), np.abs(target)) + scale)
        return bool((np.abs(answer - target) <= allowed).all())


def test_the_range_and_agreement_tests_decide_every_edge_as_their_numpy_formulas():
    rng = random.Random(5)
    for _ in range(3000):
        answer = np.array([rng.choice(EDGES) * rng.choice((1, 3)) for _ in range(rng.randint(1, 4))])
        factors = np.array([rng.choice((1.0, 1 + 1e-9, 1 - 2e-9, 1 + 5e-10, -1.0, 0.0)) for _ in answer])
        scale = rng.choice((1.0, 0.0, 1e-100, 3.0, 1e300))
        with np.errstate(all="ignore"):  # inf times 0
            target = answer * factors
            assert in_range(answer) == _numpy_in_range(answer), answer
            assert in_range(np.stack([answer, target])) == _numpy_in_range(np.stack([answer, target]))
            assert agrees(answer, target, scale) == _numpy_agrees(answer, target, scale), (answer, target)


MEDIAN_CASES = {
    "odd": [3.0, -1.0, 2.0],
    "even": [4.0, 1.0, -3.0, 2.0],
    "undefined points left out": [math.nan, 2.0, -math.inf, 5.0, 1.0],
    "zeros": [0.0, 0.0, 7.0],
    "none finite": [math.nan, math.inf],
    "far apart": [1e-300, 1e300, 3.5e-12, 2.0**-1074],
}


@pytest.mark.parametrize("values", MEDIAN_CASES.values(), ids=list(MEDIAN_CASES))
def test_a_samples_scale_is_numpys_median_of_its_finite_magnitudes(values):
    floats = np.array(values)
    magnitudes = np.abs(floats[np.isfinite(floats)])
    expected = float(np.median(magnitudes)) if magnitudes.size else 1.0
    assert float_sample({}, floats).scale == (expected if expected > 0 else 1.0)
