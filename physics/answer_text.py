"""A sympy expression written as a student would type it, for tests that type the engine's answers,
and as an instructor types it, for the messages that quote the engine's expressions to them.

sympy's own printer writes names the whitelist parser does not read (`Abs`), and some forms have no
spelling at all (`Piecewise`, `Min`, `sign`): those are not typeable, and `student_text` says so with
None rather than producing text the parser will refuse. `typed_text` always gives text, with `^` for
powers (`k1*(-L1 + leftLength)^2/2`, not sympy's `**`).
"""

from __future__ import annotations

from functools import cache

import sympy
from sympy.printing.str import StrPrinter

from physics import typeset
from physics.errors import AnswerError
from physics.mathinput import parse_math
from physics.mathinput.vocabulary import FUNCTIONS

_STRUCTURE = (sympy.Add, sympy.Mul, sympy.Pow, sympy.Symbol, sympy.Number, sympy.NumberSymbol)


@cache
def typeable_functions() -> frozenset[type]:
    """The sympy function classes the parser builds, learnt from the parser itself."""
    x = sympy.Symbol("x", real=True)  # not positive: abs(x) would simplify away
    found: set[type] = set()
    for name in FUNCTIONS:
        try:
            built = parse_math(f"{name}(x)", {"x": x}).expr
        except AnswerError:
            continue
        found.update(
            type(node) for node in sympy.preorder_traversal(built) if isinstance(node, sympy.Function)
        )
    return frozenset(found)


class _StudentPrinter(StrPrinter):  # type: ignore[misc]
    def _print_Abs(self, expr: sympy.Abs) -> str:
        return f"abs({self._print(expr.args[0])})"

    def _print_Exp1(self, expr: sympy.Basic) -> str:
        return "exp(1)"  # `e` may be a declared symbol


class _TypedPrinter(_StudentPrinter):
    def _print_Mul(self, expr: sympy.Mul) -> str:
        # one root, as a teacher writes it: sqrt(L*g/cos(alpha))*sin(alpha), not sqrt(L)*sqrt(g)*...
        factors = list(expr.args)
        merged = typeset.one_root(factors)
        if merged is factors:
            return str(super()._print_Mul(expr))
        if len(merged) == 1:  # the root alone
            return str(self._print(merged[0]))
        return str(super()._print_Mul(sympy.Mul(*merged, evaluate=False)))

    def _print_Pow(self, expr: sympy.Pow, rational: bool = False) -> str:
        parts = typeset.one_root([expr])  # a root alone: sqrt(4*R - 4*r) is 2*sqrt(R - r), as in a product
        if len(parts) > 1:
            return str(self._print(sympy.Mul(*parts, evaluate=False)))
        # sympy joins base and exponent, both already written by this printer, with its one `**`
        text: str = super()._print_Pow(expr, rational)
        return text.replace("**", "^")


def typed_text(value: object) -> str:
    """An expression, or a list, tuple or mapping of them, as an instructor types it: for messages."""
    text: str = _TypedPrinter().doprint(value)
    return text


def is_typeable(expr: sympy.Basic) -> bool:
    functions = typeable_functions()
    return all(
        isinstance(node, _STRUCTURE) or type(node) in functions for node in sympy.preorder_traversal(expr)
    )


def student_text(expr: sympy.Basic) -> str | None:
    """Text the whitelist parser reads back as `expr`; None when a student could not type it."""
    if not is_typeable(expr):
        return None
    text: str = _StudentPrinter().doprint(expr)
    return text
