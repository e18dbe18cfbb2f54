"""Every kind of answer a part may ask for, registered by its `kind` (see `problems.kinds.base`).

Adding a kind is one directory beside these (`<kind>/__init__.py`, `student.html`, `described.html`),
registered below in `Part`, `CheckIn` (its `POST /v1/check` body), `AnyCompiledPart` and `_REGISTERED`
(a test checks that they name the same kinds; mypy finds every exhaustive match that must learn the new
one). No page or service branches on a kind.
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import Field

from problems.kinds.base import AnswerKind, CompiledPart
from problems.kinds.choice import CHOICE, ChoiceCheckIn, ChoicePart, CompiledChoicePart
from problems.kinds.data import DATA, CompiledDataPart, DataCheckIn, DataPart
from problems.kinds.equation import EQUATION, CompiledEquationPart, EquationCheckIn, EquationPart
from problems.kinds.free_body import FREE_BODY, CompiledFreeBodyPart, FreeBodyCheckIn, FreeBodyPart
from problems.kinds.lagrangian import (
    KINETIC_ENERGY,
    LAGRANGIAN,
    POTENTIAL_ENERGY,
    CompiledEnergyPart,
    KineticEnergyCheckIn,
    KineticEnergyPart,
    LagrangianCheckIn,
    LagrangianPart,
    PotentialEnergyCheckIn,
    PotentialEnergyPart,
)
from problems.kinds.numeric import NUMERIC, CompiledNumericPart, NumericCheckIn, NumericPart
from problems.kinds.symbolic import SYMBOLIC, CompiledSymbolicPart, SymbolicCheckIn, SymbolicPart

AnyPart = (
    SymbolicPart
    | NumericPart
    | ChoicePart
    | LagrangianPart
    | KineticEnergyPart
    | PotentialEnergyPart
    | EquationPart
    | DataPart
    | FreeBodyPart
)
Part = Annotated[AnyPart, Field(discriminator="kind")]
CheckIn = Annotated[
    SymbolicCheckIn
    | NumericCheckIn
    | ChoiceCheckIn
    | LagrangianCheckIn
    | KineticEnergyCheckIn
    | PotentialEnergyCheckIn
    | EquationCheckIn
    | DataCheckIn
    | FreeBodyCheckIn,
    Field(discriminator="kind"),
]
# matched exhaustively
AnyCompiledPart = (
    CompiledSymbolicPart
    | CompiledNumericPart
    | CompiledChoicePart
    | CompiledEnergyPart
    | CompiledEquationPart
    | CompiledDataPart
    | CompiledFreeBodyPart
)

_REGISTERED: tuple[AnswerKind[Any, Any], ...] = (
    SYMBOLIC,
    NUMERIC,
    CHOICE,
    LAGRANGIAN,
    KINETIC_ENERGY,
    POTENTIAL_ENERGY,
    EQUATION,
    DATA,
    FREE_BODY,
)
KINDS: dict[str, AnswerKind[Any, Any]] = {kind.name: kind for kind in _REGISTERED}


def kind_of(part: AnyPart) -> AnswerKind[Any, Any]:
    """The kind that handles `part` (every `kind:` the schema admits is registered)."""
    return KINDS[part.kind]


__all__ = [
    "KINDS",
    "AnswerKind",
    "AnyCompiledPart",
    "AnyPart",
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
