"""The shape of a problem document (YAML or JSON), validated with pydantic at the edge.

Only the shape is checked here (types, required fields, simple bounds). Whether the expressions
parse, the symbols exist and the units are known is `problems.semantics`; `problems.loader` runs
both and reports every fault at once with its path.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Annotated, Any, Literal

from pydantic import Field, ValidationError

from physics.wording import counted
from problems.errors import ErrorItem, format_path
from problems.fields import (
    DEFAULT_SIGFIGS,
    MAX_ATTEMPTS,
    MAX_ITEMS,
    PART_ID,
    SLUG,
    Attempts,
    Expression,
    GivenDecl,
    LimitDecl,
    MistakeDecl,
    Name,
    Strict,
    SymbolDecl,
    Text,
    ToleranceDecl,
)
from problems.kinds import KINDS, AnyPart, ChoicePart, NumericPart, Part, SymbolicPart

__all__ = [
    "DEFAULT_SIGFIGS",
    "MAX_ATTEMPTS",
    "ChoicePart",
    "GivenDecl",
    "LimitDecl",
    "MistakeDecl",
    "NumericPart",
    "Part",
    "ProblemDocument",
    "SymbolDecl",
    "SymbolicPart",
    "ToleranceDecl",
    "format_path",
    "shape_errors",
]


class ProblemDocument(Strict):
    """One problem: its statement, symbols, per-student givens, parts and (opaque) model."""

    id: Annotated[str, Field(pattern=SLUG, max_length=64)]
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
    # when a student may see the worked solution (app/web/solution_access.py): once every part is done
    # (answered correctly or out of attempts), from the start, or never
    solutions: Literal["after_attempts", "always", "never"] = "after_attempts"
    # Validated by the engine (`physics.engine.load_model`), not here.
    model: dict[str, Any] | None = None

    def part(self, part_id: str) -> AnyPart:
        for part in self.parts:
            if part.id == part_id:
                return part
        raise KeyError(part_id)


# ---- error reporting -------------------------------------------------------------------------

_PART_TAGS = set(KINDS)
_KIND_NAMES = [f"'{name}'" for name in KINDS]
_KIND_LIST = f"{', '.join(_KIND_NAMES[:-1])} or {_KIND_NAMES[-1]}"

# A part's or a check's `kind` missing or unknown: said at the path of its `kind`, for uploads and the API.
KIND_MESSAGES = {
    "union_tag_invalid": f"kind must be {_KIND_LIST}",
    "union_tag_not_found": f"kind is required ({_KIND_LIST})",
}
# The document's name patterns in words: an author who wrote `id: Sled Problem` was shown the regular
# expression itself.
_PATTERNS_SAID = {
    SLUG: "must be lower-case letters and digits, words joined by '-' (like sled-on-slope)",
    PART_ID: "must start with a lower-case letter, then lower-case letters, digits or '_' (like normal_force)",
    r"^[A-Za-z][A-Za-z0-9_]{0,19}$": "must be a name: a letter, then at most 19 letters, digits or '_'",
    r"^[A-Za-z][A-Za-z0-9]{0,19}$": "must be a name: a letter, then at most 19 letters or digits",
}


def _pattern_said(ctx: dict[str, Any]) -> str:
    pattern = str(ctx.get("pattern", ""))
    return _PATTERNS_SAID.get(pattern, f"must match {pattern}")


# A template is formatted with pydantic's context; a function takes that context where a count
# decides the wording.
_MESSAGES: dict[str, str | Callable[[dict[str, Any]], str]] = {
    "missing": "required",
    "extra_forbidden": "unknown field",
    **KIND_MESSAGES,
    "string_type": "must be text",
    "bool_type": "must be true or false",
    "bool_parsing": "must be true or false",
    "dict_type": "must be a mapping",
    "list_type": "must be a list",
    "tuple_type": "must be a list [low, high]",
    "int_type": "must be a whole number",
    "int_parsing": "must be a whole number",
    "int_from_float": "must be a whole number",
    "string_pattern_mismatch": _pattern_said,
    "greater_than": "must be > {gt}",
    "greater_than_equal": "must be >= {ge}",
    "less_than_equal": "must be <= {le}",
    "less_than": "must be < {lt}",
    "too_short": lambda ctx: f"must have at least {counted(ctx['min_length'], 'item')}",
    "too_long": lambda ctx: f"must have at most {counted(ctx['max_length'], 'item')}",
    "string_too_short": "must not be empty",
    "string_too_long": "must be at most {max_length} characters",
}

_FIELD_MESSAGES = {("version", "extra_forbidden"): "assigned by storage; remove it from the document"}


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
        if callable(template):
            message = template(err.get("ctx", {}))
        elif template is not None:
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
