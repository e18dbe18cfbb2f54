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


R, M, L0 = sympy.symbols("R M L0", positive=True)
# a block hanging from a spring element, with a second spring written as a force in the coordinate
HUNG = {
    "coordinates": ["y"],
    "bodies": {"block": {"mass": "m", "position": {"y": "y"}}},
    "elements": {
        "spring": {"kind": "spring", "between": ["block", {"y": 0}], "stiffness": "k", "length": "L0"}
    },
    "forces": [{"body": "block", "force": {"y": "-c*y"}}],
    "gravity": "g",
    "domain": {"ranges": {"y": ["-oo", "0"]}},
    "quantities": {"rest": {"equilibrium": "y"}, "w": {"angular_frequency": "y"}},
}
# a block on a string over a disc pulley whose other run is tied to a spring: the spring as a torque
PULLEY_SPRING = {
    "coordinates": ["s"],
    "bodies": {
        "wheel": {"mass": "M", "inertia": "M*R^2/2", "position": {"x": 0, "y": 0}, "angle": "-s/R"},
        "block": {"mass": "m", "position": {"y": "-s"}},
    },
    "gravity": "g",
    "constraints": {
        "string": {"kind": "string", "gap": "y_block - y_wheel - R*phi_wheel"},
        "axleX": {"kind": "other", "gap": "x_wheel"},
        "axleY": {"kind": "other", "gap": "y_wheel"},
    },
    "forces": [{"body": "wheel", "torque": "k*R*s"}],
    "quantities": {"rest": {"equilibrium": "s"}, "w": {"angular_frequency": "s"}},
}


@pytest.mark.parametrize(
    ("data", "rest", "omega"),
    [
        (HUNG, -(k * L0 + m * g) / (k + c), sympy.sqrt((k + c) / m)),
        (PULLEY_SPRING, m * g / k, sympy.sqrt(k / (m + M / 2))),
    ],
    ids=["a second spring as a force", "a spring on the string's free end as a torque"],
)
def test_a_force_given_in_the_coordinates_moves_the_rest_and_stiffens_the_oscillation(
    data: dict[str, Any], rest: sympy.Expr, omega: sympy.Expr
) -> None:
    symbols = {**SYMBOLS, "R": R, "M": M, "L0": L0}
    result = uncached(load_model(data, symbols))
    assert sympy.simplify(result.quantities["rest"] - rest) == 0
    assert sympy.simplify(result.quantities["w"] - omega) == 0
    assert len(result.agreement["rest"]) >= 2 and len(result.agreement["w"]) >= 2
    assert set(result.simulation) == {"rest", "w"}


def test_force_faults_are_reported_with_their_paths() -> None:
    data = falling({"drag": "b", "quadratic_drag": "c"})
    data["forces"].append({"body": "nobody", "drag": "b"})
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    assert {e.path for e in caught.value.errors} == {("forces", 0), ("forces", 1, "body")}
