"""float64 with error bounds vouches only for what multiprecision confirms: wherever it vouches for a
point, the 133-bit evaluator is defined there and within the bound; and a reference prepared from
float64 has exactly the points and values multiprecision alone would give it."""

from __future__ import annotations

import random

import numpy as np
import pytest
import sympy
from mpmath import libmp

from physics.dimensions import DIMENSIONLESS
from physics.symbolic import SymbolicContext, SymbolSpec, make_symbol, prepare_reference
from physics.symbolic import sampling as sampling_module
from physics.symbolic.bounded import BoundedEvaluator
from physics.symbolic.compare import PREC
from physics.symbolic.numeric import Evaluator, to_float
from physics.symbolic.sampling import PRECISE_RELATIVE, axis_for
from tests.symbolic.support import context

POINTS = 400
NEAR = sympy.Rational(1, 10**9)
HALF_PI = sympy.pi / 2


def spec(name: str, low: sympy.Expr, high: sympy.Expr) -> SymbolSpec:
    return SymbolSpec(name, DIMENSIONLESS, low=low, high=high)


X_NEAR_ONE = spec("x", 1 - NEAR, sympy.Integer(1))  # float64 keeps only 7 digits of 1 - x
X_NEAR_POLE = spec("x", HALF_PI - NEAR, HALF_PI)  # tan(x) near its pole
X_ACROSS = spec("x", sympy.Rational(1, 2), sympy.Rational(3, 2))  # both signs of x - 1
X_POSITIVE = SymbolSpec("x", DIMENSIONLESS)
# Points that float64 rounds onto 1.0 exactly: from above, and from below.
X_ABOVE_ONE = spec("x", sympy.Integer(1), 1 + sympy.Rational(1, 2**60))
X_BELOW_ONE = spec("x", 1 - sympy.Rational(1, 2**60), sympy.Integer(1))
X_WIDE = spec("x", sympy.Integer(1), sympy.Integer(10))

x_near_one, x_near_pole, x_across, x_positive = (
    make_symbol(s) for s in (X_NEAR_ONE, X_NEAR_POLE, X_ACROSS, X_POSITIVE)
)
x_wide = make_symbol(X_WIDE)
x_above_one, x_below_one = make_symbol(X_ABOVE_ONE), make_symbol(X_BELOW_ONE)
sin, cos = sympy.sin, sympy.cos

# (id, expression, spec of its one symbol): where float64 alone would be wrong about definedness or value.
CASES = [
    # Cancels exactly: multiprecision sets the sum to 0 (undefined divisor, sqrt(0) = 0), float64 has noise.
    ("cancelled-divisor", 1 / (sin(x_across) ** 2 + cos(x_across) ** 2 - 1), X_ACROSS),
    ("cancelled-root", sympy.sqrt(sin(x_across) ** 2 + cos(x_across) ** 2 - 1), X_ACROSS),
    ("cancelled-log", sympy.log((x_across + 1) ** 2 - x_across**2 - 2 * x_across), X_ACROSS),
    ("near-singular", 1 / (1 - x_near_one), X_NEAR_ONE),
    # float64 rounds x onto 1.0, where these are defined; in multiprecision they are not.
    ("rounded-onto-the-edge-asin", sympy.asin(x_above_one), X_ABOVE_ONE),
    ("rounded-onto-the-edge-acosh", sympy.acosh(x_below_one), X_BELOW_ONE),
    ("rounded-onto-the-edge-root", sympy.sqrt(x_below_one - 1), X_BELOW_ONE),
    ("rounded-onto-the-edge-cube-root", (x_below_one - 1) ** sympy.Rational(1, 3), X_BELOW_ONE),
    ("near-edge-asin", sympy.asin(x_near_one), X_NEAR_ONE),
    ("near-edge-acosh", sympy.acosh(2 - x_near_one), X_NEAR_ONE),
    ("near-edge-atanh", sympy.atanh(x_near_one), X_NEAR_ONE),
    ("near-pole-tan", sympy.tan(x_near_pole), X_NEAR_POLE),
    ("near-pole-sec", sympy.sec(x_near_pole), X_NEAR_POLE),
    ("root-of-either-sign", sympy.sqrt(x_across - 1), X_ACROSS),
    ("log-of-either-sign", sympy.log(x_across - 1), X_ACROSS),
    ("cube-root-of-either-sign", (x_across - 1) ** sympy.Rational(1, 3), X_ACROSS),
    ("negative-integer-power", (x_across - 1) ** -3, X_ACROSS),
    ("underflow", sympy.exp(-800 * x_wide), X_WIDE),
    ("overflow", sympy.exp(800 * x_wide), X_WIDE),
    ("huge-power", x_wide**400, X_WIDE),
    ("tiny-product", sympy.exp(-700 * x_wide) * sympy.exp(-700 * x_wide), X_WIDE),
    ("huge-trig-argument", sin(10**30 * x_wide), X_WIDE),
    ("ordinary", x_positive * sin(x_positive) / (1 + x_positive**2), X_POSITIVE),
]


