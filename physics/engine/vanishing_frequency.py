"""Measuring where a frequency reaches zero (critical damping; a bead on a hoop whose bottom stops being
stable as the spin grows): no run near such a threshold swings long enough to time, and beyond it
nothing swings at all, so the runs either side of it cannot be compared as a force's can.

The square of the frequency is smooth in the parameter through the threshold (k/m - b^2/4m^2,
g/R - Omega^2), so it is measured on runs that swing well, at three values on the side where they do,
and the quadratic through them is followed to its zero.
"""

from __future__ import annotations

from collections.abc import Callable

import sympy

from physics.engine.model import QuantityKind
from physics.errors import DerivationError

Point = dict[sympy.Symbol, float]
KINDS = frozenset(
    {
        QuantityKind.ANGULAR_FREQUENCY,
        QuantityKind.DAMPED_FREQUENCY,
        QuantityKind.UNDAMPED_FREQUENCY,
        QuantityKind.NORMAL_FREQUENCY,
        QuantityKind.EPICYCLIC_FREQUENCY,
    }
)
SPACINGS = ((0.3, 0.2, 0.1), (0.6, 0.45, 0.3))  # shares of the threshold away from it, nearest tried first


def measured_zero(frequency: Callable[[float], float], expected: float, name: str) -> float:
    """The parameter at which the frequency, measured by `frequency(value)`, extrapolates to zero."""
    failures: list[str] = []
    for side in (-1, 1):
        for spacing in SPACINGS:
            values = [expected * (1 + side * share) for share in spacing]
            try:
                squares = [frequency(v) ** 2 for v in values]
            except DerivationError as error:
                failures.append(error.message)
                continue
            return _root_nearest(values, squares, expected, name)
    raise DerivationError(f"{name}: no run either side swings long enough to time: {failures[-1]}")


def _root_nearest(values: list[float], squares: list[float], expected: float, name: str) -> float:
    x = sympy.Symbol("x")
    curve = sympy.interpolate(list(zip(values, squares, strict=True)), x)
    roots = [complex(r) for r in sympy.Poly(curve, x).nroots()] if sympy.Poly(curve, x).degree() > 0 else []
    real = [r.real for r in roots if abs(r.imag) <= 1e-9 * max(1.0, abs(r.real))]
    if not real:
        raise DerivationError(f"{name}: the measured frequencies do not fall towards zero")
    return min(real, key=lambda r: abs(r - expected))
