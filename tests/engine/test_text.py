"""The fallback whitelist reader of model expressions (used when physics.mathinput is unavailable)."""

from __future__ import annotations

import pytest
import sympy

from physics.engine.text import _Parser
from physics.errors import AnswerError, UnknownFunction, UnknownSymbol

M = sympy.Symbol("m", positive=True)
TH = sympy.Symbol("theta", positive=True)
X = sympy.Symbol("x_block", real=True)
NAMES = {"m": M, "theta": TH, "x_block": X}


@pytest.mark.parametrize(("text", "expected"), [
    pytest.param("m*sin(theta)^2", M * sympy.sin(TH) ** 2, id="caret-power"),
    pytest.param("m*sin(theta)**2", M * sympy.sin(TH) ** 2, id="double-star-power"),
    pytest.param("-x_block/2 + 0.5", -X / 2 + sympy.Rational(1, 2), id="exact-decimal"),
    pytest.param("pi/2", sympy.pi / 2, id="pi"),
    pytest.param("2^-1", sympy.Rational(1, 2), id="negative-exponent"),
    pytest.param("4.58e3", sympy.Integer(4580), id="exponent-notation"),
    pytest.param("sqrt(m)", sympy.sqrt(M), id="function"),
])
def test_fallback_reader_builds_the_expression(text: str, expected: sympy.Expr) -> None:
    assert sympy.simplify(_Parser(text, NAMES).parse() - expected) == 0


@pytest.mark.parametrize(("text", "error"), [
    pytest.param("m*q", UnknownSymbol, id="undeclared-name"),
    pytest.param("eval(m)", UnknownFunction, id="unlisted-function"),
    pytest.param("m.__class__", AnswerError, id="attribute-access"),
    pytest.param("(m", AnswerError, id="unbalanced"),
    pytest.param("", AnswerError, id="empty"),
    pytest.param("m m", AnswerError, id="juxtaposition"),
])
def test_fallback_reader_refuses_anything_else(text: str, error: type[Exception]) -> None:
    with pytest.raises(error):
        _Parser(text, NAMES).parse()
