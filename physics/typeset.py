"""LaTeX for people: products written in the order a physics text writes them.

sympy orders a product's factors alphabetically, so a worked solution read `V = -g m s \\sin θ`,
`\\ddot{x} m = N \\sin θ` and `M g m \\cos θ`, where every textbook writes `-m g s \\sin θ`, `m \\ddot{x}`,
`M m g \\cos θ`. `latex` is `sympy.latex` with each product's factors ordered by what they are:
numbers, then friction coefficients (μ m g), masses (m, M, m_1), g, the other quantities, velocities
and accelerations (m \\ddot{x}), roots, and functions last (\\sin θ); a sum goes with what it holds
((M + m) g, U_0 r_0^6 (r_0^6 - r^6), g (\\sin α - μ \\cos α)), and factors of one kind keep sympy's
order. Square roots are one root where that is exact (√(2 g L), not √2 √g √L), with the numbers a root's
sum holds outside it (2 √(R - r), not √(4 R - 4 r)). A sum starts with a term added (`T - m g`, not
`-m g + T`), and a sum of terms all subtracted gives its sign to the product (`-(M + m) g`, not
`(-M - m) g`), and a negative product's sign goes into a difference it holds (`(M + m) g L (1 - \\cos θ)`,
not `-(M + m) g L (\\cos θ - 1)`). Only the printing changes, never the expression.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

import sympy
from sympy.printing.latex import LatexPrinter

_MASS = re.compile(r"^[mM](_[A-Za-z0-9]+|[0-9]+)?$")  # m, M, m_1, m1, m_block
_COEFFICIENT = re.compile(r"^mu(_[A-Za-z0-9]+|[a-z])?$")  # mu, mu_k, mu_s, muk
_DOTTED = re.compile(r"\\d?dot\b|_d?dot$")

# Ranks of a factor's kind, in the order they are written.
NUMBER, CONSTANT, COEFFICIENT, MASS, GRAVITY, QUANTITY, RATE, ROOT, FUNCTION = range(9)


class _TextbookLatex(LatexPrinter):  # type: ignore[misc]
    def __init__(self, settings: dict[str, Any] | None = None) -> None:
        super().__init__(settings)
        self._order = self._settings["order"]  # sums are written in it; products in the textbook's

    def _print_Pow(self, expr: Any) -> str:
        parts = one_root([expr])  # a root alone: √(4 R - 4 r) is 2 √(R - r), as in a product
        if len(parts) > 1:
            return str(self._print(sympy.Mul(*parts, evaluate=False)))
        return str(super()._print_Pow(expr))

    def _print_Mul(self, expr: Any) -> str:
        if not isinstance(expr, sympy.Mul) or not expr.is_commutative:
            return str(super()._print_Mul(expr))
        negative = bool(expr.could_extract_minus_sign())
        factors = list((-expr if negative else expr).as_ordered_factors())
        changed = [*factors]
        for i, factor in enumerate(changed):
            if _all_subtracted(factor):  # (-M - m) g is -(M + m) g
                changed[i], negative = -factor, not negative
        mixed = [i for i, factor in enumerate(changed) if _mixed(factor)]
        if negative and mixed:  # -(M + m) g L (cos θ - 1) is (M + m) g L (1 - cos θ)
            base, exponent = changed[mixed[-1]].as_base_exp()
            changed[mixed[-1]], negative = sympy.Pow(-base, exponent), False
        ordered = sorted(map(_divisor_root, one_root(changed)), key=self._place)
        if ordered == factors:
            positive = sympy.Mul(*factors)
            written = (
                self._print(positive)
                if len(factors) == 1
                else self._in_order(self._order, super()._print_Mul, positive)
            )
        else:
            # sympy keeps an unevaluated product's factors as given
            written = self._in_order("none", super()._print_Mul, sympy.Mul(*ordered, evaluate=False))
        if not negative:
            return str(written)
        return rf"- \left({written}\right)" if len(ordered) == 1 and ordered[0].is_Add else f"- {written}"

    def _print_Add(self, expr: Any, order: str | None = None) -> str:
        terms: list[sympy.Expr] = self._in_order(self._order, self._as_ordered_terms, expr, order)
        # A sum starts with a term added, as it is written: T - m g, (m_2 - m_1 sin θ) g, not -m g + T.
        leading = next((i for i, term in enumerate(terms) if not term.could_extract_minus_sign()), 0)
        if not leading:
            return str(self._in_order(self._order, super()._print_Add, expr, order))
        terms.insert(0, terms.pop(leading))
        return str(self._in_order("none", super()._print_Add, sympy.Add(*terms, evaluate=False)))

    def _in_order(self, order: str | None, write: Callable[..., Any], *args: Any) -> Any:
        """`write(*args)` with the printer's order setting (its `order`: sympy's default is None; "none"
        keeps an unevaluated sum's or product's arguments as given)."""
        outer = self._settings["order"]
        self._settings["order"] = order
        try:
            return write(*args)
        finally:
            self._settings["order"] = outer

    def _place(self, factor: sympy.Expr) -> tuple[int, bool]:
        """Where a factor goes: by its rank, and a sum after the factors of its rank (m (…), U_0 r_0^6
        (r_0^6 - r^6))."""
        base, exponent = factor.as_base_exp()
        return self._rank(factor), bool(base.is_Add and exponent.is_Integer)

    def _rank(self, factor: sympy.Expr) -> int:
        if not factor.free_symbols:
            return NUMBER if factor.is_Number else CONSTANT
        base, exponent = factor.as_base_exp()
        if base.is_Add:
            # a sum goes with what it holds: (M + m) with the masses, (1 - cos θ) with the functions
            if not exponent.is_Integer:
                return ROOT
            return max(self._rank(f) for term in base.args for f in sympy.Mul.make_args(term))
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


def one_root(factors: list[sympy.Expr]) -> list[sympy.Expr]:
    """A product's square roots as one: √2 √g √L √(1 - cos θ) is written √(2 g L (1 - cos θ)), and
    √L √g/√(cos α) is √(L g/cos α). Exact where at most one base above the line and one below it may be
    negative, wherever the roots' product is real (√a √b = √(a b) when a ≥ 0; √a/√b = √(a/b) unless
    a > 0 > b, where it is imaginary), as a reference is on its domain; otherwise left apart."""
    split = _numbers_out(factors)
    above = [f for f in split if f.is_Pow and f.exp == sympy.S.Half]
    below = [f for f in split if f.is_Pow and f.exp == -sympy.S.Half]
    unsure_above = [f for f in above if not f.base.is_nonnegative]
    unsure_below = [f for f in below if not f.base.is_positive]
    if len(above) + len(below) < 2 or len(unsure_above) > 1 or len(unsure_below) > 1:
        return factors if split == factors else split
    if not above:  # 1/√(G M), not √(1/(G M))
        merged = sympy.Pow(sympy.Mul(*(f.base for f in below), evaluate=False), -sympy.S.Half, evaluate=False)
    elif below:  # a quotient, which a printer writes as a fraction only when it is evaluated
        # one product, not a product over a product: 35 (R - r) would be distributed, 35 R - 35 r
        radicand = sympy.Mul(*(f.base for f in above), *(1 / f.base for f in below))
        merged = sympy.Pow(radicand, sympy.S.Half, evaluate=False)
    else:
        merged = sympy.Pow(sympy.Mul(*(f.base for f in above), evaluate=False), sympy.S.Half, evaluate=False)
    return [f for f in split if f not in above and f not in below] + [merged]


def _numbers_out(factors: list[sympy.Expr]) -> list[sympy.Expr]:
    """The factors with each root's sum freed of its numeric factor, as a teacher writes the number
    outside: √(4 R - 4 r) is 2 √(R - r), √2 √(2 - 2 cos θ) is 2 √(1 - cos θ). `factors` itself when
    no root holds one."""
    split: list[sympy.Expr] = []
    for factor in factors:
        base, power = factor.as_base_exp()
        inverted = base.is_Pow and base.exp == -1  # √(1/(7 R - 7 r))
        total = base.base if inverted else base
        content, rest = total.primitive() if abs(power) == sympy.S.Half and total.is_Add else (1, total)
        if content == 1:
            split.append(factor)
            continue
        if inverted:
            content, rest = 1 / content, 1 / rest
        split += [sympy.Pow(content, power), sympy.Pow(rest, power)]
    if len(split) == len(factors):
        return factors
    numeric = sympy.Mul(*(f for f in split if not f.free_symbols))  # √2 √2 is 2
    return [*sympy.Mul.make_args(numeric), *(f for f in split if f.free_symbols)]


def _divisor_root(factor: sympy.Expr) -> sympy.Expr:
    """1/√(G M) as one over its root: sympy's fraction would evaluate the divisor √(G M) and split it
    into √G √M again, where the typed text keeps 1/sqrt(G*M)."""
    if factor.is_Pow and factor.exp == -sympy.S.Half and factor.base.is_Mul:
        return sympy.Pow(sympy.Pow(factor.base, sympy.S.Half, evaluate=False), -1, evaluate=False)
    return factor


def _all_subtracted(factor: sympy.Expr) -> bool:
    return bool(factor.is_Add) and all(term.could_extract_minus_sign() for term in factor.args)


def _mixed(factor: sympy.Expr) -> bool:
    """A difference, or an odd power of one (1/(r - R)): a sum with terms added and subtracted, whose
    sign turns with the factor's."""
    base, exponent = factor.as_base_exp()
    if not (exponent.is_Integer and exponent % 2):
        return False
    signs = [t.could_extract_minus_sign() for t in base.args] if base.is_Add else []
    return any(signs) and not all(signs)


def latex(expr: Any, **settings: Any) -> str:
    """`sympy.latex(expr, **settings)`, with products in a physics text's order (and arctan, not
    sympy's \\operatorname{atan})."""
    return str(_TextbookLatex({"inv_trig_style": "full", **settings}).doprint(expr))
