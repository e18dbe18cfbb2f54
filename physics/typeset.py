"""LaTeX for people: products written in the order a physics text writes them.

sympy orders a product's factors alphabetically, so a worked solution read `V = -g m s \\sin θ`,
`\\ddot{x} m = N \\sin θ` and `M g m \\cos θ`, where every textbook writes `-m g s \\sin θ`, `m \\ddot{x}`,
`M m g \\cos θ`. `latex` is `sympy.latex` with each product's factors ordered by what they are: numbers,
then friction coefficients (μ m g), masses (m, M, m_1), sums in brackets ((M + m) \\ddot{X}), g, the
other quantities, velocities and accelerations (m \\ddot{x}), roots, and functions last (\\sin θ);
factors of one kind keep sympy's order. Only the printing changes: the expression is the same.
"""

from __future__ import annotations

import re
from typing import Any

import sympy
from sympy.printing.latex import LatexPrinter

_MASS = re.compile(r"^[mM](_?[A-Za-z0-9]+)?$")
_COEFFICIENT = re.compile(r"^mu(_?[A-Za-z0-9]+)?$")
_DOTTED = re.compile(r"\\d?dot\b|_d?dot$")

# Ranks of a factor's kind, in the order they are written.
NUMBER, CONSTANT, COEFFICIENT, MASS, SUM, GRAVITY, QUANTITY, RATE, ROOT, FUNCTION = range(10)


class _TextbookLatex(LatexPrinter):  # type: ignore[misc]
    def __init__(self, settings: dict[str, Any] | None = None) -> None:
        super().__init__(settings)
        self._order = self._settings["order"]  # sums are written in it; products in the textbook's

    def _print_Mul(self, expr: Any) -> str:
        if not isinstance(expr, sympy.Mul) or not expr.is_commutative:
            return str(super()._print_Mul(expr))
        if expr.could_extract_minus_sign():  # written as sympy writes it: "- " and the rest
            positive = -expr
            return f"- ({self._print(positive)})" if positive.is_Add else f"- {self._print(positive)}"
        factors = expr.as_ordered_factors()
        ordered = sorted(factors, key=self._rank)
        if ordered == factors:
            return str(super()._print_Mul(expr))
        self._settings["order"] = "none"  # sympy keeps an unevaluated product's factors as given
        try:
            return str(super()._print_Mul(sympy.Mul(*ordered, evaluate=False)))
        finally:
            self._settings["order"] = self._order

    def _print_Add(self, expr: Any, order: str | None = None) -> str:
        inner = self._settings["order"]
        self._settings["order"] = self._order
        try:
            return str(super()._print_Add(expr, order))
        finally:
            self._settings["order"] = inner

    def _rank(self, factor: sympy.Expr) -> int:
        if not factor.free_symbols:
            return NUMBER if factor.is_Number else CONSTANT
        base, exponent = factor.as_base_exp()
        if base.is_Add:
            return SUM if exponent.is_Integer else ROOT
        if isinstance(base, sympy.Symbol):
            return self._symbol_rank(base)
        if isinstance(base, sympy.Derivative):
            return RATE
        if isinstance(base, sympy.Function) or base.is_Function or exponent.free_symbols:
            return FUNCTION
        return ROOT

    def _symbol_rank(self, symbol: sympy.Symbol) -> int:
        name = symbol.name
        written = self._settings["symbol_names"].get(symbol, "")
        if _DOTTED.search(written) or _DOTTED.search(name):
            return RATE
        if _COEFFICIENT.match(name):
            return COEFFICIENT
        if _MASS.match(name):
            return MASS
        if name == "g":
            return GRAVITY
        return QUANTITY


def latex(expr: Any, **settings: Any) -> str:
    """`sympy.latex(expr, **settings)`, with products in a physics text's order."""
    return str(_TextbookLatex(settings).doprint(expr))
