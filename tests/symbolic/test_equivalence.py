"""Which answers count as the reference on its domain, and which near misses do not."""

from __future__ import annotations

import pytest
import sympy

from physics.verdict import Reason
from tests.symbolic.support import (
    U0,
    UP_TO_PI,
    L,
    M,
    a,
    b,
    context,
    cos,
    g,
    judge,
    log,
    m,
    mu,
    n,
    pi,
    r,
    r0,
    sin,
    sqrt,
    t,
    tan,
    theta,
    v,
    x,
    y,
)

s, c = sin(theta), cos(theta)
WEDGE = -m * g * s * c / (M + m * s**2)
LJ_FORCE = 12 * U0 / r * ((r0 / r) ** 12 - (r0 / r) ** 6)
LJ_OMEGA = sqrt(72 * U0 / r0**2 / (m / 2))
half = sympy.Rational(1, 2)

ACCEPTED = [
    ("reordered-product", g * s * m, m * g * s),
    ("expanded-square", a**2 + 2 * a * b + b**2, (a + b) ** 2),
    ("factored-difference", (a - b) * (a + b), a**2 - b**2),
    ("combined-fractions", a * b / (a + b), 1 / (1 / a + 1 / b)),
    ("common-denominator", (m * v**2 + M * v**2) / 2, (m + M) * v**2 / 2),
    ("pythagorean-identity", m * g * (s**2 + c**2), m * g),
    ("one-minus-cos-squared", M + m * (1 - c**2), M + m * s**2),
    ("double-angle-sin", m * g * sin(2 * theta) / 2, m * g * s * c),
    ("double-angle-cos", cos(2 * theta), 1 - 2 * s**2),
    ("wedge-tan-form", -m * g * tan(theta) / (M * (1 + tan(theta) ** 2) + m * tan(theta) ** 2), WEDGE),
    ("wedge-double-angle", -m * g * sin(2 * theta) / (2 * M + m * (1 - cos(2 * theta))), WEDGE),
    ("wedge-sec-form", -m * g * tan(theta) / (M / c**2 + m * tan(theta) ** 2), WEDGE),
    ("half-angle-sin", sqrt((1 - c) / 2), sin(theta / 2)),
    ("half-angle-cos", sqrt((1 + c) / 2), cos(theta / 2)),
    ("half-angle-tan", (1 - c) / s, tan(theta / 2)),
    ("sqrt-one-minus-sin-squared-acute", sqrt(1 - s**2), c),
    ("asin-of-sin-acute", sympy.asin(s), theta),
    ("atan-of-tan-acute", sympy.atan(tan(theta)), theta),
    ("acos-of-cos", sympy.acos(c), theta),
    ("sqrt-of-square-positive", sqrt(m**2 * g**2), m * g),
    ("sqrt-product-positive", sqrt(a) * sqrt(b), sqrt(a * b)),
    ("sqrt-of-square-real", sqrt(x**2), sympy.Abs(x)),
    ("log-of-product", log(a * b), log(a) + log(b)),
    ("log-of-power", log(a**3), 3 * log(a)),
    ("log-of-square-real", 2 * log(sympy.Abs(y)), log(y**2)),
    ("exp-of-log", sympy.exp(log(a) + log(b)), a * b),
    ("removable-singularity", (a**2 - b**2) / (a - b), a + b),
    ("removable-singularity-on-a-sample-point", (n**2 - 1) / (n - 1), n + 1),
    ("exact-decimal-half", sympy.Float(0.5) * m * v**2, m * v**2 / 2),
    ("decimal-exponent", m * v ** sympy.Float(2.0), m * v**2),
    ("lj-force-expanded", 12 * U0 * (r0**12 / r**13 - r0**6 / r**7), LJ_FORCE),
    ("lj-force-factored", 12 * U0 * r0**6 * (r0**6 - r**6) / r**13, LJ_FORCE),
    ("lj-force-from-derivative", -sympy.diff(U0 * ((r0 / r) ** 12 - 2 * (r0 / r) ** 6), r), LJ_FORCE),
    ("lj-omega-simplified", 12 * sqrt(U0 / m) / r0, LJ_OMEGA),
    ("lj-omega-separate-roots", 12 * sqrt(U0) / (r0 * sqrt(m)), LJ_OMEGA),
    ("lj-omega-reduced-mass", sqrt(72 * U0 / (r0**2 * (m * m / (m + m)))), LJ_OMEGA),
    ("pendulum-energy", sqrt(2 * g * L * (1 - c)), 2 * sqrt(g * L) * sin(theta / 2)),
    ("falling-time", sqrt(2 * L / g), sqrt(L / g) * sqrt(2)),
    ("functions-evaluated-by-sympy", sympy.gamma(n + 1), sympy.factorial(n)),
    ("beyond-double-range", sympy.exp(1000 * a) ** 2 * sympy.exp(-5000 * b), sympy.exp(2000 * a - 5000 * b)),
    ("euler-form-of-sine", (sympy.exp(sympy.I * theta) - sympy.exp(-sympy.I * theta)) / (2 * sympy.I), s),
]


