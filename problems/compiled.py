"""A problem compiled for grading: per part the question the checker needs, no YAML left.

Compiling derives the model (sympy-heavy), reconciles hand-typed answers with the derivation, and
merges the engine's known mistakes and limits with the author's. The result is cached per
(id, version, document hash), so a course's thousand submissions compile the problem once.
"""

from __future__ import annotations

import hashlib
import json
import pickle
import sys
import threading
from collections import OrderedDict
from collections.abc import Mapping
from dataclasses import dataclass, field
from decimal import Decimal
from functools import cache, cached_property
from pathlib import Path

import mpmath
import sympy

from physics.checking import (
    CompiledQuestion,
    NumericJob,
    PartJob,
    SymbolicQuestion,
    read_expression,
    read_relation,
)
from physics.dimensions import DIMENSIONLESS
from physics.errors import SpecError
from physics.numeric import NumericSpec, Tolerance
from physics.symbolic import (
    DimensionMismatch,
    KnownMistake,
    LimitCase,
    SymbolicContext,
    SymbolSpec,
    UnknownDimension,
    expression_dimension,
    judge_symbolic,
    make_symbol,
    prepare_reference,
)
from physics.units import unit_dimension
from problems.errors import ErrorItem, ProblemInvalid
from problems.modelinfo import Derived, derive_doc, missing_quantity, spec_error_items
from problems.schema import NumericPart, ProblemDocument, SymbolicPart, format_path
from problems.symbols import read_bound, symbol_specs
from problems.variants import Variant, evaluate_reference, si_values

CACHE_SIZE = 256  # live problem versions kept compiled; beyond it they are derived again


@dataclass(frozen=True)
class CompiledSymbolicPart:
    """A symbolic part: the reference and everything the checker weighs it against."""

    id: str
    quantity: str
    compiled: CompiledQuestion
    derived: bool = False  # False: the reference is the author's typed answer, which no method checked

    @property
    def expected(self) -> sympy.Expr:
        return self.compiled.expected

    @property
    def names(self) -> Mapping[str, sympy.Symbol]:
        """What the answer may use."""
        return self.compiled.names

    @property
    def context(self) -> SymbolicContext:
        return self.compiled.context

    @property
    def question(self) -> SymbolicQuestion:
        """The prepared reference (sampling the domain once; sympy-heavy, hence lazy and cached)."""
        return self.compiled.question

    @cached_property
    def _payload(self) -> tuple[str, bytes]:
        # Pickled once per part (with the prepared reference when it is already computed): a job then
        # costs the worker a copy of bytes, and the worker unpickles it once per key.
        payload = pickle.dumps(self.compiled, protocol=pickle.HIGHEST_PROTOCOL)
        return hashlib.sha256(payload).hexdigest(), payload

    def job(self, answer: str) -> PartJob:
        key, payload = self._payload
        return PartJob(answer, key, payload)

    def __getstate__(self) -> dict[str, object]:
        # The part is pickled whole when a compiled problem is persisted: not its job payload too.
        return {name: value for name, value in self.__dict__.items() if name != "_payload"}


@dataclass(frozen=True)
class CompiledNumericPart:
    """A numeric part: its expression, evaluated per student at their given values."""

    id: str
    of: str
    expr: sympy.Expr
    units: str
    units_required: bool
    tolerance: Tolerance
    document: ProblemDocument = field(repr=False)
    table: Mapping[str, sympy.Symbol] = field(repr=False)
    derived: bool = False  # its expression is a model quantity derived by the engine
    arithmetic: bool = True
    units_system: str | None = None

    def reference(self, variant: Variant) -> Decimal:
        """The expected value for this student, in `units`, to 12 significant figures."""
        values = si_values(self.document, variant, self.table)
        return evaluate_reference(self.expr, values, self.units, where=self.id)

    def spec(self, variant: Variant) -> NumericSpec:
        dimensionless = self.units.strip() == "1"
        return NumericSpec(
            expected=self.reference(variant),
            units=None if dimensionless else self.units,
            units_required=self.units_required and not dimensionless,
            tolerance=self.tolerance,
            arithmetic=self.arithmetic,
            units_system=self.units_system,
        )

    def job(self, answer: str, variant: Variant) -> NumericJob:
        return NumericJob(answer, self.spec(variant))


