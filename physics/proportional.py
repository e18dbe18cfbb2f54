"""Whether expressions are a multiple of reference expressions on a problem's domain, decided by the
judge's sampling: the answers that say the same physics up to a factor (a Lagrangian times a constant
gives the same equations of motion; an equation may be written with its sides swapped or scaled).

Every component is evaluated at the domain's sample points (float64, multiprecision where float64
cannot) and, to tell a constant factor from one that varies with the motion, again at the same points
with the `state` symbols' values rotated among the points (coordinates, velocities, unknown forces): a
factor that is the same at both is independent of the state. The factor may depend on the problem's
parameters (L/m is as good a Lagrangian as L) unless `fixed` asks for the reference itself.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property

import numpy as np
import numpy.typing as npt
import sympy

from physics.symbolic import SymbolicContext, prepare_reference
from physics.symbolic.compare import PREC
from physics.symbolic.floats import FloatEvaluator, Floats, rounded
from physics.symbolic.numeric import Evaluator

CLOSE = 1e-7  # relative agreement of two float64 values computed by different routes (cancellation)
_TINY = 1e-200


@dataclass(frozen=True)
class Matched:
    """How answers compare with targets: proportional at every point, and the factor (a number when it
    is the same at every point, else None: it depends on the parameters)."""

    proportional: bool
    factor: float | None
    failing: tuple[int, ...]  # components that are not the same multiple of their target


@dataclass(frozen=True)
class Sample:
    """The domain's points, and the same points with the state symbols' values rotated among them."""

    context: SymbolicContext
    state: tuple[sympy.Symbol, ...]
    anchor: sympy.Expr  # a reference-side expression the points are drawn for (defined at each)

    @cached_property
    def _prepared(self) -> tuple[dict[sympy.Symbol, Floats], dict[sympy.Symbol, list[object]], int]:
        sample = prepare_reference(self.anchor, self.context).sample
        return dict(sample.float_columns), dict(sample.columns), sample.size

    @property
    def size(self) -> int:
        return self._prepared[2]

    def _columns(
        self, rolled: bool
    ) -> tuple[Mapping[sympy.Symbol, Floats], Mapping[sympy.Symbol, list[object]]]:
        floats, precise, _ = self._prepared
        if not rolled:
            return floats, precise
        return (
            {s: np.roll(v, 1) if s in self.state else v for s, v in floats.items()},
            {s: (v[-1:] + v[:-1]) if s in self.state else v for s, v in precise.items()},
        )

    def values(self, expr: sympy.Expr, rolled: bool = False) -> Floats:
        """`expr` at every point (nan where undefined)."""
        floats, precise = self._columns(rolled)
        found = FloatEvaluator(floats, self.size)(expr)
        if found is not None:
            return found
        column = Evaluator(precise, self.size, PREC)(expr)  # type: ignore[arg-type]
        return rounded(column)[0]


def close(a: Floats, b: Floats, scale: float) -> npt.NDArray[np.bool_]:
    """Where a and b agree (both finite), relative to their size with `scale` as the floor."""
    with np.errstate(all="ignore"):
        allowed = CLOSE * (np.maximum(np.abs(a), np.abs(b)) + scale)
        result: npt.NDArray[np.bool_] = np.isfinite(a) & np.isfinite(b) & (np.abs(a - b) <= allowed)
    return result


def _scale(targets: Sequence[Floats]) -> float:
    magnitudes = np.abs(np.concatenate([t[np.isfinite(t)] for t in targets]))
    nonzero = magnitudes[magnitudes > _TINY]
    return float(np.median(nonzero)) if nonzero.size else 1.0


def _factors(answers: Sequence[Floats], targets: Sequence[Floats]) -> Floats:
    """The least-squares factor at each point (nan where every target is zero)."""
    a, t = np.stack(answers), np.stack(targets)
    with np.errstate(all="ignore"):
        top = np.sum(a * t, axis=0)
        bottom = np.sum(t * t, axis=0)
        result: Floats = np.where(bottom > _TINY, top / bottom, np.nan)
    return result


def matched(
    answers: Sequence[Floats],
    targets: Sequence[Floats],
    answers_rolled: Sequence[Floats] | None = None,
    targets_rolled: Sequence[Floats] | None = None,
    *,
    fixed: bool = False,
) -> Matched:
    """Whether each answer is the same multiple of its target at every point: a multiple 1 (`fixed`) or
    one that is nonzero and the same at the rolled points (independent of the state)."""
    scale = _scale(targets)
    factors = np.ones(len(targets[0])) if fixed else _factors(answers, targets)
    usable = np.isfinite(factors)
    if not fixed and (not usable.any() or np.all(np.abs(factors[usable]) <= CLOSE)):
        return Matched(False, 0.0, tuple(range(len(targets))))
    failing = tuple(
        k
        for k, (a, t) in enumerate(zip(answers, targets, strict=True))
        if not np.all(close(a, np.where(usable, factors, 0.0) * t, scale * np.nanmax(np.abs(factors))))
    )
    if failing or fixed:
        return Matched(not failing, 1.0 if fixed else None, failing)
    if answers_rolled is not None and targets_rolled is not None:
        other = _factors(answers_rolled, targets_rolled)
        both = usable & np.isfinite(other)
        if not np.all(close(factors[both], other[both], 1e-12)):
            return Matched(False, None, tuple(range(len(targets))))
    first = float(factors[usable][0])
    constant = bool(np.all(close(factors[usable], np.full(int(usable.sum()), first), 1e-12)))
    return Matched(True, first if constant else None, ())


def factor_text(factor: float | None) -> str:
    """A factor as a person writes it: 2, -1, 1/2, 0.37…; "a constant" when it depends on parameters."""
    if factor is None or not math.isfinite(factor):
        return "a constant"
    simple = Fraction(factor).limit_denominator(24)
    if abs(float(simple) - factor) <= 1e-9 * max(1.0, abs(factor)):
        return str(simple)
    return f"{factor:.3g}"
