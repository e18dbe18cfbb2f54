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


@pytest.mark.parametrize(
    ("expression", "words"),
    [
        pytest.param("later + 1", "later", id="a-quantity-defined-below"),
        pytest.param("tension +", "cannot read", id="unreadable"),
    ],
)
def test_a_formula_may_use_only_quantities_defined_above_it(expression: str, words: str) -> None:
    data = copy.deepcopy(model_data("atwood"))
    data["quantities"] = {"early": {"expression": expression}, "later": {"acceleration": "s"}}
    with pytest.raises(SpecErrors) as caught:
        load_model(data, symbols("atwood"))
    (error,) = caught.value.errors
    assert error.path == ("quantities", "early", "expression")
    assert words in error.message
