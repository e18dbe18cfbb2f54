"""Equation parts: "Newton's second law for the block along the incline", "the rolling constraint". The
part names the unknowns a student may use (N, T, a …, each with the model quantity that gives its value
where there is one) and states the asked equation; graded by `physics.equation` (the difference of the
sides a nonzero multiple of the asked equation's, on the domain)."""

from __future__ import annotations

import dataclasses
import hashlib
import pickle
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from typing import TYPE_CHECKING, Annotated, Any, Literal

import numpy as np
import sympy
from pydantic import Field

from physics import typeset
from physics.checking import PartJob, SymbolDecl, symbol_spec
from physics.equation import EquationQuestion, Unknown, WrongEquation, read_equation, standard_wrong
from physics.errors import AnswerError, SpecError
from physics.mathinput import InputLimits
from physics.mathinput.render import latex_name
from physics.pickling import pickled_by_fields
from physics.proportional import close
from physics.symbolic import SymbolicContext, SymbolSpec, make_symbol
from physics.verdict import Outcome, Reason
from problems.fields import (
    MAX_ITEMS,
    PART_ID,
    Attempts,
    CheckBody,
    MistakeDecl,
    Name,
    RequestText,
    ShortRequestText,
    Strict,
    SymbolDeclBase,
    Text,
)
from problems.kinds.base import (
    CheckResult,
    CompileContext,
    MeaningContext,
    MistakeInfo,
    PartInfo,
    Path,
    Reference,
)
from problems.modelinfo import missing_quantity

if TYPE_CHECKING:
    from problems.compiled import CompiledProblem
    from problems.schema import ProblemDocument
    from problems.variants import Variant

UnknownName = Annotated[str, Field(pattern=r"^[A-Za-z][A-Za-z0-9_]{0,19}$")]
EquationText = Annotated[str, Field(min_length=3, max_length=2000)]


class UnknownDecl(Strict):
    meaning: Text
    quantity: Name | None = None  # the model quantity that is its value (the check that the equation holds)


class EquationPart(Strict):
    id: Annotated[str, Field(pattern=PART_ID, max_length=64)]
    kind: Literal["equation"]
    prompt: Text
    asks: Text | None = None  # the equation asked for, in words ("Newton's second law for the block …")
    unknowns: Annotated[dict[UnknownName, UnknownDecl], Field(max_length=12)] = {}
    equation: EquationText  # the asked equation, `lhs = rhs`, in the symbols and the unknowns
    mistakes: Annotated[list[MistakeDecl], Field(max_length=MAX_ITEMS)] = []  # each answer an equation
    max_attempts: Attempts | None = None


class EquationCheckIn(CheckBody):
    """An ad-hoc equation check: the asked equation, the unknowns a student may use, the symbols."""

    kind: Literal["equation"]
    answer: RequestText
    expected: ShortRequestText
    unknowns: dict[UnknownName, Annotated[str, Field(max_length=300)]] = Field(
        default_factory=dict, max_length=12
    )
    symbols: dict[Annotated[str, Field(max_length=40)], SymbolDeclBase] = Field(
        default_factory=dict, max_length=50
    )
    mistakes: list[MistakeDecl] = Field(default_factory=list, max_length=50)

    def job(self) -> EquationJob:
        return EquationJob(
            answer=self.answer,
            expected=self.expected,
            unknowns=tuple(self.unknowns.items()),
            symbols=tuple(spec.decl(name) for name, spec in self.symbols.items()),
            mistakes=tuple((m.answer, m.feedback) for m in self.mistakes),
        )


@pickled_by_fields
@dataclass(frozen=True)
class EquationJob:
    """An ad-hoc equation check, its texts read in the worker."""

    answer: str
    expected: str
    unknowns: tuple[tuple[str, str], ...]  # (name, meaning)
    symbols: tuple[SymbolDecl, ...]
    mistakes: tuple[tuple[str, str], ...] = ()
    limits_config: InputLimits = field(default_factory=InputLimits)

    def question(self) -> EquationQuestion:
        return adhoc_question(self.expected, self.unknowns, self.symbols, self.mistakes)


def _read(text: str, names: Mapping[str, sympy.Symbol], path: Path) -> tuple[sympy.Expr, sympy.Expr]:
    try:
        read = read_equation(text, names)
    except AnswerError as error:
        raise SpecError.unreadable(error, path) from None
    return read.lhs, read.rhs


def _unknown_symbols(
    names: Sequence[str], table: Mapping[str, sympy.Symbol], path: Path
) -> dict[str, sympy.Symbol]:
    for name in names:
        if name in table:
            raise SpecError(f"{name!r} is both an unknown and a symbol of the problem", (*path, name))
    return {name: sympy.Symbol(name, real=True) for name in names}


