"""Deliberately wrong models and methods: each ends in a DerivationError that says what went wrong."""

from __future__ import annotations

import copy
from functools import cached_property
from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.engine.lagrange import LagrangeMethod
from physics.engine.newton import NewtonMethod
from physics.errors import DerivationError
from tests.engine.conftest import model_data, symbols

uncached = derivation._derive.__wrapped__  # these tests must not reuse (or pollute) the cache


def _load(problem: str, change: Any) -> Any:
    data = copy.deepcopy(model_data(problem))
    change(data)
    return load_model(data, symbols(problem))


def test_positions_that_violate_a_constraint_are_caught() -> None:
    model = _load("moving-wedge", lambda d: d["bodies"]["block"]["position"].update(y="s*sin(theta)"))
    with pytest.raises(DerivationError, match=r"incline.*violate"):
        uncached(model)


def test_missing_constraint_leaves_too_many_degrees_of_freedom() -> None:
    model = _load(
        "atwood", lambda d: d.update(constraints={}, quantities={"acceleration": {"acceleration": "s"}})
    )
    with pytest.raises(
        DerivationError,
        match=r"2 degrees of freedom but the model has 1 coordinate: no constraint involves y_m1 = s, y_m2 = -s$",
    ):
        uncached(model)


def test_a_component_placed_but_held_by_nothing_is_named() -> None:
    """A hanging mass given `x: 1` beside the pulley is free along x: the refusal names that component."""
    model = _load("atwood", lambda d: d["bodies"]["m2"]["position"].update(x=1))
    with pytest.raises(DerivationError, match=r"no constraint holds x_m2 = 1, which no coordinate moves"):
        uncached(model)


class GravityFlippedNewton(NewtonMethod):
    """Newton's method fed gravity with the wrong sign: one method's input is wrong."""

    @cached_property
    def applied_forces(self) -> list[sympy.Expr]:
        return [-f for f in super().applied_forces]


def test_a_sign_flipped_in_one_method_makes_the_methods_disagree(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(derivation, "_methods", lambda: (LagrangeMethod, GravityFlippedNewton))
    model = _load("atwood", lambda d: None)
    with pytest.raises(DerivationError) as caught:
        uncached(model)
    message = caught.value.message
    assert caught.value.quantity == "acceleration"
    assert "disagree" in message and "lagrange" in message and "newton" in message
    assert "m1" in message and "m2" in message  # the two formulas and the point are shown


def test_a_quantity_only_one_method_reaches_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(derivation, "_methods", lambda: (LagrangeMethod,))
    with pytest.raises(DerivationError, match="only 1 method"):
        uncached(_load("atwood", lambda d: None))


def test_a_wrong_closed_form_is_caught_by_the_simulation(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(derivation, "_simplest", lambda forms: 2 * forms[0])
    with pytest.raises(DerivationError, match="simulation disagrees"):
        uncached(_load("atwood", lambda d: None))


def test_a_potential_without_a_minimum_has_no_stable_equilibrium() -> None:
    model = _load("mass-spring", lambda d: d["potentials"][0].update(energy="-k*e^2/2"))
    with pytest.raises(DerivationError, match="stable equilibrium"):
        uncached(model)


HOOP_ON_NAIL = {
    "elements": {
        "nail": {
            "kind": "pendulum",
            "body": "hoop",
            "mass": "m",
            "inertia": "m*R^2",
            "distance": "R",
            "coordinate": "phi",
        }
    },
    "gravity": "g",
    "domain": {"ranges": {"phi": ["RANGE_LOW", "pi"]}},
    "quantities": {"omega": {"angular_frequency": "phi", "amplitude": "small"}},
}


@pytest.mark.parametrize(
    ("low", "says"),
    [
        (
            "0",
            [
                "at pi the force pushes phi away (dQ/dphi > 0): an unstable rest",
                "[0] left out: phi's declared range excludes it",
            ],
        ),
        ("pi/2", ["[0] left out", "a range is open"]),
    ],
)
def test_no_stable_rest_says_which_roots_push_away_and_which_the_range_left_out(
    low: str, says: list[str]
) -> None:
    data = copy.deepcopy(HOOP_ON_NAIL)
    data["domain"]["ranges"]["phi"][0] = low
    names = {n: sympy.Symbol(n, positive=True) for n in ("m", "R", "g")}
    with pytest.raises(DerivationError) as caught:
        uncached(load_model(data, names))
    for words in says:
        assert words in caught.value.message


def test_an_answer_that_depends_on_the_configuration_needs_a_state() -> None:
    model = _load("ballistic-pendulum", lambda d: d.update(quantities={"swing": {"acceleration": "phi"}}))
    with pytest.raises(DerivationError, match="phi"):
        uncached(model)


def test_giving_the_state_resolves_the_configuration() -> None:
    def change(d: dict[str, Any]) -> None:
        d.update(quantities={"swing": {"acceleration": "phi"}}, state={"phi": "theta"})
        d.pop("collision")

    result = uncached(_load("ballistic-pendulum", change))
    length, th, g = (symbols("ballistic-pendulum")[n] for n in ("L", "theta", "g"))
    assert sympy.simplify(result.quantities["swing"] + g * sympy.sin(th) / length) == 0


def test_a_crash_inside_a_method_becomes_a_derivation_error(monkeypatch: pytest.MonkeyPatch) -> None:
    def crash(self: LagrangeMethod, coordinate: str) -> sympy.Expr:
        raise ZeroDivisionError("division by zero")

    monkeypatch.setattr(LagrangeMethod, "acceleration", crash)
    monkeypatch.setattr(derivation, "_methods", lambda: (LagrangeMethod, NewtonMethod))
    with pytest.raises(DerivationError) as caught:
        uncached(_load("atwood", lambda d: None))
    ((path, message),) = caught.value.items()
    assert path == ("quantities", "acceleration")
    assert "lagrange failed: ZeroDivisionError" in message
    assert "newton gives" in message  # what the other method found


def test_every_quantity_no_two_methods_reach_is_reported_at_once_with_its_path(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(derivation, "_methods", lambda: (LagrangeMethod, NewtonMethod))
    monkeypatch.setattr(NewtonMethod, "force", lambda self, constraint: sympy.Symbol("nonsense"))
    model = _load("moving-wedge", lambda d: None)
    with pytest.raises(DerivationError) as caught:
        uncached(model)
    items = dict(caught.value.items())
    assert set(items) == {("quantities", "normal_force")}
    assert "lagrange gives" in items[("quantities", "normal_force")]
    assert "newton stopped" in items[("quantities", "normal_force")]


def test_a_violated_constraint_is_reported_at_the_constraint() -> None:
    model = _load("moving-wedge", lambda d: d["bodies"]["block"]["position"].update(y="s*sin(theta)"))
    with pytest.raises(DerivationError) as caught:
        uncached(model)
    assert caught.value.items()[0][0] == ("constraints", "incline")