CompiledPart = CompiledSymbolicPart | CompiledNumericPart


@dataclass(frozen=True)
class CompiledProblem:
    document: ProblemDocument
    version: int
    digest: str
    table: Mapping[str, sympy.Symbol]
    parts: Mapping[str, CompiledPart]
    derived: Derived | None = None
    constraints: tuple[sympy.Basic, ...] = ()  # relations the symbols satisfy (the problem's domain)

    def part(self, part_id: str) -> CompiledPart:
        return self.parts[part_id]

    @property
    def not_derived(self) -> tuple[str, ...]:
        """Parts whose reference is only the author's typed answer: no method derived or checked it."""
        return tuple(part_id for part_id, part in self.parts.items() if not part.derived)

    def question(self, part_id: str, variant: Variant | None = None) -> SymbolicQuestion | NumericSpec:
        """What `physics.checking.check_answer` needs; numeric parts need the student's variant."""
        part = self.parts[part_id]
        if isinstance(part, CompiledSymbolicPart):
            return part.question
        if variant is None:
            raise ValueError(f"part {part_id!r} is numeric: its question depends on the student's variant")
        return part.spec(variant)

    def job(self, part_id: str, answer: str, variant: Variant | None = None) -> PartJob | NumericJob:
        """A picklable check job for a worker process."""
        part = self.parts[part_id]
        if isinstance(part, CompiledSymbolicPart):
            return part.job(answer)
        if variant is None:
            raise ValueError(f"part {part_id!r} is numeric: its job depends on the student's variant")
        return part.job(answer, variant)

    def prepare(self) -> CompiledProblem:
        """Prepare every symbolic part's reference now (sample points, values, mistakes, limits), e.g. to
        persist them."""
        for part in self.parts.values():
            if isinstance(part, CompiledSymbolicPart):
                part.question.reference.complete()
        return self

    def reference_expressions(self) -> dict[str, sympy.Expr]:
        """Every part's reference expression (instructor-only: the solutions page)."""
        return {
            pid: p.expected if isinstance(p, CompiledSymbolicPart) else p.expr
            for pid, p in self.parts.items()
        }


@cache
def code_fingerprint() -> str:
    """A digest of the code that compiles and grades (physics/, problems/) and the libraries it leans
    on: whatever is persisted under it is stale as soon as any of that changes."""
    digest = hashlib.sha256()
    digest.update(f"{sys.version_info[:2]} sympy {sympy.__version__} mpmath {mpmath.__version__}".encode())
    root = Path(__file__).resolve().parent.parent
    for package in ("physics", "problems"):
        for path in sorted((root / package).rglob("*.py")):
            digest.update(str(path.relative_to(root)).encode())
            digest.update(path.read_bytes())
    return digest.hexdigest()


def document_digest(doc: ProblemDocument) -> str:
    canonical = json.dumps(
        doc.model_dump(mode="json"), sort_keys=True, separators=(",", ":"), ensure_ascii=False
    )
    return hashlib.sha256(canonical.encode("utf-8")).hexdigest()


_cache: OrderedDict[tuple[str, int, str], CompiledProblem] = OrderedDict()
_cache_lock = threading.Lock()


def compile_problem(doc: ProblemDocument, version: int = 0, *, use_model: bool = True) -> CompiledProblem:
    """Compile (cached by id, version and document hash); raises ProblemInvalid or DerivationError.

    `use_model=False` grades against the hand-typed answers only (no engine run).
    """
    key = (doc.id, version, document_digest(doc) + ("" if use_model else ":hand"))
    with _cache_lock:
        if key in _cache:
            _cache.move_to_end(key)
            return _cache[key]
    compiled = build_problem(doc, version, use_model=use_model)
    with _cache_lock:
        _cache[key] = compiled
        while len(_cache) > CACHE_SIZE:
            _cache.popitem(last=False)
    return compiled


