"""The sign an expression keeps on the model's domain, and where it changes, said as an author reads it.

A proof first (sympy's assumptions on the simplified expression), else the values at sampled domain
points. `where_negative` turns the factor that changes sign into a condition on one symbol
(`F > 2*g*m2`) when it is linear in it, so a refusal can say where the model goes wrong.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from enum import Enum

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.model import Model
from physics.engine.proof import domain_points

POINTS = 24
SEED = 17
_TOLERANCE = 1e-12


class Sign(Enum):
    POSITIVE = "positive"  # > 0 (or >= 0) everywhere on the domain
    NEGATIVE = "negative"  # < 0 everywhere
    MIXED = "mixed"  # negative somewhere, positive elsewhere
    NOT_REAL = "not real"  # complex everywhere
    UNKNOWN = "unknown"  # could not be evaluated (free symbols, failures)


@dataclass(frozen=True)
class Found:
    sign: Sign
    negative_at: dict[sympy.Symbol, float] | None = None  # a sampled point where it is negative


def sign_on_domain(expr: sympy.Expr, model: Model, points: int = POINTS) -> Found:
    """The sign `expr` keeps over the model's domain (zero counts as either)."""
    if expr.free_symbols - set(model.parameters):
        return Found(Sign.UNKNOWN)
    if expr.is_nonnegative:
        return Found(Sign.POSITIVE)
    if expr.is_negative:
        return Found(Sign.NEGATIVE)
    negative: dict[sympy.Symbol, float] | None = None
    positives = negatives = complex_ = 0
    for point in domain_points(model, points, seed=SEED):
        value = sympy.N(expr.subs(point), 30)
        if not value.is_number:
            return Found(Sign.UNKNOWN)
        real, imaginary = (float(v) for v in value.as_real_imag())
        if abs(imaginary) > _TOLERANCE * max(1.0, abs(real)):
            complex_ += 1
        elif real < -_TOLERANCE:
            negatives += 1
            negative = negative or point
        else:
            positives += 1
    if complex_ == points:
        return Found(Sign.NOT_REAL)
    if negatives == 0:
        return Found(Sign.POSITIVE) if positives else Found(Sign.UNKNOWN)
    return Found(Sign.NEGATIVE if positives == 0 and complex_ == 0 else Sign.MIXED, negative)


def where_negative(expr: sympy.Expr, model: Model, prefer: Sequence[sympy.Symbol] = ()) -> str | None:
    """Where expr < 0 ("F > 2*g*m2"), when its sign rests on one factor linear in a symbol; else None."""
    flip = False
    factors: list[tuple[sympy.Expr, int]] = []
    for part in sympy.fraction(sympy.factor(tidy.simplify(expr))):
        for factor, power in _powers(part):
            factors.append((factor, power))
    changing: list[sympy.Expr] = []
    negative: list[sympy.Expr] = []
    for factor, power in factors:
        if power % 2 == 0:
            continue
        found = sign_on_domain(factor, model, 12)
        if found.sign is Sign.POSITIVE:
            continue
        if found.sign is Sign.NEGATIVE:
            flip = not flip
            if not factor.is_number:  # a factor -1 says nothing of where: "-1 < 0" is no condition
                negative.append(factor)
            continue
        changing.append(factor)
    if not changing and len(negative) == 1:  # negative on the whole domain: the factor that makes it so
        changing, flip = negative, not flip
    if len(changing) != 1:
        return None
    factor = changing[0]  # expr < 0 where factor < 0 (or > 0 if flipped)
    candidates = [s for s in prefer if s in factor.free_symbols]
    candidates += [s for s in reversed(model.parameters) if s in factor.free_symbols and s not in candidates]
    for symbol in candidates:
        poly = sympy.Poly(factor, symbol) if factor.is_polynomial(symbol) else None
        if poly is None or poly.degree() != 1:
            continue
        slope, rest = poly.all_coeffs()
        slope_sign = sign_on_domain(slope, model, 12).sign
        if slope_sign not in (Sign.POSITIVE, Sign.NEGATIVE) or slope.is_zero:
            continue
        bound = tidy.simplify(-rest / slope)
        # factor < 0 <=> symbol < bound when the slope is positive
        below = (slope_sign is Sign.POSITIVE) != flip
        return f"{symbol} {'<' if below else '>'} {typed_text(bound)}"
    return f"{typed_text(factor)} {'>' if flip else '<'} 0"


def _powers(expr: sympy.Expr) -> list[tuple[sympy.Expr, int]]:
    """expr's factors with their integer powers (a non-integer power counts as a factor of its own)."""
    found: list[tuple[sympy.Expr, int]] = []
    for factor in sympy.Mul.make_args(expr):
        base, power = factor.as_base_exp()
        if power.is_Integer:
            found.append((base, int(power)))
        else:
            found.append((factor, 1))
    return found


def point_text(point: dict[sympy.Symbol, float]) -> str:
    return ", ".join(f"{s} = {v:.3g}" for s, v in point.items())
