"""`simplify` and `solve`, remembered within one derivation.

The methods meet the same expressions again and again: Lagrange's solution is simplified when solved,
again when read at the state (already substituted), again when the simplest of the methods' answers is
chosen; each method simplifies the same generalized force, the same stability slope. `sympy.simplify`
is most of a derivation's time and sympy does not cache it, so it is cached here: the same expression
in, the same result out, only computed once.

Inside `simplify`, most of the time is trigsimp's rewriting of each subexpression (sympy's `_futrig`,
applied bottom up), and different expressions share most of their subexpressions (sin(theta)**2 +
cos(theta)**2 in every denominator of an incline's solution): three calls in four meet a subexpression
already rewritten in this derivation. `_futrig` is a function of its argument alone, so it is
remembered too, which leaves every result as it was; so is `factor` as trigsimp calls it (on one
argument), which the rewriting of new subexpressions applies again to the old ones inside them.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable

import sympy

MAX_REMEMBERED = 4096  # a bound, should a caller outside `derive` never clear it

_remembered: dict[sympy.Basic, sympy.Expr] = {}
_rewritten: dict[sympy.Basic, sympy.Basic] = {}  # by sympy's _futrig
_factored: dict[sympy.Basic, sympy.Basic] = {}  # by sympy's factor inside trigsimp
_solved: dict[tuple[sympy.Basic, sympy.Symbol], list[sympy.Expr]] = {}


def integrate(expr: sympy.Expr, limits: tuple[sympy.Symbol, sympy.Expr, sympy.Expr]) -> sympy.Expr:
    """`sympy.integrate(expr, limits)`, first without the heuristic Risch algorithm (`heurisch`), sympy's
    last resort, which alone may take minutes on what its table and substitution rules integrate at once
    (a spring pulling across a rough slope: friction's work through the square root of its length, in
    asinh, minutes against seconds); with it only where they leave an integral."""
    found = sympy.integrate(expr, limits, heurisch=False)
    return found if not found.has(sympy.Integral) else sympy.integrate(expr, limits)


def simplify(expr: sympy.Expr) -> sympy.Expr:
    """`sympy.simplify(expr)`, from memory when this derivation has simplified expr already."""
    if not isinstance(expr, sympy.Basic):  # a mutable Matrix cannot be a key
        return sympy.simplify(expr)
    found = _remembered.get(expr)
    if found is None:
        found = sympy.simplify(expr)
        if len(_remembered) >= MAX_REMEMBERED:
            _remembered.clear()
        _remembered[expr] = found
    return found


def solve(expr: sympy.Expr, symbol: sympy.Symbol) -> list[sympy.Expr]:
    """`sympy.solve(expr, symbol)`, from memory when this derivation has solved it already: each method
    finds the same equilibrium among the roots of the same generalized force."""
    key = (expr, symbol)
    found = _solved.get(key)
    if found is None:
        found = sympy.solve(expr, symbol)
        if len(_solved) >= MAX_REMEMBERED:
            _solved.clear()
        _solved[key] = found
    return list(found)  # the caller's own list


def forget() -> None:
    """Start afresh: each derivation pays for its own simplifications, so vetting times stay honest."""
    _remembered.clear()
    _rewritten.clear()
    _factored.clear()
    _solved.clear()


def _remembering(
    rewrite: Callable[..., sympy.Basic], memory: dict[sympy.Basic, sympy.Basic]
) -> Callable[..., sympy.Basic]:
    """rewrite(expr), from memory when this derivation has rewritten expr already (other calls as they are)."""

    def remembered(expr: sympy.Basic, *args: object, **options: object) -> sympy.Basic:
        if args or options or not isinstance(expr, sympy.Basic):
            return rewrite(expr, *args, **options)
        found = memory.get(expr)
        if found is None:
            found = rewrite(expr)
            if len(memory) >= 4 * MAX_REMEMBERED:  # subexpressions: many more than whole ones
                memory.clear()
            memory[expr] = found
        return found

    remembered.__wrapped__ = rewrite  # type: ignore[attr-defined]
    return remembered


# sympy's `trigsimp` module (the package's name `sympy.simplify.trigsimp` is the function); `futrig` looks
# `_futrig` and `factor` up there at each call. Guarded so that a second import wraps them only once.
_trigsimp_module = importlib.import_module("sympy.simplify.trigsimp")
if not hasattr(_trigsimp_module._futrig, "__wrapped__"):
    _trigsimp_module._futrig = _remembering(_trigsimp_module._futrig, _rewritten)  # type: ignore[attr-defined]
    _trigsimp_module.factor = _remembering(_trigsimp_module.factor, _factored)  # type: ignore[attr-defined]


def single_angles(expr: sympy.Basic) -> sympy.Basic:
    """`expr` as a worked solution writes it. Where `simplify` chose double angles (m g sin 2θ/(m cos 2θ
    - 2M - m)), the same function in sin θ and cos θ when that is no longer, as textbooks write it
    (-m g sin θ cos θ/(M + m sin²θ)); each side of an equation alike. Only the written form changes."""
    if isinstance(expr, sympy.core.relational.Relational):
        return expr.func(*(single_angles(side) for side in expr.args), evaluate=False)
    if not isinstance(expr, sympy.Expr) or not _double_angles(expr):
        return expr
    expanded = sympy.expand_trig(expr)
    angles = {f.args[0] for f in expanded.atoms(sympy.sin, sympy.cos)}
    rewrites: list[dict[sympy.Basic, sympy.Basic]] = [{}]
    for angle in angles:
        rewrites += [
            {sympy.cos(angle) ** 2: 1 - sympy.sin(angle) ** 2},
            {sympy.sin(angle) ** 2: 1 - sympy.cos(angle) ** 2},
        ]
    candidates = [sympy.factor(sympy.cancel(expanded.subs(rewrite))) for rewrite in rewrites]
    limit = sympy.count_ops(expr)
    fitting = [c for c in candidates if not _double_angles(c) and sympy.count_ops(c) <= limit]
    # The fewest operations, then the fewest minus signs: M + m sin²θ rather than -M + m cos²θ - m.
    return min(fitting, key=lambda c: (sympy.count_ops(c), str(c).count("-")), default=expr)


def _double_angles(expr: sympy.Basic) -> bool:
    """sin or cos of an even multiple of an angle (sin 2θ, cos 4φ)."""
    for function in expr.atoms(sympy.sin, sympy.cos):
        factor, _ = function.args[0].as_coeff_Mul()
        if factor.is_Integer and factor % 2 == 0 and factor != 0:
            return True
    return False
