"""One entry point for checking an answer, used in-process (bank self-test) and in worker processes.

A `CheckJob` is picklable so it can cross into a killable worker. An ad-hoc check (`SymbolicJob`)
carries the request's texts, which the worker reads with the whitelist parser, because instructor
text is as untrusted as a student's. A stored problem's part (`PartJob`) carries what the server
compiled, sympy trees pickled once, never text printed by sympy and parsed again (the parser does
not read everything sympy prints: `Abs`, `sign`, `Piecewise`, `Min`). Prepared references are
cached per worker.
"""

from __future__ import annotations

import dataclasses
import pickle
import threading
from collections import OrderedDict
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property, lru_cache

import sympy

from physics.dimensions import Dimension
from physics.errors import AnswerError, SpecError
from physics.mathinput import InputLimits, parse_math
from physics.numeric import NumericSpec, check_numeric
from physics.symbolic import (
    KnownMistake,
    LimitCase,
    PreparedReference,
    SymbolicContext,
    SymbolSpec,
    judge_symbolic,
    make_symbol,
    prepare_reference,
)
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension
from physics.symbolic.reading import read_symbolic_answer
from physics.units import unit_dimension
from physics.verdict import InputProblem, ReadAs, Verdict


@dataclass(frozen=True)
class SymbolDecl:
    """A symbol as an author declares it: text fields only, read in the worker."""

    name: str
    dimension: str | None = None
    real: bool = False
    nonzero: bool = False
    negative: bool = False
    integer: bool = False
    range: tuple[str, str] | None = None


@dataclass(frozen=True)
class LimitDecl:
    substitutions: tuple[tuple[str, str], ...]  # (symbol name, value text such as "oo" or "0")
    description: str


@dataclass(frozen=True)
class SymbolicJob:
    answer: str
    expected: str
    symbols: tuple[SymbolDecl, ...]
    constraints: tuple[str, ...] = ()
    mistakes: tuple[tuple[str, str], ...] = ()  # (expression text, feedback)
    limits: tuple[LimitDecl, ...] = ()
    allowed: tuple[str, ...] | None = None  # names the answer may use; None: every declared symbol
    limits_config: InputLimits = field(default_factory=InputLimits)


@dataclass(frozen=True)
class NumericJob:
    answer: str
    spec: NumericSpec


@dataclass(frozen=True)
class SymbolicQuestion:
    """A symbolic part ready to grade: the reference prepared once, the names the answer may use."""

    names: Mapping[str, sympy.Symbol]
    reference: PreparedReference


@dataclass(frozen=True)
class CompiledQuestion:
    """A stored problem's symbolic part as the server compiled it: sympy trees, no text to read again."""

    names: Mapping[str, sympy.Symbol]  # what the answer may use
    expected: sympy.Expr
    context: SymbolicContext

    @cached_property
    def question(self) -> SymbolicQuestion:
        """The prepared reference (sampling the domain once; sympy-heavy, hence lazy and cached).

        Pickled with the question once computed, so a worker given a prepared one does not sample again.
        """
        return SymbolicQuestion(self.names, prepare_reference(self.expected, self.context))


@dataclass(frozen=True)
class PartJob:
    """An answer to a stored problem's symbolic part.

    `payload` is the part's CompiledQuestion pickled by this service's own server process (never bytes
    from a request), `key` a digest of it: a worker unpickles and prepares each key once.
    """

    answer: str
    key: str
    payload: bytes = field(repr=False)
    limits_config: InputLimits = field(default_factory=InputLimits)


CheckJob = SymbolicJob | PartJob | NumericJob

PART_CACHE_SIZE = 256
_parts: OrderedDict[str, CompiledQuestion] = OrderedDict()
_parts_lock = threading.Lock()