def build_problem(doc: ProblemDocument, version: int = 0, *, use_model: bool = True) -> CompiledProblem:
    """Compile without the cache (its caller keeps the result); raises as `compile_problem`."""
    digest = document_digest(doc) + ("" if use_model else ":hand")
    errors: list[ErrorItem] = []
    try:
        specs = symbol_specs(doc)
        table = {name: make_symbol(spec) for name, spec in specs.items()}
        constraints = _constraints(doc, table)
    except SpecError as error:
        raise ProblemInvalid([(format_path(error.path), error.message)], doc.id) from None
    derived: Derived | None = None
    if use_model and doc.model is not None:
        try:
            derived = derive_doc(doc, table)
        except SpecError as error:
            raise ProblemInvalid(
                [(format_path(("model", *path)), message) for path, message in spec_error_items(error)],
                doc.id,
            ) from None

    symbolic: dict[str, CompiledSymbolicPart] = {}
    for index, part in enumerate(doc.parts):
        if isinstance(part, SymbolicPart):
            try:
                symbolic[part.id] = _symbolic_part(part, index, table, specs, constraints, derived)
            except SpecError as error:
                errors.append((format_path(error.path or ("parts", index)), error.message))
    parts: dict[str, CompiledPart] = {}
    for index, part in enumerate(doc.parts):
        if isinstance(part, SymbolicPart) and part.id in symbolic:
            parts[part.id] = symbolic[part.id]
        elif isinstance(part, NumericPart):
            try:
                parts[part.id] = _numeric_part(doc, part, index, table, specs, symbolic, derived)
            except SpecError as error:
                errors.append((format_path(error.path or ("parts", index)), error.message))
    if errors:
        raise ProblemInvalid(errors, doc.id)
    return CompiledProblem(doc, version, digest, table, parts, derived, constraints)


def _constraints(doc: ProblemDocument, table: Mapping[str, sympy.Symbol]) -> tuple[sympy.Basic, ...]:
    return tuple(read_relation(text, table, ("constraints", i)) for i, text in enumerate(doc.constraints))


def _symbolic_part(
    part: SymbolicPart,
    index: int,
    table: Mapping[str, sympy.Symbol],
    specs: Mapping[str, SymbolSpec],
    constraints: tuple[sympy.Basic, ...],
    derived: Derived | None,
) -> CompiledSymbolicPart:
    path: tuple[str | int, ...] = ("parts", index)
    allowed_names = tuple(part.symbols) if part.symbols is not None else None
    names = dict(table) if allowed_names is None else {n: table[n] for n in allowed_names if n in table}
    hand = read_expression(part.answer, names, (*path, "answer")) if part.answer is not None else None
    derived_expr = derived.quantities.get(part.quantity_name) if derived is not None else None
    if derived is not None and derived_expr is None and (hand is None or part.quantity is not None):
        # a named quantity the model lacks is a fault even beside a typed answer: never a silent fall-back
        raise SpecError(missing_quantity(part.quantity_name, derived.quantities), (*path, "quantity"))
    expected = derived_expr if derived_expr is not None else hand
    if expected is None:
        raise SpecError("needs an answer (there is no model to derive it from)", path)

    mistakes = [
        (read_expression(m.answer, table, (*path, "mistakes", j, "answer")), m.feedback)
        for j, m in enumerate(part.mistakes)
    ]
    limits = [
        (
            {
                table[name]: read_bound(value, (*path, "limits", j, "where", name))
                for name, value in lim.where.items()
            },
            lim.description,
        )
        for j, lim in enumerate(part.limits)
    ]
    engine_mistakes = _new_mistakes(mistakes, derived.mistakes.get(part.quantity_name, ()) if derived else ())
    engine_limits = _new_limits(limits, derived.limits.get(part.quantity_name, ()) if derived else ())
    context = SymbolicContext(
        symbols={table[name]: spec for name, spec in specs.items()},
        constraints=constraints,
        mistakes=tuple(KnownMistake(e, f) for e, f in [*mistakes, *engine_mistakes]),
        limits=tuple(LimitCase(subs, d) for subs, d in limits)
        + tuple(LimitCase(subs, d) for subs, d in engine_limits),
    )
    if hand is not None and derived_expr is not None:
        _require_agreement(hand, derived_expr, names, context, (*path, "answer"))
    return CompiledSymbolicPart(
        part.id,
        part.quantity_name,
        CompiledQuestion(names, expected, context),
        derived=derived_expr is not None,
    )


