"""Units: reading unit strings by a whitelist grammar, their dimensions, and exact conversion.

pint (one exact registry, built lazily) supplies the conversion factors; `parser` reads the strings
(never pint's string parser, never eval); `parsed.ParsedUnits` carries the result.
"""

from __future__ import annotations

from collections.abc import Sequence

from physics.dimensions import Dimension
from physics.errors import AnswerError, SpecError
from physics.units.parsed import IncompatibleUnits, ParsedUnits
from physics.units.parser import UnitReading, parse_units, read_units
from physics.units.registry import UnitAtom

__all__ = [
    "IncompatibleUnits",
    "ParsedUnits",
    "UnitAtom",
    "UnitReading",
    "parse_units",
    "read_units",
    "unit_dimension",
]


def unit_dimension(text: str, path: Sequence[str | int] = ("dimension",)) -> Dimension:
    """The dimension of an author's unit expression (`kg`, `m/s^2`, `J`, `1`), for symbol declarations.

    Raises SpecError at `path` (the author's fault, not a student's) when the text is not a unit expression.
    """
    try:
        return parse_units(text).dimension
    except AnswerError as error:
        raise SpecError.unreadable(error, path, text) from error
