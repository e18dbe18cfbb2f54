"""Free-body parts: the student draws the forces on one body of the model (the page's diagram writes
them as `weight 270; normal 110`), graded against the loads the model puts on that body with the
student's own values (`physics.forces_check`)."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Annotated, Any, Literal

import sympy
from pydantic import Field

from physics.checking import QuestionJob
from physics.errors import SpecError
from physics.forces_check import (
    KINDS,
    DrawnForce,
    ExpectedForce,
    ForcesQuestion,
    direction_angle,
    findings_of,
    kind_of_label,
)
from physics.verdict import Outcome
from problems.fields import PART_ID, Attempts, CheckBody, Name, RequestText, Strict, Text
from problems.kinds.base import CheckResult, CompileContext, MeaningContext, PartInfo, Path, Reference
from problems.variants import si_values

if TYPE_CHECKING:
    from problems.compiled import CompiledProblem
    from problems.schema import ProblemDocument
    from problems.variants import Variant

ForceKind = Literal["weight", "normal", "tension", "friction", "spring", "applied", "motion"]


class FreeBodyPart(Strict):
    id: Annotated[str, Field(pattern=PART_ID, max_length=64)]
    kind: Literal["free_body"]
    prompt: Text
    body: Name  # the model's body whose forces are drawn
    tolerance: Annotated[float, Field(ge=1, le=45)] = 10.0  # degrees a direction may be off
    max_attempts: Attempts | None = None


class ForceDecl(Strict):
    kind: ForceKind
    angle: Annotated[float, Field(ge=-360, le=720)]
    label: Annotated[str, Field(max_length=20)] = ""  # its name in feedback, e.g. "N"


class FreeBodyCheckIn(CheckBody):
    """An ad-hoc free-body check: the forces expected (kind and direction), the body's name in words."""

    kind: Literal["free_body"]
    answer: RequestText
    expected: Annotated[list[ForceDecl], Field(min_length=1, max_length=12)]
    body: Annotated[str, Field(max_length=60)] = "the body"
    tolerance: Annotated[float, Field(ge=1, le=45)] = 10.0

    def job(self) -> QuestionJob:
        expected = tuple(ExpectedForce(f.kind, f.angle % 360.0, f.label) for f in self.expected)
        return QuestionJob(self.answer, ForcesQuestion(self.body, expected, self.tolerance))


@dataclass(frozen=True)
class CompiledFreeBodyPart:
    id: str
    body: str
    words: str
    model: Any = dataclasses.field(repr=False)
    document: Any = dataclasses.field(repr=False)
    table: Mapping[str, sympy.Symbol] = dataclasses.field(repr=False)
    tolerance: float = 10.0
    derived: bool = True

    @property
    def expression(self) -> sympy.Expr | None:
        return None

    def prepare(self) -> None:
        return None

    def forces(self, variant: Variant | None) -> tuple[ExpectedForce, ...]:
        """The model's forces on the body, with the student's values (typical ones without a student)."""
        from physics.figures.free_body import body_forces

        drawn = body_forces(self.model, self.body, self.values(variant))
        gravity = self.model.gravity is not None
        return tuple(
            ExpectedForce(
                kind_of_label(f.label, i == 0, gravity), round(direction_angle(f.direction), 1), f.label
            )
            for i, f in enumerate(drawn)
        )

    def values(self, variant: Variant | None) -> dict[str, float]:
        """The given values in SI, the student's (typical ones, mid-range, without a student)."""
        if variant is None:
            given = {name: float(decl.min + decl.max) / 2 for name, decl in self.document.given.items()}
            values = {self.table[n]: v * _unit(self.document, n) for n, v in given.items()}
        else:
            values = si_values(self.document, variant, self.table)
        return {symbol.name: float(value) for symbol, value in values.items()}

    def solution(self) -> Reference:
        text = "; ".join(f"{f.kind} {f.angle:g}" for f in self.forces(None))
        return Reference(text, r"\text{" + text + "}")

    def question(self, variant: Variant | None = None) -> ForcesQuestion:
        return ForcesQuestion(self.words, self.forces(variant), self.tolerance)

    def job(self, answer: str, variant: Variant | None = None) -> QuestionJob:
        return QuestionJob(answer, self.question(variant))


def _unit(doc: Any, name: str) -> float:
    from problems.variants import unit_scale

    return float(unit_scale(doc.given[name].unit))


