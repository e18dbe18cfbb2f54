"""Limiting cases the author states, and friction to zero, checked on the derived expressions."""

from __future__ import annotations

import copy
from typing import Any

import pytest

from physics.engine import derivation, load_model
from physics.errors import DerivationError, SpecErrors
from tests.engine.conftest import bank_derivation, model_data, symbols

uncached = derivation._derive.__wrapped__


def wedge(expect: dict[str, str]) -> Any:
    data = copy.deepcopy(model_data("moving-wedge"))
    data["limits"] = [{"where": {"M": "oo"}, "expect": expect, "description": "the wedge held fixed"}]
    return load_model(data, symbols("moving-wedge"))


@pytest.mark.slow
def test_a_right_stated_limit_is_recorded_as_checked() -> None:
    result = uncached(wedge({"wedge_acceleration": "0", "block_relative_acceleration": "g*sin(theta)"}))
    assert result.checks["limit block_relative_acceleration (M → oo)"] == "the wedge held fixed"
    assert "limit wedge_acceleration (M → oo)" in result.checks


@pytest.mark.slow
def test_a_stated_limit_the_derivation_does_not_reach_is_refused_at_its_path() -> None:
    with pytest.raises(DerivationError) as caught:
        uncached(wedge({"block_relative_acceleration": "g*cos(theta)"}))
    assert caught.value.path == ("limits", 0, "expect", "block_relative_acceleration")
    assert "g*sin(theta)" in caught.value.message.replace(" ", "")


def test_a_stated_limit_of_an_unknown_quantity_is_a_spec_error() -> None:
    data = copy.deepcopy(model_data("moving-wedge"))
    data["limits"] = [{"where": {"M": "oo"}, "expect": {"wedge_accel": "0"}}]
    with pytest.raises(SpecErrors) as caught:
        load_model(data, symbols("moving-wedge"))
    assert caught.value.errors[0].path == ("limits", 0, "expect", "wedge_accel")


@pytest.mark.slow
def test_friction_to_zero_is_checked_against_the_frictionless_model() -> None:
    checks = bank_derivation("skier-friction").checks
    assert "limit acceleration (no friction)" in checks
    assert "energy balance" in checks


# (an expression written with the friction's own coefficient, what it tends to with no friction)
FORMULAS_WITH_THE_COEFFICIENT = [
    pytest.param("-mu*normal*4", "0", id="friction's work"),
    pytest.param("normal*(1 + mu)", "g*m*cos(alpha)", id="normal plus friction"),
]


@pytest.mark.parametrize(("formula", "limit"), FORMULAS_WITH_THE_COEFFICIENT)
def test_a_formula_in_the_friction_coefficient_tends_to_its_own_value_with_no_friction(
    formula: str, limit: str
) -> None:
    """The frictionless model keeps the author's formula: the coefficient in it goes to zero too."""
    data = copy.deepcopy(model_data("skier-friction"))
    data["quantities"] = {"normal": {"force": "slope"}, "formula": {"expression": formula}}
    result = uncached(load_model(data, symbols("skier-friction")))
    assert f"tends to the frictionless model's {limit}" == result.checks["limit formula (no friction)"]
