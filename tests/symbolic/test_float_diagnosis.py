"""A wrong answer's reason found from float64 (confirmed in multiprecision at a few points) is the
reason the multiprecision path gives, also where float64 alone would be wrong; and references over
the same symbols share their sample points."""

from __future__ import annotations

import pytest
import sympy

from physics.dimensions import DIMENSIONLESS
from physics.symbolic import KnownMistake, SymbolicContext, SymbolSpec, make_symbol, prepare_reference
from physics.symbolic.compare import PREC
from physics.symbolic.judge import _normalize_answer, diagnose, judge_symbolic
from physics.symbolic.numeric import Evaluator, to_float
from physics.symbolic.reference import PreparedReference
from physics.verdict import Judgement, Reason
from tests.symbolic.support import context, cos, g, m, sin, theta

TINY_DIFFERENCE = 1 + sympy.Rational(1, 10**14)  # below float64's agreement threshold, far above 2^-83
# Values near 1e150: beyond float64's safe range, so only multiprecision can look.
HUGE_SPEC = SymbolSpec("X", DIMENSIONLESS, low=sympy.Integer(10) ** 150, high=2 * sympy.Integer(10) ** 150)
X = make_symbol(HUGE_SPEC)
HUGE = SymbolicContext({X: HUGE_SPEC})
# 1/(1 - x) for x just below 1: float64 keeps only a few digits of 1 - x.
NEAR_ONE_SPEC = SymbolSpec("x", DIMENSIONLESS, low=1 - sympy.Rational(1, 10**9), high=sympy.Integer(1))
x = make_symbol(NEAR_ONE_SPEC)
NEAR_ONE = SymbolicContext({x: NEAR_ONE_SPEC})
MISTAKE = KnownMistake(m * g * cos(theta), "That is the normal component.")
WITH_MISTAKE = context(m * g * sin(theta), mistakes=(MISTAKE,))

# (answer, reference, context, the reason multiprecision gives)
CASES = [
    pytest.param(
        2 * m * g * sin(theta), m * g * sin(theta), WITH_MISTAKE, Reason.CONSTANT_FACTOR, id="factor"
    ),
    pytest.param(-m * g * sin(theta), m * g * sin(theta), WITH_MISTAKE, Reason.SIGN_ERROR, id="sign"),
    pytest.param(m * g * cos(theta), m * g * sin(theta), WITH_MISTAKE, Reason.KNOWN_MISTAKE, id="mistake"),
    pytest.param(m * g * sin(theta) ** 2, m * g * sin(theta), WITH_MISTAKE, Reason.WRONG_VALUE, id="wrong"),
    pytest.param(m * sin(theta), m * g * sin(theta), WITH_MISTAKE, Reason.WRONG_DIMENSION, id="dimension"),
    # float64 sees these as the mistake, the opposite sign and the reference itself:
    pytest.param(
        TINY_DIFFERENCE * m * g * cos(theta),
        m * g * sin(theta),
        WITH_MISTAKE,
        Reason.WRONG_VALUE,
        id="near-mistake",
    ),
    pytest.param(
        -TINY_DIFFERENCE * m * g * sin(theta),
        m * g * sin(theta),
        WITH_MISTAKE,
        Reason.WRONG_VALUE,
        id="near-sign",
    ),
    pytest.param(
        TINY_DIFFERENCE * m * g * sin(theta),
        m * g * sin(theta),
        WITH_MISTAKE,
        Reason.WRONG_VALUE,
        id="near-equal",
    ),
    pytest.param(-X, X, HUGE, Reason.SIGN_ERROR, id="huge-sign"),
    pytest.param(3 * X, X, HUGE, Reason.CONSTANT_FACTOR, id="huge-factor"),
    pytest.param(X + 1 / X, X, HUGE, Reason.EQUIVALENT, id="huge-within-tolerance"),
    pytest.param(2 / (1 - x), 1 / (1 - x), NEAR_ONE, Reason.CONSTANT_FACTOR, id="near-singular-factor"),
    pytest.param(-1 / (x - 1), 1 / (1 - x), NEAR_ONE, Reason.EQUIVALENT, id="near-singular-equal"),
    pytest.param(1 / (1 - x) + 1, 1 / (1 - x), NEAR_ONE, Reason.WRONG_VALUE, id="near-singular-off-by-one"),
]


def multiprecision_only(answer: sympy.Expr, reference: PreparedReference) -> Judgement:
    """The diagnosis from every sample point in multiprecision, without any float64 shortcut."""
    expr = _normalize_answer(answer, reference)
    values = Evaluator(reference.sample.columns, reference.sample.size, PREC)(expr)
    return diagnose(expr, values, reference, undefined=any(v is None for v in values))


@pytest.mark.parametrize(("answer", "expected", "ctx", "reason"), CASES)
def test_the_reason_is_the_one_multiprecision_gives(answer, expected, ctx, reason):
    reference = prepare_reference(expected, ctx)
    judgement = judge_symbolic(answer, reference)
    assert judgement.reason is reason
    if reason is not Reason.EQUIVALENT:
        assert judgement == multiprecision_only(answer, reference)


def test_references_over_the_same_symbols_share_their_sample_points():
    first = prepare_reference(m * g * sin(theta), WITH_MISTAKE)
    second = prepare_reference(m * g * cos(theta) ** 2, WITH_MISTAKE)
    assert first.sample.columns == second.sample.columns


def test_a_reference_undefined_on_some_shared_points_is_sampled_where_it_is_defined():
    spec = SymbolSpec("x", DIMENSIONLESS, low=sympy.Integer(0), high=sympy.Integer(1))
    y = make_symbol(spec)
    unit = SymbolicContext({y: spec})
    everywhere = prepare_reference(y, unit)
    upper_half = prepare_reference(sympy.sqrt(2 * y - 1), unit)
    assert any(to_float(v) < 0.5 for v in everywhere.sample.columns[y])  # the shared points reach below 1/2
    assert all(value is not None for value in upper_half.values)
    assert judge_symbolic(sympy.sqrt(y - sympy.Rational(1, 2)) * sympy.sqrt(2), upper_half).correct
