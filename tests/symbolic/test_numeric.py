"""The multiprecision evaluator: real values where defined, None where not, exact zeros for cancellations."""

from __future__ import annotations

import pytest
import sympy
from mpmath import libmp

from physics.symbolic.numeric import Evaluator, from_rational

x = sympy.Symbol("x", real=True)
PREC = 133


def at(expr, *points):
    column = [from_rational(p, q, PREC) for p, q in points]
    return [None if v is None else libmp.to_float(v) for v in Evaluator({x: column}, len(column), PREC)(expr)]


CASES = [
    ("sqrt-of-negative", sympy.sqrt(x), (-1, 1), None),
    ("log-of-zero", sympy.log(x), (0, 1), None),
    ("log-of-negative", sympy.log(x), (-2, 1), None),
    ("division-by-zero", 1 / x, (0, 1), None),
    ("asin-beyond-one", sympy.asin(x), (3, 2), None),
    ("acosh-below-one", sympy.acosh(x), (1, 2), None),
    ("cube-root-of-negative-is-not-real", x ** sympy.Rational(1, 3), (-8, 1), None),
    ("zero-to-negative-power", x ** sympy.Rational(-3, 2), (0, 1), None),
    ("imaginary-unit", sympy.I * x, (1, 1), None),
    ("integer-power-of-negative", x**3, (-2, 1), -8.0),
    ("symbolic-integer-power-of-negative", (-x) ** (x + 1), (2, 1), -8.0),
    ("cube-root", x ** sympy.Rational(1, 3), (8, 1), 2.0),
    ("abs", sympy.Abs(x), (-3, 1), 3.0),
    ("sign", sympy.sign(x), (-3, 1), -1.0),
    ("acot-at-zero", sympy.acot(x), (0, 1), float(sympy.pi / 2)),
    ("sec", sympy.sec(x), (0, 1), 1.0),
    ("atan2", sympy.atan2(x, 1), (1, 1), float(sympy.pi / 4)),
    ("max", sympy.Max(x, 2), (1, 1), 2.0),
    ("unknown-function-by-sympy", sympy.gamma(x), (5, 1), 24.0),
    ("exp", sympy.exp(x), (0, 1), 1.0),
]


@pytest.mark.parametrize(("expr", "point", "value"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_value_or_undefined_at_a_point(expr, point, value):
    result = at(expr, point)[0]
    if value is None:
        assert result is None
    else:
        assert result == pytest.approx(value, rel=1e-14)


def test_a_cancellation_to_rounding_noise_is_exact_zero():
    identity = sympy.sin(x) ** 2 + sympy.cos(x) ** 2 - 1
    assert at(identity, (1, 3), (7, 5), (-22, 7)) == [0.0, 0.0, 0.0]


def test_a_genuine_small_difference_survives():
    close_to_pi = sympy.pi - sympy.Rational(355, 113)
    assert at(close_to_pi + 0 * x, (1, 1))[0] == pytest.approx(float(sympy.pi) - 355 / 113, rel=1e-6)


def test_only_the_undefined_points_are_none():
    assert at(sympy.sqrt(x), (-1, 1), (4, 1)) == [None, 2.0]


TOWERS = [
    "x^(x^(x^x))",
    "exp(exp(exp(exp(x))))",
    "2^(2^(2^(2^x)))",
    "sinh(sinh(sinh(sinh(x))))",
    "tan(exp(exp(exp(x))))",
    "sin(10^300 x)",
    "log(exp(exp(exp(x))))",
]


@pytest.mark.timeout(20)
@pytest.mark.parametrize("answer", TOWERS)
def test_towers_of_functions_are_judged_without_computing_astronomical_numbers(answer):
    # mpmath would compute ln 2 or pi to as many bits as the argument has: minutes for these.
    from physics.checking import SymbolDecl, run_job
    from problems.kinds.symbolic import SymbolicJob

    verdict = run_job(SymbolicJob(answer, "x", (SymbolDecl("x", "1"),)))
    assert (verdict.outcome.value, verdict.reason.value) == ("incorrect", "wrong_value")


POINTS = [(-3, 1), (0, 1), (1, 3), (7, 5), (-22, 7), (4, 1)]


@pytest.mark.parametrize(
    "expr",
    [c[1] for c in CASES] + [sympy.sin(x) ** 2 + sympy.cos(x) ** 2 - 1],
    ids=[c[0] for c in CASES] + ["cancellation"],
)
def test_a_points_value_is_the_same_whichever_points_are_evaluated_with_it(expr):
    # The judge evaluates an answer once per point and reuses the value in later checks at other
    # groups of points: the evaluator must compute each point on its own.
    together = Evaluator({x: [from_rational(p, q, PREC) for p, q in POINTS]}, len(POINTS), PREC)(expr)
    alone = [Evaluator({x: [from_rational(p, q, PREC)]}, 1, PREC)(expr)[0] for p, q in POINTS]
    assert together == alone
    pairs = [
        Evaluator({x: [from_rational(*a, PREC), from_rational(*b, PREC)]}, 2, PREC)(expr)
        for a, b in zip(POINTS, POINTS[::-1])
    ]
    assert [pair[0] for pair in pairs] == alone


def _folded(columns, prec):
    """How a product was evaluated before: factor by factor, a list per factor, each step through _safe."""
    from physics.symbolic.numeric import RND, _safe

    out = list(columns[0])
    for column in columns[1:]:
        out = [
            None if a is None or b is None else _safe(libmp.mpf_mul, a, b, prec, RND)
            for a, b in zip(out, column)
        ]
    return out


def test_a_product_is_the_factor_by_factor_fold_point_by_point():
    import random

    rng = random.Random(5)
    values = [None, libmp.fzero, libmp.from_int(3), libmp.from_int(-7), from_rational(1, 3, PREC)]
    values += [
        libmp.from_man_exp(1, 2**40),
        libmp.from_man_exp(-5, -(2**40)),
    ]  # a product past the exponent range
    values += [from_rational(rng.randint(-(10**9), 10**9), rng.randint(1, 10**9), PREC) for _ in range(6)]
    for _ in range(300):
        columns = [[rng.choice(values) for _ in range(4)] for _ in range(rng.randint(2, 6))]
        evaluator = Evaluator({}, 4, PREC)
        assert evaluator._product(columns) == _folded(columns, PREC)
