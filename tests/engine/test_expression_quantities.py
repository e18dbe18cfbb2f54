"""A quantity defined as a formula of other quantities is derived by each method from its own values."""

from __future__ import annotations

import copy

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.errors import SpecErrors
from tests.engine.conftest import model_data, symbols

uncached = derivation._derive.__wrapped__


def test_a_formula_of_earlier_quantities_is_derived_by_each_method() -> None:
    data = copy.deepcopy(model_data("atwood"))
    data["quantities"]["net_force_on_m1"] = {"expression": "tension - m1*g"}
    data["quantities"]["time_to_fall_1m"] = {"expression": "sqrt(2/acceleration)"}
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
