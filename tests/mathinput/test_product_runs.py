"""A product is the tree the left-to-right fold Mul(Mul(a, b), c)... builds, with its size checks.

The builder multiplies a run of factors in one Mul call where that gives the very same tree and no
step of the fold would have refused anything (`build._Run`). These read each text twice, once with
the builder and once with the plain fold written out here (how products were built before), and
require the same sympy tree, argument for argument, or the same refusal (kind, message, position).
"""

from __future__ import annotations

import random

import pytest
import sympy

from physics.errors import AnswerError
from physics.mathinput import InputLimits, parse_math
from physics.mathinput import build as build_module
from physics.mathinput import reader as reader_module
from physics.mathinput.tree import Product
from tests.mathinput.support import names


class FoldingBuilder(build_module.Builder):
    """Every product as the fold, one Mul call and one size check per factor."""

    def _product(self, node: Product) -> sympy.Expr:
        result = self._build(node.first)
        for operator, factor in node.rest:
            value = self._build(factor)
            if operator == "/":
                value = build_module._reciprocal(value)
            result = self._checked(sympy.Mul(result, value))
        return result


DECLARED = names("x", "y", "z", "m", "M", "g", "theta", "k", "r", "L", "U0", "r0", "mu", "alpha")
SMALL = InputLimits(max_int_bits=64, max_exponent=6)

PRODUCTS = [
    # typical answers (bench/check_bench.py, bench/load.py) and their distinct-phase forms
    "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)**2)",
    "(-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)**2))*(m + 2 M)**2/(m**2 + 4 m M + 4 M**2)",
    "(M + m)*g*sin(theta)/(M + m*sin(theta)**2)",
    "M*m*g*cos(theta)/(M + m*sin(theta)**2)",
    "g*r**2/(r**2 + k**2)*(r + 3 k)^2/(r^2 + 6 r k + 9 k^2)",
    "12*U0/r0*((r0/r)**13 - (r0/r)**7)",
    "12*sqrt(U0/m)/r0",
    "(m + M)/m*sqrt(2*g*L*(1 - cos(theta)))",
    "2*(m + M)/m*sqrt(g*L)*sin(theta/2)",
    "g*(sin(alpha) - mu*cos(alpha))*(alpha + 5 mu)^2/(alpha^2 + 10 alpha mu + 25 mu^2)",
    "m g sin(theta) cos(theta) x y z",
    # a number next to a sum: the fold distributes it (2x + 2y), one Mul call would not
    "2*(x + y)*z",
    "x*2*(x + y)*z",
    "(x + y)*2*z",
    "-(x + y)*z*k",
    "x/x*2*(x + y)*z",
    "(2 x)/x*(x + y)*z",
    "(-x)/x*(x + y)*z",
    # a number opening the run or joining it: one Mul call, unless a sum stands alone beside it
    "14 m M",
    "1/2 m g^2 x",
    "2*x*(x + y)*z",
    "2*(x + y)^2*z",
    "2*x*3*y*(1/5)",
    "x*y*2*(x + y)",
    "(x + y)*2*3*z",
    "3*4*x*y",
    "1*x*y",
    "-2*x*y*z",
    "2*(x/2)*(x + y)*z",
    "2*(x + y)*(y + z)*k",
    "2*(3 (x + y))*z",
    "(2^40)*x*y*z",
    "2^200*x*y*z",
    "x*y*z*2^200*k",
    # repeated bases, numeric roots, exp
    "x*y*x*z",
    "x^2*y/x^2*z",
    "(x + y)^2*z/(x + y)*(x + y)^-1*k",
    "-(x + y)^2*(x + y)^-1*(x + y)^-1*z",
    "exp(x)*exp(y)*exp(-x)*z",
    "e*exp(x)*y*z",
    "sqrt(2)*sqrt(3)*sqrt(2)*x*y",
    "sqrt(2)*3^(2/3)*12^(1/3)*x",  # numeric roots merge in an order that depends on the grouping
    "x*sqrt(3)*2^(1/3)*6^(1/4)*12^(1/3)",
    "sqrt(x)*sqrt(x)*sqrt(x)*y",
    "sqrt(x^2)*sqrt(x^2)*sqrt(x^2)*y",
    "pi*pi*x*y",
    "sin(x)*sin(x)*y*z",
    "x*y*z/(x*y)*k",
    "x*y*z/(x*y*z)*(x + y)",
    "3/4*x*y*z",
    "x*y*z*(1/2)*(2/3)*k",
    "(3 x)*(5 y)*(7 z)/(105 x)*k",
    # sizes: the fold refuses at the step where a power or a number grows too large
    "x^4*x^4/x^4*y",
    "x^100*x^100/x^100*y",
    "(2^4000 x)*(2^4000 y)/(2^4000 z)*k",
    "(2^200 x)*(2^200 y)*(2^200 z)*k",
    "(2^40 x)*(2^40 y)/(2^40 z)*k",
    "(x + 2)^60 (x + 2)^60 y z",
    "0*x*y*z",
    "x*y*0*(x + y)",
    "log(0)*x*y",
]


def _read(text: str, limits: InputLimits) -> tuple[str, str] | tuple[type, str, int | None]:
    try:
        parsed = parse_math(text, DECLARED, limits=limits)
    except AnswerError as error:
        return type(error), error.message, error.position
    return sympy.srepr(parsed.expr), parsed.read_as.text


def _both(text: str, limits: InputLimits, monkeypatch: pytest.MonkeyPatch) -> None:
    built = _read(text, limits)
    with monkeypatch.context() as patched:
        patched.setattr(reader_module, "Builder", FoldingBuilder)
        folded = _read(text, limits)
    assert built == folded, text


@pytest.mark.parametrize("text", PRODUCTS)
def test_a_product_is_the_tree_the_fold_builds(text, monkeypatch):
    _both(text, InputLimits(), monkeypatch)


@pytest.mark.parametrize("text", PRODUCTS)
def test_a_product_is_refused_where_the_fold_refuses_it_under_small_limits(text, monkeypatch):
    _both(text, SMALL, monkeypatch)


PIECES = [
    "x", "y", "z", "m", "M", "k", "theta", "2", "3", "1/2", "0.5", "-1", "2^40", "2^200", "pi", "e",
    "sqrt(2)", "sqrt(x)", "x^2", "x^-1", "x^4", "(x + y)", "(x - y)", "(x + y)^2", "(x + y)^-1",
    "exp(x)", "exp(-x)", "sin(theta)", "cos(theta)", "(2 x)", "(-x)", "(3 y z)", "(x/y)",
]  # fmt: skip


@pytest.mark.parametrize("seed", range(6))
def test_random_products_are_the_trees_the_fold_builds(seed, monkeypatch):
    rng = random.Random(seed)
    for _ in range(120):
        factors = [rng.choice(PIECES) for _ in range(rng.randint(3, 7))]
        text = factors[0] + "".join(rng.choice(("*", "/", " ")) + f for f in factors[1:])
        _both(text, InputLimits(), monkeypatch)
        _both(text, SMALL, monkeypatch)
