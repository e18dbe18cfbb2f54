"""Several degrees of freedom oscillating: every normal-mode frequency, ordered, each askable."""

from __future__ import annotations

import time
from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.errors import SpecErrors

uncached = derivation._derive.__wrapped__
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in ("m", "k", "g", "L")}
m, k, g, L = SYMBOLS.values()


def three_springs() -> dict[str, Any]:
    """Two equal masses between two walls, joined by three equal springs; x1, x2 from rest."""
    return {
        "coordinates": ["x1", "x2"],
        "bodies": {"a": {"mass": "m", "position": {"x": "x1"}}, "b": {"mass": "m", "position": {"x": "x2"}}},
        "potentials": [
            {"bodies": ["a"], "anchor": {"x": 0}, "distance": "d", "energy": "k*d^2/2"},
            {"bodies": ["a", "b"], "distance": "d", "energy": "k*d^2/2"},
            {"bodies": ["b"], "anchor": {"x": 0}, "distance": "d", "energy": "k*d^2/2"},
        ],
        "quantities": {"slow": {"normal_frequency": 1}, "fast": {"normal_frequency": 2}},
    }


def double_pendulum() -> dict[str, Any]:
    return {
        "coordinates": ["p1", "p2"],
        "bodies": {
            "upper": {"mass": "m", "position": {"x": "L*sin(p1)", "y": "-L*cos(p1)"}},
            "lower": {"mass": "m", "position": {"x": "L*sin(p1) + L*sin(p2)", "y": "-L*cos(p1) - L*cos(p2)"}},
        },
        "gravity": "g",
        "constraints": {
            "rod1": {"kind": "string", "gap": "L - sqrt(x_upper^2 + y_upper^2)"},
            "rod2": {"kind": "string", "gap": "L - sqrt((x_lower - x_upper)^2 + (y_lower - y_upper)^2)"},
        },
        "domain": {"ranges": {"p1": ["-pi/2", "pi/2"], "p2": ["-pi/2", "pi/2"]}},
        "quantities": {"slow": {"normal_frequency": 1}, "fast": {"normal_frequency": 2}},
    }


def test_two_masses_and_three_springs_have_both_modes_in_order() -> None:
    result = uncached(load_model(three_springs(), SYMBOLS))
    assert sympy.simplify(result.quantities["slow"] - sympy.sqrt(k / m)) == 0
    assert sympy.simplify(result.quantities["fast"] - sympy.sqrt(3 * k / m)) == 0
    assert set(result.agreement["fast"]) == {"lagrange", "newton", "conservation"}
    assert result.simulation["fast"].max_relative_error < 1e-3


@pytest.mark.slow
def test_double_pendulum_small_oscillations() -> None:
    started = time.process_time()
    result = uncached(load_model(double_pendulum(), SYMBOLS))
    spent = time.process_time() - started
    for name, sign in (("slow", -1), ("fast", 1)):
        expected = sympy.sqrt((2 + sign * sympy.sqrt(2)) * g / L)
        assert abs(float((result.quantities[name] - expected).subs({g: 9.8, L: 1.3}))) < 1e-9
        assert len(result.agreement[name]) >= 2
        assert result.simulation[name].max_relative_error < 1e-3
    print(f"double pendulum derived in {spent:.1f} s CPU")


def test_a_mode_number_beyond_the_coordinates_is_a_spec_error() -> None:
    data = three_springs()
    data["quantities"]["third"] = {"normal_frequency": 3}
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    assert caught.value.errors[0].path == ("quantities", "third", "normal_frequency")
