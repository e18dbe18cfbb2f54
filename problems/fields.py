"""The field types problem documents are made of (shared by the document schema and each answer kind).

Numbers become exact decimals as written, bounded so that the grader can hold them; texts and lists
have size limits; every model forbids unknown fields.
"""

from __future__ import annotations

import math
import re
from decimal import Decimal, InvalidOperation
from typing import Annotated, Any

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, model_validator

DEFAULT_SIGFIGS = 3

MAX_TEXT = 20_000
MAX_EXPRESSION = 2_000
MAX_ITEMS = 64

# What the database and the grader can hold: attempt counters are 32-bit integers (and a limit this
# high is no limit in practice); given values, tolerances and bounds are exact decimals that the grader
# also turns into floats, so their size and precision stay far inside a double's range.
MAX_ATTEMPTS = 1_000_000
MAX_DIGITS = 40
MAX_EXPONENT = 100

SLUG = r"^[a-z0-9]+(?:-[a-z0-9]+)*$"
PART_ID = r"^[a-z][a-z0-9_]*$"
_NUMBER_TEXT = re.compile(r"^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$")


def _to_decimal(value: Any) -> Any:
    """Numbers become exact decimals as written (9.81 stays 9.81); bools, non-finite values and numbers
    too large, too small or too precise to grade are refused."""
    return _in_range(_as_decimal(value))


def _in_range(value: Decimal) -> Decimal:
    if not value.is_finite():
        raise ValueError("must be a finite number")
    if value and not -MAX_EXPONENT <= value.adjusted() <= MAX_EXPONENT:
        raise ValueError(f"must be between 1e-{MAX_EXPONENT} and 1e{MAX_EXPONENT} in size (or 0)")
    # Not normalize(): it rounds to the context's 28 digits first.
    if len("".join(map(str, value.as_tuple().digits)).strip("0")) > MAX_DIGITS:
        raise ValueError(f"must have at most {MAX_DIGITS} significant digits")
    return value


def _as_decimal(value: Any) -> Decimal:
    if isinstance(value, bool):
        raise ValueError("must be a number, not true/false")
    if isinstance(value, int):
        # Compared before converting: a 10,000-digit integer is refused without building it.
        if abs(value) >= 10 ** (MAX_EXPONENT + 1):
            raise ValueError(f"must be between 1e-{MAX_EXPONENT} and 1e{MAX_EXPONENT} in size (or 0)")
        return Decimal(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError("must be a finite number")
        return Decimal(repr(value))
    if isinstance(value, str) and _NUMBER_TEXT.match(value.strip()):
        try:
            return Decimal(value.strip())
        except InvalidOperation:
            raise ValueError("must be a number") from None
    if isinstance(value, Decimal):
        return value
    raise ValueError("must be a number")


def _to_bound(value: Any) -> Any:
    """A range bound: a number (kept exact) or expression text such as "pi/2"; text that is a plain
    number ("1e500") is held to the limits of a number."""
    if isinstance(value, str):
        return _to_decimal(value) if _NUMBER_TEXT.match(value.strip()) else value
    if isinstance(value, bool) or not isinstance(value, int | float | Decimal):
        raise ValueError("must be a number or expression text")
    return _to_decimal(value)


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
ExactNumber = Annotated[Decimal, BeforeValidator(_to_decimal), Field(allow_inf_nan=False)]
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
