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
]


@pytest.mark.parametrize(("expr", "typed"), TYPED, ids=[t for _, t in TYPED])
def test_an_expression_reads_as_typed_and_parses_back(expr: sympy.Expr, typed: str) -> None:
    assert typed_text(expr) == typed
    assert sympy.simplify(parse_math(typed, NAMES).expr - expr) == 0


def test_a_list_of_roots_reads_as_typed() -> None:
    assert typed_text([-sympy.sqrt(b / m), x**2]) == "[-sqrt(b)/sqrt(m), x^2]"
