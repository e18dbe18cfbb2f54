"""A quantity kind is an entry in a table: every kind has exactly one handler, declared by the module
that owns its physics, and a kind without one is an error (never a fall-through into another physics)."""

from __future__ import annotations

import dataclasses

import pytest
import sympy

from physics.engine import quantity_table
from physics.engine.model import Quantity, QuantityKind
from physics.errors import DerivationError


def test_every_quantity_kind_has_a_handler() -> None:
    assert set(quantity_table.table()) == set(QuantityKind)


def test_each_handler_lives_in_a_declared_owner_module() -> None:
    owners = {handler.__module__ for handler in quantity_table.table().values()}
    assert owners == set(quantity_table.OWNERS)


def test_a_second_handler_for_an_owned_kind_is_refused() -> None:
    def rival(method: object, quantity: Quantity) -> sympy.Expr:
        return sympy.Integer(0)

    quantity_table.table()
    with pytest.raises(RuntimeError, match="'acceleration' has two handlers"):
        quantity_table.derives(QuantityKind.ACCELERATION)(rival)  # type: ignore[arg-type]
    assert quantity_table.table()[QuantityKind.ACCELERATION] is not rival


def test_a_kind_without_a_handler_is_a_derivation_error() -> None:
    unknown = dataclasses.replace(Quantity("v1", QuantityKind.ACCELERATION), kind="teleportation")  # type: ignore[arg-type]
    with pytest.raises(DerivationError, match="v1: no derivation for quantities of kind 'teleportation'"):
        quantity_table.handler(unknown)
