"""Dimensions of expressions, and answers graded wrong for their dimension."""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy

from physics.dimensions import DIMENSIONLESS, Dimension
from physics.symbolic import (
    DimensionMismatch,
    SymbolicContext,
    UnknownDimension,
    describe,
    expression_dimension,
    judge_symbolic,
    prepare_reference,
)
from physics.verdict import Reason
from tests.symbolic.support import (
    ACCELERATION,
    ENERGY,
    FORCE,
    KG,
    METRE,
    SECOND,
    SPEED,
    L,
    M,
    a,
    context,
    cos,
    g,
    judge,
    log,
    m,
    mu,
    sin,
    sqrt,
    t,
    theta,
    v,
)

DIMS = {m: KG, M: KG, g: ACCELERATION, v: SPEED, L: METRE, t: SECOND, mu: DIMENSIONLESS, theta: DIMENSIONLESS}

CONSISTENT = [
    ("force", m * g * sin(theta), FORCE),
    ("kinetic-energy", m * v**2 / 2, ENERGY),
    ("sum-of-masses", (m + M) * g, FORCE),
    ("square-root", sqrt(2 * L / g), SECOND),
    ("rational-power", (L**3) ** sympy.Rational(1, 3), METRE),
    ("ratio-in-log", log(M / m), DIMENSIONLESS),
    ("ratio-in-exp", v * sympy.exp(-g * t / v), SPEED),
    ("abs-keeps-dimension", sympy.Abs(v), SPEED),
    ("pure-number", 2 * sympy.pi, DIMENSIONLESS),
    ("friction", g * (sin(theta) - mu * cos(theta)), ACCELERATION),
    ("atan2-of-lengths", sympy.atan2(L, v * t), DIMENSIONLESS),
]


@pytest.mark.parametrize(("expr", "dim"), [c[1:] for c in CONSISTENT], ids=[c[0] for c in CONSISTENT])
def test_consistent_expressions_have_their_dimension(expr, dim):
    assert expression_dimension(expr, DIMS) == dim


INCONSISTENT = [
    ("mass-plus-acceleration", m + g, "add", "adds"),
    ("number-plus-length", 1 + L, "add", "adds"),
    ("sin-of-mass", sin(m), "function", "takes sin of"),
    ("exp-of-time", sympy.exp(t), "function", "takes exp of"),
    ("log-of-length", log(L), "function", "takes log of"),
    ("dimensional-exponent", g**t, "exponent", "exponent"),
    ("symbolic-power-of-length", L**mu, "power", "raises"),
]


@pytest.mark.parametrize(
    ("expr", "kind", "words"), [c[1:] for c in INCONSISTENT], ids=[c[0] for c in INCONSISTENT]
)
def test_inconsistent_expressions_raise_a_mismatch_saying_which(expr, kind, words):
    with pytest.raises(DimensionMismatch) as raised:
        expression_dimension(expr, DIMS)
    assert raised.value.kind == kind
    assert words in raised.value.message


def test_mismatch_names_both_dimensions_of_a_sum():
    with pytest.raises(DimensionMismatch) as raised:
        expression_dimension(m + g, DIMS)
    assert describe(KG) in raised.value.message
    assert describe(ACCELERATION) in raised.value.message


def test_a_symbol_without_dimension_is_reported():
    with pytest.raises(UnknownDimension) as raised:
        expression_dimension(m * a, DIMS)
    assert raised.value.symbol == "a"


WRONG_DIMENSION = [
    ("force-for-acceleration", m * g * sin(theta), g * sin(theta), [describe(FORCE), describe(ACCELERATION)]),
    ("adds-mass-to-acceleration", g * sin(theta) + m, g * sin(theta), ["adds"]),
    ("sin-of-dimensional", g * sin(m), g * sin(theta), ["takes sin of"]),
    ("missing-square", m * v / 2, m * v**2 / 2, [describe(ENERGY)]),
]


@pytest.mark.parametrize(
    ("answer", "expected", "words"), [c[1:] for c in WRONG_DIMENSION], ids=[c[0] for c in WRONG_DIMENSION]
)
def test_an_answer_of_the_wrong_dimension_is_graded_so(answer, expected, words):
    judgement = judge(answer, expected)
    assert judgement.reason is Reason.WRONG_DIMENSION
    assert not judgement.correct
    for word in words:
        assert word in judgement.feedback


def test_no_dimension_verdict_when_a_symbol_of_the_answer_has_no_dimension():
    judgement = judge(a * g, g, context(a * g, g))
    assert judgement.reason is not Reason.WRONG_DIMENSION


def test_an_equivalent_answer_is_correct_even_written_with_logs_of_dimensional_quantities():
    answer = log(M) - log(m)
    assert judge(answer, log(M / m)).correct


def test_the_declared_expected_dimension_is_used_when_the_reference_has_symbols_without_one():
    base = context(a * g, v)
    reference = prepare_reference(a * g, SymbolicContext(base.symbols, expected_dimension=ACCELERATION))
    answer = g * v  # every symbol of the answer has a dimension: it can be checked
    assert judge_symbolic(answer, reference).reason is Reason.WRONG_DIMENSION


def test_a_zero_answer_has_every_dimension():
    judgement = judge(0 * g, g * sin(theta))
    assert judgement.reason is Reason.WRONG_VALUE


HALF = Fraction(1, 2)
ALGEBRA = [
    # (left, right) exponents: a product, quotient or power of Dimensions must be the Dimension that the
    # checking constructor builds from the exponents they add up to
    ({"mass": 1}, {"length": 2, "time": -2}),
    ({"length": 1, "time": -1}, {"time": 1}),
    ({"length": 1}, {"length": -1}),
    ({"mass": 1, "length": 2, "time": -2}, {"mass": 1, "length": 2, "time": -2}),
    ({"length": HALF}, {"length": HALF, "current": 3}),
    ({}, {"temperature": -1}),
]


@pytest.mark.parametrize(("left", "right"), ALGEBRA)
def test_dimension_arithmetic_gives_the_dimension_of_the_summed_exponents(left, right):
    a_dim, b_dim = Dimension(left), Dimension(right)
    bases = set(left) | set(right)
    total = Dimension({b: Fraction(left.get(b, 0)) + right.get(b, 0) for b in bases})
    difference = Dimension({b: Fraction(left.get(b, 0)) - right.get(b, 0) for b in bases})
    assert a_dim * b_dim == total
    assert hash(a_dim * b_dim) == hash(total)
    assert a_dim / b_dim == difference
    assert all(isinstance(p, Fraction) for p in (a_dim / b_dim).exponents.values())
    for power in (2, -1, HALF, Fraction(-3, 2), 0):
        assert a_dim**power == Dimension({b: Fraction(p) * power for b, p in left.items()})
    assert a_dim / a_dim == DIMENSIONLESS
