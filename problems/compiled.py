"""A problem compiled for grading: per part what its kind compiled (`problems.kinds`), no YAML left.

Compiling derives the model (sympy-heavy) once, then hands each part to its kind, expression parts
first (a numeric part evaluates one of them); each kind reconciles what it needs with the derivation
(a symbolic part's typed answer must agree with it, the engine's mistakes and limits join the
author's). The result is cached per (id, version, document hash), so a course's thousand submissions
compile the problem once.
"""

from __future__ import annotations

import hashlib
import json
import threading
from collections import OrderedDict
from collections.abc import Mapping
from dataclasses import dataclass

import sympy

from physics.checking import CheckJob, Question, read_relation
from physics.errors import SpecError
from physics.symbolic import KnownMistake, make_symbol
from problems.errors import ErrorItem, ProblemInvalid, format_path
from problems.kinds import (
    AnyCompiledPart,
    CompiledChoicePart,
    CompiledNumericPart,
    CompiledPart,
    CompiledSymbolicPart,
    kind_of,
)
from problems.kinds.base import CompileContext
from problems.modelinfo import Derived, derive_doc, spec_error_items
from problems.schema import ProblemDocument
from problems.symbols import symbol_specs
from problems.variants import Variant

CACHE_SIZE = 256  # live problem versions kept compiled; beyond it they are derived again

__all__ = [
    "CompiledChoicePart",
    "CompiledNumericPart",
    "CompiledPart",
    "CompiledProblem",
    "CompiledSymbolicPart",
    "build_problem",
    "compile_problem",
    "document_digest",
]


@dataclass(frozen=True)
class CompiledProblem:
    document: ProblemDocument
    version: int
    digest: str
    table: Mapping[str, sympy.Symbol]
    parts: Mapping[str, AnyCompiledPart]
    derived: Derived | None = None
    constraints: tuple[sympy.Basic, ...] = ()  # relations the symbols satisfy (the problem's domain)

    def part(self, part_id: str) -> AnyCompiledPart:
        return self.parts[part_id]

    @property
    def not_derived(self) -> tuple[str, ...]:
        """Parts whose reference is only the author's typed answer: no method derived or checked it."""
        return tuple(part_id for part_id, part in self.parts.items() if not part.derived)

    def question(self, part_id: str, variant: Variant | None = None) -> Question:
        """What `physics.checking.check_answer` needs; a numeric part needs the student's variant."""
        return self.parts[part_id].question(variant)

    def job(self, part_id: str, answer: str, variant: Variant | None = None) -> CheckJob:
        """A picklable check job for a worker process."""
        return self.parts[part_id].job(answer, variant)

    def prepare(self) -> CompiledProblem:
        """Prepare every symbolic part's reference now (sample points, values, mistakes, limits), e.g. to
        persist them."""
        for part in self.parts.values():
            part.prepare()
        return self

    def reference_expressions(self) -> dict[str, sympy.Expr]:
        """Every part's reference expression, for the parts answered by one (instructor-only)."""
        return {pid: p.expression for pid, p in self.parts.items() if p.expression is not None}


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

    # Expression parts first: a numeric part evaluates one of them (its `of`).
    expressions: dict[str, tuple[sympy.Expr, bool]] = {}
    mistakes: dict[str, tuple[KnownMistake, ...]] = {}
    compiled: dict[str, AnyCompiledPart] = {}
    order = sorted(range(len(doc.parts)), key=lambda i: not kind_of(doc.parts[i]).expression_answer)
    for index in order:
        part = doc.parts[index]
        context = CompileContext(table, specs, constraints, doc, derived, dict(expressions), dict(mistakes))
        try:
            compiled[part.id] = done = kind_of(part).compile(part, ("parts", index), context)
        except SpecError as error:
            errors.append((format_path(error.path or ("parts", index)), error.message))
            continue
        if done.expression is not None and kind_of(part).expression_answer:
            expressions[part.id] = (done.expression, done.derived)
            if isinstance(done, CompiledSymbolicPart):
                mistakes[part.id] = done.context.mistakes
    parts = {part.id: compiled[part.id] for part in doc.parts if part.id in compiled}
    if errors:
        raise ProblemInvalid(errors, doc.id)
    return CompiledProblem(doc, version, digest, table, parts, derived, constraints)


def _constraints(doc: ProblemDocument, table: Mapping[str, sympy.Symbol]) -> tuple[sympy.Basic, ...]:
    return tuple(read_relation(text, table, ("constraints", i)) for i, text in enumerate(doc.constraints))
