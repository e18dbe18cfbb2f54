"""One entry point for checking an answer, used in-process (bank self-test) and in worker processes.

Every kind of part compiles to a `Question` (`grade` and `read` an answer); a `CheckJob` is an answer
with the means to get its question in the process that grades, picklable so it can cross into a
killable worker. An ad-hoc symbolic check (`problems.kinds.symbolic.SymbolicJob`) carries the request's
texts, which the worker reads with the whitelist parser, because instructor text is as untrusted as a
student's: the kind's own compile makes of them a `CompiledQuestion`, as of a stored problem's part. A
stored part (`PartJob`) carries what the server compiled, sympy trees pickled once, never text printed
by sympy and parsed again (the parser does not read everything sympy prints: `Abs`, `sign`, `Piecewise`,
`Min`). Questions are cached per worker.
"""

from __future__ import annotations

import dataclasses
import pickle
import threading
from collections import OrderedDict
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from typing import Protocol, cast

import sympy

from physics.dimensions import Dimension
from physics.errors import AmbiguousGrouping, AnswerError, SpecError
from physics.mathinput import InputLimits, ParsedMath, parse_expression
from physics.mathinput.powered import other_reading_hint, reading_note
from physics.mathinput.reader import build_reading, read_tree
from physics.numeric import NumericSpec
from physics.pickling import pickled_by_fields
from physics.symbolic import (
    PreparedReference,
    SymbolicContext,
    SymbolSpec,
    judge_symbolic,
    prepare_reference,
)
from physics.symbolic.bracketed_sums import unbracketed_sum
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension
from physics.symbolic.fraction_exponents import fraction_exponent
from physics.symbolic.judge import FACTOR_FEEDBACK
from physics.symbolic.quick import judged
from physics.symbolic.reading import read_symbolic_answer, shorter_arguments
from physics.symbolic.symbol_e import symbol_e_raised
from physics.symbolic.typed_values import typed_value_hint, with_units_hint
from physics.units import unit_dimension
from physics.verdict import InputProblem, Outcome, Preview, Reason, Verdict


@pickled_by_fields
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


class Question(Protocol):
    """A part ready to grade, whatever its kind: what a worker runs an answer against."""

    def grade(self, answer: str, limits: InputLimits) -> Verdict:
        """The verdict; an unreadable answer is an `invalid` verdict, never an exception."""
        ...

    def read(self, answer: str, limits: InputLimits) -> Preview:
        """How the answer reads, without grading it."""
        ...


class CheckJob(Protocol):
    """One answer and the question it answers, picklable so it can cross into a killable worker."""

    @property
    def answer(self) -> str: ...

    @property
    def limits_config(self) -> InputLimits: ...

    def question(self) -> Question:
        """The question, built (or unpickled) in the process that grades; SpecError on a bad reference."""
        ...


