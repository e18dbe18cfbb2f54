"""A torque on a rigid body, the load kind added as one module (physics/engine/loads/torque.py): a
motor's constant torque has the potential -tau phi, a bearing's torque in the velocity has none; every
method takes both from the model's list of loads."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.dimensions import Dimension
from physics.engine import derivation, load_model
from physics.errors import SpecErrors

uncached = derivation._derive.__wrapped__
NAMES = ("m", "M", "R", "g", "tau", "c")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, M, R, g, tau, c = (SYMBOLS[n] for n in NAMES)


def winch(torque: str, quantities: dict[str, Any]) -> dict[str, Any]:
    """A block hanging from a string wound on a wheel on a fixed axle; s: how far the block has gone
    down, so the wheel turns clockwise (phi = -s/R) and a counter-clockwise torque holds the block up."""
    return {
        "coordinates": ["s"],
        "bodies": {
            "wheel": {"mass": "M", "inertia": "M*R^2/2", "position": {"x": 0, "y": 0}, "angle": "-s/R"},
            "block": {"mass": "m", "position": {"y": "-s"}},
        },
        "gravity": "g",
        "constraints": {
            "string": {"kind": "string", "gap": "y_block - y_wheel - R*phi_wheel"},
            "axleX": {"kind": "other", "gap": "x_wheel"},
            "axleY": {"kind": "other", "gap": "y_wheel"},
        },
        "forces": [{"body": "wheel", "torque": torque}],
        "domain": {"positive": ["m*g*R - tau"]},
        "quantities": quantities,
    }


def test_a_motor_torque_slows_the_falling_block_by_every_method() -> None:
    data = winch("tau", {"a": {"acceleration": "s"}, "T": {"force": "string"}})
    result = uncached(load_model(data, SYMBOLS))
    expected = (m * g - tau / R) / (M / 2 + m)
    assert sympy.simplify(result.quantities["a"] - expected) == 0
    assert sympy.simplify(result.quantities["T"] - m * (g - expected)) == 0
    assert {"lagrange", "newton"} <= set(result.agreement["a"])
    assert {"lagrange", "newton"} <= set(result.agreement["T"])
    assert result.simulation["a"].max_relative_error < 1e-3


def test_a_bearing_torque_in_the_velocity_gives_a_terminal_speed() -> None:
    # the wheel turns at -s'/R: a bearing's torque c s'/R opposes it, a generalized force -c s'/R^2
    data = winch("c*s_dot/R", {"v": {"terminal_velocity": "s"}})
    data["domain"] = {}
    result = uncached(load_model(data, SYMBOLS))
    assert sympy.simplify(result.quantities["v"] - m * g * R**2 / c) == 0
    assert {"lagrange", "newton"} <= set(result.agreement["v"])
    assert "energy balance" in result.checks


def test_a_torque_on_a_particle_is_refused_at_its_entry() -> None:
    data = winch("tau", {"a": {"acceleration": "s"}})
    data["forces"] = [{"body": "block", "torque": "tau"}]
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    assert [e.path for e in caught.value.errors] == [("forces", 0, "torque")]


def test_a_torque_must_be_a_force_times_a_length() -> None:
    mass, length, time = (Dimension({n: 1}) for n in ("mass", "length", "time"))
    dimensions = {
        "m": mass,
        "M": mass,
        "R": length,
        "g": length / time**2,
        "tau": mass * length / time**2,  # a force, not a torque
        "c": mass * length**2 / time,
    }
    with pytest.raises(SpecErrors) as caught:
        load_model(winch("tau", {"a": {"acceleration": "s"}}), SYMBOLS, dimensions)
    assert [e.path for e in caught.value.errors] == [("forces", 0, "torque")]
