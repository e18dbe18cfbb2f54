"""A problem's symbols in the forms the core needs: SymbolSpecs, sympy Symbols, and text declarations.

Every text (a range bound such as "pi/2") is read with the whitelist parser; the same names give
the same sympy Symbols here, in the engine and in the checker (assumptions come from the spec).
"""

from __future__ import annotations

from decimal import Decimal
from typing import TYPE_CHECKING

import sympy

from physics.checking import read_expression
from physics.checking import symbol_spec as checker_symbol_spec
from physics.symbolic import SymbolSpec, make_symbol
from problems.fields import SymbolDecl

if TYPE_CHECKING:
    from problems.schema import ProblemDocument


def read_bound(value: Decimal | str, path: tuple[str | int, ...]) -> sympy.Expr:
    """A range bound or limit value: an exact decimal, or expression text without symbols."""
    if isinstance(value, Decimal):
        numerator, denominator = value.as_integer_ratio()
        return sympy.Rational(numerator, denominator)
    return read_expression(value, {}, path)


def symbol_spec(name: str, decl: SymbolDecl) -> SymbolSpec:
    """The core's spec for one declared symbol, read exactly as the grading workers read it."""
    return checker_symbol_spec(decl.decl(name))


def symbol_specs(doc: ProblemDocument) -> dict[str, SymbolSpec]:
    return {name: symbol_spec(name, decl) for name, decl in doc.symbols.items()}


def symbol_table(doc: ProblemDocument) -> dict[str, sympy.Symbol]:
    """name -> sympy Symbol with the declared assumptions (positive unless said otherwise)."""
    return {name: make_symbol(spec) for name, spec in symbol_specs(doc).items()}
