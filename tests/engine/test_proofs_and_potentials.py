"""Equality proofs on the domain, and the choice of the physical equilibrium among several roots."""

from __future__ import annotations

import copy

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.engine.proof import domain_points, prove_equal
from physics.errors import DerivationError
from tests.engine.conftest import bank_model, model_data, s, symbols

uncached = derivation._derive.__wrapped__


def test_a_form_that_needs_the_angle_range_is_proved_symbolically() -> None:
    th = s("moving-wedge", "theta")
    how = prove_equal(
        sympy.sin(th), sympy.sqrt(1 - sympy.cos(th) ** 2), bank_model("moving-wedge"), "q", ("a", "b")
    )
    assert how.startswith("symbolic")


def test_different_expressions_are_reported_with_both_formulas_and_a_point() -> None:
    th = s("moving-wedge", "theta")
    with pytest.raises(DerivationError) as caught:
        prove_equal(sympy.sin(th), sympy.cos(th), bank_model("moving-wedge"), "q", ("lagrange", "newton"))
    assert "lagrange gives sin(theta)" in caught.value.message
    assert "newton gives cos(theta)" in caught.value.message
    assert caught.value.quantity == "q"


def test_domain_points_respect_ranges_and_conditions() -> None:
    model = bank_model("skier-friction")
    alpha, mu = s("skier-friction", "alpha"), s("skier-friction", "mu")
    for point in domain_points(model, 20):
        assert 0 < point[alpha] < 1.5708
        assert point[mu] < sympy.tan(point[alpha])


def test_the_stable_root_is_chosen_among_several_equilibria() -> None:
    data = copy.deepcopy(model_data("mass-spring"))
    data["potentials"][0]["energy"] = "k*(e - 1)^2/2 - k*(e - 1)^3/3"  # minimum at 1, maximum at 2
    data["domain"] = {"ranges": {"x": ["0", "oo"]}}  # the block stays on one side of the anchor
    data["quantities"] = {"rest": {"equilibrium": "x"}, "omega": {"angular_frequency": "x"}}
    result = uncached(load_model(data, symbols("mass-spring")))
    assert result.quantities["rest"] == 1
    m, k = s("mass-spring", "m"), s("mass-spring", "k")
    assert sympy.simplify(result.quantities["omega"] - sympy.sqrt(k / m)) == 0
    assert result.simulation["omega"].max_relative_error < 1e-3