@dataclass(frozen=True)
class SymbolicQuestion:
    """A symbolic part ready to grade: the reference prepared once, the names the answer may use."""

    names: Mapping[str, sympy.Symbol]
    reference: PreparedReference

    def grade(self, answer: str, limits: InputLimits) -> Verdict:
        verdict = self._graded(answer, limits)
        if verdict.outcome is not Outcome.INCORRECT or verdict.read_as is None:
            return verdict
        if verdict.reason is Reason.WRONG_DIMENSION and self.reference.dimension is not None:
            dimensions = {symbol.name: dim for symbol, dim in self.reference.dims.items()}
            question = (
                unbracketed_sum(answer, self.names, limits, dimensions, self.reference.dimension)
                or symbol_e_raised(answer, self.names, limits, dimensions)
                or fraction_exponent(answer, self.names, limits, dimensions, self.reference.dimension)
            )
            if question is not None:  # `mg/m+M`: m·g/(m + M) meant; `e^(-t/τ)` with e a charge: exp
                return Verdict.invalid(question)
        hint = typed_value_hint(
            verdict.read_as.text,
            verdict.reason,
            self.names,
            lambda text: self._graded(text, limits).outcome is Outcome.CORRECT,
        )
        if hint is None:
            return verdict
        if verdict.reason is Reason.CONSTANT_FACTOR:  # the hint says which factor: in place of the guess
            return dataclasses.replace(verdict, feedback=verdict.feedback.replace(FACTOR_FEEDBACK, hint))
        return dataclasses.replace(verdict, feedback=f"{verdict.feedback} {hint}")

    def _graded(self, answer: str, limits: InputLimits) -> Verdict:
        reference = self.reference
        dimensions = {symbol.name: dim for symbol, dim in reference.dims.items()}
        try:
            reading = read_tree(answer, self.names, limits=limits)
        except AmbiguousGrouping:
            reading = None  # settled by dimension, where it can be, as the answer is read in full below
        except AnswerError as error:
            return Verdict.invalid(with_units_hint(error, answer, self.reference.dimension))
        # Judged on the parse tree where it is enough, most answers skip building sympy's (quick.py); a
        # wrong one with a bare powered argument is built, to tell whether the other reading is right.
        if reading is not None:
            quick = judged(reading, reference, limits.max_exponent)
            if (
                quick is not None
                and (quick.correct or not reading.powered)
                and not (reading.long_words and quick.reason is Reason.WRONG_DIMENSION)
            ):
                return _led(Verdict.graded(quick, reading.read_as), reading.read_as.note)
        try:
            if reading is None:
                parsed = read_symbolic_answer(answer, self.names, limits, dimensions, reference.dimension)
            else:
                parsed = build_reading(reading, limits)
            judgement = judge_symbolic(parsed.expr, reference)
            if (
                parsed.long_words
                and judgement.reason is Reason.WRONG_DIMENSION
                and reference.dimension is not None
            ):
                # `sinθmgL`: sin(θ·m·g·L) has no dimension; sin(θ)·m·g·L may be the only reading with one
                shorter = shorter_arguments(
                    answer, self.names, limits, dimensions, reference.dimension, parsed
                )
                if shorter is not parsed:
                    parsed, judgement = shorter, judge_symbolic(shorter.expr, reference)
        except AnswerError as error:
            return Verdict.invalid(with_units_hint(error, answer, self.reference.dimension))
        lead = parsed.read_as.note  # how the answer was read (chosen by dimension, `sin θ^2`): said first
        if not judgement.correct and self._other_reading_is_right(answer, limits, parsed):
            # In place of the note on `sin θ^2`: it was read as sin(θ²), and (sin θ)² would be right.
            assert lead is not None  # a bare powered argument always has its note
            lead = lead.replace(str(reading_note(parsed.powered)), other_reading_hint(parsed.powered))
        return _led(Verdict.graded(judgement, parsed.read_as), lead)

    def _other_reading_is_right(self, answer: str, limits: InputLimits, parsed: ParsedMath) -> bool:
        """Whether reading each bare function argument's power as the function's (`sin θ^2` as
        (sin θ)²) makes the answer right: then the student is told how to write what they meant."""
        if not parsed.powered:
            return False
        reference = self.reference
        dimensions = {symbol.name: dim for symbol, dim in reference.dims.items()}
        try:
            other = read_symbolic_answer(
                answer, self.names, limits, dimensions, reference.dimension, powers_outside=True
            )
            return judge_symbolic(other.expr, reference).correct
        except AnswerError:
            return False

    def read(self, answer: str, limits: InputLimits) -> Preview:
        dimensions = {symbol.name: dim for symbol, dim in self.reference.dims.items()}
        return _preview(answer, self.names, limits, dimensions, self.reference.dimension)


def _preview(
    answer: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    dimensions: Mapping[str, Dimension],
    expected: Dimension | None,
) -> Preview:
    """How a symbolic answer reads, or why it cannot be read; a sum whose brackets are left out beside a
    division (`mg/m+M`), a power of a charge e (`e^(-t/τ)`) and an exponent's fraction typed on it
    (`(R+h)^3/2`) are asked about before the answer is submitted, as grading asks."""
    try:
        parsed = read_symbolic_answer(answer, names, limits, dimensions, expected)
    except AnswerError as error:
        return Preview(None, InputProblem(error.message, error.position))
    if expected is not None:
        question = (
            unbracketed_sum(answer, names, limits, dimensions, expected)
            or symbol_e_raised(answer, names, limits, dimensions)
            or fraction_exponent(answer, names, limits, dimensions, expected)
        )
        if question is not None:
            return Preview(None, InputProblem(question.message, question.position))
    return Preview(parsed.read_as, None)


def _led(verdict: Verdict, lead: str | None) -> Verdict:
    """The verdict with `lead` (how the answer was read) said before its feedback."""
    return verdict if lead is None else dataclasses.replace(verdict, feedback=f"{lead}. {verdict.feedback}")


@dataclass(frozen=True)
class CompiledQuestion:
    """A symbolic part as compiled from its texts: sympy trees, never text to read again."""

    names: Mapping[str, sympy.Symbol]  # what the answer may use
    expected: sympy.Expr
    context: SymbolicContext

    @cached_property
    def question(self) -> SymbolicQuestion:
        """The prepared reference (sampling the domain once; sympy-heavy, hence lazy and cached).

        Pickled with the question once computed, so a worker given a prepared one does not sample again.
        """
        return SymbolicQuestion(self.names, prepare_reference(self.expected, self.context))

    def grade(self, answer: str, limits: InputLimits) -> Verdict:
        return self.question.grade(answer, limits)

    def read(self, answer: str, limits: InputLimits) -> Preview:
        # Only the expected dimension is needed to read: the reference is not prepared for a preview.
        symbols = self.context.symbols
        dimensions = {spec.name: spec.dimension for spec in symbols.values() if spec.dimension is not None}
        try:
            expected_dimension: Dimension | None = expression_dimension(
                self.expected,
                {s: spec.dimension for s, spec in symbols.items() if spec.dimension is not None},
            )
        except (DimensionMismatch, UnknownDimension):
            expected_dimension = None
        return _preview(answer, self.names, limits, dimensions, expected_dimension)


