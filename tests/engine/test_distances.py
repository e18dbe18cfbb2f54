"""Distances in potentials are lengths: the hanging-spring trap derives the right answer or is refused."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derive, load_model
from physics.errors import DerivationError, SpecErrors

NAMES = ("m", "k", "g", "L0")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, k, g, L0 = (SYMBOLS[n] for n in NAMES)


def hanging_spring(
    position: str, coordinate: str, ranges: dict[str, list[str]] | None = None, positive: tuple[str, ...] = ()
) -> dict[str, Any]:
    """A mass on a vertical spring of natural length L0 hung from an anchor at the origin."""
    data: dict[str, Any] = {
        "coordinates": [coordinate],
        "bodies": {"bob": {"mass": "m", "position": {"y": position}}},
        "gravity": "g",
        "potentials": [{"bodies": ["bob"], "anchor": {"y": 0}, "distance": "d", "energy": "k*(d - L0)^2/2"}],
        "quantities": {"rest": {"equilibrium": coordinate}, "omega": {"angular_frequency": coordinate}},
    }
    if ranges is not None:
        data["domain"] = {"ranges": ranges}
    if positive:  # the spring stiff enough that the rest stays inside the declared range
        data.setdefault("domain", {})["positive"] = list(positive)
    return data


def test_a_spring_whose_side_is_not_declared_is_refused_with_the_reason() -> None:
    with pytest.raises(SpecErrors) as caught:
        load_model(hanging_spring("y", "y"), SYMBOLS)
    (error,) = caught.value.errors
    assert error.path == ("potentials", 0, "distance")
    assert "not even in d" in error.message
    assert "domain.ranges" in error.message


@pytest.mark.parametrize(
    ("position", "coordinate", "ranges", "positive", "rest"),
    [
        pytest.param("y", "y", {"y": ["-oo", "0"]}, (), -(L0 + m * g / k), id="below-the-anchor"),
        pytest.param("-s", "s", {"s": ["0", "oo"]}, (), L0 + m * g / k, id="length-down-from-the-anchor"),
        pytest.param(
            "y", "y", {"y": ["0", "oo"]}, ("k*L0 - m*g",), L0 - m * g / k, id="standing-on-the-spring"
        ),
        # the foot at -L0 and the block above it: y >= -L0 settles |L0 + y| on a range open above
        pytest.param(
            "y + L0", "y", {"y": ["-L0", "oo"]}, ("k*L0 - m*g",), -m * g / k, id="foot-below-the-origin"
        ),
    ],
)
def test_a_declared_side_gives_the_extension_m_g_over_k(
    position: str, coordinate: str, ranges: dict[str, list[str]], positive: tuple[str, ...], rest: sympy.Expr
) -> None:
    result = derive(load_model(hanging_spring(position, coordinate, ranges, positive), SYMBOLS))
    assert sympy.simplify(result.quantities["rest"] - rest) == 0
    assert sympy.simplify(result.quantities["omega"] - sympy.sqrt(k / m)) == 0
    assert set(result.simulation) == {"rest", "omega"}


def test_an_energy_even_in_the_distance_needs_no_side() -> None:
    data = hanging_spring("y", "y")
    data["potentials"][0]["energy"] = "k*d^2/2"
    result = derive(load_model(data, SYMBOLS))
    assert sympy.simplify(result.quantities["rest"] + m * g / k) == 0


def test_a_range_that_straddles_the_anchor_does_not_fix_the_side() -> None:
    with pytest.raises(SpecErrors) as caught:
        load_model(hanging_spring("y", "y", {"y": ["-2*L0", "L0"]}), SYMBOLS)
    assert caught.value.errors[0].path == ("potentials", 0, "distance")


def test_a_rest_outside_the_declared_range_is_refused() -> None:
    # standing on the spring where m g > k L0: the rest L0 - m g/k would be below its foot
    with pytest.raises(DerivationError, match="outside y's declared range"):
        derive(load_model(hanging_spring("y", "y", {"y": ["0", "oo"]}), SYMBOLS))


def test_a_bounded_range_on_one_side_fixes_it() -> None:
    bounded = hanging_spring("y", "y", {"y": ["-10*L0", "-L0/100"]}, ("9*k*L0 - m*g",))
    result = derive(load_model(bounded, SYMBOLS))
    assert sympy.simplify(result.quantities["rest"] + L0 + m * g / k) == 0


def test_a_symmetric_pair_of_stable_equilibria_is_resolved_by_the_declared_range() -> None:
    names = {n: sympy.Symbol(n, positive=True) for n in ("m", "k", "a", "b")}
    data: dict[str, Any] = {
        "coordinates": ["x"],
        "bodies": {"bead": {"mass": "m", "position": {"x": "x"}}},
        "potentials": [
            {"bodies": ["bead"], "anchor": {"x": 0}, "distance": "d", "energy": "k*((d - b)^2 - a^2)^2"}
        ],
        "domain": {"positive": ["b - a"], "ranges": {"x": ["b", "b + 2*a"]}},  # minima at b - a and b + a
        "quantities": {"rest": {"equilibrium": "x"}},
    }
    result = derive(load_model(data, names))
    assert sympy.simplify(result.quantities["rest"] - names["a"] - names["b"]) == 0
    data["domain"]["ranges"] = {"x": ["0", "oo"]}  # both minima in range: refused, saying so
    with pytest.raises(DerivationError, match="stable equilibri"):
        derive(load_model(data, names))


def test_a_spring_anchored_down_a_slope_rests_on_the_side_its_range_declares() -> None:
    # the anchor D down the slope, the block above it (s <= D): the length sqrt((s - D)^2) is D - s, so
    # the spring is squeezed at rest; it had been taken as s - D, a rest beyond the anchor, and refused
    data = {
        "elements": {
            "ramp": {"kind": "incline", "body": "block", "mass": "m", "angle": "theta", "coordinate": "s"},
            "spring": {
                "kind": "spring",
                "between": ["block", {"x": "D*cos(theta)", "y": "-D*sin(theta)"}],
                "stiffness": "k",
                "length": "L0",
            },
        },
        "gravity": "g",
        "domain": {
            "ranges": {"theta": ["0", "pi/2"], "s": ["-oo", "D"]},
            "positive": ["k*L0 - m*g*sin(theta)"],
        },
        "quantities": {"rest": {"equilibrium": "s"}},
    }
    theta, length = sympy.Symbol("theta", positive=True), sympy.Symbol("D", positive=True)
    rest = derive(load_model(data, {**SYMBOLS, "theta": theta, "D": length})).quantities["rest"]
    assert sympy.simplify(rest - (length - L0 + m * g * sympy.sin(theta) / k)) == 0
