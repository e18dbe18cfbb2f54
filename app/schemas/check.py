"""Request and response bodies of `POST /v1/check` (API.md)."""

from __future__ import annotations

import re
from decimal import Decimal, InvalidOperation
from typing import Annotated, Literal

from pydantic import (
    AfterValidator,
    BaseModel,
    ConfigDict,
    Field,
    StrictBool,
    StrictFloat,
    StrictInt,
    StrictStr,
    field_validator,
)

from physics.checking import NumericJob, SymbolDecl, SymbolicJob
from physics.numeric import DEFAULT_TOLERANCE, NumericSpec, Tolerance
from physics.verdict import Verdict

Number = StrictInt | StrictFloat


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


_DECIMAL = re.compile(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?")


def exact_decimal(value: Number | str) -> Decimal:
    """JSON numbers arrive as floats; their shortest repr is the decimal the client wrote."""
    if isinstance(value, str) and not _DECIMAL.fullmatch(value.strip()):
        # Decimal() alone would also take "4_58" (as 458), "NaN" and "Infinity".
        raise ValueError(f"not a decimal number: {value!r}")
    try:
        result = Decimal(value if isinstance(value, str) else repr(value))
    except InvalidOperation:
        raise ValueError(f"not a decimal number: {value!r}") from None
    if not result.is_finite():
        raise ValueError("must be a finite number")
    return result


def _bound_text(bound: Number | str) -> str:
    return bound if isinstance(bound, str) else repr(bound)


class Strict(BaseModel):
    model_config = ConfigDict(extra="forbid")


class SymbolIn(Strict):
    dimension: ShortText | None = None
    real: StrictBool = False
    nonzero: StrictBool = False
    negative: StrictBool = False
    integer: StrictBool = False
    range: tuple[Number | ShortText, Number | ShortText] | None = None
    meaning: ShortText | None = None

    def decl(self, name: str) -> SymbolDecl:
        bounds = None if self.range is None else (_bound_text(self.range[0]), _bound_text(self.range[1]))
        return SymbolDecl(
            name=name,
            dimension=self.dimension,
            real=self.real,
            nonzero=self.nonzero,
            negative=self.negative,
            integer=self.integer,
            range=bounds,
        )


class MistakeIn(Strict):
    answer: ShortText
    feedback: ShortText


class ToleranceIn(Strict):
    rel: Number | StrictStr | None = None
    abs: Number | StrictStr | None = None
    sigfigs: Annotated[StrictInt, Field(ge=1, le=15)] | None = None

    @field_validator("rel", "abs")
    @classmethod
    def non_negative(cls, value: Number | str | None) -> Number | str | None:
        if value is not None and exact_decimal(value) < 0:
            raise ValueError("must not be negative")
        return value

    def tolerance(self) -> Tolerance:
        return Tolerance(
            rel=None if self.rel is None else exact_decimal(self.rel),
            abs=None if self.abs is None else exact_decimal(self.abs),
            sigfigs=self.sigfigs,
        )


class SymbolicCheckIn(Strict):
    kind: Literal["symbolic"]
    answer: Text
    expected: ShortText
    symbols: dict[Annotated[str, Field(max_length=40)], SymbolIn] = Field(default_factory=dict, max_length=50)
    constraints: list[ShortText] = Field(default_factory=list, max_length=20)
    mistakes: list[MistakeIn] = Field(default_factory=list, max_length=50)

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
    expected: Number | ShortText
    units: ShortText | None = None
    units_required: StrictBool = True
    tolerance: ToleranceIn | None = None
    arithmetic: StrictBool = True  # the number may be arithmetic (`229/50 m/s^2`); False: a plain decimal
    units_system: Literal["SI"] | None = None  # "SI": refuse answers in ft, lb, atm, …

    @field_validator("expected")
    @classmethod
    def finite(cls, value: Number | str) -> Number | str:
        exact_decimal(value)
        return value

    def job(self) -> NumericJob:
        spec = NumericSpec(
            expected=exact_decimal(self.expected),
            units=self.units,
            units_required=self.units_required,
            tolerance=DEFAULT_TOLERANCE if self.tolerance is None else self.tolerance.tolerance(),
            arithmetic=self.arithmetic,
            units_system=self.units_system,
        )
        return NumericJob(answer=self.answer, spec=spec)


CheckIn = Annotated[SymbolicCheckIn | NumericCheckIn, Field(discriminator="kind")]


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
