"""Thresholds where a frequency reaches zero (critical damping, the spin at which the bottom of a hoop
stops being stable): derived, and measured on runs that swing, extrapolated to the zero."""

from __future__ import annotations

import math
from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.engine.vanishing_frequency import measured_zero
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__
NAMES = ("m", "k", "b", "g", "R", "omega")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, k, b, g, R, omega = (SYMBOLS[n] for n in NAMES)

CRITICAL_DAMPING: dict[str, Any] = {
    "coordinates": ["x"],
    "bodies": {"block": {"mass": "m", "position": {"x": "x"}}},
    "elements": {"spring": {"kind": "spring", "between": ["block", {"x": 0}], "stiffness": "k"}},
    "forces": [{"body": "block", "drag": "b"}],
    "domain": {"positive": ["4*k*m - b^2"]},
    "quantities": {"critical": {"solve": "b", "zero": {"damped_frequency": "x"}}},
}
HOOP_BOTTOM: dict[str, Any] = {
    "coordinates": ["theta"],
    "bodies": {"bead": {"mass": "m", "position": {"x": "R*sin(theta)", "y": "-R*cos(theta)"}}},
    "gravity": "g",
    "elements": {"frame": {"kind": "rotating", "rate": "omega", "bodies": ["bead"]}},
    "constraints": {"hoop": {"kind": "other", "gap": "R - sqrt(x_bead^2 + y_bead^2)"}},
    "domain": {"positive": ["g - omega^2*R"]},
    "quantities": {"critical": {"solve": "omega", "zero": {"angular_frequency": "theta"}}},
}


@pytest.mark.parametrize(
    ("data", "expected"),
    [
        pytest.param(CRITICAL_DAMPING, 2 * sympy.sqrt(k * m), id="critical-damping"),
        pytest.param(HOOP_BOTTOM, sympy.sqrt(g / R), id="hoop-critical-spin"),
    ],
)
def test_a_frequency_reaching_zero_is_derived_and_measured(
    data: dict[str, Any], expected: sympy.Expr
) -> None:
    derived = uncached(load_model(data, SYMBOLS))
    assert sympy.simplify(derived.quantities["critical"] - expected) == 0
    assert "extrapolates to zero" in derived.simulation["critical"].compared


def test_the_zero_is_found_from_the_side_that_swings() -> None:
    def frequency(value: float) -> float:  # omega^2 = 4 - p^2: swings below p = 2, not above
        if value >= 2:
            raise DerivationError("no oscillation seen in the simulation")
        return math.sqrt(4 - value**2)

    assert measured_zero(frequency, 2.0, "critical") == pytest.approx(2.0, rel=1e-9)


def test_a_frequency_that_does_not_fall_is_reported() -> None:
    with pytest.raises(DerivationError, match="do not fall towards zero"):
        measured_zero(lambda value: 1.0 + 0 * value, 2.0, "critical")
