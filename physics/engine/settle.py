"""What the model's declared inequalities settle in an expression: |R − r| is R − r where R > r is
declared, atan(tan θ) is θ where θ ranges inside (−π/2, π/2), √(1/cos α) is 1/√(cos α) where cos α > 0.

sympy simplifies under the symbols' own assumptions only, so a ball rolling in a bowl written with an
angle (`sqrt(x^2 + y^2)` of a centre at distance R − r, `atan(x/(-y))` of its angle) leaves
`R - r - abs(R - r)` where the model states R − r > 0. Each absolute value whose argument keeps one sign
on the domain (declared positive, or the same sign at every sampled point, coordinates inside their
declared ranges) loses its bars; an inverse function of its own function loses both where the
argument lies inside the inverse's principal range.
"""

from __future__ import annotations

import random

import sympy

from physics.engine import tidy
from physics.engine.model import Model
from physics.engine.proof import domain_points

POINTS = 12
SEED = 29
_HALF_PI = sympy.pi / 2
# inverse function, its own function, and the principal range where inverse(own(x)) = x
_INVERSES = (
    (sympy.atan, sympy.tan, (-_HALF_PI, _HALF_PI)),
    (sympy.asin, sympy.sin, (-_HALF_PI, _HALF_PI)),
    (sympy.acos, sympy.cos, (sympy.Integer(0), sympy.pi)),
)


def settle(expr: sympy.Expr, model: Model) -> sympy.Expr:
    """expr with the absolute values, inverse-of-own-function pairs and radicals of quotients the domain
    decides removed."""
    settled = expr
    if any(_root_of_quotient(power) for power in expr.atoms(sympy.Pow)):
        settled = expr.replace(_root_of_quotient, lambda e: _split_root(e, model))
    if not settled.has(sympy.Abs, sympy.atan, sympy.asin, sympy.acos):
        return settled
    settled = settled.replace(lambda e: isinstance(e, sympy.Abs), lambda e: _unsigned(e, model))
    for inverse, own, (low, high) in _INVERSES:
        settled = settled.replace(
            lambda e, inverse=inverse: isinstance(e, inverse),
            lambda e, own=own, low=low, high=high: _inverted(e, own, low, high, model),
        )
    return settled


def _root_of_quotient(expr: sympy.Basic) -> bool:
    """A fractional power of a product with a symbolic divisor, sqrt(1/cos(alpha)): sympy splits it only
    where it knows the divisor's sign, so a conical pendulum's period would read
    2 pi sqrt(L)/(sqrt(g) sqrt(1/cos(alpha))). Sums are left whole (sqrt(g/L - w^2) as written)."""
    return (
        isinstance(expr, sympy.Pow)
        and expr.exp.is_Rational
        and not expr.exp.is_Integer
        and isinstance(expr.base, sympy.Pow | sympy.Mul)
        and bool(expr.base.as_numer_denom()[1].free_symbols)
    )


def _split_root(power: sympy.Pow, model: Model) -> sympy.Expr:
    """(n/d)^r as n^r/d^r, which holds for every n where d > 0: the domain must keep d positive."""
    numerator, denominator = power.base.as_numer_denom()
    if _sign(denominator, model) != 1:
        return power
    return numerator**power.exp / denominator**power.exp


def _unsigned(absolute: sympy.Expr, model: Model) -> sympy.Expr:
    argument = absolute.args[0]
    sign = _sign(argument, model)
    return absolute if sign == 0 else sign * argument


def _inverted(call: sympy.Expr, own: type, low: sympy.Expr, high: sympy.Expr, model: Model) -> sympy.Expr:
    inner = tidy.simplify(call.args[0])
    if inner.func is not own:
        return call
    angle = inner.args[0]
    declared = _declared_range(angle, model)
    if declared is not None:  # a coordinate or symbol with a range: its bounds decide, not samples
        inside = bool((declared[0] - low).is_nonnegative and (high - declared[1]).is_nonnegative)
        return angle if inside else call
    if _sign(angle - low, model) == 1 and _sign(high - angle, model) == 1:
        return angle
    return call


def _declared_range(angle: sympy.Expr, model: Model) -> tuple[sympy.Expr, sympy.Expr] | None:
    names = {c.symbol: c.name for c in model.coordinates}
    for name, low, high in model.coordinate_ranges:
        if names.get(angle) == name:
            return low, high
    for symbol, low, high in model.ranges:
        if symbol == angle:
            return low, high
    return None


def _sign(expr: sympy.Expr, model: Model) -> int:
    """1 or -1 when expr keeps that sign on the domain (0 when it cannot be settled): declared positive,
    proved by sympy's assumptions, or the same sign at every sampled point with the coordinates inside
    their declared ranges."""
    for declared in model.positive:
        if tidy.simplify(expr - declared) == 0:
            return 1
        if tidy.simplify(expr + declared) == 0:
            return -1
    if expr.is_positive:
        return 1
    if expr.is_negative:
        return -1
    coordinates = {c.symbol: c.name for c in model.coordinates}
    bounds = {name: (low, high) for name, low, high in model.coordinate_ranges}
    if any(s in coordinates and coordinates[s] not in bounds for s in expr.free_symbols):
        return 0
    if expr.free_symbols - set(model.parameters) - set(coordinates):
        return 0
    rng = random.Random(SEED)  # noqa: S311 - reproducible sampling, not security
    signs = set()
    for point in domain_points(model, POINTS, seed=SEED):
        place: dict[sympy.Symbol, float] = dict(point)
        for symbol, name in coordinates.items():
            if symbol in expr.free_symbols:
                low, high = _finite(*(float(b.subs(point)) for b in bounds[name]))
                place[symbol] = low + (high - low) * (0.02 + 0.96 * rng.random())
        value = sympy.N(expr.subs(place), 30)
        if not value.is_real:
            return 0
        signs.add(1 if value > 0 else -1 if value < 0 else 0)
    return signs.pop() if len(signs) == 1 else 0


def _finite(low: float, high: float) -> tuple[float, float]:
    """A stretch of a coordinate's range to sample: a half-line from its end, ten units long."""
    if low == -float("inf"):
        low = (high if high != float("inf") else 5.0) - 10.0
    if high == float("inf"):
        high = low + 10.0
    return low, high


def plain_angle(root: sympy.Expr, model: Model) -> sympy.Expr:
    """An angle sympy writes as 2 atan(half-angle form) is atan(tan(root)) when it lies in (-pi/2, pi/2):
    taken when it is simpler and equal at domain points."""
    if not root.has(sympy.atan):
        return root
    candidate = sympy.atan(tidy.simplify(sympy.expand_trig(sympy.tan(root))))
    if sympy.count_ops(candidate) >= sympy.count_ops(root):
        return root
    try:
        same = all(
            abs(complex(sympy.N((candidate - root).subs(point), 20))) < 1e-12
            for point in domain_points(model, 6, seed=13)
        )
    except (TypeError, ValueError):
        return root
    return candidate if same else root
