"""A lab's data and its fit: measurements of a model quantity at several settings with realistic noise,
reproducible from a seed, and the least-squares value of one parameter with its standard error.

The quantity is the engine's closed form (proved equal to its simulation), y = Q(x; p, …), one
parameter p fitted by Gauss–Newton (exact in one step when Q is proportional to p, as a = g sin θ is):
p̂ minimises Σ (yᵢ − Q(xᵢ; p))², and its standard error is s / √Σ (∂Q/∂p)², s² = Σ rᵢ² / (n − 1).
"""

from __future__ import annotations

import hashlib
import math
import random
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import sympy

from physics.symbolic.floats import FloatEvaluator, Floats

_STEPS = 50


@dataclass(frozen=True)
class Fit:
    value: float
    standard_error: float


def _values(
    expr: sympy.Expr, x: sympy.Symbol, xs: Sequence[float], fixed: Mapping[sympy.Symbol, float]
) -> Floats:
    n = len(xs)
    columns = {x: np.array(xs, dtype=float), **{s: np.full(n, float(v)) for s, v in fixed.items()}}
    found = FloatEvaluator(columns, n)(expr)
    if found is None:
        raise ValueError(f"cannot evaluate {expr} at the settings")
    return found


def fit_parameter(
    quantity: sympy.Expr,
    x: sympy.Symbol,
    parameter: sympy.Symbol,
    xs: Sequence[float],
    ys: Sequence[float],
    fixed: Mapping[sympy.Symbol, float],
    start: float,
) -> Fit:
    """The least-squares value of `parameter` for ys ≈ quantity(xs), the other symbols at `fixed`."""
    slope = sympy.diff(quantity, parameter)
    p = float(start)
    y = np.array(ys, dtype=float)
    for _ in range(_STEPS):
        at = {**fixed, parameter: p}
        residual = y - _values(quantity, x, xs, at)
        jacobian = _values(slope, x, xs, at)
        step = float(jacobian @ residual / (jacobian @ jacobian))
        p += step
        if abs(step) <= 1e-13 * max(1.0, abs(p)):
            break
    at = {**fixed, parameter: p}
    residual = y - _values(quantity, x, xs, at)
    jacobian = _values(slope, x, xs, at)
    spread = math.sqrt(float(residual @ residual) / max(1, len(xs) - 1))
    error = spread / math.sqrt(float(jacobian @ jacobian))
    if not (math.isfinite(p) and math.isfinite(error)):
        raise ValueError("the fit does not converge: are the data and the quantity the same measurement?")
    return Fit(p, error)


def proportional_fit(xs: Sequence[float], ys: Sequence[float]) -> float:
    """The slope of y = k x through the origin (what a student gets fitting against the wrong variable)."""
    x, y = np.array(xs, dtype=float), np.array(ys, dtype=float)
    return float(x @ y / (x @ x))


def measurements(
    quantity: sympy.Expr,
    x: sympy.Symbol,
    xs: Sequence[float],
    fixed: Mapping[sympy.Symbol, float],
    relative_noise: float,
    seed: str,
    figures: int = 3,
) -> list[float]:
    """The quantity at each setting with Gaussian noise of `relative_noise` of its size, rounded to
    `figures` significant figures, as a lab notebook records it; the same for the same seed."""
    # reproducible noise for a lab table, not a secret: the seed names the student and the part
    rng = random.Random(int.from_bytes(hashlib.sha256(seed.encode()).digest()[:8], "big"))  # noqa: S311
    exact = _values(quantity, x, xs, fixed)
    out = []
    for value in exact.tolist():
        noisy = value * (1 + relative_noise * rng.gauss(0.0, 1.0))
        out.append(float(f"{noisy:.{figures}g}"))
    return out