def compiled_question(job: PartJob) -> CompiledQuestion:
    """The job's question, unpickled once per key in this process (LRU)."""
    with _parts_lock:
        found = _parts.get(job.key)
        if found is not None:
            _parts.move_to_end(job.key)
            return found
    # Safe to unpickle: the server process wrote these bytes itself (CompiledSymbolicPart.job);
    # requests never carry a payload.
    loaded = pickle.loads(job.payload)  # noqa: S301
    if not isinstance(loaded, CompiledQuestion):
        raise TypeError(f"a part job carries a {type(loaded).__name__}, not a CompiledQuestion")
    with _parts_lock:
        _parts[job.key] = loaded
        while len(_parts) > PART_CACHE_SIZE:
            _parts.popitem(last=False)
    return loaded


def check_answer(
    answer: str, question: SymbolicQuestion | NumericSpec, limits: InputLimits | None = None
) -> Verdict:
    """Grade one answer; an unreadable answer is an `invalid` verdict, never an exception."""
    if isinstance(question, NumericSpec):
        return check_numeric(answer, question)
    reference = question.reference
    dimensions = {symbol.name: dim for symbol, dim in reference.dims.items()}
    try:
        parsed = read_symbolic_answer(
            answer, question.names, limits or InputLimits(), dimensions, reference.dimension
        )
        judgement = judge_symbolic(parsed.expr, reference)
    except AnswerError as error:
        return Verdict.invalid(error)
    verdict = Verdict.graded(judgement, parsed.read_as)
    if parsed.read_as.note is not None:  # the reading was chosen by dimension: say so first
        return dataclasses.replace(verdict, feedback=f"{parsed.read_as.note}. {verdict.feedback}")
    return verdict


@dataclass(frozen=True)
class Preview:
    """How an answer reads, before it is submitted: never a verdict, never a hint of correctness."""

    read_as: ReadAs | None
    error: InputProblem | None


def preview(job: CheckJob) -> Preview:
    """Read the answer as its check would, without grading it."""
    if isinstance(job, NumericJob):
        verdict = check_numeric(job.answer, job.spec)
        return Preview(verdict.read_as, verdict.error)
    if isinstance(job, PartJob):
        compiled = compiled_question(job)
        names = compiled.names
        symbols = compiled.context.symbols
        dimensions = {spec.name: spec.dimension for spec in symbols.values() if spec.dimension is not None}
        try:
            expected_dimension: Dimension | None = expression_dimension(
                compiled.expected,
                {s: spec.dimension for s, spec in symbols.items() if spec.dimension is not None},
            )
        except (DimensionMismatch, UnknownDimension):
            expected_dimension = None
    else:
        specs = {decl.name: symbol_spec(decl) for decl in job.symbols}
        table = {name: make_symbol(spec) for name, spec in specs.items()}
        names = table if job.allowed is None else {n: table[n] for n in job.allowed if n in table}
        dimensions = {name: spec.dimension for name, spec in specs.items() if spec.dimension is not None}
        expected_dimension = _expected_dimension(job.expected, table, dimensions)
    try:
        read = read_symbolic_answer(
            job.answer,
            names,
            job.limits_config,
            dimensions,
            expected_dimension,
        )
        return Preview(read.read_as, None)
    except AnswerError as error:
        return Preview(None, InputProblem(error.message, error.position))


def _expected_dimension(
    expected: str, table: Mapping[str, sympy.Symbol], dimensions: Mapping[str, Dimension]
) -> Dimension | None:
    """The dimension a symbolic answer must have, for settling its ambiguous divisions (None: unknown)."""
    try:
        reference = read_expression(expected, table, ("expected",))
        return expression_dimension(reference, {table[name]: dim for name, dim in dimensions.items()})
    except (SpecError, DimensionMismatch, UnknownDimension):
        return None


def run_job(job: CheckJob) -> Verdict:
    """Grade a job of plain texts; raises SpecError when the reference side is unusable."""
    if isinstance(job, NumericJob):
        return check_numeric(job.answer, job.spec)
    if isinstance(job, PartJob):
        return check_answer(job.answer, compiled_question(job).question, job.limits_config)
    question = symbolic_question(
        job.expected, job.symbols, job.constraints, job.mistakes, job.limits, job.allowed
    )
    return check_answer(job.answer, question, job.limits_config)


