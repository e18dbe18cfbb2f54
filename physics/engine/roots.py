"""Which roots of an equation a model allows for the symbol solved for: real, of the sign the symbol is
declared with (a symbol of the table is positive unless said otherwise), and inside its declared range
(`domain.ranges`, or the symbol table's `range`), at every sampled point of the domain. Of several such
roots, those where the expressions `domain.positive` keeps positive that involve the symbol stay so (or
reach zero: a threshold at the domain's edge): how an author chooses between roots that only an
inequality separates (a banked curve's least and greatest speeds lie either side of its design speed,
`g*R*tan(theta) - v^2` positive picks the least).

`sympy.solve` returns every branch: ±√ for a speed, acos(2/3) and 2π − acos(2/3) for an angle. When a
root's sign rests on the domain (a cos(θ) with θ in (0, π/2)), sympy's assumptions cannot decide it;
the domain's points can.
"""

from __future__ import annotations

import sympy

from physics.engine.model import Model
from physics.engine.proof import domain_points

# several roots: the author says which side of what separates them (a banked curve's least and
# greatest speeds, either side of the design speed)
CHOOSE = (
    ": say which one the problem means, by {0}'s range (domain.ranges) or by an inequality that "
    "separates them under domain.positive (the answer may reach its edge)"
)
POINTS = 12
SEED = 23
_TOLERANCE = 1e-9


def admissible(roots: list[sympy.Expr], symbol: sympy.Symbol, model: Model) -> list[sympy.Expr]:
    """The roots the symbol's declared sign and range allow (a root that cannot be evaluated is kept)."""
    bounds = declared_range(symbol, model)
    kept = []
    for root in roots:
        if root.is_real is False:
            continue
        if (symbol.is_positive or symbol.is_nonnegative) and root.is_negative:
            continue
        if symbol.is_negative and root.is_positive:
            continue
        if _allowed_at_points(root, symbol, bounds, model):
            kept.append(root)
    return chosen_by_positives(kept, symbol, model)


def declared_range(symbol: sympy.Symbol, model: Model) -> tuple[float, float] | None:
    for declared, low, high in (*model.ranges, *model.symbol_ranges):
        if declared == symbol:
            return float(low), float(high)
    return None


def _allowed_at_points(
    root: sympy.Expr, symbol: sympy.Symbol, bounds: tuple[float, float] | None, model: Model
) -> bool:
    if root.free_symbols - set(model.parameters):
        return True
    for point in domain_points(model, POINTS, seed=SEED):
        value = sympy.N(root.subs(point), 30)
        if not value.is_number:
            return True
        real, imaginary = (float(v) for v in value.as_real_imag())
        scale = max(1.0, abs(real))
        if abs(imaginary) > _TOLERANCE * scale:
            return False
        if (symbol.is_positive and real <= 0) or (symbol.is_nonnegative and real < -_TOLERANCE * scale):
            return False
        if symbol.is_negative and real >= 0:
            return False
        if (
            bounds is not None
            and not bounds[0] - _TOLERANCE * scale <= real <= bounds[1] + _TOLERANCE * scale
        ):
            return False
    return True


def chosen_by_positives(roots: list[sympy.Expr], symbol: sympy.Symbol, model: Model) -> list[sympy.Expr]:
    """Of several roots, those that keep the `domain.positive` expressions involving the symbol at every
    sampled point; all of them where none does (a single root is never dropped: the positives bound the
    other symbols' sampling, not where an answer may lie)."""
    if len(roots) < 2:
        return roots
    chosen = [r for r in roots if _keeps_positives_at_points(r, symbol, model)]
    return chosen or roots


def _keeps_positives_at_points(root: sympy.Expr, symbol: sympy.Symbol, model: Model) -> bool:
    if root.free_symbols - set(model.parameters):
        return True
    for point in domain_points(model, POINTS, seed=SEED):
        value = complex(sympy.N(root.subs(point), 30))
        if not keeps_positives(value.real, symbol, model, point):
            return False
    return True


def keeps_positives(
    value: float, symbol: sympy.Symbol, model: Model, point: dict[sympy.Symbol, sympy.Expr]
) -> bool:
    """Whether every expression `domain.positive` keeps positive and `symbol` appears in is not negative
    at the point with the symbol at `value` (zero allowed: a threshold lies on the domain's edge)."""
    for expr in model.positive:
        if symbol not in expr.free_symbols:
            continue
        found = complex(sympy.N(expr.subs({**point, symbol: value}), 20))
        if found.real < -_TOLERANCE * max(1.0, abs(found.real), abs(value)):
            return False
    return True
