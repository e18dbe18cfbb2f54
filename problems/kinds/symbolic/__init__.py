"""Symbolic parts: the answer is an expression in the problem's symbols, equivalent to a reference that
the engine derives (or the author types), weighed against known mistakes and limiting cases."""

from __future__ import annotations

import dataclasses
import hashlib
import pickle
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property, lru_cache, partial
from typing import TYPE_CHECKING, Annotated, Any, Literal

import sympy
from pydantic import Field

from physics import typeset
from physics.answer_text import student_text, typed_text
from physics.checking import (
    CompiledQuestion,
    PartJob,
    Question,
    SymbolDecl,
    SymbolicQuestion,
    check_answer,
    read_expression,
    read_relation,
    symbol_spec,
)
from physics.errors import PhyscheckError, SpecError
from physics.mathinput import InputLimits, parse_math
from physics.mathinput.limits import DEFAULT_LIMITS
from physics.mathinput.render import in_student_style
from physics.pickling import pickled_by_fields
from physics.symbolic import (
    KnownMistake,
    LimitCase,
    SymbolicContext,
    judge_symbolic,
    make_symbol,
    prepare_reference,
)
from physics.symbolic.tree_reference import TreeDomain, prepared_from_text, tree_domain
from physics.verdict import Outcome, Preview, Reason, Verdict
from physics.wording import symbol_label
from problems.fields import (
    MAX_ITEMS,
    PART_ID,
    Attempts,
    CheckBody,
    Expression,
    LimitDecl,
    MistakeDecl,
    Name,
    RequestText,
    ShortRequestText,
    Strict,
    SymbolDeclBase,
    Text,
)
from problems.kinds.base import (
    ADHOC_PART,
    CheckResult,
    CompileContext,
    LimitInfo,
    MeaningContext,
    MistakeInfo,
    PartInfo,
    Path,
    Reference,
    explain,
)
from problems.modelinfo import missing_quantity
from problems.symbols import read_bound

if TYPE_CHECKING:
    from problems.compiled import CompiledProblem
    from problems.schema import ProblemDocument
    from problems.variants import Variant


class SymbolicPart(Strict):
    id: Annotated[str, Field(pattern=PART_ID, max_length=64)]
    kind: Literal["symbolic"]
    prompt: Text
    quantity: Name | None = None
    answer: Expression | None = None
    symbols: Annotated[list[Name], Field(max_length=MAX_ITEMS)] | None = None
    mistakes: Annotated[list[MistakeDecl], Field(max_length=MAX_ITEMS)] = []
    limits: Annotated[list[LimitDecl], Field(max_length=MAX_ITEMS)] = []
    max_attempts: Attempts | None = None  # graded attempts; None: the problem's

    @property
    def quantity_name(self) -> str:
        """The model quantity this part asks for: `quantity`, else the part's own id."""
        return self.quantity or self.id


class SymbolicCheckIn(CheckBody):
    """An ad-hoc symbolic check: the reference and its symbols, read in the worker like a part's."""

    kind: Literal["symbolic"]
    answer: RequestText
    expected: ShortRequestText
    symbols: dict[Annotated[str, Field(max_length=40)], SymbolDeclBase] = Field(
        default_factory=dict, max_length=50
    )
    constraints: list[ShortRequestText] = Field(default_factory=list, max_length=20)
    mistakes: list[MistakeDecl] = Field(default_factory=list, max_length=50)

    def job(self) -> SymbolicJob:
        return SymbolicJob(
            answer=self.answer,
            expected=self.expected,
            symbols=tuple(spec.decl(name) for name, spec in self.symbols.items()),
            constraints=tuple(self.constraints),
            mistakes=tuple((m.answer, m.feedback) for m in self.mistakes),
        )


