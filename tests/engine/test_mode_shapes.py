"""Mode shapes: the amplitude ratio of two coordinates in normal mode n, by every method that gives the
modes, checked on a motion released along the mode."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.errors import DerivationError, SpecErrors
from tests.engine.test_normal_modes import SYMBOLS, three_springs

uncached = derivation._derive.__wrapped__


def shapes() -> dict[str, Any]:
    data = three_springs()
    data["quantities"] = {
        "together": {"mode_shape": {"mode": 1, "ratio": ["x2", "x1"]}},
        "opposite": {"mode_shape": {"mode": 2, "ratio": ["x2", "x1"]}},
    }
    return data


def test_the_two_modes_of_three_springs_move_together_and_oppositely() -> None:
    result = uncached(load_model(shapes(), SYMBOLS))
    assert result.quantities["together"] == 1
    assert result.quantities["opposite"] == -1
    for name in ("together", "opposite"):
        assert {"lagrange", "newton", "conservation"} <= set(result.agreement[name])
        assert "released along the mode" in result.simulation[name].compared


def test_newton_carries_its_cartesian_mode_back_to_the_coordinates() -> None:
    """Coordinates that are not the bodies' positions: the centre X and the stretch r of two blocks on a
    wall-spring-block-spring-block chain, whose slow mode has x2/x1 the golden ratio."""
    data = {
        "coordinates": ["X", "r"],
        "bodies": {
            "left": {"mass": "m", "position": {"x": "X - r/2"}},
            "right": {"mass": "m", "position": {"x": "X + r/2"}},
        },
        "potentials": [
            {"bodies": ["left"], "anchor": {"x": 0}, "distance": "d", "energy": "k*d^2/2"},
            {"bodies": ["left", "right"], "distance": "d", "energy": "k*d^2/2"},
        ],
        "quantities": {"shape": {"mode_shape": {"mode": 1, "ratio": ["r", "X"]}}},
    }
    result = uncached(load_model(data, SYMBOLS))
    golden = (1 + sympy.sqrt(5)) / 2
    assert sympy.simplify(result.quantities["shape"] - 2 * (golden - 1) / (golden + 1)) == 0
    assert {"lagrange", "newton", "conservation"} <= set(result.agreement["shape"])
    assert result.simulation["shape"].max_relative_error < 1e-3


def test_a_damped_system_has_no_mode_shape() -> None:
    data = shapes()
    data["forces"] = [{"body": "a", "drag": "k"}]
    with pytest.raises(DerivationError, match="normal modes are for undamped systems"):
        uncached(load_model(data, SYMBOLS))


def test_mode_shape_faults_are_reported_with_their_paths() -> None:
    data = shapes()
    data["quantities"] = {
        "a": {"mode_shape": {"mode": 3, "ratio": ["x2", "x1"]}},
        "b": {"mode_shape": {"mode": 1, "ratio": ["x2", "y"]}},
        "c": {"mode_shape": {"mode": 1, "ratio": ["x1", "x1"], "of": 2}},
    }
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    assert {e.path for e in caught.value.errors} == {
        ("quantities", "a", "mode_shape", "mode"),
        ("quantities", "b", "mode_shape", "ratio", 1),
        ("quantities", "c", "mode_shape", "ratio"),
        ("quantities", "c", "mode_shape", "of"),
    }
