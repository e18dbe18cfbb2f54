"""Lagrangian and energy parts: the student writes L (or T, or V) in the model's coordinates and their
velocities; graded against the model's by its Euler–Lagrange equations (or its derivatives) on the
domain (`physics.lagrangian`). Three kinds, one module: `lagrangian`, `kinetic_energy`,
`potential_energy` (their templates: `lagrangian/`; the other two directories include them)."""

from __future__ import annotations

import dataclasses
import hashlib
import json
import pickle
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from typing import TYPE_CHECKING, Annotated, Any, Literal

import sympy
from pydantic import Field, model_validator

from physics import typeset
from physics.checking import PartJob, SymbolDecl, symbol_spec
from physics.errors import AnswerError, PhyscheckError, SpecError
from physics.lagrangian import (
    Alternative,
    Asked,
    Coordinate,
    EnergyQuestion,
    dotted_latex,
    euler_lagrange,
    standard_alternatives,
    state_dimensions,
    velocity_names,
)
from physics.mathinput import InputLimits, parse_expression
from physics.mathinput.render import latex_name
from physics.pickling import pickled_by_fields
from physics.symbolic import SymbolicContext, SymbolSpec, make_symbol
from physics.verdict import Outcome, Reason
from problems.fields import (
    MAX_ITEMS,
    PART_ID,
    Attempts,
    CheckBody,
    MistakeDecl,
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

if TYPE_CHECKING:
    from problems.compiled import CompiledProblem
    from problems.schema import ProblemDocument
    from problems.variants import Variant


class _EnergyPartBase(Strict):
    id: Annotated[str, Field(pattern=PART_ID, max_length=64)]
    prompt: Text
    # Wrong answers the author expects (in the coordinates and velocities), beside the model's own.
    mistakes: Annotated[list[MistakeDecl], Field(max_length=MAX_ITEMS)] = []
    max_attempts: Attempts | None = None


class LagrangianPart(_EnergyPartBase):
    kind: Literal["lagrangian"]


class KineticEnergyPart(_EnergyPartBase):
    kind: Literal["kinetic_energy"]


class PotentialEnergyPart(_EnergyPartBase):
    kind: Literal["potential_energy"]


EnergyPart = LagrangianPart | KineticEnergyPart | PotentialEnergyPart
CoordinateName = Annotated[str, Field(pattern=r"^[A-Za-z][A-Za-z0-9]{0,19}$")]


class _EnergyCheckInBase(CheckBody):
    """An ad-hoc check of a Lagrangian or an energy: the coordinates, the reference's T and V (typed in
    the coordinates and `<coordinate>_dot` or `x'` for the velocities), the symbols they use."""

    answer: RequestText
    coordinates: Annotated[list[CoordinateName], Field(min_length=1, max_length=6)]
    kinetic: ShortRequestText | None = None
    potential: ShortRequestText | None = None
    symbols: dict[Annotated[str, Field(max_length=40)], SymbolDeclBase] = Field(
        default_factory=dict, max_length=50
    )
    mistakes: list[MistakeDecl] = Field(default_factory=list, max_length=50)

    def job(self) -> EnergyJob:
        return EnergyJob(
            answer=self.answer,
            asked=self._asked(),
            coordinates=tuple(self.coordinates),
            kinetic=self.kinetic,
            potential=self.potential,
            symbols=tuple(spec.decl(name) for name, spec in self.symbols.items()),
            mistakes=tuple((m.answer, m.feedback) for m in self.mistakes),
        )

    def _asked(self) -> Asked:
        return Asked(getattr(self, "kind"))  # noqa: B009 (each subclass declares it)

    @model_validator(mode="after")
    def _references_given(self) -> _EnergyCheckInBase:
        asked = self._asked()
        if asked is not Asked.POTENTIAL and self.kinetic is None:
            raise ValueError("kinetic is required (the reference's kinetic energy)")
        if asked is not Asked.KINETIC and self.potential is None:
            raise ValueError("potential is required (the reference's potential energy)")
        return self


class LagrangianCheckIn(_EnergyCheckInBase):
    kind: Literal["lagrangian"]


class KineticEnergyCheckIn(_EnergyCheckInBase):
    kind: Literal["kinetic_energy"]


class PotentialEnergyCheckIn(_EnergyCheckInBase):
    kind: Literal["potential_energy"]


@pickled_by_fields
@dataclass(frozen=True)
class EnergyJob:
    """An ad-hoc energy check: the request's texts, read in the worker (instructor text is as untrusted
    as a student's)."""

    answer: str
    asked: Asked
    coordinates: tuple[str, ...]
    kinetic: str | None
    potential: str | None
    symbols: tuple[SymbolDecl, ...]
    mistakes: tuple[tuple[str, str], ...] = ()
    limits_config: InputLimits = field(default_factory=InputLimits)

    def question(self) -> EnergyQuestion:
        return adhoc_question(
            self.asked, self.coordinates, self.kinetic, self.potential, self.symbols, self.mistakes
        )


def _read(text: str, names: Mapping[str, sympy.Symbol], path: Path) -> sympy.Expr:
    try:
        return parse_expression(text, names, velocities=True)
    except AnswerError as error:
        raise SpecError.unreadable(error, path) from None


def _state(names: Sequence[str]) -> tuple[tuple[Coordinate, ...], dict[sympy.Symbol, SymbolSpec]]:
    coordinates = tuple(
        Coordinate(
            name,
            sympy.Symbol(name, real=True),
            sympy.Symbol(f"{name}_dot", real=True),
            sympy.Symbol(f"{name}_ddot", real=True),
        )
        for name in names
    )
    specs = {
        s: SymbolSpec(s.name, real=True) for c in coordinates for s in (c.symbol, c.velocity, c.acceleration)
    }
    return coordinates, specs


@lru_cache(maxsize=64)
def adhoc_question(
    asked: Asked,
    coordinate_names: tuple[str, ...],
    kinetic_text: str | None,
    potential_text: str | None,
    symbols: tuple[SymbolDecl, ...],
    mistakes: tuple[tuple[str, str], ...] = (),
) -> EnergyQuestion:
    """The question of an ad-hoc check (cached: a course re-uses its references); SpecError at the body's
    path."""
    specs = {decl.name: symbol_spec(decl) for decl in symbols}
    table = {name: make_symbol(spec) for name, spec in specs.items()}
    clash = sorted(set(coordinate_names) & set(table))
    if clash:
        raise SpecError(f"{clash[0]!r} is both a coordinate and a symbol", ("coordinates",))
    coordinates, state = _state(coordinate_names)
    names = {**table, **velocity_names(coordinates)}
    kinetic = _read(kinetic_text, names, ("kinetic",)) if kinetic_text is not None else sympy.Integer(0)
    potential = (
        _read(potential_text, names, ("potential",)) if potential_text is not None else sympy.Integer(0)
    )
    authored = tuple(
        Alternative(_read(text, names, ("mistakes", j, "answer")), feedback)
        for j, (text, feedback) in enumerate(mistakes)
    )
    return _question(
        asked, names, coordinates, kinetic, potential, table, specs, state, authored, ()
    ).prepare()


def _expected(asked: Asked, kinetic: sympy.Expr, potential: sympy.Expr) -> sympy.Expr:
    if asked is Asked.LAGRANGIAN:
        return kinetic - potential
    return kinetic if asked is Asked.KINETIC else potential


def _question(
    asked: Asked,
    names: Mapping[str, sympy.Symbol],
    coordinates: tuple[Coordinate, ...],
    kinetic: sympy.Expr,
    potential: sympy.Expr,
    table: Mapping[str, sympy.Symbol],
    specs: Mapping[str, SymbolSpec],
    state: Mapping[sympy.Symbol, SymbolSpec],
    authored: tuple[Alternative, ...],
    terms: tuple[tuple[str, sympy.Expr], ...],
    constraints: tuple[sympy.Basic, ...] = (),
) -> EnergyQuestion:
    expected = _expected(asked, kinetic, potential)
    if expected == 0 or not expected.has(*(s for c in coordinates for s in (c.symbol, c.velocity))):
        raise SpecError(f"the model's {asked.value.replace('_', ' ')} does not depend on the coordinates", ())
    context = SymbolicContext(
        symbols={**{table[name]: spec for name, spec in specs.items() if name in table}, **state},
        constraints=constraints,
    )
    alternatives = authored + standard_alternatives(asked, kinetic, potential, coordinates, terms)
    known = {table[name]: spec.dimension for name, spec in specs.items() if name in table and spec.dimension}
    dimensions = (
        state_dimensions(kinetic - potential, coordinates, known) if len(known) == len(table) else None
    )
    return EnergyQuestion(asked, dict(names), coordinates, expected, context, alternatives, dimensions)


@dataclass(frozen=True)
class CompiledEnergyPart:
    id: str
    kind: str
    prepared: EnergyQuestion
    kinetic: sympy.Expr
    potential: sympy.Expr
    authored: int = 0  # how many of the alternatives the author wrote (the first ones)
    derived: bool = True  # the reference is the engine's T and V of the model

    @property
    def expression(self) -> sympy.Expr | None:
        return None  # not an expression a numeric part could evaluate (it has velocities)

    def prepare(self) -> None:
        self.prepared.prepare()

    def solution(self) -> Reference:
        question = self.prepared
        primes = {c.velocity: sympy.Symbol(f"{c.name}'") for c in question.coordinates}
        return Reference(
            sympy.sstr(question.expected.xreplace(primes)),
            dotted_latex(question.expected, question.coordinates),
        )

    def question(self, variant: Variant | None = None) -> EnergyQuestion:
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


class EnergyKind:
    def asked_quantities(self, part: _EnergyPartBase) -> frozenset[str]:
        return frozenset()  # the energies come from the model's bodies, not its quantities

    expression_answer = False

    def __init__(self, asked: Asked) -> None:
        self.asked = asked
        self.name = asked.value

    def findings(self, feedback: str) -> tuple[str, ...]:
        """An incorrect energy says one thing: the term missing, the sign, the equation that fails."""
        return (feedback.strip(),) if feedback.strip() else ()

    def check_meaning(self, part: EnergyPart, path: Path, context: MeaningContext) -> None:
        if context.quantities is None:
            context.out.add(
                (*path, "kind"),
                f"a {self.name} part needs the problem's model (its coordinates, kinetic and potential energy)",
            )

    def compile(self, part: EnergyPart, path: Path, context: CompileContext) -> CompiledEnergyPart:
        from problems.energies import model_energies  # the engine's mechanics, only where a model is

        doc = context.doc
        if doc is None or doc.model is None:
            raise SpecError(f"a {self.name} part needs the problem's model", (*path, "kind"))
        energies = model_energies(doc, context.table, context.derived.raw if context.derived else None)
        coordinates = energies.coordinates
        names = {**context.table, **velocity_names(coordinates)}
        authored = tuple(
            Alternative(_read(m.answer, names, (*path, "mistakes", j, "answer")), m.feedback)
            for j, m in enumerate(part.mistakes)
        )
        try:
            question = _question(
                self.asked,
                names,
                coordinates,
                energies.kinetic,
                energies.potential,
                context.table,
                context.specs,
                energies.specs,
                authored,
                energies.terms,
                context.constraints,
            )
        except SpecError as error:
            raise SpecError(error.message, (*path, *error.path)) from None
        return CompiledEnergyPart(
            part.id, self.name, question, energies.kinetic, energies.potential, authored=len(authored)
        )

    def student_view(self, part: EnergyPart, doc: ProblemDocument) -> dict[str, Any]:
        return {
            "units": None,
            "symbols": list(doc.symbols),
            "tolerance": None,
            "coordinates": coordinate_rows(doc),
        }

    def selftest(
        self, problem: str, part: CompiledEnergyPart, students: Sequence[Variant]
    ) -> list[CheckResult]:
        """The reference accepted (as typed, with x' for velocities; for a Lagrangian also doubled and
        with a total time derivative added), every known wrong answer rejected with its feedback."""
        question = part.prepared
        results: list[CheckResult] = []
        primes = {c.velocity: sympy.Symbol(f"{c.name}'") for c in question.coordinates}
        typed = sympy.sstr(question.expected.xreplace(primes))
        verdict = question.grade(typed, InputLimits())
        results.append(
            CheckResult(
                problem,
                part.id,
                "reference as typed",
                verdict.outcome is Outcome.CORRECT,
                "" if verdict.outcome is Outcome.CORRECT else f"{typed!r}: {verdict.feedback}",
            )
        )
        if self.asked is Asked.LAGRANGIAN:
            first = question.coordinates[0]
            # d/dt(q²/2) is no energy: judged as equations of motion alone, without the dimension check
            unchecked = dataclasses.replace(question, dimensions=None)
            for label, form, judged in (
                ("doubled", 2 * question.expected, question),
                (
                    "plus a total time derivative",
                    question.expected + first.symbol * first.velocity,
                    unchecked,
                ),
            ):
                judgement = judged.judge(form)
                results.append(
                    CheckResult(
                        problem,
                        part.id,
                        label,
                        judgement.correct,
                        "" if judgement.correct else judgement.feedback,
                    )
                )
        for index, alternative in enumerate(question.alternatives, start=1):
            judgement = question.judge(alternative.expr)
            ok = not judgement.correct and judgement.reason is Reason.KNOWN_MISTAKE
            results.append(
                CheckResult(
                    problem,
                    part.id,
                    f"mistake {index}",
                    ok,
                    "" if ok else f"{sympy.sstr(alternative.expr)} was judged: {judgement.feedback}",
                )
            )
        return results

    def texts(self, part: EnergyPart, path: str) -> Iterator[tuple[str, str]]:
        for m, mistake in enumerate(part.mistakes):
            yield f"{path}.mistakes[{m}].feedback", mistake.feedback

    def describe(
        self, part: CompiledEnergyPart, info: PartInfo, compiled: CompiledProblem, variant: Variant | None
    ) -> PartInfo:
        question = part.prepared
        coordinates = question.coordinates
        facts: list[tuple[str, str]] = []
        if self.asked is Asked.LAGRANGIAN:
            accelerations = {c.acceleration: rf"\ddot{{{typeset.latex(c.symbol)}}}" for c in coordinates}
            facts.append(("Kinetic energy", "T = " + dotted_latex(part.kinetic, coordinates)))
            facts.append(("Potential energy", "V = " + dotted_latex(part.potential, coordinates)))
            for c, equation in zip(coordinates, euler_lagrange(question.expected, coordinates), strict=True):
                tidy = sympy.collect(sympy.expand(equation), [a.acceleration for a in coordinates])
                names = {c2.velocity: rf"\dot{{{typeset.latex(c2.symbol)}}}" for c2 in coordinates}
                facts.append(
                    (
                        f"Lagrange's equation for {c.name}",
                        typeset.latex(sympy.Eq(tidy, 0), symbol_names={**names, **accelerations}),
                    )
                )
        return dataclasses.replace(
            info,
            latex=dotted_latex(question.expected, coordinates),
            facts=tuple(facts),
            mistakes=tuple(
                MistakeInfo(
                    dotted_latex(alt.expr, coordinates), sympy.sstr(alt.expr), alt.feedback, i < part.authored
                )
                for i, alt in enumerate(question.alternatives)
            ),
        )


def coordinate_rows(doc: ProblemDocument) -> list[dict[str, str]]:
    """The model's coordinates as a student types them, with their velocities and what each measures
    (loading a model is ~10 ms: kept per model and symbols, as every student view of a part asks)."""
    key = json.dumps(
        [doc.model, {n: d.model_dump(mode="json") for n, d in doc.symbols.items()}], sort_keys=True
    )
    return [dict(row) for row in _coordinate_rows(key, doc)]


_ROWS: dict[str, tuple[dict[str, str], ...]] = {}


def _coordinate_rows(key: str, doc: ProblemDocument) -> tuple[dict[str, str], ...]:
    found = _ROWS.get(key)
    if found is None:
        found = _ROWS[key] = tuple(_rows(doc))
        while len(_ROWS) > 256:
            _ROWS.pop(next(iter(_ROWS)))
    return found


def _rows(doc: ProblemDocument) -> list[dict[str, str]]:
    from problems.modelinfo import load_doc_model
    from problems.symbols import symbol_table

    try:
        model = load_doc_model(doc, symbol_table(doc))
    except PhyscheckError:
        return []
    said = doc.model.get("notation", {}) if isinstance(doc.model, Mapping) else {}
    rows = []
    for c in model.coordinates:
        entry = said.get(c.name) if isinstance(said, Mapping) else None
        says = entry.get("says", "") if isinstance(entry, Mapping) else ""
        rows.append(
            {
                "name": c.name,
                "latex": latex_name(c.name),
                "velocity": f"{c.name}'",
                "velocity_latex": rf"\dot{{{latex_name(c.name)}}}",
                "meaning": str(says or ""),
            }
        )
    return rows


LAGRANGIAN = EnergyKind(Asked.LAGRANGIAN)
KINETIC_ENERGY = EnergyKind(Asked.KINETIC)
POTENTIAL_ENERGY = EnergyKind(Asked.POTENTIAL)