def columns(symbol_spec: SymbolSpec) -> tuple[sympy.Symbol, list]:
    symbol = make_symbol(symbol_spec)
    axis = axis_for(symbol_spec, PREC)
    rng = random.Random(7)
    return symbol, [axis(rng.random()) for _ in range(POINTS)]


def within(value: float, bound: float, exact: tuple) -> bool:
    difference = libmp.mpf_abs(libmp.mpf_sub(libmp.from_float(value), exact, PREC, libmp.round_nearest))
    return bool(libmp.mpf_le(difference, libmp.from_float(bound)))


@pytest.mark.parametrize(
    ("expr", "symbol_spec"), [case[1:] for case in CASES], ids=[case[0] for case in CASES]
)
def test_a_vouched_point_is_defined_in_multiprecision_and_within_the_bound(expr, symbol_spec):
    symbol, column = columns(symbol_spec)
    floats = np.array([to_float(v) for v in column])
    bounded = BoundedEvaluator({symbol: floats}, POINTS)(expr)
    exact = Evaluator({symbol: column}, POINTS, PREC)(expr)
    vouched = bounded.vouched
    for index in np.flatnonzero(vouched):
        assert exact[index] is not None, f"vouched for an undefined point x = {floats[index]}"
        assert within(bounded.values[index], bounded.errors[index], exact[index]), floats[index]


@pytest.mark.parametrize(
    ("expr", "refused"),
    [
        (1 / (sin(x_across) ** 2 + cos(x_across) ** 2 - 1), "cancelled-divisor"),
        (sympy.sqrt(sin(x_across) ** 2 + cos(x_across) ** 2 - 1), "cancelled-root"),
        (sympy.asin(x_above_one), "rounded-onto-the-edge-asin"),
        (sympy.sqrt(x_below_one - 1), "rounded-onto-the-edge-root"),
        (sin(10**30 * x_wide), "huge-trig-argument"),
    ],
)
def test_float64_does_not_vouch_where_it_cannot_tell(expr, refused):
    case = next(c for c in CASES if c[0] == refused)
    symbol, column = columns(case[2])
    floats = np.array([to_float(v) for v in column])
    assert not BoundedEvaluator({symbol: floats}, POINTS)(expr).vouched.any()


def test_an_ordinary_expression_is_vouched_for_and_precise_everywhere():
    symbol, column = columns(X_POSITIVE)
    floats = np.array([to_float(v) for v in column])
    bounded = BoundedEvaluator({symbol: floats}, POINTS)(x_positive * sin(x_positive) / (1 + x_positive**2))
    assert bounded.precise(PRECISE_RELATIVE).all()


def multiprecision_only(monkeypatch, expected, ctx):
    """The reference prepared with float64 vouching for nothing."""
    with monkeypatch.context() as patch:
        patch.setattr(sampling_module, "_bounded", lambda exprs, floats, size: [None] * len(exprs))
        return prepare_reference(expected, ctx)


NEAR_ONE = SymbolicContext({x_near_one: X_NEAR_ONE})
ACROSS = SymbolicContext({x_across: X_ACROSS})
WIDE = SymbolicContext({x_wide: X_WIDE})
m, M, g, theta = (sympy.Symbol(name, positive=True) for name in ("m", "M", "g", "theta"))
WEDGE = -m * g * sin(theta) * cos(theta) / (M + m * sin(theta) ** 2)

REFERENCES = [
    pytest.param(WEDGE, context(WEDGE), id="wedge"),
    pytest.param(1 / (1 - x_near_one), NEAR_ONE, id="near-singular"),
    pytest.param(sympy.sqrt(x_across - 1), ACROSS, id="root-defined-on-half"),
    pytest.param(1 / (x_across - 1) ** 2, ACROSS, id="double-pole"),
    pytest.param(sympy.exp(-800 * x_wide), WIDE, id="underflow"),
    pytest.param(sympy.exp(800 * x_wide), WIDE, id="overflow"),
]


@pytest.mark.parametrize(("expected", "ctx"), REFERENCES)
def test_a_reference_gets_the_points_and_values_multiprecision_alone_gives(monkeypatch, expected, ctx):
    prepared = prepare_reference(expected, ctx)
    alone = multiprecision_only(monkeypatch, expected, ctx)
    assert prepared.sample.columns == alone.sample.columns
    assert prepared.values == alone.values
    assert prepared.precise_values == alone.precise_values
    if alone.floats.usable:
        assert prepared.floats.usable
        assert np.allclose(prepared.floats.values, alone.floats.values, rtol=PRECISE_RELATIVE, atol=0)


def test_a_typical_reference_is_prepared_without_multiprecision_values():
    prepared = prepare_reference(WEDGE, context(WEDGE))
    assert prepared.sample.required == (None,)  # computed only when a check needs them
    assert "values" not in prepared.__dict__