@pytest.mark.parametrize(
    ("answer", "expected"), [case[1:] for case in ACCEPTED], ids=[c[0] for c in ACCEPTED]
)
def test_equivalent_forms_are_accepted(answer, expected):
    judgement = judge(answer, expected)
    assert judgement.correct, judgement
    assert judgement.reason is Reason.EQUIVALENT


NEAR_MISSES = [
    ("sign", -m * g * s, m * g * s, Reason.SIGN_ERROR),
    ("wedge-sign", -WEDGE, WEDGE, Reason.SIGN_ERROR),
    ("factor-two", 2 * m * g * s, m * g * s, Reason.CONSTANT_FACTOR),
    ("factor-half", m * g * s / 2, m * g * s, Reason.CONSTANT_FACTOR),
    ("factor-pi", pi * sqrt(L / g), sqrt(L / g), Reason.CONSTANT_FACTOR),
    ("sin-for-cos", m * g * c, m * g * s, Reason.WRONG_VALUE),
    ("missing-square", M + m * s, M + m * s**2, Reason.WRONG_VALUE),
    ("equal-only-at-quarter-pi", sin(2 * theta), sympy.Integer(1), Reason.WRONG_VALUE),
    ("tan-vs-one-equal-at-quarter-pi", m * g * tan(theta), m * g, Reason.WRONG_VALUE),
    ("abs-vs-identity-for-real", sympy.Abs(x), x, Reason.WRONG_VALUE),
    ("log-identity-needs-positivity", 2 * log(y), log(y**2), Reason.WRONG_VALUE),
    ("pi-vs-355-over-113", sympy.Rational(355, 113) * L, pi * L, Reason.CONSTANT_FACTOR),
    ("sqrt2-vs-decimal", sympy.Rational(141421356, 10**8) * v, sqrt(2) * v, Reason.CONSTANT_FACTOR),
    ("lj-force-wrong-power", 12 * U0 / r * ((r0 / r) ** 12 - (r0 / r) ** 5), LJ_FORCE, Reason.WRONG_VALUE),
    ("lj-omega-full-mass", sqrt(72 * U0 / (m * r0**2)), LJ_OMEGA, Reason.CONSTANT_FACTOR),
    ("tiny-values-factor", 2 * sympy.exp(-1000 * a), sympy.exp(-1000 * a), Reason.CONSTANT_FACTOR),
    (
        "huge-values-near-factor",
        sympy.exp(1000 * a) * (1 + sympy.Rational(1, 10**6)),
        sympy.exp(1000 * a),
        Reason.CONSTANT_FACTOR,
    ),
    ("shifted-by-constant", m * g * s + m * g / 1000, m * g * s, Reason.WRONG_VALUE),
    ("swapped-masses", -M * g * s * c / (m + M * s**2), WEDGE, Reason.WRONG_VALUE),
    ("time-instead-of-length", sqrt(2 * t / g), sqrt(2 * L / g), Reason.WRONG_DIMENSION),
]