def _new_mistakes(
    hand: list[tuple[sympy.Expr, str]], engine: tuple[tuple[sympy.Expr, str], ...]
) -> list[tuple[sympy.Expr, str]]:
    """The engine's mistakes that the author has not already described (the author's wording wins)."""
    kept = list(hand)
    for expr, feedback in engine:
        if not any(_same_expression(expr, other) for other, _ in kept):
            kept.append((expr, feedback))
    return kept[len(hand) :]


def _new_limits(
    hand: list[tuple[dict[sympy.Symbol, sympy.Expr], str]],
    engine: tuple[tuple[Mapping[sympy.Symbol, sympy.Expr], str], ...],
) -> list[tuple[Mapping[sympy.Symbol, sympy.Expr], str]]:
    seen = [dict(subs) for subs, _ in hand]
    kept: list[tuple[Mapping[sympy.Symbol, sympy.Expr], str]] = []
    for subs, description in engine:
        if dict(subs) not in seen:
            seen.append(dict(subs))
            kept.append((subs, description))
    return kept


def _same_expression(a: sympy.Expr, b: sympy.Expr) -> bool:
    if a == b:
        return True
    try:
        return bool(sympy.simplify(a - b) == 0)
    except (TypeError, ValueError, NotImplementedError):
        return False


def _require_agreement(
    hand: sympy.Expr,
    derived: sympy.Expr,
    names: Mapping[str, sympy.Symbol],
    context: SymbolicContext,
    path: tuple[str | int, ...],
) -> None:
    """A hand-typed answer must be equivalent to the engine's derivation, on the problem's domain."""
    if sympy.simplify(hand - derived) == 0:
        return
    bare = SymbolicContext(symbols=context.symbols, constraints=context.constraints)
    judgement = judge_symbolic(hand, prepare_reference(derived, bare))
    if not judgement.correct:
        raise SpecError(f"disagrees with the model, which derives {sympy.sstr(derived)}", path)


def _numeric_part(
    doc: ProblemDocument,
    part: NumericPart,
    index: int,
    table: Mapping[str, sympy.Symbol],
    specs: Mapping[str, SymbolSpec],
    symbolic: Mapping[str, CompiledSymbolicPart],
    derived: Derived | None,
) -> CompiledNumericPart:
    path: tuple[str | int, ...] = ("parts", index)
    if part.of in symbolic:
        expr, from_model = symbolic[part.of].expected, symbolic[part.of].derived
    elif derived is not None and part.of in derived.quantities:
        expr, from_model = derived.quantities[part.of], True
    else:
        raise SpecError(f"{part.of!r} is neither a symbolic part nor a model quantity", (*path, "of"))
    missing = sorted(s.name for s in expr.free_symbols if s.name not in doc.given)
    if missing:
        raise SpecError(f"needs given values for {', '.join(missing)}", (*path, "of"))
    _require_dimension(expr, part, specs, table, path)
    tolerance = Tolerance(rel=part.tolerance.rel, abs=part.tolerance.abs, sigfigs=part.tolerance.sigfigs)
    return CompiledNumericPart(
        part.id,
        part.of,
        expr,
        part.units,
        part.units_required,
        tolerance,
        doc,
        table,
        from_model,
        arithmetic=part.arithmetic,
        units_system=part.units_system,
    )


def _require_dimension(
    expr: sympy.Expr,
    part: NumericPart,
    specs: Mapping[str, SymbolSpec],
    table: Mapping[str, sympy.Symbol],
    path: tuple[str | int, ...],
) -> None:
    dims = {table[n]: s.dimension for n, s in specs.items() if s.dimension is not None}
    try:
        have = expression_dimension(expr, dims)
    except UnknownDimension:
        return  # a symbol without a declared dimension: nothing to compare against
    except DimensionMismatch as error:
        raise SpecError(
            f"the expression for {part.of} is dimensionally inconsistent: {error}", (*path, "of")
        ) from None
    want = DIMENSIONLESS if part.dimensionless else unit_dimension(part.units)
    if have != want:
        raise SpecError(f"{part.units} does not match the dimension of {part.of}", (*path, "units"))