@lru_cache(maxsize=256)
def symbolic_question(
    expected: str,
    symbols: tuple[SymbolDecl, ...],
    constraints: tuple[str, ...] = (),
    mistakes: tuple[tuple[str, str], ...] = (),
    limits: tuple[LimitDecl, ...] = (),
    allowed: tuple[str, ...] | None = None,
) -> SymbolicQuestion:
    """Read and prepare the reference side of a symbolic job (cached: a course re-uses its references)."""
    specs = {decl.name: symbol_spec(decl) for decl in symbols}
    table = {name: make_symbol(spec) for name, spec in specs.items()}
    context = SymbolicContext(
        symbols={table[name]: spec for name, spec in specs.items()},
        constraints=tuple(
            read_relation(text, table, ("constraints", i)) for i, text in enumerate(constraints)
        ),
        mistakes=tuple(
            KnownMistake(read_expression(text, table, ("mistakes", i)), feedback)
            for i, (text, feedback) in enumerate(mistakes)
        ),
        limits=tuple(_limit_case(decl, table, i) for i, decl in enumerate(limits)),
    )
    reference = prepare_reference(read_expression(expected, table, ("expected",)), context)
    names = table if allowed is None else {name: table[name] for name in allowed if name in table}
    return SymbolicQuestion(names=names, reference=reference)


def symbol_spec(decl: SymbolDecl) -> SymbolSpec:
    """The core's spec for a declared symbol, its texts read; SpecError (with path) on a bad one."""
    dimension = None
    if decl.dimension is not None:
        try:
            dimension = unit_dimension(decl.dimension)
        except (AnswerError, SpecError) as error:
            raise SpecError(error.message, ("symbols", decl.name, "dimension")) from None
    low = high = None
    if decl.range is not None:
        low, high = (
            read_expression(text, {}, ("symbols", decl.name, "range", i)) for i, text in enumerate(decl.range)
        )
    return SymbolSpec(
        name=decl.name,
        dimension=dimension,
        real=decl.real,
        nonzero=decl.nonzero,
        negative=decl.negative,
        integer=decl.integer,
        low=low,
        high=high,
    )


def _limit_case(decl: LimitDecl, table: Mapping[str, sympy.Symbol], index: int) -> LimitCase:
    substitutions: dict[sympy.Symbol, sympy.Expr] = {}
    for name, value in decl.substitutions:
        if name not in table:
            raise SpecError(f"limit names an undeclared symbol {name!r}", ("limits", index, name))
        substitutions[table[name]] = read_expression(value, {}, ("limits", index, name))
    return LimitCase(substitutions=substitutions, description=decl.description)


_INFINITY_WORDS = {"oo": sympy.oo, "inf": sympy.oo, "infinity": sympy.oo, "∞": sympy.oo, "-oo": -sympy.oo}


def read_expression(text: str, table: Mapping[str, sympy.Symbol], path: tuple[str | int, ...]) -> sympy.Expr:
    if text.strip() in _INFINITY_WORDS:
        return _INFINITY_WORDS[text.strip()]
    try:
        return parse_math(text, table).expr
    except AnswerError as error:
        where = f" at character {error.position}" if error.position is not None else ""
        raise SpecError(f"{error.message}{where}", path) from None


_RELATIONS = {"<=": sympy.Le, ">=": sympy.Ge, "≤": sympy.Le, "≥": sympy.Ge, "<": sympy.Lt, ">": sympy.Gt}


def read_relation(text: str, table: Mapping[str, sympy.Symbol], path: tuple[str | int, ...]) -> sympy.Basic:
    """Read `lhs < rhs` (one of < > <= >= ≤ ≥, exactly once); each side with the whitelist parser."""
    found = [(text.find(op), op) for op in _RELATIONS if op in text]
    # "<=" also contains "<": keep the longest operator at the first position.
    found.sort(key=lambda hit: (hit[0], -len(hit[1])))
    if not found:
        raise SpecError("a constraint needs one of < > <= >=", path)
    position, op = found[0]
    lhs, rhs = text[:position], text[position + len(op) :]
    if any(other in rhs for other in _RELATIONS):
        raise SpecError("a constraint may compare only two sides", path)
    return _RELATIONS[op](read_expression(lhs, table, path), read_expression(rhs, table, path))
