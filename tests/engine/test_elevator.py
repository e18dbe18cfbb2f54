"""A body carried by a support that moves as prescribed, with no coordinate of its own: the scale in an
accelerating elevator reads m (g + a), by two methods and the simulation."""

from __future__ import annotations

import sympy

from physics.engine import derivation, load_model

uncached = derivation._derive.__wrapped__
m, a, g = sympy.symbols("m a g", positive=True)


def test_a_scale_in_an_accelerating_elevator_reads_the_weight_plus_m_a() -> None:
    data = {
        "coordinates": [],
        "bodies": {"person": {"mass": "m", "position": {"y": "a*t^2/2"}}},
        "gravity": "g",
        "constraints": {"scale": {"kind": "surface", "gap": "y_person - a*t^2/2"}},
        "quantities": {"reading": {"force": "scale"}},
    }
    derived = uncached(load_model(data, {"m": m, "a": a, "g": g}))
    assert sympy.simplify(derived.quantities["reading"] - m * (g + a)) == 0
    assert len(derived.agreement["reading"]) >= 2
    assert "reading" in derived.simulation
