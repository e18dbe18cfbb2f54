"""The bank's one seam to the engine: load a document's model, list its quantities, derive them.

The model section is opaque to the bank; `physics.engine` validates and derives it. Everything the
bank needs from a derivation is copied here into plain typed data (`Derived`), so the rest of
`problems/` does not depend on the engine's internal shapes.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import sympy

from physics.engine import derive, load_model
from physics.engine.scenarios import quantity_names
from physics.engine.scenarios import unused as unused_quantities
from physics.errors import SpecError, SpecErrors
from physics.symbolic import KnownMistake, LimitCase
from problems.symbols import symbol_specs, symbol_table

if TYPE_CHECKING:
    from problems.schema import ProblemDocument

MIN_AGREEING_METHODS = 2  # a derived quantity counts as checked when two methods give it


@dataclass(frozen=True)
class Derived:
    """A derivation, reduced to what the bank uses; `raw` keeps the engine's object (solutions page)."""

    quantities: Mapping[str, sympy.Expr]
    mistakes: Mapping[str, tuple[KnownMistake, ...]] = field(default_factory=dict)
    limits: Mapping[str, tuple[LimitCase, ...]] = field(default_factory=dict)
    # quantity -> the methods that derived it and agree (the engine raises when methods disagree)
    agreement: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    proofs: Mapping[str, str] = field(default_factory=dict)  # quantity -> how agreement was shown
    raw: Any = None

    @property
    def disagreements(self) -> tuple[str, ...]:
        """Quantities not confirmed by two methods (methods that disagree make the engine raise)."""
        return tuple(
            f"{name}: derived by {', '.join(methods) or 'no method'} only"
            for name, methods in self.agreement.items()
            if len(methods) < MIN_AGREEING_METHODS
        )


def missing_quantity(name: str, quantities: Iterable[str]) -> str:
    known = sorted(quantities)
    return f"the model has no quantity {name!r}; its quantities are {', '.join(known) or 'none'}"


def spec_error_items(error: SpecError) -> list[tuple[tuple[str | int, ...], str]]:
    """(path, message) for a SpecError or each member of a SpecErrors."""
    if isinstance(error, SpecErrors):
        return [(e.path, e.message) for e in error.errors]
    return [(error.path, error.message)]


def load_doc_model(doc: ProblemDocument, table: Mapping[str, sympy.Symbol]) -> Any:
    """The engine's Model for `doc.model`; raises SpecError/SpecErrors with paths inside the model."""
    if doc.model is None:
        raise SpecError("the problem has no model", ("model",))
    specs = symbol_specs(doc)
    dimensions = {name: spec.dimension for name, spec in specs.items() if spec.dimension is not None}
    ranges = {
        name: (
            spec.low if spec.low is not None else -sympy.oo,
            spec.high if spec.high is not None else sympy.oo,
        )
        for name, spec in specs.items()
        if spec.has_range
    }
    return load_model(doc.model, table, dimensions, ranges)


@dataclass(frozen=True)
class ModelQuantities:
    """The quantities a model defines, which of them each `expression` uses, and those listed `unused`."""

    names: frozenset[str]
    uses: Mapping[str, frozenset[str]] = field(default_factory=dict)
    unused: frozenset[str] = frozenset()


def model_quantities(doc: ProblemDocument) -> ModelQuantities:
    """What the model defines (cheap: loads, does not derive)."""
    model = load_doc_model(doc, symbol_table(doc))
    names = quantity_names(model)  # a scenario's as `<scenario>.<name>`
    return ModelQuantities(
        frozenset(names),
        {name: frozenset(uses) for name, uses in names.items() if uses},
        frozenset(unused_quantities(model)),
    )


def model_quantity_names(doc: ProblemDocument) -> frozenset[str]:
    """Names of the quantities the model defines (cheap: loads, does not derive)."""
    return model_quantities(doc).names


def derive_doc(doc: ProblemDocument, table: Mapping[str, sympy.Symbol]) -> Derived:
    """Run the engine on the document's model (sympy-heavy; callers cache)."""
    derivation = derive(load_doc_model(doc, table))
    return Derived(
        quantities=dict(derivation.quantities),
        mistakes={
            name: tuple(_mistake(m) for m in items) for name, items in _per_quantity(derivation, "mistakes")
        },
        limits={name: tuple(_limit(c) for c in items) for name, items in _per_quantity(derivation, "limits")},
        agreement={name: tuple(methods) for name, methods in derivation.agreement.items()},
        proofs=dict(derivation.proofs),
        raw=derivation,
    )


def _per_quantity(derivation: Any, attribute: str) -> Iterable[tuple[str, Iterable[Any]]]:
    value = getattr(derivation, attribute, None) or {}
    return value.items() if isinstance(value, Mapping) else ()


def _mistake(item: Any) -> KnownMistake:
    # KnownMistake(expr, feedback), or a plain (expr, feedback) pair.
    if isinstance(item, tuple):
        return KnownMistake(item[0], str(item[1]))
    return KnownMistake(item.expr, str(item.feedback))


def _limit(item: Any) -> LimitCase:
    if isinstance(item, tuple):
        return LimitCase(dict(item[0]), str(item[1]))
    return LimitCase(dict(item.substitutions), str(item.description))