@pytest.mark.parametrize(
    ("answer", "expected", "reason"), [case[1:] for case in NEAR_MISSES], ids=[c[0] for c in NEAR_MISSES]
)
def test_near_misses_are_rejected_with_their_reason(answer, expected, reason):
    judgement = judge(answer, expected)
    assert not judgement.correct
    assert judgement.reason is reason, judgement.feedback


def test_sqrt_of_one_minus_sin_squared_is_cos_only_on_the_acute_range():
    answer = sqrt(1 - s**2)
    assert judge(answer, c, context(answer, c)).correct
    wide = judge(answer, c, context(answer, c, angle=UP_TO_PI))
    assert not wide.correct
    assert wide.reason is Reason.WRONG_VALUE


def test_asin_of_sin_is_not_theta_beyond_a_right_angle():
    answer = sympy.asin(s)
    assert not judge(answer, theta, context(answer, theta, angle=UP_TO_PI)).correct


@pytest.mark.parametrize(
    "digits",
    [
        pytest.param("3.14159265358979", id="15-digits"),
        pytest.param("3.1415926535897932384626433832795", id="32-digits"),
        pytest.param("3.1415926535897932384626433832795028841971693993751", id="50-digits"),
    ],
)
def test_a_decimal_approximation_of_pi_is_not_pi(digits):
    # The second, double-precision look resolves about 60 digits; beyond that an answer counts as equal.
    from fractions import Fraction

    value = Fraction(digits)
    answer = sympy.Rational(value.numerator, value.denominator) * L
    judgement = judge(answer, pi * L)
    assert not judgement.correct


def test_a_constraint_restricts_the_domain_of_equivalence():
    answer = sympy.Abs(1 - mu * tan(theta))
    expected = 1 - mu * tan(theta)
    constrained = context(answer, expected, constraints=(sympy.Lt(mu * tan(theta), 1),))
    assert judge(answer, expected, constrained).correct
    assert not judge(answer, expected, context(answer, expected)).correct


def test_max_with_zero_equals_the_expression_where_a_constraint_keeps_it_positive():
    answer = sympy.Max(g * (s - mu * c), 0)
    expected = g * (s - mu * c)
    constrained = context(answer, expected, constraints=(sympy.Gt(tan(theta), mu),))
    assert judge(answer, expected, constrained).correct


def test_an_answer_undefined_on_part_of_the_domain_is_wrong_and_told_so():
    answer = sqrt(cos(2 * theta))  # equals the reference below pi/4, is not real above it
    judgement = judge(answer, sqrt(sympy.Abs(cos(2 * theta))))
    assert not judgement.correct
    assert judgement.reason is Reason.WRONG_VALUE
    assert "not defined" in judgement.feedback


def test_answer_symbols_are_matched_by_name_whatever_their_assumptions():
    plain_m, plain_g = sympy.Symbol("m"), sympy.Symbol("g")
    assert judge(plain_m * plain_g, m * g, context(m * g)).correct


CONSTANTS = [
    ("same-constant-written-otherwise", sympy.atan(1) * 4, pi, True, Reason.EQUIVALENT),
    ("decimal-for-a-constant", sympy.Rational(785, 1000), pi / 4, False, Reason.WRONG_VALUE),
    ("negated-constant", -pi / 4, pi / 4, False, Reason.SIGN_ERROR),
]


@pytest.mark.parametrize(
    ("answer", "expected", "correct", "reason"), [c[1:] for c in CONSTANTS], ids=[c[0] for c in CONSTANTS]
)
def test_plain_numbers_are_compared_without_talking_of_factors(answer, expected, correct, reason):
    from physics.symbolic import SymbolicContext, judge_symbolic, prepare_reference

    judgement = judge_symbolic(answer, prepare_reference(expected, SymbolicContext({})))
    assert (judgement.correct, judgement.reason) == (correct, reason)


def test_a_complex_valued_answer_is_wrong_where_it_is_not_real():
    answer = sympy.exp(sympy.I * theta)  # its real part is the reference, but it is not real
    judgement = judge(answer, c)
    assert not judgement.correct
