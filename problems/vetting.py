"""Vetting a problem document in stages, reporting every fault that any stage can find, at once.

The stages: reading (YAML or JSON), shape (the schema), meaning (expressions, symbols, units, parts),
the model's derivation, and the self-test. Each runs whenever what it needs is sound, even after
another stage found faults elsewhere: a malformed part does not hide a model that fails to derive, since
the model needs only the symbols and the model section. A stage that cannot run says so, at the path it
would have checked, with the reason (never a silent skip).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import sympy
from pydantic import ValidationError

from physics.engine import derive, load_model
from physics.errors import AnswerError, DerivationError, SpecError
from physics.symbolic import make_symbol
from problems.compiled import compile_problem
from problems.errors import ErrorItem, ProblemInvalid
from problems.loader import Format, parse_problem, read_text
from problems.modelinfo import derive_doc, spec_error_items
from problems.schema import ProblemDocument, SymbolDecl, format_path
from problems.selftest import verify_problem
from problems.semantics import semantic_errors
from problems.symbols import symbol_spec, symbol_table
from problems.usage import is_usage_fault

NOT_DERIVED = "not derived: {why}; fix those first"
NOT_SELF_TESTED = "not self-tested: {why}; the self-test runs once the document has no other errors"


def stage_not_run(message: str) -> bool:
    """Whether an error item only says a stage could not run because of the others (not a fault)."""
    return message.startswith((NOT_DERIVED.partition("{")[0], NOT_SELF_TESTED.partition("{")[0]))


@dataclass(frozen=True)
class Vetting:
    """A sound document (and no errors), or every error found with its path."""

    document: ProblemDocument | None
    errors: list[ErrorItem] = field(default_factory=list)


class _Errors:
    """Errors in the order found, each once (stages may find the same fault twice)."""

    def __init__(self) -> None:
        self.items: dict[ErrorItem, None] = {}

    def add(self, items: list[ErrorItem]) -> None:
        self.items.update(dict.fromkeys(items))

    def has(self, prefix: str) -> bool:
        return any(path == prefix or path.startswith((f"{prefix}.", f"{prefix}[")) for path, _ in self.items)

    def model_broken(self) -> bool:
        """A fault that keeps the model from loading (not one of which quantities the parts ask for)."""
        return any(
            (path == "model" or path.startswith(("model.", "model["))) and not is_usage_fault(message)
            for path, message in self.items
        )

    def __bool__(self) -> bool:
        return bool(self.items)


def vet_document(source: str | bytes, fmt: Format, variants: int) -> Vetting:
    """Every stage that can run on `source`; the self-test with `variants` students' values."""
    try:
        data = read_text(source, fmt)
    except ProblemInvalid as error:
        return Vetting(None, error.errors)  # nothing else can be read
    errors = _Errors()
    try:
        doc = parse_problem(data, fmt, check_meaning=False) if isinstance(data, Mapping) else None
    except ProblemInvalid as error:
        errors.add(error.errors)
        doc = None
    if doc is None:
        if not isinstance(data, Mapping):
            return Vetting(None, [("", "a problem document must be a mapping at the top level")])
        errors.add(_model_alone(data, errors))
        errors.add([("parts", NOT_SELF_TESTED.format(why="the document's shape has errors"))])
        return Vetting(None, list(errors.items))
    errors.add(semantic_errors(doc))
    if errors:
        errors.add(_derivation(doc, errors))
        errors.add([("parts", NOT_SELF_TESTED.format(why="the document has the errors above"))])
        return Vetting(None, list(errors.items))
    errors.add(_attempt(lambda: compile_problem(doc)))
    if errors:
        return Vetting(None, list(errors.items))
    report = verify_problem(doc, variants=variants)
    if not report.ok:
        index = {part.id: i for i, part in enumerate(doc.parts)}
        return Vetting(
            None,
            [
                (
                    f"parts[{index[f.part]}]" if f.part in index else "model",
                    f"self-test, {f.check}: {f.detail}",
                )
                for f in report.failures
            ],
        )
    return Vetting(doc)


def _attempt(step: Callable[[], object]) -> list[ErrorItem]:
    """The step's faults as (path, message): shape and meaning faults, and derivation findings."""
    try:
        step()
    except ProblemInvalid as error:
        return error.errors
    except SpecError as error:
        return [(format_path(("model", *path)), message) for path, message in spec_error_items(error)]
    except DerivationError as error:
        return [(format_path(("model", *path)), message) for path, message in error.items()]
    return []


def _derivation(doc: ProblemDocument, errors: _Errors) -> list[ErrorItem]:
    """The model derived beside faults elsewhere in the document (parts, givens, statement)."""
    if doc.model is None:
        return []
    if errors.has("symbols"):
        return [("model", NOT_DERIVED.format(why="the symbols have errors"))]
    if errors.model_broken():
        return []  # it did not load: its faults are listed already
    return _attempt(lambda: derive_doc(doc, symbol_table(doc)))


def _model_alone(data: Mapping[str, Any], errors: _Errors) -> list[ErrorItem]:
    """The model derived from the raw document when its shape has errors elsewhere: it needs only the
    symbols (each declaration sound) and the model section."""
    model, declared = data.get("model"), data.get("symbols")
    if not isinstance(model, Mapping):
        return []  # no model, or a malformed one (the shape check says so)
    if errors.has("symbols") or errors.has("model") or not isinstance(declared, Mapping):
        return [("model", NOT_DERIVED.format(why="the symbols or the model section have errors"))]
    table: dict[str, sympy.Symbol] = {}
    dimensions = {}
    ranges = {}
    try:
        for name, raw in declared.items():
            spec = symbol_spec(str(name), SymbolDecl.model_validate(raw))
            table[str(name)] = make_symbol(spec)
            if spec.dimension is not None:
                dimensions[str(name)] = spec.dimension
            if spec.has_range:
                low, high = spec.low, spec.high
                ranges[str(name)] = (-sympy.oo if low is None else low, sympy.oo if high is None else high)
    except (ValidationError, SpecError, AnswerError):
        return [("model", NOT_DERIVED.format(why="the symbols have errors"))]
    return _attempt(lambda: derive(load_model(model, table, dimensions, ranges)))