@pickled_by_fields
@dataclass(frozen=True)
class SymbolicJob:
    """An ad-hoc symbolic check: the request's texts, compiled in the worker (instructor text is as
    untrusted as a student's) by the kind's own compile, as a one-part problem (`adhoc_part`)."""

    answer: str
    expected: str
    symbols: tuple[SymbolDecl, ...]
    constraints: tuple[str, ...] = ()
    mistakes: tuple[tuple[str, str], ...] = ()  # (expression text, feedback)
    limits_config: InputLimits = field(default_factory=InputLimits)

    def question(self) -> Question:
        if not self.constraints and not self.mistakes:
            found = adhoc_tree_question(self.expected, self.symbols)
            if found is not None:
                return found
        return adhoc_part(self.expected, self.symbols, self.constraints, self.mistakes).compiled


@dataclass(frozen=True)
class AdhocTreeQuestion:
    """An ad-hoc check whose reference was prepared from its parse tree (tree_reference.py): graded
    against it, read as the compiled part reads (which needs only the reference's dimension)."""

    expected: str
    symbols: tuple[SymbolDecl, ...]
    question: SymbolicQuestion  # as CompiledQuestion's

    def grade(self, answer: str, limits: InputLimits) -> Verdict:
        return self.question.grade(answer, limits)

    def read(self, answer: str, limits: InputLimits) -> Preview:
        return adhoc_part(self.expected, self.symbols, (), ()).compiled.read(answer, limits)


@lru_cache(maxsize=256)
def adhoc_tree_question(expected: str, symbols: tuple[SymbolDecl, ...]) -> AdhocTreeQuestion | None:
    """An ad-hoc check without constraints or mistakes with its reference prepared from its parse tree,
    where that gives what compiling and preparing it would (physics.symbolic.tree_reference); else None,
    and `adhoc_part` compiles it (or says what is wrong with it). Cached as adhoc_part is."""
    domain = _adhoc_domain(symbols)
    prepared = None if domain is None else prepared_from_text(expected, domain, DEFAULT_LIMITS)
    if domain is None or prepared is None:
        return None
    return AdhocTreeQuestion(expected, symbols, SymbolicQuestion(domain.names, prepared))


@lru_cache(maxsize=256)
def _adhoc_domain(symbols: tuple[SymbolDecl, ...]) -> TreeDomain | None:
    """The declared symbols as adhoc_part reads them, once per set (a course's references share theirs);
    None where adhoc_part says what is wrong with them."""
    try:
        specs = {decl.name: symbol_spec(decl) for decl in symbols}
        table = {name: make_symbol(spec) for name, spec in specs.items()}
    except PhyscheckError:
        return None
    return tree_domain(table, SymbolicContext(symbols={table[name]: spec for name, spec in specs.items()}))


