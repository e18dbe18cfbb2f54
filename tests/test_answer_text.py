"""Expressions quoted to an instructor read as they would type them: `^` for powers, parsed back the same."""

from __future__ import annotations

import pytest
import sympy

from physics.answer_text import typed_text
from physics.mathinput import parse_math

k1, L1, left, b, m, x = sympy.symbols("k1 L1 leftLength b m x", positive=True)
NAMES = {s.name: s for s in (k1, L1, left, b, m, x)}

# (expression, how an instructor types it)
TYPED = [
    (b**2, "b^2"),
    (k1 * (left - L1) ** 2 / 2, "k1*(-L1 + leftLength)^2/2"),
    (-(x**2), "-x^2"),
    (x ** sympy.Rational(-3, 2), "x^(-3/2)"),
    (1 / (m * x**2), "1/(m*x^2)"),
    (2 ** (x**2), "2^(x^2)"),
    (sympy.sqrt(4 * m * x - b**2), "sqrt(-b^2 + 4*m*x)"),
    (sympy.Abs(x - L1), "abs(L1 - x)"),
    (sympy.exp(-b * x / (2 * m)), "exp(-b*x/(2*m))"),
    # a product's square roots are one root, as a teacher writes it
    (sympy.sqrt(k1 / m), "sqrt(k1/m)"),
    (2 * sympy.pi * sympy.sqrt(2 * x * m), "2*pi*sqrt(2*m*x)"),
    (x ** sympy.Rational(3, 2) / (sympy.sqrt(b) * sympy.sqrt(m)), "x^(3/2)/sqrt(b*m)"),
    # a number leaves the root, as it would from sqrt(4*m): not sqrt(4*x - 4*b) nor sqrt(2*m*(2 - 2*cos(x)))
    (sympy.sqrt(4 * x - 4 * b), "2*sqrt(-b + x)"),
    (m * sympy.sqrt(9 * x + 9 * b), "3*m*sqrt(b + x)"),
    (1 / sympy.sqrt(4 * x + 4 * b), "1/(2*sqrt(b + x))"),
    (sympy.sqrt(2) * sympy.sqrt(m) * sympy.sqrt(2 - 2 * sympy.cos(x)), "2*sqrt(m*(1 - cos(x)))"),
    # the surd left under the root stays a factor of the sum, not distributed over it
    (
        2 * sympy.sqrt(5) * sympy.pi * sympy.sqrt(7 * x - 7 * b) / (5 * sympy.sqrt(m)),
        "2*pi*sqrt(35*(-b + x)/m)/5",
    ),
]


@pytest.mark.parametrize(("expr", "typed"), TYPED, ids=[t for _, t in TYPED])
def test_an_expression_reads_as_typed_and_parses_back(expr: sympy.Expr, typed: str) -> None:
    assert typed_text(expr) == typed
    assert sympy.simplify(parse_math(typed, NAMES).expr - expr) == 0


def test_a_list_of_roots_reads_as_typed() -> None:
    assert typed_text([-sympy.sqrt(b / m), x**2]) == "[-sqrt(b/m), x^2]"


def test_a_root_over_a_root_of_unknown_sign_is_one_root_where_the_quotient_is_real() -> None:
    """A conical pendulum's speed: sqrt(b)/sqrt(cos(x)) is sqrt(b/cos(x)) wherever it is real (cos(x) > 0)."""
    speed = sympy.sqrt(b) * sympy.sin(x) / sympy.sqrt(sympy.cos(x))
    typed = typed_text(speed)
    assert typed == "sqrt(b/cos(x))*sin(x)"
    assert abs(complex((parse_math(typed, NAMES).expr - speed).subs({b: 2.0, x: 0.4}))) < 1e-12


def test_roots_of_two_bases_of_unknown_sign_stay_apart() -> None:
    """sqrt(u)*sqrt(v) is -sqrt(u*v) where both are negative: one root would be another number."""
    u, v = sympy.symbols("u v", real=True)
    assert typed_text(sympy.sqrt(u) * sympy.sqrt(v)) == "sqrt(u)*sqrt(v)"
