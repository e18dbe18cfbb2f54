"""Applied forces and drag: given forces (constant or in the coordinates and velocities), linear and
quadratic drag; each derived by Lagrange and Newton, simulated, and the energy books kept."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.errors import SpecErrors

uncached = derivation._derive.__wrapped__
NAMES = ("m", "F", "alpha", "mu", "g", "b", "c", "k", "A")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, F, alpha, mu, g, b, c, k, A = (SYMBOLS[n] for n in NAMES)


def pulled_block() -> dict[str, Any]:
    """A block on a rough floor pulled by F at alpha above the horizontal (a constant force)."""
    return {
        "coordinates": ["x"],
        "bodies": {"block": {"mass": "m", "position": {"x": "x", "y": 0}}},
        "gravity": "g",
        "constraints": {"floor": {"kind": "surface", "gap": "y_block"}},
        "friction": [{"constraint": "floor", "body": "block", "coefficient": "mu", "sliding": "x"}],
        "forces": [{"body": "block", "force": {"x": "F*cos(alpha)", "y": "F*sin(alpha)"}}],
        "domain": {
            "ranges": {"alpha": ["0", "pi/2"]},
            "positive": ["m*g - F*sin(alpha)", "F*cos(alpha) - mu*(m*g - F*sin(alpha))"],
        },
        "quantities": {"a": {"acceleration": "x"}, "N": {"force": "floor"}},
    }


def falling(drag: dict[str, str]) -> dict[str, Any]:
    """A ball falling with drag; y up."""
    return {
        "coordinates": ["y"],
        "bodies": {"ball": {"mass": "m", "position": {"y": "y"}}},
        "gravity": "g",
        "forces": [{"body": "ball", **drag}],
        "quantities": {"v": {"terminal_velocity": "y"}},
    }


def test_a_constant_pull_with_friction_is_derived_by_every_method() -> None:
    result = uncached(load_model(pulled_block(), SYMBOLS))
    normal = m * g - F * sympy.sin(alpha)
    assert sympy.simplify(result.quantities["N"] - normal) == 0
    assert sympy.simplify(result.quantities["a"] - (F * sympy.cos(alpha) - mu * normal) / m) == 0
    assert len(result.agreement["a"]) >= 2
    assert {"a", "N"} <= set(result.simulation)
    assert "energy balance" in result.checks


@pytest.mark.parametrize(
    ("drag", "expected"),
    [
        pytest.param({"drag": "b"}, -m * g / b, id="linear"),
        pytest.param({"quadratic_drag": "c"}, -sympy.sqrt(m * g / c), id="quadratic"),
    ],
)
def test_terminal_velocity_under_drag(drag: dict[str, str], expected: sympy.Expr) -> None:
    result = uncached(load_model(falling(drag), SYMBOLS))
    assert sympy.simplify(result.quantities["v"] - expected) == 0
    assert {"lagrange", "newton"} <= set(result.agreement["v"])
    assert result.simulation["v"].max_relative_error < 1e-3
    assert "energy balance" in result.checks


def test_a_force_given_in_the_coordinate_acts_like_a_spring() -> None:
    data = {
        "coordinates": ["x"],
        "bodies": {"block": {"mass": "m", "position": {"x": "x"}}},
        "forces": [{"body": "block", "force": {"x": "-k*x - b*x_dot"}}],
        "state": {"x": "A"},
        "quantities": {"a": {"acceleration": "x"}},
    }
    result = uncached(load_model(data, SYMBOLS))
    assert sympy.simplify(result.quantities["a"] + k * A / m) == 0


def test_force_faults_are_reported_with_their_paths() -> None:
    data = falling({"drag": "b", "quadratic_drag": "c"})
    data["forces"].append({"body": "nobody", "drag": "b"})
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    assert {e.path for e in caught.value.errors} == {("forces", 0), ("forces", 1, "body")}