@lru_cache(maxsize=256)
def adhoc_part(
    expected: str,
    symbols: tuple[SymbolDecl, ...],
    constraints: tuple[str, ...] = (),
    mistakes: tuple[tuple[str, str], ...] = (),
) -> CompiledSymbolicPart:
    """An ad-hoc check as the one part of a problem without a document, compiled as a bank part is (cached:
    a course re-uses its references); SpecError at the body's path."""
    specs = {decl.name: symbol_spec(decl) for decl in symbols}
    table = {name: make_symbol(spec) for name, spec in specs.items()}
    relations = tuple(read_relation(text, table, ("constraints", i)) for i, text in enumerate(constraints))
    # The body was validated as sent; the part is only its other shape (nothing stripped: positions hold).
    part = SymbolicPart.model_construct(
        id=ADHOC_PART,
        kind="symbolic",
        prompt="",
        answer=expected,
        mistakes=[MistakeDecl.model_construct(answer=text, feedback=feedback) for text, feedback in mistakes],
    )
    try:
        return SYMBOLIC.compile(part, (), CompileContext(table, specs, relations))
    except SpecError as error:  # at the body's path: its reference is `expected`, a mistake its index
        path = ("expected",) if error.path == ("answer",) else error.path[:2]
        raise SpecError(error.message, path) from None


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
    def expression(self) -> sympy.Expr:
        return self.compiled.expected

    @property
    def names(self) -> Mapping[str, sympy.Symbol]:
        """What the answer may use."""
        return self.compiled.names

    @property
    def context(self) -> SymbolicContext:
        return self.compiled.context

    @property
    def prepared(self) -> SymbolicQuestion:
        """The prepared reference (sampling the domain once; sympy-heavy, hence lazy and cached)."""
        return self.compiled.question

    def prepare(self) -> None:
        self.prepared.reference.complete()  # sample points, values, mistakes and limits

    def solution(self) -> Reference:
        return Reference(sympy.sstr(self.expected), typeset.latex(self.expected))

    def question(self, variant: Variant | None = None) -> SymbolicQuestion:
        return self.prepared

    @cached_property
    def _payload(self) -> tuple[str, bytes]:
        # Pickled once per part (with the prepared reference when it is already computed): a job then
        # costs the worker a copy of bytes, and the worker unpickles it once per key.
        payload = pickle.dumps(self.compiled, protocol=pickle.HIGHEST_PROTOCOL)
        return hashlib.sha256(payload).hexdigest(), payload

    def job(self, answer: str, variant: Variant | None = None) -> PartJob:
        key, payload = self._payload
        return PartJob(answer, key, payload)

    def __getstate__(self) -> dict[str, object]:
        # The part is pickled whole when a compiled problem is persisted: not its job payload too.
        return {name: value for name, value in self.__dict__.items() if name != "_payload"}