@dataclass(frozen=True)
class NumericJob:
    """A numeric answer against the value expected of this student (bank or ad-hoc alike)."""

    answer: str
    spec: NumericSpec
    limits_config: InputLimits = field(default_factory=InputLimits)

    def question(self) -> NumericSpec:
        return self.spec


@dataclass(frozen=True)
class QuestionJob:
    """An answer with a small question carried whole (a kind whose question is plain data)."""

    answer: str
    payload: Question
    limits_config: InputLimits = field(default_factory=InputLimits)

    def question(self) -> Question:
        return self.payload


@dataclass(frozen=True)
class PartJob:
    """An answer to a stored problem's part whose question is heavy (sympy trees, prepared samples).

    `payload` is the part's question pickled by this service's own server process (never bytes from a
    request), `key` a digest of it: a worker unpickles and prepares each key once.
    """

    answer: str
    key: str
    payload: bytes = field(repr=False)
    limits_config: InputLimits = field(default_factory=InputLimits)

    def question(self) -> Question:
        return compiled_question(self)


PART_CACHE_SIZE = 256
_parts: OrderedDict[str, Question] = OrderedDict()
_parts_lock = threading.Lock()


def compiled_question(job: PartJob) -> Question:
    """The job's question, unpickled once per key in this process (LRU)."""
    with _parts_lock:
        found = _parts.get(job.key)
        if found is not None:
            _parts.move_to_end(job.key)
            return found
    # Safe to unpickle: the server process wrote these bytes itself (`part_job`); requests never carry
    # a payload.
    loaded = pickle.loads(job.payload)  # noqa: S301
    if not callable(getattr(loaded, "grade", None)) or not callable(getattr(loaded, "read", None)):
        raise TypeError(f"a part job carries a {type(loaded).__name__}, not a question")
    with _parts_lock:
        _parts[job.key] = loaded
        while len(_parts) > PART_CACHE_SIZE:
            _parts.popitem(last=False)
    return cast(Question, loaded)


def check_answer(answer: str, question: Question, limits: InputLimits | None = None) -> Verdict:
    """Grade one answer; an unreadable answer is an `invalid` verdict, never an exception."""
    return question.grade(answer, limits or InputLimits())


def preview(job: CheckJob) -> Preview:
    """Read the answer as its check would, without grading it."""
    return job.question().read(job.answer, job.limits_config)


def run_job(job: CheckJob) -> Verdict:
    """Grade a job; raises SpecError when the reference side is unusable."""
    return job.question().grade(job.answer, job.limits_config)


@lru_cache(maxsize=1024)
def symbol_spec(decl: SymbolDecl) -> SymbolSpec:
    """The core's spec for a declared symbol, its texts read; SpecError (with path) on a bad one.

    Cached: references of a course declare the same symbols again and again (`m` in kg, `theta` in
    (0, pi/2)), and reading their units and ranges is a fifth of reading a new reference."""
    dimension = None
    if decl.dimension is not None:
        dimension = unit_dimension(decl.dimension, ("symbols", decl.name, "dimension"))
    low = high = None
    if decl.range is not None:
        low, high = (_read_bound(decl.name, i, text) for i, text in enumerate(decl.range))
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


def _read_bound(name: str, index: int, text: str) -> sympy.Expr:
    found = _range_bound(text)
    return read_expression(text, {}, ("symbols", name, "range", index)) if found is None else found


@lru_cache(maxsize=256)
def _range_bound(text: str) -> sympy.Expr | None:
    """A range bound's text read (`pi/2`, `oo`), once per text: the same bounds come under every name (a
    renamed domain's `theta_2`); None where it is unreadable (read again with its path, to say so)."""
    try:
        return read_expression(text, {}, ())
    except SpecError:
        return None


_INFINITY_WORDS = {"oo": sympy.oo, "inf": sympy.oo, "infinity": sympy.oo, "∞": sympy.oo, "-oo": -sympy.oo}


def read_expression(text: str, table: Mapping[str, sympy.Symbol], path: tuple[str | int, ...]) -> sympy.Expr:
    if text.strip() in _INFINITY_WORDS:
        return _INFINITY_WORDS[text.strip()]
    try:
        return parse_expression(text, table)
    except AnswerError as error:
        raise SpecError.unreadable(error, path) from None


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
