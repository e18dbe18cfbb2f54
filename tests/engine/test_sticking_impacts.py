"""Impacts in the plane: bodies that stick move on together; an approach across the plane needs a normal;
a symbol's own range bounds the sampled domain (a restitution is never checked at 1.02)."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.engine.proof import domain_points
from physics.errors import SpecErrors

uncached = derivation._derive.__wrapped__
m1, m2, u1, u2, e, alpha = sympy.symbols("m1 m2 u1 u2 e alpha", positive=True)
SYMBOLS = {s.name: s for s in (m1, m2, u1, u2, e, alpha)}


def _pucks(impact: dict[str, Any], state: dict[str, str]) -> dict[str, Any]:
    return {
        "coordinates": ["x1", "y1", "x2", "y2"],
        "bodies": {
            "puck1": {"mass": "m1", "position": {"x": "x1", "y": "y1"}},
            "puck2": {"mass": "m2", "position": {"x": "x2", "y": "y2"}},
        },
        "state": state,
        "impact": impact,
        "quantities": {
            "speed": {"final_speed": "puck1"},
            "other": {"final_speed": "puck2"},
            "lost": {"kinetic_energy_lost": "impact"},
        },
    }


def test_pucks_that_stick_at_right_angles_keep_both_momenta() -> None:
    model = load_model(
        _pucks({"bodies": ["puck1", "puck2"], "stick": True}, {"x1_dot": "u1", "y2_dot": "u2"}), SYMBOLS
    )
    derived = uncached(model)
    together = sympy.sqrt((m1 * u1) ** 2 + (m2 * u2) ** 2) / (m1 + m2)
    assert sympy.simplify(derived.quantities["speed"] - together) == 0
    assert sympy.simplify(derived.quantities["other"] - together) == 0
    assert sympy.simplify(derived.quantities["lost"] - m1 * m2 * (u1**2 + u2**2) / (2 * (m1 + m2))) == 0


@pytest.mark.parametrize(
    ("impact", "state", "message"),
    [
        (
            {"bodies": ["puck1", "puck2"], "restitution": 0},
            {"x1_dot": "u1", "y2_dot": "u2"},
            "approach across the plane",
        ),
        (
            {"bodies": ["puck1", "puck2"], "stick": True, "restitution": 0},
            {"x1_dot": "u1"},
            "need no restitution",
        ),
        ({"bodies": ["puck1", "puck2"], "stick": True}, {}, "do not move towards each other"),
        ({"bodies": ["puck1", "puck2"], "stick": "yes"}, {"x1_dot": "u1"}, "stick is true"),
    ],
)
def test_an_impact_whose_line_is_not_stated_is_refused(
    impact: dict[str, Any], state: dict[str, str], message: str
) -> None:
    with pytest.raises(SpecErrors, match=message):
        load_model(_pucks(impact, state), SYMBOLS)


def test_an_approach_along_x_keeps_the_default_normal() -> None:
    model = load_model(_pucks({"bodies": ["puck1", "puck2"], "restitution": 1}, {"x1_dot": "u1"}), SYMBOLS)
    assert model.impact is not None and dict(model.impact.normal) == {"x": 1}


def test_sticking_is_refused_for_a_body_a_constraint_holds() -> None:
    data = _pucks({"bodies": ["puck1", "puck2"], "stick": True}, {"x1_dot": "u1"})
    data["coordinates"] = ["x1", "x2", "y2"]
    data["bodies"]["puck1"]["position"] = {"x": "x1", "y": 0}
    data["constraints"] = {"track": {"kind": "surface", "gap": "y_puck1"}}
    with pytest.raises(SpecErrors, match="track also pushes"):
        load_model(data, SYMBOLS)


def test_a_symbols_own_range_bounds_the_sampled_domain() -> None:
    data = {
        "coordinates": ["x", "y"],
        "bodies": {"ball": {"mass": "m1", "position": {"x": "x", "y": "y"}}},
        "state": {"x_dot": "u1*cos(alpha)", "y_dot": "u1*sin(alpha)"},
        "impact": {"bodies": ["ball", {"fixed": "wall"}], "normal": {"x": 1}, "restitution": "e"},
        "quantities": {"speed": {"final_speed": "ball"}},
    }
    ranges = {"e": (sympy.Integer(0), sympy.Integer(1)), "alpha": (sympy.Integer(0), sympy.pi / 2)}
    model = load_model(data, SYMBOLS, ranges=ranges)
    points = domain_points(model, 40)
    assert all(0 <= p[e] <= 1 and 0 <= p[alpha] <= float(sympy.pi / 2) for p in points)
    speed = uncached(model).quantities["speed"]
    assert sympy.simplify(speed**2 - u1**2 * (e**2 * sympy.cos(alpha) ** 2 + sympy.sin(alpha) ** 2)) == 0
