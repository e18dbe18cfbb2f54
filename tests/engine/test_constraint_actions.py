"""Constraints carry how they act: the contact-sign check takes the unilateral ones (a surface, a
string), the impact code the impulsive one, from one list (`Model.acting`)."""

from __future__ import annotations

import pytest
import sympy

from physics.engine import load_model
from physics.engine.model import Action

SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in ("m", "M", "R", "u", "e", "L")}
DATA = {
    "coordinates": ["x1", "x2", "phi"],
    "bodies": {
        "cart1": {"mass": "m", "position": {"x": "x1", "y": 0}},
        "cart2": {"mass": "M", "position": {"x": "x2", "y": 0}},
        "wheel": {"mass": "m", "inertia": "m*R^2/2", "position": {"x": "x2", "y": "R"}, "angle": "phi"},
    },
    "constraints": {
        "floor": {"kind": "surface", "gap": "y_cart1"},
        "rails": {"kind": "other", "gap": "y_cart2"},
        "axle": {"kind": "other", "gap": "y_wheel - y_cart2 - R"},
        "tether": {"kind": "string", "gap": "L - (x_wheel - x_cart2)"},
        "grip": {"kind": "rolling", "gap": "x_wheel - x_cart2 + R*phi_wheel"},
    },
    "impact": {"bodies": ["cart1", "cart2"], "restitution": "e"},
    "state": {"x1_dot": "u"},
    "quantities": {"v": {"final_speed": "cart1"}},
}


@pytest.mark.parametrize(
    ("action", "names"),
    [
        pytest.param(Action.UNILATERAL, ["floor", "tether"], id="a surface pushes, a string pulls"),
        pytest.param(Action.BILATERAL, ["rails", "axle", "grip"], id="axles, rails and grips either way"),
    ],
)
def test_constraints_are_listed_by_how_they_act(action: Action, names: list[str]) -> None:
    model = load_model(DATA, SYMBOLS)
    assert [getattr(c, "name", None) for c in model.acting(action)] == names


def test_the_impact_is_the_impulsive_constraint() -> None:
    model = load_model(DATA, SYMBOLS)
    assert model.acting(Action.IMPULSIVE) == (model.impact,)
    assert model.acting(Action.IMPULSIVE)[0].action is Action.IMPULSIVE
