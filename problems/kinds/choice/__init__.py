"""Multiple-choice parts: a conceptual question (which way does friction act, which quantity is
conserved) answered by the letter of one of the stated choices; exactly one is right."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Annotated, Any, Literal

import sympy
from pydantic import Field, StrictBool

from physics.checking import QuestionJob
from physics.choice import MAX_CHOICES, Choice, ChoiceQuestion, label
from physics.errors import SpecError
from physics.verdict import Outcome, Reason
from problems.fields import PART_ID, Attempts, CheckBody, RequestText, Strict, Text
from problems.kinds.base import (
    ADHOC_PART,
    CheckResult,
    CompileContext,
    MeaningContext,
    MistakeInfo,
    PartInfo,
    Path,
    Reference,
    explain,
)

if TYPE_CHECKING:
    from problems.compiled import CompiledProblem
    from problems.schema import ProblemDocument
    from problems.variants import Variant


class ChoiceDecl(Strict):
    """One choice as an author states it, in a choice part or in a `POST /v1/check` of kind choice."""

    text: Text
    correct: StrictBool = False
    feedback: Text | None = None  # shown to a student who picks this (wrong) choice


class ChoicePart(Strict):
    id: Annotated[str, Field(pattern=PART_ID, max_length=64)]
    kind: Literal["choice"]
    prompt: Text
    choices: Annotated[list[ChoiceDecl], Field(min_length=2, max_length=MAX_CHOICES)]
    max_attempts: Attempts | None = None


class ChoiceCheckIn(CheckBody):
    """An ad-hoc choice check: the answer (a letter, or a choice's whole text) against the choices a part
    would state, exactly one of them `correct`."""

    kind: Literal["choice"]
    answer: RequestText
    choices: Annotated[list[ChoiceDecl], Field(min_length=2, max_length=MAX_CHOICES)]

    def job(self) -> QuestionJob:
        # A one-part problem without a document, compiled as a bank part is (its faults at `choices`).
        part = ChoicePart.model_construct(id=ADHOC_PART, kind="choice", prompt="", choices=self.choices)
        return CHOICE.compile(part, (), CompileContext({}, {}, ())).job(self.answer)


@dataclass(frozen=True)
class CompiledChoicePart:
    id: str
    multiple: ChoiceQuestion
    derived: bool = False  # the author states the right choice: there is nothing to derive

    @property
    def expression(self) -> sympy.Expr | None:
        return None

    def prepare(self) -> None:
        return None  # nothing is computed lazily

    def solution(self) -> Reference:
        right = self.multiple.correct
        return Reference(f"{label(right)}: {self.multiple.choices[right].text}", rf"\text{{{label(right)}}}")

    def question(self, variant: Variant | None = None) -> ChoiceQuestion:
        return self.multiple

    def job(self, answer: str, variant: Variant | None = None) -> QuestionJob:
        return QuestionJob(answer, self.multiple)


class ChoiceKind:
    def asked_quantities(self, part: ChoicePart) -> frozenset[str]:
        return frozenset()

    name = "choice"
    expression_answer = False

    def check_meaning(self, part: ChoicePart, path: Path, context: MeaningContext) -> None:
        right = [j for j, choice in enumerate(part.choices) if choice.correct]
        if len(right) != 1:
            context.out.add((*path, "choices"), f"mark exactly one choice correct: true ({len(right)} are)")
        seen: dict[str, int] = {}
        for j, choice in enumerate(part.choices):
            plain = " ".join(choice.text.split()).casefold()
            if plain in seen:
                context.out.add(
                    (*path, "choices", j, "text"),
                    f"the same text as choices[{seen[plain]}]: students could not tell them apart",
                )
            seen.setdefault(plain, j)
            if choice.correct and choice.feedback is not None:
                context.out.add(
                    (*path, "choices", j, "feedback"),
                    "feedback is for wrong choices; the right one is told 'Correct.'",
                )

    def compile(self, part: ChoicePart, path: Path, context: CompileContext) -> CompiledChoicePart:
        right = [j for j, choice in enumerate(part.choices) if choice.correct]
        if len(right) != 1:
            raise SpecError(f"mark exactly one choice correct: true ({len(right)} are)", (*path, "choices"))
        choices = tuple(Choice(choice.text, choice.feedback) for choice in part.choices)
        return CompiledChoicePart(part.id, ChoiceQuestion(choices, right[0]))

    def student_view(self, part: ChoicePart, doc: ProblemDocument) -> dict[str, Any]:
        choices = [{"label": label(j), "text": choice.text} for j, choice in enumerate(part.choices)]
        return {"units": None, "symbols": [], "tolerance": None, "choices": choices}

    def selftest(
        self, problem: str, part: CompiledChoicePart, students: Sequence[Variant]
    ) -> list[CheckResult]:
        """The right choice accepted (by letter and by text), every other rejected with its feedback, and a
        letter beyond the choices unreadable."""
        question = part.multiple
        results = []
        right = question.choices[question.correct]
        for j, choice in enumerate(question.choices):
            verdict = question.grade(label(j))
            if j == question.correct:
                ok = verdict.outcome is Outcome.CORRECT
            else:
                wanted = Reason.WRONG_VALUE if choice.feedback is None else Reason.KNOWN_MISTAKE
                ok = verdict.outcome is Outcome.INCORRECT and verdict.reason is wanted
            results.append(
                CheckResult(
                    problem, part.id, f"choice {label(j)}", ok, "" if ok else explain(label(j), verdict)
                )
            )
        by_text = question.grade(right.text)
        ok = by_text.outcome is Outcome.CORRECT
        results.append(
            CheckResult(
                problem, part.id, "right choice by its text", ok, "" if ok else explain(right.text, by_text)
            )
        )
        beyond = label(len(question.choices)) if len(question.choices) < MAX_CHOICES else "?"
        unreadable = question.grade(beyond)
        ok = unreadable.outcome is Outcome.INVALID
        results.append(
            CheckResult(problem, part.id, "no such choice", ok, "" if ok else explain(beyond, unreadable))
        )
        return results

    def texts(self, part: ChoicePart, path: str) -> Iterator[tuple[str, str]]:
        for j, choice in enumerate(part.choices):
            yield f"{path}.choices[{j}].text", choice.text
            if choice.feedback is not None:
                yield f"{path}.choices[{j}].feedback", choice.feedback

    def describe(
        self, part: CompiledChoicePart, info: PartInfo, compiled: CompiledProblem, variant: Variant | None
    ) -> PartInfo:
        return dataclasses.replace(
            info,
            latex=part.solution().latex,
            expected=part.solution().text,
            mistakes=tuple(
                MistakeInfo(rf"\text{{{label(j)}}}", label(j), choice.feedback, True)
                for j, choice in enumerate(part.multiple.choices)
                if choice.feedback is not None
            ),
        )


CHOICE = ChoiceKind()
