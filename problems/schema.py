"""The shape of a problem document (YAML or JSON), validated with pydantic at the edge.

Only the shape is checked here (types, required fields, simple bounds). Whether the expressions
parse, the symbols exist and the units are known is `problems.semantics`; `problems.loader` runs
both and reports every fault at once with its path.
"""

from __future__ import annotations

import math
import re
from decimal import Decimal, InvalidOperation
from typing import Annotated, Any, Literal

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, ValidationError, model_validator

from problems.errors import ErrorItem

DEFAULT_REL_TOLERANCE = Decimal("0.01")
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

_SLUG = r"^[a-z0-9]+(?:-[a-z0-9]+)*$"
_PART_ID = r"^[a-z][a-z0-9_]*$"
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


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, str_strip_whitespace=True)


class SymbolDecl(_Strict):
    """A symbol the answers may use. Positive and real unless the flags say otherwise."""

    meaning: Text
    dimension: Annotated[str, Field(min_length=1, max_length=100)]
    real: bool = False
    nonzero: bool = False
    negative: bool = False
    integer: bool = False
    range: tuple[Bound, Bound] | None = None


class GivenDecl(_Strict):
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


class MistakeDecl(_Strict):
    answer: Expression
    feedback: Text


class LimitDecl(_Strict):
    where: Annotated[dict[Name, Bound], Field(min_length=1, max_length=MAX_ITEMS)]
    description: Text


class ToleranceDecl(_Strict):
    rel: Annotated[ExactNumber, Field(gt=0)] | None = None
    abs: Annotated[ExactNumber, Field(gt=0)] | None = None
    sigfigs: Annotated[int, BeforeValidator(_whole), Field(ge=1, le=15)] | None = None

    @model_validator(mode="after")
    def _at_least_one(self) -> ToleranceDecl:
        if self.rel is None and self.abs is None and self.sigfigs is None:
            raise ValueError("give at least one of rel, abs, sigfigs")
        return self


class SymbolicPart(_Strict):
    id: Annotated[str, Field(pattern=_PART_ID, max_length=64)]
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


class NumericPart(_Strict):
    id: Annotated[str, Field(pattern=_PART_ID, max_length=64)]
    kind: Literal["numeric"]
    prompt: Text
    of: Name
    units: Annotated[str, Field(min_length=1, max_length=100)]
    tolerance: ToleranceDecl = ToleranceDecl(rel=DEFAULT_REL_TOLERANCE)
    units_required: bool = True
    arithmetic: bool = True  # the number may be arithmetic (`229/50 m/s^2`); False: a plain decimal
    units_system: Literal["SI"] | None = None  # "SI": refuse answers in ft, lb, atm, …
    max_attempts: Attempts | None = None

    @property
    def dimensionless(self) -> bool:
        """`units: "1"` asks for a pure number."""
        return self.units == "1"


Part = Annotated[SymbolicPart | NumericPart, Field(discriminator="kind")]


class ProblemDocument(_Strict):
    """One problem: its statement, symbols, per-student givens, parts and (opaque) model."""

    id: Annotated[str, Field(pattern=_SLUG, max_length=64)]
    title: Annotated[str, Field(min_length=1, max_length=200)]
    topics: Annotated[
        list[Annotated[str, Field(min_length=1, max_length=64)]], Field(max_length=MAX_ITEMS)
    ] = []
    statement: Text
    symbols: Annotated[dict[Name, SymbolDecl], Field(min_length=1, max_length=MAX_ITEMS)]
    constraints: Annotated[list[Expression], Field(max_length=MAX_ITEMS)] = []
    given: Annotated[dict[Name, GivenDecl], Field(max_length=MAX_ITEMS)] = {}
    parts: Annotated[list[Part], Field(min_length=1, max_length=MAX_ITEMS)]
    max_attempts: Attempts | None = None  # per part, unless a part sets its own
    # Validated by the engine (`physics.engine.load_model`), not here.
    model: dict[str, Any] | None = None

    def part(self, part_id: str) -> SymbolicPart | NumericPart:
        for part in self.parts:
            if part.id == part_id:
                return part
        raise KeyError(part_id)

    @property
    def symbolic_parts(self) -> list[SymbolicPart]:
        return [p for p in self.parts if isinstance(p, SymbolicPart)]

    @property
    def numeric_parts(self) -> list[NumericPart]:
        return [p for p in self.parts if isinstance(p, NumericPart)]


# ---- error reporting -------------------------------------------------------------------------

_PART_TAGS = {"symbolic", "numeric"}

_MESSAGES: dict[str, str] = {
    "missing": "required",
    "extra_forbidden": "unknown field",
    "union_tag_invalid": "kind must be 'symbolic' or 'numeric'",
    "union_tag_not_found": "kind is required ('symbolic' or 'numeric')",
    "string_type": "must be text",
    "bool_type": "must be true or false",
    "bool_parsing": "must be true or false",
    "dict_type": "must be a mapping",
    "list_type": "must be a list",
    "tuple_type": "must be a list [low, high]",
    "int_type": "must be a whole number",
    "int_parsing": "must be a whole number",
    "int_from_float": "must be a whole number",
    "string_pattern_mismatch": "must match {pattern}",
    "greater_than": "must be > {gt}",
    "greater_than_equal": "must be >= {ge}",
    "less_than_equal": "must be <= {le}",
    "less_than": "must be < {lt}",
    "too_short": "must have at least {min_length} item(s)",
    "too_long": "must have at most {max_length} item(s)",
    "string_too_short": "must not be empty",
    "string_too_long": "must be at most {max_length} characters",
}

_FIELD_MESSAGES = {("version", "extra_forbidden"): "assigned by storage; remove it from the document"}


def format_path(loc: tuple[str | int, ...]) -> str:
    """("parts", 2, "tolerance", "rel") -> "parts[2].tolerance.rel"."""
    out = ""
    for item in loc:
        if isinstance(item, int):
            out += f"[{item}]"
        else:
            out += f".{item}" if out else str(item)
    return out


def _clean_loc(loc: tuple[str | int, ...], error_type: str) -> tuple[str | int, ...]:
    parts = list(loc)
    # The discriminated union inserts the tag (parts[2].numeric.units); authors never wrote it.
    cleaned: list[str | int] = []
    for i, item in enumerate(parts):
        if item in _PART_TAGS and i >= 2 and parts[i - 2] == "parts" and isinstance(parts[i - 1], int):
            continue
        # Bound = Decimal | str reports per-member locations; the author wrote one value.
        if isinstance(item, str) and (item.startswith("function-before[") or item in {"decimal", "str"}):
            continue
        cleaned.append(item)
    if error_type in {"union_tag_invalid", "union_tag_not_found"}:
        cleaned.append("kind")
    return tuple(cleaned)


def shape_errors(exc: ValidationError) -> list[ErrorItem]:
    """Every pydantic error as (path, message), in the order pydantic found them, without repeats."""
    found: dict[ErrorItem, None] = {}  # ordered and without repeats, in linear time
    for err in exc.errors(include_url=False):
        loc = _clean_loc(tuple(err["loc"]), err["type"])
        path = format_path(loc)
        template = _FIELD_MESSAGES.get((str(loc[-1]) if loc else "", err["type"])) or _MESSAGES.get(
            err["type"]
        )
        if template is not None:
            try:
                message = template.format(**err.get("ctx", {}))
            except (KeyError, IndexError):
                message = template
        else:
            message = str(err["msg"])
            if message.startswith("Value error, "):
                message = message[len("Value error, ") :]
        found[(path, message)] = None
    return list(found)
