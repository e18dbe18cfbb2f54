"""Forces that depend on the time t: accelerations and forces at the state's time by Lagrange and Newton,
simulated with a clock, the driving force's work counted in the energy books."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.dimensions import DIMENSIONLESS, Dimension
from physics.engine import derivation, load_model
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__
NAMES = ("m", "k", "b", "F0", "w", "A", "g")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, k, b, F0, w, A, g = SYMBOLS.values()


def driven_cart(state: dict[str, str] | None = None) -> dict[str, Any]:
    """A cart on a spring and a dashpot, driven by F0 cos(w t), on a floor."""
    return {
        "coordinates": ["x"],
        "bodies": {"cart": {"mass": "m", "position": {"x": "x", "y": 0}}},
        "gravity": "g",
        "constraints": {"floor": {"kind": "surface", "gap": "y_cart"}},
        "elements": {"spring": {"kind": "spring", "between": [{"x": 0}, "cart"], "stiffness": "k"}},
        "forces": [{"body": "cart", "force": {"x": "F0*cos(w*t)"}}, {"body": "cart", "drag": "b"}],
        "state": {"x": "A", "t": "pi/(3*w)"} if state is None else state,
        "quantities": {"a": {"acceleration": "x"}, "N": {"force": "floor"}},
    }


@pytest.mark.parametrize(
    "domain",
    [pytest.param({}, id="slow-drive"), pytest.param({"ranges": {"w": ["100", "300"]}}, id="fast-drive")],
)
def test_a_driving_force_is_taken_at_the_states_time_and_its_work_is_counted(domain: dict[str, Any]) -> None:
    result = uncached(load_model({**driven_cart(), "domain": domain}, SYMBOLS))
    assert sympy.simplify(result.quantities["a"] - (F0 / 2 - k * A) / m) == 0
    assert {"lagrange", "newton"} <= set(result.agreement["a"])
    assert result.simulation["a"].max_relative_error < 1e-3
    assert "energy balance" in result.checks


def test_without_a_time_in_the_state_the_answer_needs_one() -> None:
    with pytest.raises(DerivationError, match=r"leaves \['t'\]"):
        uncached(load_model(driven_cart({"x": "A"}), SYMBOLS))


def test_a_time_of_the_symbol_table_leaves_answers_functions_of_it() -> None:
    t = sympy.Symbol("t", positive=True)
    result = uncached(load_model(driven_cart({"x": "A"}), {**SYMBOLS, "t": t}))
    assert sympy.simplify(result.quantities["a"] - (F0 * sympy.cos(w * t) - k * A) / m) == 0
    assert result.simulation["a"].points == 3


def test_a_time_of_the_symbol_table_that_the_state_gives_is_taken_at_the_states_time() -> None:
    t = sympy.Symbol("t", positive=True)
    result = uncached(load_model(driven_cart(), {**SYMBOLS, "t": t}))
    assert sympy.simplify(result.quantities["a"] - (F0 / 2 - k * A) / m) == 0
    assert result.simulation["a"].max_relative_error < 1e-3


def test_what_needs_a_steady_equilibrium_is_refused_with_a_driving_force() -> None:
    data = driven_cart()
    data["quantities"] = {"rest": {"equilibrium": "x"}, "a": {"acceleration": "x"}}
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    assert [e.path for e in caught.value.errors] == [("quantities", "rest", "equilibrium")]


def test_a_time_in_the_state_that_no_force_uses_is_refused() -> None:
    data = driven_cart()
    data["forces"] = [{"body": "cart", "drag": "b"}]
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    assert [e.path for e in caught.value.errors] == [("state", "t")]


def test_the_time_is_a_time_in_the_dimensional_check() -> None:
    mass, length, time = Dimension({"mass": 1}), Dimension({"length": 1}), Dimension({"time": 1})
    force = mass * length / time**2
    declared = {
        "m": mass,
        "k": force / length,
        "b": mass / time,
        "F0": force,
        "w": DIMENSIONLESS / time,
        "A": length,
        "g": length / time**2,
    }
    load_model(driven_cart(), SYMBOLS, declared)  # consistent: w t is a pure number
    data = driven_cart()
    data["forces"][0]["force"]["x"] = "F0*cos(w + t)"  # 1/s added to s
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS, declared)
    assert caught.value.errors[0].path == ("forces", 0, "force", "x")


def test_a_swapped_drive_phase_gets_feedback_about_the_drive_not_a_surface() -> None:
    t = sympy.Symbol("t", positive=True)
    result = uncached(load_model(driven_cart({"x": "A"}), {**SYMBOLS, "t": t}))
    sine_drive = (F0 * sympy.sin(w * t) - k * A) / m
    swapped = [slip.feedback for slip in result.mistakes["a"] if sympy.simplify(slip.expr - sine_drive) == 0]
    assert swapped and "driving force" in swapped[0]
    amplitude = (F0 - k * A) / m  # F0 cos(w t) taken as F0
    taken = [slip.feedback for slip in result.mistakes["a"] if sympy.simplify(slip.expr - amplitude) == 0]
    assert taken and "amplitude" in taken[0]
    assert all("surface" not in slip.feedback for slip in result.mistakes["a"])