class FreeBodyKind:
    def asked_quantities(self, part: FreeBodyPart) -> frozenset[str]:
        return frozenset()  # the forces on a body come from the model's loads, not its quantities

    name = "free_body"
    expression_answer = False

    def findings(self, feedback: str) -> tuple[str, ...]:
        """One per force drawn wrong: missing, pointing the wrong way, or not there at all."""
        return findings_of(feedback)

    def check_meaning(self, part: FreeBodyPart, path: Path, context: MeaningContext) -> None:
        if context.quantities is None:
            context.out.add(
                (*path, "kind"), "a free_body part needs the problem's model (its bodies and forces)"
            )

    def compile(self, part: FreeBodyPart, path: Path, context: CompileContext) -> CompiledFreeBodyPart:
        from physics.figures.free_body import across_the_page
        from problems.modelinfo import load_doc_model

        doc = context.doc
        if doc is None or doc.model is None:
            raise SpecError("a free_body part needs the problem's model", (*path, "kind"))
        model = load_doc_model(doc, context.table)
        names = [b.name for b in model.bodies]
        if part.body not in names:
            raise SpecError(
                f"the model has no body {part.body!r}; its bodies are {', '.join(names)}", (*path, "body")
            )
        notation = getattr(context.derived.raw if context.derived else None, "notation", None)
        words = dict(getattr(notation, "bodies", {}) or {}).get(part.body, f"the {part.body}")
        compiled = CompiledFreeBodyPart(part.id, part.body, words, model, doc, context.table, part.tolerance)
        # a body on z is drawn where its forces lie in the page (a conical pendulum's bob at phi = 0)
        across = across_the_page(model, part.body, compiled.values(None))
        if across:
            raise SpecError(
                f"a free-body diagram is drawn in the x–y plane, and {part.body!r} moves along z: {across}, "
                "so its forces would lose their z parts (a body on z is drawn where its forces lie in the "
                "page, as a conical pendulum's bob at phi = 0)",
                (*path, "body"),
            )
        return compiled

    def student_view(self, part: FreeBodyPart, doc: ProblemDocument) -> dict[str, Any]:
        return {
            "units": None,
            "symbols": [],
            "tolerance": None,
            "body": part.body,
            "palette": [{"kind": kind, "words": words} for kind, words in KINDS.items()],
        }

    def selftest(
        self, problem: str, part: CompiledFreeBodyPart, students: Sequence[Variant]
    ) -> list[CheckResult]:
        """Per student: the model's forces accepted; each left out, a "force of motion" added, each
        turned by 45° refused."""
        results: list[CheckResult] = []
        for index, variant in enumerate(students[:3]):
            question = part.question(variant)
            right = [DrawnForce(f.kind, f.angle) for f in question.expected]
            cases: list[tuple[str, list[DrawnForce], bool]] = [("as the model draws them", right, True)]
            cases.append(("with a force of motion", [*right, DrawnForce("motion", 0.0)], False))
            for j, force in enumerate(right):
                cases.append((f"without {force.kind}", right[:j] + right[j + 1 :], False))
                turned = DrawnForce(force.kind, (force.angle + 45) % 360)
                cases.append((f"{force.kind} turned 45°", [*right[:j], turned, *right[j + 1 :]], False))
            for label, drawn, ok_if_right in cases:
                text = "; ".join(f"{d.kind} {d.angle:g}" for d in drawn)
                verdict = question.grade(text)
                ok = (
                    verdict.outcome is Outcome.CORRECT
                ) == ok_if_right and verdict.outcome is not Outcome.INVALID
                results.append(
                    CheckResult(
                        problem, part.id, f"student {index} {label}", ok, "" if ok else verdict.feedback
                    )
                )
        return results

    def texts(self, part: FreeBodyPart, path: str) -> Iterator[tuple[str, str]]:
        return iter(())

    def describe(
        self, part: CompiledFreeBodyPart, info: PartInfo, compiled: CompiledProblem, variant: Variant | None
    ) -> PartInfo:
        forces = part.forces(variant)
        return dataclasses.replace(
            info,
            latex=part.solution().latex,
            expected=part.solution().text,
            facts=tuple((f"{f.kind} ({f.label})", f"{f.angle:g}^\\circ") for f in forces),
        )


FREE_BODY = FreeBodyKind()
