"""Dimensional consistency of the model itself: a check the methods cannot make, since they share the model."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.dimensions import DIMENSIONLESS, Dimension
from physics.engine import load_model
from physics.errors import SpecErrors

MASS, LENGTH, TIME = Dimension({"mass": 1}), Dimension({"length": 1}), Dimension({"time": 1})
DIMENSIONS = {
    "m": MASS,
    "k": MASS / TIME**2,
    "g": LENGTH / TIME**2,
    "L": LENGTH,
    "theta": DIMENSIONLESS,
}
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in DIMENSIONS}


def pendulum_on_spring() -> dict[str, Any]:
    return {
        "coordinates": ["s", "phi"],
        "bodies": {"bob": {"mass": "m", "position": {"x": "(L + s)*sin(phi)", "y": "-(L + s)*cos(phi)"}}},
        "gravity": "g",
        "potentials": [
            {"bodies": ["bob"], "anchor": {"x": 0, "y": 0}, "distance": "d", "energy": "k*(d - L)^2/2"}
        ],
        "state": {"s": "L/2", "phi": "theta"},
        "quantities": {"a": {"acceleration": "s"}},
    }


def _faults(change: Any) -> dict[tuple[str | int, ...], str]:
    data = pendulum_on_spring()
    change(data)
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS, DIMENSIONS)
    return {e.path: e.message for e in caught.value.errors}


def test_a_consistent_model_loads_and_its_coordinates_are_inferred() -> None:
    load_model(pendulum_on_spring(), SYMBOLS, DIMENSIONS)


@pytest.mark.parametrize(
    ("change", "path", "words"),
    [
        pytest.param(
            lambda d: d["potentials"][0].update(energy="k*(d - L)"),
            ("potentials", 0, "energy"),
            "expected an energy",
            id="a-force-written-as-the-energy",
        ),
        pytest.param(
            lambda d: d["bodies"]["bob"]["position"].update(x="(L + s)*sin(phi) + m"),
            ("bodies", "bob", "position", "x"),
            "adds",
            id="a-mass-added-to-a-position",
        ),
        pytest.param(
            lambda d: d.update(gravity="g*L"), ("gravity",), "expected an acceleration", id="gravity"
        ),
        pytest.param(
            lambda d: d["bodies"]["bob"].update(mass="m*L"),
            ("bodies", "bob", "mass"),
            "expected a mass",
            id="mass",
        ),
        pytest.param(lambda d: d["state"].update(s="theta"), ("state", "s"), "expected a length", id="state"),
    ],
)
def test_a_dimensional_slip_in_the_model_is_refused_at_its_path(
    change: Any, path: tuple[Any, ...], words: str
) -> None:
    faults = _faults(change)
    assert path in faults, faults
    assert words in faults[path]


def test_without_declared_dimensions_nothing_is_checked() -> None:
    data = pendulum_on_spring()
    data["potentials"][0]["energy"] = "k*(d - L)"
    load_model(data, SYMBOLS)


def test_a_rotating_frames_rate_typed_as_a_speed_is_refused_at_the_rate() -> None:
    """`rate: w*r` (the rim's speed) made a centrifugal energy in kg·m⁴/s²: the refusal names the rate
    where the element wrote it, before the energy it generated."""
    w, r = sympy.Symbol("w", positive=True), sympy.Symbol("r", positive=True)
    data = {
        "coordinates": [],
        "bodies": {"coin": {"mass": "m", "position": {"x": "r", "y": 0}}},
        "gravity": "g",
        "constraints": {"table": {"kind": "surface", "gap": "y_coin"}},
        "elements": {"frame": {"kind": "rotating", "rate": "w*r", "bodies": ["coin"]}},
        "quantities": {"normal": {"force": "table"}},
    }
    with pytest.raises(SpecErrors) as caught:
        load_model(data, {**SYMBOLS, "w": w, "r": r}, {**DIMENSIONS, "w": TIME**-1, "r": LENGTH})
    first = caught.value.errors[0]
    assert first.path == ("elements", "frame", "rate")
    assert first.message.startswith("r*w is a speed; expected an angular frequency or rate")
