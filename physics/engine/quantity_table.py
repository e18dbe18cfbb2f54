"""Which code derives each kind of quantity: a table, filled by the modules that own the physics.

A module that owns a kind of quantity (trajectory.py the flight of a projectile, damping.py the decay of
an oscillation, ...) declares its handler with `@derives(kind, ...)`. `Method.answer` looks the kind up
here, so a new kind is one module and one line in `OWNERS`, and a kind nobody derives is an error, never
a fall-through into some other physics.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping
from functools import cache
from types import MappingProxyType
from typing import TYPE_CHECKING

import sympy

from physics.engine.model import Quantity, QuantityKind
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.method import Method

Handler = Callable[["Method", Quantity], sympy.Expr]

# The modules whose `@derives` declarations make the table (importing one registers its kinds).
OWNERS = (
    "physics.engine.basic_quantities",
    "physics.engine.collision",
    "physics.engine.damping",
    "physics.engine.extremum",
    "physics.engine.impact",
    "physics.engine.mode_shapes",
    "physics.engine.orbits",
    "physics.engine.slipping",
    "physics.engine.trajectory",
    "physics.engine.turning",
    "physics.engine.work_energy",
)

_HANDLERS: dict[QuantityKind, Handler] = {}


def derives(*kinds: QuantityKind) -> Callable[[Handler], Handler]:
    """Declare `handler` as the one derivation of these kinds: `handler(method, quantity) -> expr`."""

    def register(handler: Handler) -> Handler:
        for kind in kinds:
            owner = _HANDLERS.get(kind)
            if owner is not None and owner is not handler:
                raise RuntimeError(
                    f"quantity kind {kind.value!r} has two handlers: {_named(owner)} and {_named(handler)}"
                )
            _HANDLERS[kind] = handler
        return handler

    return register


@cache
def table() -> Mapping[QuantityKind, Handler]:
    """Every kind's handler, after the owning modules have declared theirs; every kind must have one."""
    for owner in OWNERS:
        importlib.import_module(owner)
    missing = sorted(kind.value for kind in QuantityKind if kind not in _HANDLERS)
    if missing:
        raise RuntimeError(f"no handler derives the quantity kinds {missing}")
    return MappingProxyType(_HANDLERS)


def handler(quantity: Quantity) -> Handler:
    found = table().get(quantity.kind)
    if found is None:
        raise DerivationError(
            f"{quantity.name}: no derivation for quantities of kind {quantity.kind!r}", quantity=quantity.name
        )
    return found


def _named(handler: Handler) -> str:
    return f"{handler.__module__}.{handler.__qualname__}"
