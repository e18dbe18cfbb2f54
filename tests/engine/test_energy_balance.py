"""Energy bookkeeping in the simulation: the change of T + V equals the work of the non-conservative forces."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.engine.simulation import Dynamics
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in ("m", "theta", "mu", "g")}


def rough_incline(state: dict[str, Any] | None) -> dict[str, Any]:
    """A block on a rough incline, s measured up the slope, friction opposing sliding up."""
    data: dict[str, Any] = {
        "coordinates": ["s"],
        "bodies": {"block": {"mass": "m", "position": {"x": "s*cos(theta)", "y": "s*sin(theta)"}}},
        "gravity": "g",
        "constraints": {"slope": {"kind": "surface", "gap": "y_block*cos(theta) - x_block*sin(theta)"}},
        "friction": [{"constraint": "slope", "body": "block", "coefficient": "mu", "sliding": "s"}],
        "domain": {"ranges": {"theta": ["0", "pi/2"]}},
        "quantities": {"a": {"acceleration": "s"}},
    }
    if state is not None:
        data["state"] = state
    return data


def test_a_block_moving_up_keeps_the_books_and_friction_takes_energy_out() -> None:
    result = uncached(load_model(rough_incline({"s_dot": 1}), SYMBOLS))
    th, mu, g = SYMBOLS["theta"], SYMBOLS["mu"], SYMBOLS["g"]
    assert sympy.simplify(result.quantities["a"] + g * (sympy.sin(th) + mu * sympy.cos(th))) == 0
    assert "energy balance" in result.checks


def test_a_block_released_at_rest_slides_down_against_the_assumed_friction_and_is_refused() -> None:
    with pytest.raises(DerivationError) as caught:
        uncached(load_model(rough_incline(None), SYMBOLS))
    assert caught.value.path == ("friction", 0)
    assert "slides towards decreasing s" in caught.value.message  # gravity, not a weak push: it does slide
    assert "static friction" not in caught.value.message


def test_a_crate_pushed_more_weakly_than_friction_is_refused_as_held_by_static_friction() -> None:
    # released at rest, F < mu m g: the equations send it backwards, against the push
    data = {
        "elements": {
            "floor": {"kind": "surface", "body": "crate", "mass": "m", "coordinate": "x", "friction": "mu"}
        },
        "forces": [{"body": "crate", "force": {"x": "F"}}],
        "gravity": "g",
        "state": {"x": 0},
        "domain": {"positive": ["mu*m*g - F"]},
        "quantities": {"a": {"acceleration": "x"}},
    }
    with pytest.raises(DerivationError) as caught:
        uncached(load_model(data, {**SYMBOLS, "F": sympy.Symbol("F", positive=True)}))
    assert caught.value.path == ("elements", "floor", "friction")
    assert "it stays at rest, static friction holding it" in caught.value.message


def test_equations_that_lose_track_of_the_friction_work_fail_the_books(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(Dynamics, "power", lambda self, q, qd, params, multipliers: 0.0)
    with pytest.raises(DerivationError, match="energy bookkeeping fails"):
        uncached(load_model(rough_incline({"s_dot": 1}), SYMBOLS))
