"""Where the motion from the state first stops (`turning_point`): derived by several methods, measured by
the simulation, and refused where the motion never turns."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__
NAMES = ("m", "k", "g", "h", "L0", "v", "mu", "theta", "R", "M", "G")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, k, g, h, L0, v, mu, theta, R, M, G = (SYMBOLS[n] for n in NAMES)
SLOPE = {"ranges": {"theta": ["0", "pi/2"]}}

SPRING_DROP: dict[str, Any] = {
    "coordinates": ["y"],
    "bodies": {"block": {"mass": "m", "position": {"y": "y"}}},
    "elements": {
        "spring": {"kind": "spring", "between": ["block", {"y": "-L0"}], "stiffness": "k", "length": "L0"}
    },
    "gravity": "g",
    "state": {"y": 0, "y_dot": "-sqrt(2*g*h)"},
    "domain": {"ranges": {"y": ["-L0", "oo"]}},
    "quantities": {"lowest": {"turning_point": "y"}},
}
UP_A_ROUGH_SLOPE: dict[str, Any] = {
    "elements": {
        "ramp": {
            "kind": "incline",
            "body": "block",
            "mass": "m",
            "angle": "theta",
            "coordinate": "s",
            "direction": "up",
            "friction": "mu",
        }
    },
    "gravity": "g",
    "state": {"s": 0, "s_dot": "v"},
    "domain": SLOPE,
    "quantities": {"lowest": {"turning_point": "s"}},
}
ROLLING_UP: dict[str, Any] = {
    "elements": {
        "ball": {
            "kind": "rolling",
            "mass": "m",
            "radius": "R",
            "inertia": "2*m*R^2/5",
            "angle": "theta",
            "coordinate": "s",
            "direction": "up",
        }
    },
    "gravity": "g",
    "state": {"s": 0, "s_dot": "v"},
    "domain": SLOPE,
    "quantities": {"lowest": {"turning_point": "s"}},
}
HANGING_FROM_REST: dict[str, Any] = {  # released with the spring unstretched: it falls twice m g / k
    **SPRING_DROP,
    "bodies": {"block": {"mass": "m", "position": {"y": "-y"}}},
    "elements": {
        "spring": {"kind": "spring", "between": ["block", {"y": "L0"}], "stiffness": "k", "length": "L0"}
    },
    "state": {"y": 0},
    "domain": {"ranges": {"y": ["-L0", "oo"]}},
}

# several coordinates, the others cyclic: their momenta keep the state's values, as for a speed `at`
BUMPER: dict[str, Any] = {  # cart 1 at v runs into cart 2 at rest through a spring of natural length L0
    "coordinates": ["x1", "d"],
    "bodies": {
        "cart1": {"mass": "m", "position": {"x": "x1"}},
        "cart2": {"mass": "M", "position": {"x": "x1 + d"}},
    },
    "elements": {
        "bumper": {"kind": "spring", "between": ["cart1", "cart2"], "stiffness": "k", "length": "L0"}
    },
    "state": {"x1": 0, "d": "L0", "x1_dot": "v", "d_dot": "-v"},
    "domain": {"ranges": {"d": ["0", "oo"]}, "positive": ["L0^2*k*(m + M) - v^2*m*M"]},
    "quantities": {"lowest": {"turning_point": "d"}},
}
APOGEE: dict[str, Any] = {  # launched sideways at v from R, below the escape speed
    "coordinates": ["r", "phi"],
    "bodies": {"craft": {"mass": "m", "position": {"x": "r*cos(phi)", "y": "r*sin(phi)"}}},
    "potentials": [{"bodies": ["craft"], "anchor": {"x": 0, "y": 0}, "distance": "d", "energy": "-G*M*m/d"}],
    "state": {"r": "R", "phi": 0, "phi_dot": "v/R"},
    "domain": {"ranges": {"r": ["0", "oo"]}, "positive": ["v^2*R - G*M", "2*G*M - v^2*R"]},
    "quantities": {"lowest": {"turning_point": "r"}},
}

# `after: impact`: in the motion just after the model's impact. Cart 1 at v bounces elastically off
# cart 2, at rest on a spring of natural length L0 to a wall at x = L0: how far cart 2 squeezes it
STRUCK_ON_A_SPRING: dict[str, Any] = {
    "coordinates": ["x1", "x2"],
    "bodies": {
        "cart1": {"mass": "m", "position": {"x": "x1"}},
        "cart2": {"mass": "M", "position": {"x": "x2"}},
    },
    "elements": {
        "spring": {"kind": "spring", "between": ["cart2", {"x": "L0"}], "stiffness": "k", "length": "L0"}
    },
    "state": {"x1": 0, "x2": 0, "x1_dot": "v", "x2_dot": 0},
    "impact": {"bodies": ["cart1", "cart2"], "normal": {"x": 1}, "restitution": 1},
    "domain": {"ranges": {"x2": ["-oo", "L0"]}},
    "quantities": {"lowest": {"turning_point": "x2", "after": "impact"}},
}


@pytest.mark.parametrize(
    ("data", "expected"),
    [
        pytest.param(
            SPRING_DROP, -(m * g + sympy.sqrt(m**2 * g**2 + 2 * m * g * h * k)) / k, id="spring-drop"
        ),
        pytest.param(
            UP_A_ROUGH_SLOPE, v**2 / (2 * g * (sympy.sin(theta) + mu * sympy.cos(theta))), id="rough-slope"
        ),
        pytest.param(ROLLING_UP, 7 * v**2 / (10 * g * sympy.sin(theta)), id="rolling-up"),
        pytest.param(HANGING_FROM_REST, 2 * m * g / k, id="from-rest"),
        pytest.param(BUMPER, L0 - v * sympy.sqrt(m * M / (k * (m + M))), id="bumper-closest"),
        pytest.param(APOGEE, R**2 * v**2 / (2 * G * M - R * v**2), id="apogee"),
        pytest.param(
            STRUCK_ON_A_SPRING, 2 * m * v * sympy.sqrt(M / k) / (m + M), id="after-an-impact-on-a-spring"
        ),
    ],
)
@pytest.mark.sample(3)
def test_the_turning_point_is_derived_by_several_methods_and_simulated(
    data: dict[str, Any], expected: sympy.Expr
) -> None:
    derived = uncached(load_model(data, SYMBOLS))
    assert sympy.simplify(derived.quantities["lowest"] - expected) == 0
    assert len(derived.agreement["lowest"]) >= 2
    assert "lowest" in derived.simulation


def test_a_motion_that_never_stops_ahead_is_refused() -> None:
    ramp = {**UP_A_ROUGH_SLOPE["elements"]["ramp"]}
    del ramp["friction"]
    sliding_away = {**UP_A_ROUGH_SLOPE, "elements": {"ramp": ramp}, "state": {"s": 0, "s_dot": "-v"}}
    with pytest.raises(DerivationError, match="does not turn"):
        uncached(load_model(sliding_away, SYMBOLS))
