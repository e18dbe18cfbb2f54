"""The field types problem documents are made of (shared by the document schema and each answer kind).

Numbers become exact decimals as written, by the one reader and within the limits of
`physics.numeric.decimals`; texts and lists have size limits; every model forbids unknown fields.
"""

from __future__ import annotations

from decimal import Decimal
from typing import Annotated, Any

from pydantic import (
    AfterValidator,
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    StrictBool,
    StrictStr,
    model_validator,
)

from physics.checking import SymbolDecl as CheckSymbolDecl
from physics.numeric import DEFAULT_TOLERANCE, Tolerance
from physics.numeric.decimals import is_number_text, read_decimal

DEFAULT_SIGFIGS = 3

MAX_TEXT = 20_000
MAX_EXPRESSION = 2_000
MAX_ITEMS = 64

# Attempt counters are 32-bit integers in the database (and a limit this high is no limit in practice).
MAX_ATTEMPTS = 1_000_000

SLUG = r"^[a-z0-9]+(?:-[a-z0-9]+)*$"
PART_ID = r"^[a-z][a-z0-9_]*$"


def _to_bound(value: Any) -> Any:
    """A range bound: a number (kept exact) or expression text such as "pi/2"; text that is a plain
    number ("1e500") is held to the limits of a number."""
    if isinstance(value, str):
        if is_number_text(value):
            return read_decimal(value)
        if len(value) > MAX_EXPRESSION:
            raise ValueError(f"must be at most {MAX_EXPRESSION} characters")
        return value
    if isinstance(value, bool) or not isinstance(value, int | float | Decimal):
        raise ValueError("must be a number or expression text")
    return read_decimal(value)


def bound_text(value: Decimal | str) -> str:
    """A bound as the checker reads it: number text as written, or the expression."""
    return str(value) if isinstance(value, Decimal) else value


def _whole(value: Any) -> Any:
    """YAML and JSON `true` would otherwise pass as the integer 1."""
    if isinstance(value, bool):
        raise ValueError("must be a whole number, not true/false")
    return value


def _attempts(value: Any) -> Any:
    # Said here too: a float such as 1e30 would otherwise fail as "unable to parse", not as too many.
    if isinstance(value, int | float) and not isinstance(value, bool) and value > MAX_ATTEMPTS:
        raise ValueError(f"must be <= {MAX_ATTEMPTS}")
    return _whole(value)


Attempts = Annotated[int, BeforeValidator(_attempts), Field(ge=1, le=MAX_ATTEMPTS)]
ExactNumber = Annotated[Decimal, BeforeValidator(read_decimal), Field(allow_inf_nan=False)]
Bound = Annotated[Decimal | str, BeforeValidator(_to_bound)]
Text = Annotated[str, Field(min_length=1, max_length=MAX_TEXT)]
Expression = Annotated[str, Field(min_length=1, max_length=MAX_EXPRESSION)]
Name = Annotated[str, Field(min_length=1, max_length=32)]


class Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, str_strip_whitespace=True)


def storable(text: str) -> str:
    """Refuse what no database stores (NUL, lone surrogates) as a field's fault, not later as a 500."""
    if "\x00" in text:
        raise ValueError("must not contain a NUL character")
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        raise ValueError("must be valid Unicode text (a lone surrogate was sent)") from None
    return text


# An HTTP request's text: a JSON string exactly as sent (an answer's error positions count from its
# first character, so nothing is stripped).
RequestText = Annotated[StrictStr, AfterValidator(storable)]
ShortRequestText = Annotated[RequestText, Field(max_length=MAX_EXPRESSION)]


class CheckBody(BaseModel):
    """A `POST /v1/check` body: a one-part problem given in the request (each kind defines its own)."""

    model_config = ConfigDict(extra="forbid")


Dimension = Annotated[str, Field(min_length=1, max_length=100)]


class SymbolDeclBase(Strict):
    """A symbol the answers may use: positive and real unless the flags or an open range say otherwise.

    The one declaration of a symbol, as `POST /v1/check` takes it (meaning and dimension optional) and,
    with both required, as a problem document does (`SymbolDecl`); `decl` is what the checker reads.
    """

    meaning: Text | None = None
    dimension: Dimension | None = None
    real: StrictBool = False
    nonzero: StrictBool = False
    negative: StrictBool = False
    integer: StrictBool = False
    range: tuple[Bound, Bound] | None = None

    def decl(self, name: str) -> CheckSymbolDecl:
        """The symbol as the checker's plain text declaration, read in the process that grades."""
        return CheckSymbolDecl(
            name=name,
            dimension=self.dimension,
            real=self.real,
            nonzero=self.nonzero,
            negative=self.negative,
            integer=self.integer,
            range=None if self.range is None else (bound_text(self.range[0]), bound_text(self.range[1])),
        )


class SymbolDecl(SymbolDeclBase):
    """A symbol of a problem document: its meaning and its dimension are required."""

    meaning: Text
    dimension: Dimension


class GivenDecl(Strict):
    """A per-student value: drawn in [min, max] (min = max fixes it), in `unit`, rounded to sigfigs or step
    (neither: DEFAULT_SIGFIGS significant figures)."""

    min: ExactNumber
    max: ExactNumber
    unit: Annotated[str, Field(min_length=1, max_length=100)]
    sigfigs: Annotated[int, BeforeValidator(_whole), Field(ge=1, le=12)] | None = None
    step: Annotated[ExactNumber, Field(gt=0)] | None = None

    @model_validator(mode="after")
    def _one_rounding(self) -> GivenDecl:
        if self.sigfigs is not None and self.step is not None:
            raise ValueError("give sigfigs or step, not both")
        return self


class MistakeDecl(Strict):
    """A known wrong answer and what to tell the student who gives it."""

    answer: Expression
    feedback: Text


class LimitDecl(Strict):
    where: Annotated[dict[Name, Bound], Field(min_length=1, max_length=MAX_ITEMS)]
    description: Text


class ToleranceDecl(Strict):
    """A numeric part's (or check's) tolerance; every key given must pass, and 0 asks for the exact value."""

    rel: Annotated[ExactNumber, Field(ge=0)] | None = None
    abs: Annotated[ExactNumber, Field(ge=0)] | None = None
    sigfigs: Annotated[int, BeforeValidator(_whole), Field(ge=1, le=15)] | None = None

    @model_validator(mode="after")
    def _at_least_one(self) -> ToleranceDecl:
        # An empty tolerance would pass every answer.
        if self.rel is None and self.abs is None and self.sigfigs is None:
            raise ValueError("give at least one of rel, abs, sigfigs")
        return self

    @classmethod
    def of(cls, tolerance: Tolerance) -> ToleranceDecl:
        return cls(rel=tolerance.rel, abs=tolerance.abs, sigfigs=tolerance.sigfigs)

    def tolerance(self) -> Tolerance:
        """The core's tolerance."""
        return Tolerance(rel=self.rel, abs=self.abs, sigfigs=self.sigfigs)


DEFAULT_TOLERANCE_DECL = ToleranceDecl.of(DEFAULT_TOLERANCE)
