"""Several scenarios of one system in one model: each overrides part of the model (the kind of impact,
where a push acts), is derived, proved and simulated on its own, and its quantities are named
`<scenario>.<name>`; a faulty scenario is refused at its own path. Also two uncoupled pendulums in one
model, each with its own frequency."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derive, load_model
from physics.engine.notation import audit
from physics.engine.scenarios import merged, quantity_names
from physics.errors import DerivationError, SpecErrors

NAMES = ("m1", "m2", "u", "F", "m", "M", "L", "g")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m1, m2, u, F, m, M, L, g = (SYMBOLS[n] for n in NAMES)


def carts(**scenarios: Any) -> dict[str, Any]:
    """cart1 runs into cart2 at rest: elastic, unless a scenario says otherwise."""
    return {
        "coordinates": ["x1", "x2"],
        "bodies": {
            "cart1": {"mass": "m1", "position": {"x": "x1"}},
            "cart2": {"mass": "m2", "position": {"x": "x2"}},
        },
        "state": {"x1_dot": "u"},
        "impact": {"bodies": ["cart1", "cart2"], "restitution": 1},
        "quantities": {"v2": {"final_velocity": "cart2"}},
        "scenarios": scenarios,
    }


STICKING = {
    "impact": {"restitution": 0},
    "quantities": {"v2": {"final_velocity": "cart2"}, "lost": {"kinetic_energy_lost": "impact"}},
}


def pushed(**scenarios: Any) -> dict[str, Any]:
    """Two blocks side by side on a smooth floor, block1 pushed towards block2."""
    return {
        "coordinates": ["s"],
        "bodies": {
            "block1": {"mass": "m1", "position": {"x": "s"}},
            "block2": {"mass": "m2", "position": {"x": "s"}},
        },
        "constraints": {"contact": {"kind": "surface", "gap": "x_block2 - x_block1"}},
        "forces": [{"body": "block1", "force": {"x": "F"}}],
        "quantities": {"contact_force": {"force": "contact"}},
        "scenarios": scenarios,
    }


def test_each_scenario_is_derived_and_simulated_under_its_own_name() -> None:
    derived = derive(load_model(carts(sticking=STICKING), SYMBOLS))
    assert sympy.simplify(derived.quantities["v2"] - 2 * m1 * u / (m1 + m2)) == 0
    assert sympy.simplify(derived.quantities["sticking.v2"] - m1 * u / (m1 + m2)) == 0
    assert sympy.simplify(derived.quantities["sticking.lost"] - m1 * m2 * u**2 / (2 * (m1 + m2))) == 0
    for name in ("v2", "sticking.v2", "sticking.lost"):
        assert len(derived.agreement[name]) >= 2
        assert derived.simulation[name].points > 0
    titles = [s.title for r in derived.methods for s in r.steps]
    assert any(t.endswith("(scenario sticking)") for t in titles)


def test_a_scenario_moves_a_load_to_the_other_body() -> None:
    other_side = {
        "forces": [{"body": "block2", "force": {"x": "-F"}}],
        "quantities": {"contact_force": {"force": "contact"}},
    }
    derived = derive(load_model(pushed(other_side=other_side), SYMBOLS)).quantities
    assert sympy.simplify(derived["contact_force"] - m2 * F / (m1 + m2)) == 0
    assert sympy.simplify(derived["other_side.contact_force"] - m1 * F / (m1 + m2)) == 0


def test_a_scenario_keeps_what_it_does_not_change_and_asks_only_its_own_questions() -> None:
    base = carts()
    scenario = merged({k: v for k, v in base.items() if k != "scenarios"}, STICKING)
    assert scenario["impact"] == {"bodies": ["cart1", "cart2"], "restitution": 0}
    assert scenario["quantities"] == STICKING["quantities"]
    assert "state" in scenario
    removed = merged(base, {"state": None, "quantities": {}})
    assert "state" not in removed
    names = quantity_names(load_model(carts(sticking=STICKING), SYMBOLS))
    assert set(names) == {"v2", "sticking.v2", "sticking.lost"}


@pytest.mark.parametrize(
    ("scenario", "path", "said"),
    [
        ({"impact": {"restitution": 0}}, ("scenarios", "sticking", "quantities"), "asks its own quantities"),
        (
            {"impact": {"bodies": ["cart1", "cart3"]}, "quantities": {"v": {"final_velocity": "cart2"}}},
            ("scenarios", "sticking", "impact", "bodies", 1),
            "unknown body 'cart3'",
        ),
        ("elastic", ("scenarios", "sticking"), "a mapping of the sections"),
    ],
)
def test_a_faulty_scenario_is_refused_at_its_path(scenario: Any, path: tuple[Any, ...], said: str) -> None:
    with pytest.raises(SpecErrors) as caught:
        load_model(carts(sticking=scenario), SYMBOLS)
    assert any(e.path == path and said in e.message for e in caught.value.errors), caught.value


def test_a_scenario_that_does_not_derive_is_refused_naming_the_scenario() -> None:
    # the carts move apart in this scenario: no impact happens
    apart = {"state": {"x1_dot": "-u"}, "quantities": {"v2": {"final_velocity": "cart2"}}}
    with pytest.raises(DerivationError) as caught:
        derive(load_model(carts(apart=apart), SYMBOLS))
    assert caught.value.path[:2] == ("scenarios", "apart")
    assert "in scenario 'apart'" in caught.value.message
    assert "do not approach" in caught.value.message


def test_two_uncoupled_pendulums_each_have_their_own_period() -> None:
    data = {
        "elements": {
            "string": {"kind": "pendulum", "body": "bob", "mass": "m", "length": "L", "coordinate": "phi"},
            "axle": {
                "kind": "pendulum",
                "body": "rod",
                "mass": "M",
                "inertia": "M*L^2/12",
                "distance": "L/2",
                "coordinate": "psi",
                "pivot": {"x": "2*L", "y": 0},
            },
        },
        "gravity": "g",
        "quantities": {"simple": {"angular_frequency": "phi"}, "rod": {"angular_frequency": "psi"}},
    }
    derived = derive(load_model(data, SYMBOLS))
    assert sympy.simplify(derived.quantities["simple"] - sympy.sqrt(g / L)) == 0
    assert sympy.simplify(derived.quantities["rod"] - sympy.sqrt(3 * g / (2 * L))) == 0
    assert {"lagrange", "conservation"} <= set(derived.agreement["rod"])


def test_two_uncoupled_springs_each_have_their_own_frequency_by_newton_too() -> None:
    data = {
        "coordinates": ["x1", "x2"],
        "bodies": {"a": {"mass": "m", "position": {"x": "x1"}}, "b": {"mass": "M", "position": {"x": "x2"}}},
        "potentials": [
            {"bodies": ["a"], "anchor": {"x": 0}, "distance": "d", "energy": "m*g*d^2/(2*L)"},
            {"bodies": ["b"], "anchor": {"x": 0}, "distance": "e", "energy": "M*g*e^2/L"},
        ],
        "quantities": {"first": {"angular_frequency": "x1"}, "second": {"angular_frequency": "x2"}},
    }
    derived = derive(load_model(data, SYMBOLS))
    assert sympy.simplify(derived.quantities["first"] - sympy.sqrt(g / L)) == 0
    assert sympy.simplify(derived.quantities["second"] - sympy.sqrt(2 * g / L)) == 0
    assert "newton" in derived.agreement["second"]


@pytest.mark.parametrize(("name", "said"), [("other_side", "other side"), ("otherSide", "other side")])
def test_a_scenario_s_worked_steps_name_it_in_words_and_pass_the_notation_audit(name: str, said: str) -> None:
    scenario = {
        "forces": [{"body": "block2", "force": {"x": "-F"}}],
        "quantities": {"contact_force": {"force": "contact"}},
    }
    model = load_model(pushed(**{name: scenario}), SYMBOLS)
    derived = derive(model)
    titles = [s.title for r in derived.methods for s in r.steps]
    assert any(t.endswith(f"(scenario {said})") for t in titles)
    assert audit(model, derived.notation, derived.methods) == []