class SymbolicKind:
    def asked_quantities(self, part: SymbolicPart) -> frozenset[str]:
        return frozenset({part.quantity_name})

    name = "symbolic"
    expression_answer = True

    def check_meaning(self, part: SymbolicPart, path: Path, context: MeaningContext) -> None:
        out, doc, table, quantities = context.out, context.doc, context.table, context.quantities
        allowed = dict(table)
        if part.symbols is not None:
            allowed = {}
            for j, name in enumerate(part.symbols):
                if name not in doc.symbols:
                    out.add((*path, "symbols", j), f"{name!r} is not a declared symbol")
                elif name in table:
                    allowed[name] = table[name]
        if part.answer is not None:
            out.attempt(partial(read_expression, part.answer, allowed, (*path, "answer")))
        if quantities is None and part.answer is None:
            out.add(path, "needs an answer (there is no model to derive it from)")
        elif (
            quantities is not None
            and part.quantity_name not in quantities
            and (part.quantity is not None or part.answer is None)  # a named quantity never falls back
        ):
            out.add((*path, "quantity"), missing_quantity(part.quantity_name, quantities))
        for j, mistake in enumerate(part.mistakes):
            out.attempt(partial(read_expression, mistake.answer, table, (*path, "mistakes", j, "answer")))
        for j, limit in enumerate(part.limits):
            for name, value in limit.where.items():
                lpath = (*path, "limits", j, "where", name)
                if name not in doc.symbols:
                    out.add(lpath, f"{name!r} is not a declared symbol")
                else:
                    out.attempt(partial(read_bound, value, lpath))

    def compile(self, part: SymbolicPart, path: Path, context: CompileContext) -> CompiledSymbolicPart:
        table, derived = context.table, context.derived
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
            KnownMistake(read_expression(m.answer, table, (*path, "mistakes", j, "answer")), m.feedback)
            for j, m in enumerate(part.mistakes)
        ]
        limits = [
            LimitCase(
                {
                    table[name]: read_bound(value, (*path, "limits", j, "where", name))
                    for name, value in lim.where.items()
                },
                lim.description,
            )
            for j, lim in enumerate(part.limits)
        ]
        quantity = part.quantity_name
        # The author's mistakes and limits first (their wording wins), then the engine's new ones.
        mistakes += _new_mistakes(mistakes, derived.mistakes.get(quantity, ()) if derived else ())
        limits += _new_limits(limits, derived.limits.get(quantity, ()) if derived else ())
        symbolic_context = SymbolicContext(
            symbols={table[name]: spec for name, spec in context.specs.items()},
            constraints=context.constraints,
            mistakes=tuple(mistakes),
            limits=tuple(limits),
        )
        if hand is not None and derived_expr is not None:
            _require_agreement(hand, derived_expr, symbolic_context, (*path, "answer"))
        return CompiledSymbolicPart(
            part.id,
            quantity,
            CompiledQuestion(names, expected, symbolic_context),
            derived=derived_expr is not None,
        )

    def student_view(self, part: SymbolicPart, doc: ProblemDocument) -> dict[str, Any]:
        names = part.symbols if part.symbols is not None else list(doc.symbols)
        return {"units": None, "symbols": names, "tolerance": None}

    def selftest(
        self, problem: str, part: CompiledSymbolicPart, students: Sequence[Variant]
    ) -> list[CheckResult]:
        """Equivalent rewritings of the reference accepted, every known mistake rejected with its feedback."""
        results: list[CheckResult] = []
        question = part.prepared
        for label, form in equivalent_forms(part.expected).items():
            text, verdict = _grade(form, question)
            ok = verdict.outcome is Outcome.CORRECT
            results.append(
                CheckResult(problem, part.id, f"rewrite {label}", ok, "" if ok else explain(text, verdict))
            )
        for index, mistake in enumerate(part.context.mistakes, start=1):
            text, verdict = _grade(mistake.expr, question)
            ok = (
                verdict.outcome is Outcome.INCORRECT
                and verdict.reason is Reason.KNOWN_MISTAKE
                and mistake.feedback in verdict.feedback
            )
            results.append(
                CheckResult(problem, part.id, f"mistake {index}", ok, "" if ok else explain(text, verdict))
            )
        return results

    def texts(self, part: SymbolicPart, path: str) -> Iterator[tuple[str, str]]:
        for m, mistake in enumerate(part.mistakes):
            yield f"{path}.mistakes[{m}].feedback", mistake.feedback
        for n, limit in enumerate(part.limits):
            yield f"{path}.limits[{n}].description", limit.description

    def describe(
        self, part: CompiledSymbolicPart, info: PartInfo, compiled: CompiledProblem, variant: Variant | None
    ) -> PartInfo:
        written = getattr(compiled.document.part(part.id), "mistakes", ())
        return dataclasses.replace(
            info,
            latex=typeset.latex(part.expected),
            mistakes=tuple(
                described_mistake(m.expr, m.feedback, written, i, compiled.table)
                for i, m in enumerate(part.context.mistakes)
            ),
            limits=tuple(
                LimitInfo(limit_where(case.substitutions), _beyond_where(case))
                for case in part.context.limits
            ),
        )


SYMBOLIC = SymbolicKind()


def described_mistake(
    expr: sympy.Expr,
    feedback: str,
    written: Sequence[Any],
    index: int,
    table: Mapping[str, sympy.Symbol],
) -> MistakeInfo:
    """A known mistake as the author typed it (`r0/2^(1/6)`, read by our own reader and typeset from its
    parse tree), or for one the engine found (after the author's), as sympy writes it."""
    authored = len(written)
    if index < authored:
        try:
            read = parse_math(str(written[index].answer), table).read_as
            return MistakeInfo(read.latex, in_student_style(read.text), feedback, True)
        except PhyscheckError:
            pass
    return MistakeInfo(typeset.latex(expr), typed_text(expr), feedback, index < authored)


def _beyond_where(case: LimitCase) -> str:
    """A limit's description where it says more than its `where`: the engine describes a bare angle's
    limit as `θ → 0`, which the page would show as "θ → 0: θ → 0"."""
    restated = ", ".join(
        f"{symbol_label(symbol.name)} → {'∞' if value == sympy.oo else value}"
        for symbol, value in case.substitutions.items()
    )
    return "" if case.description == restated else case.description


