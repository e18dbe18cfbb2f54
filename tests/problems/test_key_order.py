"""A YAML mapping has no order: a tool that re-serialises a problem (sorting its keys, or reversing them)
leaves every bank model loading to the same quantities, and an expression still derives from a quantity
written after it."""

from __future__ import annotations

from typing import Any

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table
from tests.bank import bank_documents

BANK = bank_documents()
WITH_MODELS = sorted(name for name, doc in BANK.items() if doc.model is not None)


def _reversed(value: Any) -> Any:
    if isinstance(value, dict):
        return {key: _reversed(value[key]) for key in reversed(list(value))}
    if isinstance(value, list):
        return [_reversed(item) for item in value]
    return value


def _quantities(model: Any) -> list[tuple[str, str, str]]:
    return sorted((q.name, q.kind.value, str(q.expression or q.target)) for q in model.quantities)


@pytest.mark.parametrize("problem", WITH_MODELS)
def test_a_bank_model_reserialised_with_sorted_or_reversed_keys_loads_the_same(problem: str) -> None:
    doc = BANK[problem]
    table = symbol_table(doc)
    original = _quantities(load_doc_model(doc, table))
    assert doc.model is not None
    for text in (
        yaml.safe_dump(doc.model, sort_keys=True),
        yaml.safe_dump(_reversed(doc.model), sort_keys=False),
    ):
        assert _quantities(load_model(yaml.safe_load(text), table)) == original


def test_an_expression_before_the_quantity_it_uses_derives() -> None:
    doc = BANK["conical-pendulum"]
    assert doc.model is not None
    data = _reversed(doc.model)
    names = list(data["quantities"])
    assert names.index("cone_cosine") < names.index("cone_angle")  # the expression comes first
    table = symbol_table(doc)
    derived = derivation._derive.__wrapped__(load_model(data, table)).quantities
    assert sympy.simplify(derived["cone_cosine"] - sympy.cos(derived["cone_angle"])) == 0