def _build(
    equation: str,
    unknowns: tuple[Unknown, ...],
    table: Mapping[str, sympy.Symbol],
    specs: Mapping[str, SymbolSpec],
    mistakes: Sequence[tuple[str, str]],
    path: Path,
    asks: str = "",
    constraints: tuple[sympy.Basic, ...] = (),
) -> tuple[EquationQuestion, int]:
    names = {**table, **{u.name: u.symbol for u in unknowns}}
    lhs, rhs = _read(equation, names, (*path, "equation"))
    if not (lhs - rhs).has(*(u.symbol for u in unknowns)):
        raise SpecError(
            "the equation uses none of the unknowns: name them under unknowns", (*path, "equation")
        )
    authored = tuple(
        WrongEquation(_difference(text, names, (*path, "mistakes", j, "answer")), feedback)
        for j, (text, feedback) in enumerate(mistakes)
    )
    context = SymbolicContext(
        symbols={
            **{table[name]: spec for name, spec in specs.items() if name in table},
            **{u.symbol: SymbolSpec(u.name, real=True) for u in unknowns},
        },
        constraints=constraints,
    )
    question = EquationQuestion(
        names, unknowns, lhs, rhs, context, authored + standard_wrong(lhs, rhs, unknowns), asks
    )
    return question, len(authored)


def _difference(text: str, names: Mapping[str, sympy.Symbol], path: Path) -> sympy.Expr:
    lhs, rhs = _read(text, names, path)
    return sympy.expand(lhs - rhs)


@lru_cache(maxsize=64)
def adhoc_question(
    expected: str,
    unknowns: tuple[tuple[str, str], ...],
    symbols: tuple[SymbolDecl, ...],
    mistakes: tuple[tuple[str, str], ...] = (),
) -> EquationQuestion:
    specs = {decl.name: symbol_spec(decl) for decl in symbols}
    table = {name: make_symbol(spec) for name, spec in specs.items()}
    made = _unknown_symbols([name for name, _ in unknowns], table, ("unknowns",))
    declared = tuple(Unknown(name, made[name], meaning) for name, meaning in unknowns)
    try:
        question, _ = _build(expected, declared, table, specs, mistakes, ())
    except SpecError as error:  # the body's reference is `expected`, a part's `equation`
        path = tuple("expected" if step == "equation" else step for step in error.path)
        raise SpecError(error.message, path) from None
    return question.prepare()


@dataclass(frozen=True)
class CompiledEquationPart:
    id: str
    prepared: EquationQuestion
    authored: int = 0
    derived: bool = False  # True: the model's values of the unknowns confirm that the equation holds

    @property
    def expression(self) -> sympy.Expr | None:
        return None

    def prepare(self) -> None:
        self.prepared.prepare()

    def solution(self) -> Reference:
        q = self.prepared
        return Reference(
            f"{sympy.sstr(q.lhs)} = {sympy.sstr(q.rhs)}",
            typeset.latex(sympy.Eq(q.lhs, q.rhs, evaluate=False)),
        )

    def question(self, variant: Variant | None = None) -> EquationQuestion:
        return self.prepared

    @cached_property
    def _payload(self) -> tuple[str, bytes]:
        payload = pickle.dumps(self.prepared.prepare(), protocol=pickle.HIGHEST_PROTOCOL)
        return hashlib.sha256(payload).hexdigest(), payload

    def job(self, answer: str, variant: Variant | None = None) -> PartJob:
        key, payload = self._payload
        return PartJob(answer, key, payload)

    def __getstate__(self) -> dict[str, object]:
        return {name: value for name, value in self.__dict__.items() if name != "_payload"}


def _holds(question: EquationQuestion) -> bool | None:
    """Whether the asked equation holds with the model's values of the unknowns (None: not all known)."""
    values = {u.symbol: u.value for u in question.unknowns if u.value is not None}
    if len(values) < len(question.unknowns):
        return None
    left = question.sample.values(question.lhs.xreplace(values))
    right = question.sample.values(question.rhs.xreplace(values))
    scale = float(np.nanmedian(np.abs(left))) if np.isfinite(left).any() else 1.0
    return bool(np.all(close(left, right, scale)))


