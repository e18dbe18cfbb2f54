"""The built-in bank: the contract's problems, symbols and parts exist exactly as named."""

from __future__ import annotations

from decimal import Decimal

import pytest

from problems.loader import load_bank
from problems.schema import NumericPart, ProblemDocument
from tests.bank import bank_documents

# API.md's table, plus the task's additions; (symbols, parts) per problem id.
CONTRACT: dict[str, tuple[set[str], list[str]]] = {
    "moving-wedge": (
        {"m", "M", "theta", "g"},
        ["wedge_acceleration", "block_relative_acceleration", "normal_force", "wedge_acceleration_numeric"],
    ),
    "yo-yo": ({"m", "r", "k", "g"}, ["acceleration", "tension", "acceleration_numeric"]),
    "lennard-jones": (
        {"U0", "r0", "r", "m"},
        [
            "equilibrium_separation",
            "force",
            "spring_constant",
            "oscillation_frequency",
            "oscillation_frequency_numeric",
        ],
    ),
    "ballistic-pendulum": (
        {"m", "M", "L", "theta", "g"},
        ["bullet_speed", "energy_fraction_lost", "bullet_speed_numeric"],
    ),
    "skier-friction": (
        {"alpha", "mu", "g", "m"},
        ["friction_coefficient", "acceleration", "friction_coefficient_numeric", "acceleration_numeric"],
    ),
    "incline-pulley": ({"m1", "m2", "theta", "g"}, ["acceleration", "tension", "acceleration_numeric"]),
    "rolling-incline": (
        {"m", "R", "theta", "g"},
        [
            "acceleration_cylinder",
            "acceleration_hoop",
            "acceleration_sphere",
            "acceleration_sliding",
            "acceleration_cylinder_numeric",
        ],
    ),
    "mass-spring": ({"m", "k"}, ["angular_frequency", "period", "period_numeric"]),
    "atwood": ({"m1", "m2", "g"}, ["acceleration", "tension", "acceleration_numeric"]),
}


def bank() -> dict[str, ProblemDocument]:
    return bank_documents()


def test_bank_holds_the_contract_problems_unchanged_and_more() -> None:
    assert set(CONTRACT) < set(bank())


def _ids() -> list[str]:
    return sorted(doc.id for doc in load_bank(check_meaning=False))


@pytest.mark.parametrize("problem_id", sorted(CONTRACT))
def test_problem_has_the_contract_symbols_and_parts(problem_id: str) -> None:
    symbols, parts = CONTRACT[problem_id]
    doc = bank()[problem_id]
    assert set(doc.symbols) == symbols
    assert [p.id for p in doc.parts] == parts


@pytest.mark.parametrize("problem_id", _ids())
def test_numeric_parts_are_the_numeric_ones_and_have_givens_for_g(problem_id: str) -> None:
    doc = bank()[problem_id]
    for part in doc.parts:
        assert isinstance(part, NumericPart) == part.id.endswith("_numeric")
    if "g" in doc.given:
        assert doc.given["g"].min == doc.given["g"].max == Decimal("9.81") and doc.given["g"].unit == "m/s^2"
    for name, given in doc.given.items():
        if doc.symbols[name].dimension == "1" and given.unit != "1":
            assert given.unit == "deg", f"{problem_id}: angles are given in degrees"


def test_skier_slides_for_every_allowed_slope_and_friction() -> None:
    import math

    doc = bank()["skier-friction"]
    alpha, mu = doc.given["alpha"], doc.given["mu"]
    assert float(mu.max) < math.tan(math.radians(float(alpha.min)))


def test_built_in_bank_passes_the_meaning_checks() -> None:
    assert {doc.id for doc in load_bank()} == set(bank())


def test_bank_has_thirty_problems_and_every_symbolic_part_comes_from_its_model() -> None:
    from problems.modelinfo import model_quantity_names
    from problems.schema import SymbolicPart

    docs = load_bank(check_meaning=False)
    assert len(docs) >= 30
    typed_only = [
        f"{doc.id}/{part.id}"
        for doc in docs
        for part in doc.parts
        if isinstance(part, SymbolicPart) and part.quantity_name not in model_quantity_names(doc)
    ]
    assert typed_only == []
