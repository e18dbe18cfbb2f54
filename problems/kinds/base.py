"""What every answer kind provides, and the contexts it works in.

An answer kind is one module (`problems/kinds/<kind>.py`) that, for one `kind:` of part, defines
  schema    the part's pydantic model (`kind: Literal[...]`), validated with the rest of the document
  meaning   the faults of a well-shaped part, each with its path, none stopping the rest
  compile   the part as the grader needs it: a `CompiledPart`, whose `job` crosses into a worker
  student   what a student sees of it (never a reference)
  selftest  the cases the bank self-test grades it by
  describe  what an instructor reads of it (`PartInfo`): its reference, mistakes, limits
  findings  (optional, `ReportsFindings`) what an incorrect answer's stored feedback says is wrong, one
            item per finding, for the class results to count ("the normal force is missing")
  check     its `POST /v1/check` body (`<Kind>CheckIn`): a one-part problem given in the request, built
            from the same declarations, whose `job` compiles it by the kind's own compile (its one part
            `ADHOC_PART`, no document) and grades it as a part of the kind is graded
and is registered by its `kind` in `problems.kinds.KINDS`, which `problems.kinds.kind_of` matches.

A kind owns its presentation too: its directory (`problems/kinds/<kind>/`) holds, beside the module,
  student.html    what the student page shows above the answer box (the student view's fields as `part`)
  described.html  what the instructor page and the worked solution show of the reference (`PartInfo` as
                  `part`; `view` is "facts" for the instructor's list, "answer" for the solution's line)
which the web pages include by the part's kind: no page branches on a kind.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol, TypeVar, runtime_checkable

import sympy

from physics.checking import CheckJob, Question
from physics.errors import AnswerError, SpecError
from physics.symbolic import KnownMistake, SymbolSpec
from physics.verdict import Verdict
from problems.errors import ErrorItem, format_path

if TYPE_CHECKING:
    from problems.compiled import CompiledProblem
    from problems.modelinfo import Derived
    from problems.schema import ProblemDocument
    from problems.variants import Variant

T = TypeVar("T")
P_contra = TypeVar("P_contra", contravariant=True)
C = TypeVar("C", bound="CompiledPart")
Path = tuple[str | int, ...]

ADHOC_PART = "check"  # the id of the one part a `POST /v1/check` body is


class Faults:
    """Runs checks, turning each SpecError into one (path, message) and carrying on."""

    def __init__(self) -> None:
        self.errors: list[ErrorItem] = []

    def add(self, path: Path, message: str) -> None:
        item = (format_path(path), message)
        if item not in self.errors:
            self.errors.append(item)

    def attempt(self, check: Callable[[], T], path: Path = ()) -> T | None:
        try:
            return check()
        except SpecError as error:
            self.add(error.path or path, error.message)
        except AnswerError as error:
            self.add(path, error.message)
        return None


@dataclass(frozen=True)
class MeaningContext:
    """What a part's meaning check may consult: the document, its symbols, the model's quantities."""

    doc: ProblemDocument
    table: Mapping[str, sympy.Symbol]  # every readable declared symbol
    quantities: frozenset[str] | None  # the model's quantity names; None: no model
    expression_parts: frozenset[str]  # ids of parts answered by an expression (what `of` may name)
    out: Faults


@dataclass(frozen=True)
class CompileContext:
    """What compiling a part may use: its problem's symbols and domain, and, for a bank part, its document,
    its model's derivation and the expression parts compiled before it (`expressions`, and the known
    `mistakes` of those that have them: a numeric part evaluated from one recognises them too). A
    `POST /v1/check` body is a one-part problem with no document (`doc` None), its part `ADHOC_PART`:
    the same compile reads it."""

    table: Mapping[str, sympy.Symbol]
    specs: Mapping[str, SymbolSpec]
    constraints: tuple[sympy.Basic, ...]
    doc: ProblemDocument | None = None
    derived: Derived | None = None
    expressions: Mapping[str, tuple[sympy.Expr, bool]] = field(default_factory=dict)  # id -> (expr, derived)
    mistakes: Mapping[str, tuple[KnownMistake, ...]] = field(default_factory=dict)  # id -> its mistakes


@dataclass(frozen=True)
class Reference:
    """A part's reference answer as the instructor's solution shows it."""

    text: str
    latex: str
    units: str | None = None


@dataclass(frozen=True)
class CheckResult:
    problem: str
    part: str | None
    check: str  # e.g. "rewrite factor", "mistake 1", "variant 7 in km/h", "methods agree"
    ok: bool
    detail: str = ""


def explain(text: str, verdict: Verdict) -> str:
    """A self-test failure's detail: what was typed and how it was judged."""
    return f"{text!r} was {verdict.outcome.value} ({verdict.reason.value}): {verdict.feedback}"


