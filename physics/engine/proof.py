"""Proving two derived expressions equal on the model's domain, and drawing points of that domain.

Symbolic first (simplification under the symbols' assumptions); when that does not close, dense
sampling at 30 significant digits over the domain (ranges and positivity conditions), reported as such.
"""

from __future__ import annotations

import math
import random
import zlib
from collections.abc import Sequence
from functools import lru_cache

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.model import Model
from physics.errors import DerivationError
from physics.wording import counted

SAMPLES = 60
DIGITS = 30
TOLERANCE = sympy.Float("1e-20", DIGITS)
MAX_OPS_SYMBOLIC = 400


def domain_points(model: Model, count: int, seed: int = 20260101) -> list[dict[sympy.Symbol, float]]:
    """`count` random points of the parameters' domain (ranges, positive symbols, positivity conditions)."""
    return [dict(point) for point in _domain_points(model, count, seed)]


def clear_domain_points() -> None:
    _domain_points.cache_clear()


@lru_cache(maxsize=256)
def _domain_points(model: Model, count: int, seed: int) -> tuple[dict[sympy.Symbol, float], ...]:
    """Drawn once per model, count and seed: every equilibrium's stability test asks for the same ones."""
    rng = random.Random(seed)  # noqa: S311 - reproducible sampling, not security
    bounds = {s: (float(lo), float(hi)) for s, lo, hi in model.ranges}
    points: list[dict[sympy.Symbol, float]] = []
    for _ in range(200 * count):
        point: dict[sympy.Symbol, float] = {}
        for s in model.parameters:
            if s in bounds:
                lo, hi = bounds[s]
                point[s] = lo + (hi - lo) * (0.02 + 0.96 * rng.random())
            elif s.is_positive:
                point[s] = 10 ** rng.uniform(-0.5, 0.5)
            else:
                point[s] = rng.uniform(-2.0, 2.0)
        if all(float(c.subs(point)) > 0 for c in model.positive):
            points.append(point)
            if len(points) == count:
                return tuple(points)
    raise DerivationError(
        f"could not find {counted(count, 'point')} in the domain (conditions {typed_text(model.positive)})"
    )


def prove_equal(first: sympy.Expr, second: sympy.Expr, model: Model, what: str, names: Sequence[str]) -> str:
    """How `first` == `second` was shown ("symbolic" or "sampled ..."); DerivationError if they differ."""
    difference = first - second
    if sympy.count_ops(difference) <= MAX_OPS_SYMBOLIC:
        for attempt in (sympy.cancel, tidy.simplify, lambda e: tidy.simplify(e.rewrite(sympy.sin))):
            if attempt(difference) == 0:
                return "symbolic"
        angles = _angle_substitution(model)
        if angles and tidy.simplify(difference.subs(angles)) == 0:
            return "symbolic (angles in range as atan of a positive parameter)"
    worst = 0.0
    for point in domain_points(model, SAMPLES, seed=zlib.crc32(what.encode())):
        exact = {s: sympy.Float(v, DIGITS) for s, v in point.items()}
        a = sympy.N(first, DIGITS, subs=exact)
        b = sympy.N(second, DIGITS, subs=exact)
        if not (a.is_real and b.is_real):
            raise DerivationError(
                f"{what}: not real at {typed_text(point)}: {names[0]} gives {typed_text(a)}, {names[1]} gives {typed_text(b)}",
                quantity=what,
            )
        gap = abs(a - b)
        if gap > TOLERANCE * max(1, abs(a), abs(b)):
            raise DerivationError(
                f"{what}: the methods disagree. {names[0]} gives {typed_text(first)}, {names[1]} gives {typed_text(second)}; "
                f"at {_show(point)} they are {float(a):.10g} and {float(b):.10g}",
                quantity=what,
            )
        worst = max(worst, float(gap / max(1, abs(a))))
    return f"sampled ({SAMPLES} points of the domain, {DIGITS} digits, worst relative gap {worst:.1e})"


def proven_sign(expr: sympy.Expr, model: Model) -> int | None:
    """1 or -1 when sympy's assumptions prove `expr` positive or negative over the whole domain, 0 when
    they prove it is not real, None when they cannot tell. The proof uses the symbols' declared signs and
    each angle ranging over (0, pi/2) or (0, pi) (through a positive tangent), not sampled values."""
    for form in (expr, expr.subs(_angle_substitution(model))):
        if form.is_positive:
            return 1
        if form.is_negative:
            return -1
        if form.is_extended_real is False:
            return 0
    return None


def _angle_substitution(model: Model) -> dict[sympy.Symbol, sympy.Expr]:
    """theta = atan(t) (or 2 atan(t)) with t > 0 for an angle ranging over (0, pi/2) (or (0, pi)): the
    trigonometric functions become algebraic in t with known signs, which lets simplify close sqrt forms
    that need the range (sqrt(1 - cos^2) = sin only when sin > 0)."""
    result: dict[sympy.Symbol, sympy.Expr] = {}
    for symbol, low, high in model.ranges:
        if low != 0:
            continue
        t = sympy.Dummy(f"t_{symbol}", positive=True)
        if high == sympy.pi / 2:
            result[symbol] = sympy.atan(t)
        elif high == sympy.pi:
            result[symbol] = 2 * sympy.atan(t)
    return result


def _show(point: dict[sympy.Symbol, float]) -> str:
    return ", ".join(f"{s}={v:.4g}" for s, v in point.items() if math.isfinite(v))
