"""Bad model files: every fault reported at once, each with its path inside the model section."""

from __future__ import annotations

import copy
from typing import Any

import pytest

from physics.engine import load_model
from physics.errors import SpecError, SpecErrors
from tests.engine.conftest import model_data, symbols


def _errors(data: Any, problem: str = "moving-wedge") -> dict[tuple[str | int, ...], str]:
    with pytest.raises(SpecErrors) as caught:
        load_model(data, symbols(problem))
    return {e.path: e.message for e in caught.value.errors}


def _wedge() -> dict[str, Any]:
    return copy.deepcopy(model_data("moving-wedge"))


def _with(change: Any) -> dict[str, Any]:
    data = _wedge()
    change(data)
    return data


BROKEN = [
    pytest.param(lambda d: d.update(bogus=1), ("bogus",), id="unknown-section"),
    pytest.param(lambda d: d["bodies"]["block"].pop("mass"), ("bodies", "block", "mass"), id="missing-mass"),
    pytest.param(
        lambda d: d["bodies"]["block"]["position"].update(x="X + s*cos(theta"),
        ("bodies", "block", "position", "x"),
        id="unbalanced-parenthesis",
    ),
    pytest.param(
        lambda d: d["bodies"]["block"]["position"].update(w="0"),
        ("bodies", "block", "position", "w"),
        id="unknown-axis",
    ),
    pytest.param(
        lambda d: d["constraints"]["incline"].update(gap="x_crate - x_wedge"),
        ("constraints", "incline", "gap"),
        id="gap-names-unknown-body",
    ),
    pytest.param(
        lambda d: d["constraints"]["inclineFloor"].update(kind="glue"),
        ("constraints", "inclineFloor", "kind"),
        id="unknown-constraint-kind",
    ),
    pytest.param(
        lambda d: d["quantities"].update(extra={"acceleration": "Y"}),
        ("quantities", "extra", "acceleration"),
        id="quantity-of-unknown-coordinate",
    ),
    pytest.param(
        lambda d: d["quantities"].update(extra={"force": "incline", "acceleration": "X"}),
        ("quantities", "extra"),
        id="quantity-of-two-kinds",
    ),
    pytest.param(lambda d: d.update(gravity="__import__('os')"), ("gravity",), id="code-in-an-expression"),
    pytest.param(lambda d: d.update(coordinates=["X", "X"]), ("coordinates", 1), id="duplicate-coordinate"),
    pytest.param(
        lambda d: d["domain"]["ranges"].update(beta=["0", "1"]),
        ("domain", "ranges", "beta"),
        id="range-of-unknown-symbol",
    ),
    pytest.param(
        lambda d: d["domain"]["ranges"].update(m=["0", "M"]),
        ("domain", "ranges", "m"),
        id="range-bounded-by-another-symbol",  # was a TypeError in sampling: `positive: [M - m]` says it
    ),
    pytest.param(
        lambda d: d.update(
            friction=[{"constraint": "incline", "body": "block", "coefficient": "nu", "sliding": "s"}]
        ),
        ("friction", 0, "coefficient"),
        id="friction-with-unknown-symbol",
    ),
]


@pytest.mark.parametrize(("change", "path"), BROKEN)
def test_bad_model_reports_the_fault_at_its_path(change: Any, path: tuple[str | int, ...]) -> None:
    assert path in _errors(_with(change))


def test_every_fault_is_reported_at_once() -> None:
    changes: list[Any] = [p.values[0] for p in BROKEN[:7]]

    def breaks(d: dict[str, Any]) -> None:
        for change in changes:
            change(d)

    found = _errors(_with(breaks))
    expected = {p.values[1] for p in BROKEN[:7]}
    assert expected <= set(found)


def test_spec_errors_is_a_spec_error_with_the_first_path() -> None:
    with pytest.raises(SpecError) as caught:
        load_model(_with(lambda d: d.update(bogus=1)), symbols("moving-wedge"))
    assert caught.value.path == ("bogus",)
    assert "bogus" in caught.value.message


def test_model_that_is_not_a_mapping_is_refused() -> None:
    assert () in _errors(["coordinates"])


def test_problem_symbols_are_the_ones_in_the_results() -> None:
    table = symbols("moving-wedge")
    model = load_model(_wedge(), table)
    assert set(model.parameters) == set(table.values())
    # equal, not necessarily identical: parsers cache name tables, and sympy may rebuild a Symbol
    assert model.body("block").mass == table["m"]


def test_a_coordinate_named_like_a_problem_symbol_is_that_symbol() -> None:
    model = load_model(model_data("lennard-jones"), symbols("lennard-jones"))
    assert model.coordinate("r").symbol is symbols("lennard-jones")["r"]
    assert model.coordinate("X").symbol.is_real and not model.coordinate("X").symbol.is_positive


def test_loaded_models_are_hashable_and_equal_when_loaded_twice() -> None:
    first = load_model(_wedge(), symbols("moving-wedge"))
    second = load_model(_wedge(), symbols("moving-wedge"))
    assert first == second and hash(first) == hash(second)


def test_attribute_access_in_an_expression_is_refused() -> None:
    assert ("bodies", "block", "mass") in _errors(
        _with(lambda d: d["bodies"]["block"].update(mass="m.__class__"))
    )


def test_an_oversized_model_is_refused_before_anything_is_read() -> None:
    data = _with(lambda d: d.update(coordinates=[f"q{i}" for i in range(40)]))
    assert ("coordinates",) in _errors(data)


def test_a_collision_quantity_names_the_projectile() -> None:
    data = copy.deepcopy(model_data("ballistic-pendulum"))
    data["quantities"]["bullet_speed"] = {"projectile_speed": "arrow"}
    found = _errors(data, "ballistic-pendulum")
    assert ("quantities", "bullet_speed", "projectile_speed") in found
