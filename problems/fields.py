"""The field types problem documents are made of (shared by the document schema and each answer kind).

Numbers become exact decimals as written, by the one reader and within the limits of
`physics.numeric.decimals`; texts and lists have size limits; every model forbids unknown fields.
"""

from __future__ import annotations

from decimal import Decimal
from typing import Annotated, Any

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, model_validator

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
        return read_decimal(value) if is_number_text(value) else value
    if isinstance(value, bool) or not isinstance(value, int | float | Decimal):
        raise ValueError("must be a number or expression text")
    return read_decimal(value)


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


class SymbolDecl(Strict):
    """A symbol the answers may use. Positive and real unless the flags say otherwise."""

    meaning: Text
    dimension: Annotated[str, Field(min_length=1, max_length=100)]
    real: bool = False
    nonzero: bool = False
    negative: bool = False
    integer: bool = False
    range: tuple[Bound, Bound] | None = None


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
    answer: Expression
    feedback: Text


class LimitDecl(Strict):
    where: Annotated[dict[Name, Bound], Field(min_length=1, max_length=MAX_ITEMS)]
    description: Text


class ToleranceDecl(Strict):
    rel: Annotated[ExactNumber, Field(gt=0)] | None = None
    abs: Annotated[ExactNumber, Field(gt=0)] | None = None
    sigfigs: Annotated[int, BeforeValidator(_whole), Field(ge=1, le=15)] | None = None

    @model_validator(mode="after")
    def _at_least_one(self) -> ToleranceDecl:
        if self.rel is None and self.abs is None and self.sigfigs is None:
            raise ValueError("give at least one of rel, abs, sigfigs")
        return self
