"""Every kind of answer a part may ask for, registered by its `kind` (see `problems.kinds.base`).

Adding a kind is one module beside these, registered below in `Part`, `CheckIn` (its `POST /v1/check`
body), `AnyCompiledPart` and `_REGISTERED` (a test checks that they name the same kinds; mypy finds
every exhaustive match that must learn the new one).
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import Field

from problems.kinds.base import AnswerKind, CompiledPart
from problems.kinds.choice import CHOICE, ChoiceCheckIn, ChoicePart, CompiledChoicePart
from problems.kinds.numeric import NUMERIC, CompiledNumericPart, NumericCheckIn, NumericPart
from problems.kinds.symbolic import SYMBOLIC, CompiledSymbolicPart, SymbolicCheckIn, SymbolicPart

Part = Annotated[SymbolicPart | NumericPart | ChoicePart, Field(discriminator="kind")]
CheckIn = Annotated[SymbolicCheckIn | NumericCheckIn | ChoiceCheckIn, Field(discriminator="kind")]
AnyCompiledPart = CompiledSymbolicPart | CompiledNumericPart | CompiledChoicePart  # matched exhaustively

_REGISTERED: tuple[AnswerKind[Any, Any], ...] = (SYMBOLIC, NUMERIC, CHOICE)
KINDS: dict[str, AnswerKind[Any, Any]] = {kind.name: kind for kind in _REGISTERED}


def kind_of(part: SymbolicPart | NumericPart | ChoicePart) -> AnswerKind[Any, Any]:
    """The kind that handles `part` (every `kind:` the schema admits is registered)."""
    return KINDS[part.kind]


__all__ = [
    "KINDS",
    "AnswerKind",
    "AnyCompiledPart",
    "CheckIn",
    "ChoicePart",
    "CompiledChoicePart",
    "CompiledNumericPart",
    "CompiledPart",
    "CompiledSymbolicPart",
    "NumericPart",
    "Part",
    "SymbolicPart",
    "kind_of",
]