def limit_where(substitutions: Mapping[sympy.Symbol, sympy.Expr]) -> str:
    terms = []
    for symbol, value in substitutions.items():
        arrow = r"\to" if value in (sympy.oo, -sympy.oo) or value == 0 else "="
        terms.append(f"{typeset.latex(symbol)} {arrow} {typeset.latex(value)}")
    return ",\\ ".join(terms)


# ---- compiling ----------------------------------------------------------------------------------


def _new_mistakes(hand: list[KnownMistake], engine: tuple[KnownMistake, ...]) -> list[KnownMistake]:
    """The engine's mistakes that the author has not already described (the author's wording wins)."""
    kept = list(hand)
    for mistake in engine:
        if not any(_same_expression(mistake.expr, other.expr) for other in kept):
            kept.append(mistake)
    return kept[len(hand) :]


def _new_limits(hand: list[LimitCase], engine: tuple[LimitCase, ...]) -> list[LimitCase]:
    """The engine's limiting cases that the author has not already stated."""
    seen = [dict(case.substitutions) for case in hand]
    kept: list[LimitCase] = []
    for case in engine:
        if dict(case.substitutions) not in seen:
            seen.append(dict(case.substitutions))
            kept.append(case)
    return kept


def _same_expression(a: sympy.Expr, b: sympy.Expr) -> bool:
    if a == b:
        return True
    try:
        return bool(sympy.simplify(a - b) == 0)
    except (TypeError, ValueError, NotImplementedError):
        return False


def _require_agreement(hand: sympy.Expr, derived: sympy.Expr, context: SymbolicContext, path: Path) -> None:
    """A hand-typed answer must be equivalent to the engine's derivation, on the problem's domain."""
    if sympy.simplify(hand - derived) == 0:
        return
    bare = SymbolicContext(symbols=context.symbols, constraints=context.constraints)
    judgement = judge_symbolic(hand, prepare_reference(derived, bare))
    if not judgement.correct:
        raise SpecError(f"disagrees with the model, which derives {typed_text(derived)}", path)


# ---- self-test ----------------------------------------------------------------------------------


def equivalent_forms(expr: sympy.Expr) -> dict[str, sympy.Expr]:
    """Equivalent forms of `expr` (label -> form), without repeats."""
    forms: dict[str, sympy.Expr] = {"as derived": expr}
    transforms: dict[str, Callable[[sympy.Expr], sympy.Expr]] = {
        "expand": sympy.expand,
        "factor": sympy.factor,
        "trigsimp": sympy.trigsimp,
        "fu": sympy.fu,
        "together": sympy.together,
        "cancel": sympy.cancel,
        "expand_trig": sympy.expand_trig,
    }
    for label, transform in transforms.items():
        try:
            form = transform(expr)
        except (TypeError, ValueError, NotImplementedError, sympy.PolynomialError):
            continue
        if all(form != other for other in forms.values()):
            forms[label] = form
    return forms


def rewritings(expr: sympy.Expr) -> dict[str, str]:
    """The equivalent forms a student could type, as text the student parser reads (label -> text)."""
    texts: dict[str, str] = {}
    for label, form in equivalent_forms(expr).items():
        text = student_text(form)
        if text is not None and text not in texts.values():
            texts[label] = text
    return texts


def _grade(form: sympy.Expr, question: SymbolicQuestion) -> tuple[str, Verdict]:
    """Grade a form as a student's typed text when one could type it (sympy prints forms such as
    `Piecewise` or `Min` that no student can), else as the tree itself."""
    text = student_text(form)
    if text is not None:
        return text, check_answer(text, question)
    return sympy.sstr(form), Verdict.graded(judge_symbolic(form, question.reference), None)
