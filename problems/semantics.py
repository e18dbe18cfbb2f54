"""Meaning checks on a well-shaped problem document; every fault is collected, none stops the rest.

Each expression is read with the whitelist parser, as the grading workers read it. Unknown symbols,
unknown units, empty ranges, givens for undeclared symbols, duplicate part ids and placeholders with
no given value are reported here with their paths; each part's own faults by its kind
(`problems.kinds`).
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import partial

import sympy

from physics.checking import read_relation
from physics.errors import SpecError
from physics.symbolic import SymbolSpec, make_symbol
from physics.units import unit_dimension
from problems.errors import ErrorItem
from problems.kinds import kind_of
from problems.kinds.base import Faults, MeaningContext
from problems.modelinfo import ModelQuantities, spec_error_items
from problems.modelinfo import model_quantities as defined_quantities
from problems.schema import GivenDecl, ProblemDocument, SymbolDecl
from problems.symbols import read_bound, symbol_spec
from problems.usage import usage_errors
from problems.variants import placeholders, unit_scale, valid_range_errors


def semantic_errors(doc: ProblemDocument, model_quantities: frozenset[str] | None = None) -> list[ErrorItem]:
    """Every meaning fault of `doc`, in document order. `model_quantities` defaults to the engine's view."""
    out = Faults()
    table: dict[str, sympy.Symbol] = {}
    symbols_ok = True
    bad_ranges: set[str] = set()
    for name, decl in doc.symbols.items():
        if not name.isidentifier() or name.startswith("_"):
            out.add(("symbols", name), "a symbol name must be letters, digits and _ (not first)")
            symbols_ok = False
            continue
        spec = out.attempt(partial(symbol_spec, name, decl), ("symbols", name))
        if (
            spec is not None
            and spec.low is not None
            and spec.high is not None
            and _not_below(spec.low, spec.high)
        ):
            out.add(("symbols", name, "range"), "low must be < high")
            spec = None
        if spec is None:
            # Keep the name readable in expressions, so one bad declaration is reported once.
            symbols_ok = False
            bad_ranges.add(name)
            spec = SymbolSpec(name, real=decl.real, nonzero=decl.nonzero, negative=decl.negative)
        symbol = out.attempt(partial(make_symbol, spec), ("symbols", name))
        if symbol is not None:
            table[name] = symbol

    for index, text in enumerate(doc.constraints):
        out.attempt(partial(read_relation, text, table, ("constraints", index)))

    for name, given in doc.given.items():
        _check_given(out, doc, name, given, doc.symbols.get(name), check_range=name not in bad_ranges)

    for name in placeholders(doc.statement):
        if name not in doc.given:
            out.add(("statement",), f"{{{name}}} names no given value")

    usage = None
    if model_quantities is None:
        usage = _model_quantities(doc, out, symbols_ok)
        model_quantities = usage.names if usage is not None else None
    _check_parts(out, doc, table, model_quantities)
    if usage is not None and not isinstance(usage.names, _AnyName):
        for path, message in usage_errors(doc, usage):
            out.errors.append((path, message))
    return out.errors


def _not_below(low: sympy.Expr, high: sympy.Expr) -> bool:
    difference = (high - low).evalf(30)
    return bool(difference.is_number and difference <= 0)


def _check_given(
    out: Faults,
    doc: ProblemDocument,
    name: str,
    given: GivenDecl,
    decl: SymbolDecl | None,
    check_range: bool,
) -> None:
    path: tuple[str | int, ...] = ("given", name)
    if decl is None:
        out.add(path, f"{name!r} is not a declared symbol")
        return
    for message in valid_range_errors(given):
        out.add(path, message)
    unit_dim = out.attempt(lambda: unit_dimension(given.unit, (*path, "unit")))
    symbol_dim = out.attempt(lambda: unit_dimension(decl.dimension, ("symbols", name, "dimension")))
    if unit_dim is not None and symbol_dim is not None and unit_dim != symbol_dim:
        out.add((*path, "unit"), f"{given.unit} does not have the dimension of {name} ({decl.dimension})")
        return
    if unit_dim is None:
        return
    scale = out.attempt(lambda: unit_scale(given.unit), (*path, "unit"))
    if scale is None:
        return
    low_si, high_si = (sympy.Rational(*v.as_integer_ratio()) * scale for v in (given.min, given.max))
    if not decl.real and not decl.negative and low_si <= 0:
        out.add((*path, "min"), f"must be > 0 ({name} is declared positive)")
    if decl.negative and high_si >= 0:
        out.add((*path, "max"), f"must be < 0 ({name} is declared negative)")
    if decl.range is not None and check_range:
        try:
            low = read_bound(decl.range[0], ("symbols", name, "range", 0))
            high = read_bound(decl.range[1], ("symbols", name, "range", 1))
        except SpecError:
            return  # reported with the symbol
        if bool((low_si - low).evalf(30) <= 0) or bool((high - high_si).evalf(30) <= 0):
            out.add(path, f"values must lie inside the range of {name} ({low}, {high})")


class _AnyName(frozenset[str]):
    """Stands for a model whose quantities could not be listed (its faults are reported already)."""

    def __contains__(self, item: object) -> bool:
        return True


def _model_quantities(doc: ProblemDocument, out: Faults, symbols_ok: bool) -> ModelQuantities | None:
    """The quantities the model defines (None: no model); model faults are reported under `model`."""
    if doc.model is None:
        return None
    if not symbols_ok:
        return ModelQuantities(_AnyName())
    try:
        return defined_quantities(doc)
    except SpecError as error:
        for path, message in spec_error_items(error):
            out.add(("model", *path), message)
        return ModelQuantities(_AnyName())


def _check_parts(
    out: Faults,
    doc: ProblemDocument,
    table: Mapping[str, sympy.Symbol],
    quantities: frozenset[str] | None,
) -> None:
    seen: dict[str, int] = {}
    expression_parts = frozenset(p.id for p in doc.parts if kind_of(p).expression_answer)
    context = MeaningContext(doc, table, quantities, expression_parts, out)
    for index, part in enumerate(doc.parts):
        path: tuple[str | int, ...] = ("parts", index)
        if part.id in seen:
            out.add((*path, "id"), f"duplicate part id {part.id!r} (also parts[{seen[part.id]}])")
        else:
            seen[part.id] = index
        kind_of(part).check_meaning(part, path, context)
