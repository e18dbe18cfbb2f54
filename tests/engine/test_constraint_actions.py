"""Constraints carry how they act: the contact-sign check takes the unilateral ones (a surface, a
string), the impact code the impulsive one, from one list (`Model.acting`)."""

from __future__ import annotations

import pytest
import sympy

from physics.engine import derive, load_model
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


def stacked(gap: str) -> dict[str, object]:
    """A pull F on the top block; a grip written by hand holds it on the bottom one, which slides free."""
    return {
        "coordinates": ["X"],
        "bodies": {
            "bottom": {"mass": "M", "position": {"x": "X", "y": 0}},
            "top": {"mass": "m", "position": {"x": "X", "y": 0}},
        },
        "gravity": "g",
        "forces": [{"body": "top", "force": {"x": "F"}}],
        "constraints": {
            "floor": {"kind": "surface", "gap": "y_bottom"},
            "rests": {"kind": "surface", "gap": "y_top - y_bottom"},
            "grip": {"kind": "other", "gap": gap},
        },
        "quantities": {"friction": {"force": "grip"}},
    }


F, g = sympy.symbols("F g", positive=True)
m, M = SYMBOLS["m"], SYMBOLS["M"]


@pytest.mark.parametrize(
    ("gap", "expected"),
    [
        # the friction on bottom, along +x (it drags bottom forward): bottom is written with +
        ("x_bottom - x_top", F * M / (M + m)),
        # the same friction is then that on top along +x, which holds it back
        ("x_top - x_bottom", -F * M / (M + m)),
    ],
)
def test_a_hand_written_constraint_s_force_acts_on_the_body_its_gap_grows_with(
    gap: str, expected: sympy.Expr
) -> None:
    result = derive(load_model(stacked(gap), {**SYMBOLS, "F": F, "g": g}))
    assert sympy.simplify(result.quantities["friction"] - expected) == 0