@dataclass(frozen=True)
class MistakeInfo:
    latex: str
    text: str  # the same, as plain text (chart labels)
    feedback: str
    by_author: bool  # written in the problem (else found by the engine)
    value: str | None = None  # a numeric part's, for the variant described: "1.83 s"


@dataclass(frozen=True)
class LimitInfo:
    where: str  # TeX, e.g. "k = 0"
    description: str


@dataclass(frozen=True)
class PartInfo:
    """A part as an instructor reads it (the kind's `described.html` shows it)."""

    id: str
    kind: str
    prompt: str
    latex: str  # the reference (for a numeric part, the expression it is evaluated from)
    units: str | None = None
    tolerance: str | None = None  # numeric parts: "within 1 %", …
    expected: str | None = (
        None  # numeric parts, for the variant described: "4.580 m/s²" (to the part's sigfigs)
    )
    expected_full: str | None = None  # …and the 12 significant figures it is checked against
    mistakes: tuple[MistakeInfo, ...] = ()
    limits: tuple[LimitInfo, ...] = ()
    error: str | None = None  # the numeric reference could not be evaluated for this variant
    facts: tuple[tuple[str, str], ...] = ()  # further (label, TeX) lines a kind shows (a new kind's own)


class CompiledPart(Protocol):
    """A part ready to grade: no YAML left, picklable (compiled problems are persisted)."""

    @property
    def id(self) -> str: ...

    @property
    def derived(self) -> bool:
        """Its reference was derived (or checked) by the engine, not only typed by the author."""
        ...

    @property
    def expression(self) -> sympy.Expr | None:
        """Its reference as an expression (a numeric part: what it evaluates); None: not an expression."""
        ...

    def prepare(self) -> None:
        """Do now the work grading would do lazily (e.g. to persist it)."""
        ...

    def solution(self) -> Reference:
        """The reference answer as the instructor's solution shows it."""
        ...

    def question(self, variant: Variant | None = None) -> Question:
        """What grades an answer; a part whose reference depends on the student needs their variant."""
        ...

    def job(self, answer: str, variant: Variant | None = None) -> CheckJob:
        """A picklable check job for a worker process."""
        ...


@runtime_checkable
class ReportsFindings(Protocol):
    """A kind whose incorrect answers' feedback names findings a class results page counts across students
    (a force left out, a kinetic term missing): read back from the stored feedback, so that submissions
    filed before need nothing more."""

    def findings(self, feedback: str) -> tuple[str, ...]: ...


class AnswerKind(Protocol[P_contra, C]):
    """One kind of part, from its schema to its self-test (module docstring)."""

    @property
    def name(self) -> str:
        """The `kind:` value that selects it."""
        ...

    @property
    def expression_answer(self) -> bool:
        """Answered by an expression that a numeric part's `of` may name."""
        ...

    def asked_quantities(self, part: P_contra) -> frozenset[str]:
        """The model quantities the part asks for or uses (a model quantity no part uses is a fault)."""
        ...

    def check_meaning(self, part: P_contra, path: Path, context: MeaningContext) -> None:
        """Report every fault of a well-shaped part into `context.out`."""
        ...

    def compile(self, part: P_contra, path: Path, context: CompileContext) -> C:
        """The compiled part; SpecError (with its path) on a fault."""
        ...

    def student_view(self, part: P_contra, doc: ProblemDocument) -> dict[str, Any]:
        """The part's fields in a student's view beyond id, kind, prompt and attempts; never a reference."""
        ...

    def selftest(self, problem: str, part: C, students: Sequence[Variant]) -> list[CheckResult]:
        """Grade the part's own reference (accepted) and its known wrong answers (rejected)."""
        ...

    def texts(self, part: P_contra, path: str) -> Iterator[tuple[str, str]]:
        """(path, text) of what people read in the part beyond its prompt (feedback, descriptions)."""
        ...

    def describe(
        self, part: C, info: PartInfo, compiled: CompiledProblem, variant: Variant | None
    ) -> PartInfo:
        """What an instructor reads of the compiled part: `info` (its id, kind and prompt) completed."""
        ...
