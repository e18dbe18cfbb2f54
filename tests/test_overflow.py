"""The complex128 look that keeps sympy's evalf away from numbers of unbounded size: it vetoes an
expression whose value at the point leaves float64's range on the way, and nothing else."""

from __future__ import annotations

import pytest
import sympy

from physics.overflow import beyond_float, overflows, too_costly
from physics.symbolic.numeric import complex_value, from_int, from_rational

x, y = sympy.symbols("x y", positive=True)
E = sympy.exp


@pytest.mark.parametrize(
    ("expr", "vetoed"),
    [
        pytest.param(x * y + sympy.sin(x), False, id="ordinary"),
        pytest.param(sympy.sqrt(-x) * sympy.sqrt(-y), False, id="complex-intermediates"),
        pytest.param(sympy.log(-x), False, id="complex-log"),
        pytest.param(E(E(x)), False, id="two-exps-stay-finite"),
        pytest.param(E(E(E(E(x)))), True, id="exp-tower"),
        pytest.param(E(E(E(E(10 + sympy.sqrt(-x))))), True, id="exp-tower-through-a-complex-value"),
        pytest.param(sympy.sin(E(E(E(E(x))))), True, id="function-of-a-huge-number"),
        pytest.param(x ** (x ** (x**x)) * 0 + 10 ** (10**400 * x), True, id="huge-power"),
        pytest.param(1 / (x - 2), True, id="division-by-zero"),
        pytest.param(sympy.log(x - 2), True, id="log-of-zero"),
        pytest.param(sympy.factorial(x), False, id="small-factorial"),
        pytest.param(sympy.factorial(sympy.factorial(sympy.factorial(y))), True, id="factorial-tower"),
        pytest.param(sympy.factorial(sympy.sqrt(-x)), False, id="complex-factorial-left-to-evalf"),
        pytest.param(sympy.gamma(x), False, id="unknown-function-left-to-evalf"),
    ],
)
def test_overflow_vetoes_only_values_beyond_float64(expr, vetoed):
    assert overflows(expr, {x: from_int(2), y: from_int(3)}) is vetoed


@pytest.mark.parametrize(
    "value",
    [
        pytest.param(from_int(10**400), id="beyond-float64"),
        pytest.param(from_rational(1, 10**400, 133), id="underflows"),
    ],
)
def test_a_point_value_float64_cannot_hold_vetoes_nothing(value):
    # evalf computes log(x) there well; only an intermediate that overflows is a reason to stand aside.
    assert overflows(sympy.log(x) * y, {x: value, y: from_int(3)}) is False


def test_complex_value_of_an_exp_tower_is_none_not_a_huge_computation():
    point = {x: from_int(3)}
    assert complex_value(E(E(E(E(E(E(x)))))), point, 133) is None
    # Complex intermediates still go through evalf: sqrt(-x)^2 = -x, real.
    real, imaginary = complex_value(sympy.sqrt(-x) * sympy.sqrt(-x), point, 133)  # type: ignore[misc]
    assert (real, imaginary) == (from_int(-3), from_int(0))


def nested(level: int, times: int) -> sympy.Expr:
    expr = x**2 + 2
    for _ in range(times):
        expr = level(expr)
    return expr


@pytest.mark.parametrize(
    ("expr", "costly"),
    [
        pytest.param(sympy.sqrt(sympy.cos(2 * x)), False, id="sqrt-of-cos"),
        pytest.param(-sympy.I * (E(sympy.I * x) - E(-sympy.I * x)) / 2, False, id="euler-sine"),
        pytest.param(sympy.sqrt(-x) * sympy.sqrt(-y), False, id="two-roots"),
        pytest.param(nested(lambda e: sympy.log(e, 10), 3), False, id="log10-three-deep"),
        pytest.param(nested(lambda e: sympy.log(e, 10), 12), True, id="log10-twelve-deep"),
        pytest.param(
            nested(lambda e: 3 * (-1 - e) ** sympy.Rational(1, 3), 7), True, id="cube-roots-seven-deep"
        ),
        pytest.param(nested(lambda e: sympy.log(-e) * sympy.log(-1 - e), 4), True, id="wide-and-deep"),
    ],
)
def test_evalf_is_refused_where_its_nested_reevaluations_grow_too_costly(expr, costly):
    assert too_costly(expr) is costly


def test_complex_value_of_a_deep_nest_is_none_not_a_long_evalf():
    assert complex_value(nested(lambda e: sympy.log(e, 10), 12), {x: from_int(3)}, 133) is None


@pytest.mark.parametrize(
    ("constant", "beyond"),
    [
        pytest.param(E(2**62) * sympy.pi, True, id="overflows"),
        pytest.param(sympy.sinh(sympy.Integer(10) ** 40), True, id="sinh-of-a-big-integer"),
        pytest.param(sympy.Integer(2) ** 4000 * sympy.pi, True, id="big-integer"),
        pytest.param(E(40) * sympy.pi, False, id="large-but-finite"),
        pytest.param(
            1 / (sympy.sin(1) ** 2 + sympy.cos(1) ** 2 - 1 + sympy.pi - sympy.pi), False, id="near-zero"
        ),
        pytest.param(
            sympy.log(sympy.pi - sympy.pi + 0 * sympy.E), False, id="log-of-zero-is-not-an-overflow"
        ),
    ],
)
def test_beyond_float_is_an_overflow_only(constant, beyond):
    assert beyond_float(constant) is beyond
