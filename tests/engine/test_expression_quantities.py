"""A quantity defined as a formula of other quantities is derived by each method from its own values."""

from __future__ import annotations

import copy

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.errors import SpecErrors
from tests.engine.conftest import model_data, symbols

uncached = derivation._derive.__wrapped__


def test_a_formula_of_earlier_quantities_is_derived_by_each_method() -> None:
    data = copy.deepcopy(model_data("atwood"))
    data["quantities"]["net_force_on_m1"] = {"expression": "tension - m1*g"}
    data["quantities"]["time_to_fall_1m"] = {"expression": "sqrt(2/acceleration)"}
    data["domain"] = {"positive": ["m2 - m1"]}  # m2 falls: the time is real, and simulated
    result = uncached(load_model(data, symbols("atwood")))
    m1, m2, g = (symbols("atwood")[n] for n in ("m1", "m2", "g"))
    acceleration = (m2 - m1) * g / (m1 + m2)
    assert sympy.simplify(result.quantities["net_force_on_m1"] - m1 * acceleration) == 0
    assert sympy.simplify(result.quantities["time_to_fall_1m"] ** 2 - 2 / acceleration) == 0
    assert len(result.agreement["net_force_on_m1"]) >= 2
    assert set(result.agreement["time_to_fall_1m"]) == {"lagrange", "newton", "conservation", "dalembert"}


def test_a_formula_may_use_a_quantity_defined_below_it() -> None:
    data = copy.deepcopy(model_data("atwood"))
    data["quantities"] = {"early": {"expression": "2*later"}, "later": {"acceleration": "s"}}
    result = uncached(load_model(data, symbols("atwood")))
    assert sympy.simplify(result.quantities["early"] - 2 * result.quantities["later"]) == 0


@pytest.mark.parametrize(
    ("expression", "words"),
    [
        pytest.param("nowhere + 1", "nowhere", id="no-such-quantity"),
        pytest.param("tension +", "cannot read", id="unreadable"),
        pytest.param("early + 1", "nknown", id="itself"),
    ],
)
def test_a_formula_must_use_quantities_of_the_model(expression: str, words: str) -> None:
    data = copy.deepcopy(model_data("atwood"))
    data["quantities"] = {"early": {"expression": expression}, "later": {"acceleration": "s"}}
    with pytest.raises(SpecErrors) as caught:
        load_model(data, symbols("atwood"))
    (error,) = caught.value.errors
    assert error.path == ("quantities", "early", "expression")
    assert words in error.message


def test_formulas_that_use_each_other_in_a_circle_are_refused() -> None:
    data = copy.deepcopy(model_data("atwood"))
    data["quantities"] = {
        "a": {"expression": "b + 1"},
        "b": {"expression": "2*a"},
        "c": {"acceleration": "s"},
    }
    with pytest.raises(SpecErrors) as caught:
        load_model(data, symbols("atwood"))
    (error,) = caught.value.errors
    assert error.path == ("quantities", "a", "expression")
    assert "a circle: a -> b -> a" in error.message


# (bank problem, added expressions, the one that must be simulated, the inputs its check names)
SIMULATED_FORMULAS = [
    pytest.param("atwood", {"net": {"expression": "tension - m1*g"}}, "net", "tension", id="of-a-force"),
    pytest.param(
        "atwood",
        {"half": {"expression": "net/2"}, "net": {"expression": "tension - m1*g"}},
        "half",
        "net",
        id="of-an-expression",
    ),
]


@pytest.mark.parametrize(("problem", "added", "name", "inputs"), SIMULATED_FORMULAS)
def test_a_formula_is_simulated_on_its_inputs_measured_values(
    problem: str, added: dict[str, object], name: str, inputs: str
) -> None:
    data = copy.deepcopy(model_data(problem))
    data["quantities"].update(added)
    result = uncached(load_model(data, symbols(problem)))
    check = result.simulation[name]
    assert f"of the measured {inputs}" in check.compared
    assert check.max_relative_error < 1e-4


CARTS = """
coordinates: [x1, x2]
bodies:
  cart1: {mass: m1, position: {x: x1}}
  cart2: {mass: m2, position: {x: x2}}
state: {x1_dot: u}
impact: {bodies: [cart1, cart2], restitution: 1}
quantities:
  v2: {final_velocity: cart2}
  energy2: {expression: "m2*v2^2/2"}
"""


def test_a_formula_of_an_impacts_velocity_is_simulated_through_the_integrated_contact() -> None:
    table = {n: sympy.Symbol(n, positive=True) for n in ("m1", "m2", "u")}
    result = uncached(load_model(yaml.safe_load(CARTS), table))
    assert "of the measured v2" in result.simulation["energy2"].compared
    assert result.simulation["energy2"].max_relative_error < 1e-4
