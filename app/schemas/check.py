"""Request and response bodies of `POST /v1/check` (API.md).

A check is a one-part problem given in the request: its symbols, mistakes, tolerance and choices are the
declarations a problem document uses (`problems.fields`, `problems.kinds`), its numbers are read by the
one decimal reader, and its job is what the part's kind compiles to.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import (
    AfterValidator,
    BaseModel,
    ConfigDict,
    Field,
    StrictBool,
    StrictStr,
)

from physics.checking import NumericJob, QuestionJob, SymbolicJob
from physics.choice import MAX_CHOICES
from physics.numeric import NumericSpec
from physics.verdict import Verdict
from problems.fields import DEFAULT_TOLERANCE_DECL, ExactNumber, MistakeDecl, SymbolDeclBase, ToleranceDecl
from problems.kinds.choice import ChoiceDecl, choice_question


def storable(text: str) -> str:
    """Refuse what no database stores (NUL, lone surrogates) here, as a 422, not later as a 500."""
    if "\x00" in text:
        raise ValueError("must not contain a NUL character")
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        raise ValueError("must be valid Unicode text (a lone surrogate was sent)") from None
    return text


Text = Annotated[StrictStr, AfterValidator(storable)]
ShortText = Annotated[Text, Field(max_length=2000)]


class Strict(BaseModel):
    model_config = ConfigDict(extra="forbid")


class SymbolicCheckIn(Strict):
    kind: Literal["symbolic"]
    answer: Text
    expected: ShortText
    symbols: dict[Annotated[str, Field(max_length=40)], SymbolDeclBase] = Field(
        default_factory=dict, max_length=50
    )
    constraints: list[ShortText] = Field(default_factory=list, max_length=20)
    mistakes: list[MistakeDecl] = Field(default_factory=list, max_length=50)

    def job(self) -> SymbolicJob:
        return SymbolicJob(
            answer=self.answer,
            expected=self.expected,
            symbols=tuple(spec.decl(name) for name, spec in self.symbols.items()),
            constraints=tuple(self.constraints),
            mistakes=tuple((m.answer, m.feedback) for m in self.mistakes),
        )


class NumericCheckIn(Strict):
    kind: Literal["numeric"]
    answer: Text
    expected: ExactNumber
    units: ShortText | None = None
    units_required: StrictBool = True
    tolerance: ToleranceDecl | None = None  # absent: DEFAULT_TOLERANCE, as for a part
    arithmetic: StrictBool = True  # the number may be arithmetic (`229/50 m/s^2`); False: a plain decimal
    units_system: Literal["SI"] | None = None  # "SI": refuse answers in ft, lb, atm, …

    def job(self) -> NumericJob:
        spec = NumericSpec(
            expected=self.expected,
            units=self.units,
            units_required=self.units_required,
            tolerance=(self.tolerance or DEFAULT_TOLERANCE_DECL).tolerance(),
            arithmetic=self.arithmetic,
            units_system=self.units_system,
        )
        return NumericJob(answer=self.answer, spec=spec)


class ChoiceCheckIn(Strict):
    """A multiple-choice answer (a letter, or a choice's whole text) against choices given in the request,
    exactly one of them `correct`, as a choice part states them."""

    kind: Literal["choice"]
    answer: Text
    choices: Annotated[list[ChoiceDecl], Field(min_length=2, max_length=MAX_CHOICES)]

    def job(self) -> QuestionJob:
        return QuestionJob(self.answer, choice_question(self.choices, ("choices",)))


CheckIn = Annotated[SymbolicCheckIn | NumericCheckIn | ChoiceCheckIn, Field(discriminator="kind")]


class ReadAsPublic(BaseModel):
    model_config = ConfigDict(from_attributes=True)  # built straight from physics.verdict.ReadAs

    text: str
    latex: str
    # Set when the expected dimension chose between readings (`mv/qB` as m·v/(q·B)); shown to students.
    note: str | None = None


class InputErrorPublic(BaseModel):
    model_config = ConfigDict(from_attributes=True)  # built straight from physics.verdict.InputProblem

    message: str
    position: int | None


class VerdictPublic(BaseModel):
    verdict: Literal["correct", "incorrect", "invalid"]
    score: float
    reason: str
    feedback: str
    read_as: ReadAsPublic | None
    error: InputErrorPublic | None

    @classmethod
    def of(cls, verdict: Verdict) -> VerdictPublic:
        return cls(
            verdict=verdict.outcome.value,
            score=verdict.score,
            reason=verdict.reason.value,
            feedback=verdict.feedback,
            read_as=verdict.read_as,
            error=verdict.error,
        )