class EquationKind:
    def asked_quantities(self, part: EquationPart) -> frozenset[str]:
        return frozenset(u.quantity for u in part.unknowns.values() if u.quantity is not None)

    name = "equation"
    expression_answer = False

    def check_meaning(self, part: EquationPart, path: Path, context: MeaningContext) -> None:
        for name, unknown in part.unknowns.items():
            if name in context.table:
                context.out.add(
                    (*path, "unknowns", name), f"{name!r} is both an unknown and a symbol of the problem"
                )
            if unknown.quantity is not None and (
                context.quantities is None or unknown.quantity not in context.quantities
            ):
                context.out.add(
                    (*path, "unknowns", name, "quantity"),
                    missing_quantity(unknown.quantity, context.quantities or ()),
                )

    def compile(self, part: EquationPart, path: Path, context: CompileContext) -> CompiledEquationPart:
        made = _unknown_symbols(list(part.unknowns), context.table, (*path, "unknowns"))
        unknowns: list[Unknown] = []
        for name, decl in part.unknowns.items():
            value = None
            if decl.quantity is not None:
                quantities = context.derived.quantities if context.derived is not None else {}
                if decl.quantity not in quantities:
                    raise SpecError(
                        missing_quantity(decl.quantity, quantities), (*path, "unknowns", name, "quantity")
                    )
                value = quantities[decl.quantity]
            unknowns.append(Unknown(name, made[name], decl.meaning, value))
        question, authored = _build(
            part.equation,
            tuple(unknowns),
            context.table,
            context.specs,
            [(m.answer, m.feedback) for m in part.mistakes],
            path,
            part.asks or "",
            context.constraints,
        )
        holds = _holds(question)
        if holds is False:
            raise SpecError(
                "the equation does not hold with the model's values of the unknowns: check each term's sign "
                "and the unknowns' quantities",
                (*path, "equation"),
            )
        return CompiledEquationPart(part.id, question, authored, derived=holds is True)

    def student_view(self, part: EquationPart, doc: ProblemDocument) -> dict[str, Any]:
        unknowns = [
            {"name": name, "latex": latex_name(name), "meaning": decl.meaning}
            for name, decl in part.unknowns.items()
        ]
        return {
            "units": None,
            "symbols": list(doc.symbols),
            "tolerance": None,
            "unknowns": unknowns,
            "asks": part.asks,
        }

    def selftest(
        self, problem: str, part: CompiledEquationPart, students: Sequence[Variant]
    ) -> list[CheckResult]:
        """The asked equation accepted as typed, with its sides swapped and doubled; each known wrong
        version rejected with its feedback."""
        question = part.prepared
        results: list[CheckResult] = []
        typed = f"{sympy.sstr(question.lhs)} = {sympy.sstr(question.rhs)}"
        for label, text in (
            ("as stated", typed),
            ("sides swapped", f"{sympy.sstr(question.rhs)} = {sympy.sstr(question.lhs)}"),
            ("doubled", f"2*({sympy.sstr(question.lhs)}) = 2*({sympy.sstr(question.rhs)})"),
        ):
            verdict = question.grade(text, InputLimits())
            ok = verdict.outcome is Outcome.CORRECT
            results.append(
                CheckResult(problem, part.id, label, ok, "" if ok else f"{text!r}: {verdict.feedback}")
            )
        for index, wrong in enumerate(question.wrong, start=1):
            judgement = question.judge(wrong.difference, sympy.Integer(0))
            ok = not judgement.correct and judgement.reason is Reason.KNOWN_MISTAKE
            results.append(
                CheckResult(problem, part.id, f"mistake {index}", ok, "" if ok else judgement.feedback)
            )
        return results

    def texts(self, part: EquationPart, path: str) -> Iterator[tuple[str, str]]:
        if part.asks is not None:
            yield f"{path}.asks", part.asks
        for name, unknown in part.unknowns.items():
            yield f"{path}.unknowns.{name}.meaning", unknown.meaning
        for m, mistake in enumerate(part.mistakes):
            yield f"{path}.mistakes[{m}].feedback", mistake.feedback

    def describe(
        self, part: CompiledEquationPart, info: PartInfo, compiled: CompiledProblem, variant: Variant | None
    ) -> PartInfo:
        question = part.prepared
        facts = tuple(
            (f"{u.name}: {u.meaning}", typeset.latex(u.symbol) + " = " + typeset.latex(u.value))
            for u in question.unknowns
            if u.value is not None
        )
        return dataclasses.replace(
            info,
            latex=part.solution().latex,
            facts=facts,
            mistakes=tuple(
                MistakeInfo(
                    typeset.latex(sympy.Eq(w.difference, 0)),
                    f"{sympy.sstr(w.difference)} = 0",
                    w.feedback,
                    i < part.authored,
                )
                for i, w in enumerate(question.wrong)
            ),
        )


EQUATION = EquationKind()
