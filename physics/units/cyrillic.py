"""Units written in Russian (`м/с²`, `кг`, `Н·м`, `км/ч`), as a student whose school writes SI's units in
Cyrillic types them. They are refused naming the Latin symbols to type, never read as them: the
spelling is the student's to fix, and the suggestion is made only where it reads as units."""

from __future__ import annotations

import re

from physics.dimensions import Dimension
from physics.errors import AnswerError
from physics.units.parser import read_units

# The Russian symbols of units, and the SI symbol of each.
_UNITS = {
    "м": "m", "с": "s", "г": "g", "т": "t", "Н": "N", "Дж": "J", "Вт": "W", "Па": "Pa", "ч": "h", "мин": "min",
    "рад": "rad", "Гц": "Hz", "В": "V", "А": "A", "Ом": "Ω", "Кл": "C", "Тл": "T", "К": "K", "л": "L",
    "моль": "mol", "эВ": "eV", "об": "rev", "сут": "d", "Ф": "F", "Гн": "H", "Вб": "Wb",
}  # fmt: skip
# Their prefixes, the longest first (`мк`, micro, before `м`, milli).
_PREFIXES = {"мк": "µ", "к": "k", "М": "M", "Г": "G", "м": "m", "н": "n", "п": "p", "с": "c", "д": "d"}
_WORD = re.compile(r"[\u0400-\u04ff]+")


def latin_units(unit_text: str) -> str | None:
    """The units with each Russian symbol in Latin (`м/с²` → `m/s²`), or None: no Cyrillic word, or
    one that is no unit's symbol."""
    words = _WORD.findall(unit_text)
    if not words:
        return None
    latin = {word: _latin_symbol(word) for word in words}
    if any(symbol is None for symbol in latin.values()):
        return None
    return _WORD.sub(lambda found: latin[found.group()] or "", unit_text)


def _latin_symbol(word: str) -> str | None:
    if word in _UNITS:
        return _UNITS[word]
    for prefix, latin in _PREFIXES.items():
        if word.startswith(prefix) and word[len(prefix) :] in _UNITS:
            return latin + _UNITS[word[len(prefix) :]]
    return None


def cyrillic_units_hint(unit_text: str, expected: Dimension | None) -> str:
    """A sentence naming the Latin units to type for units written in Russian, or "" (`expected` settles
    the reading of glued Latin names, as for any units)."""
    latin = latin_units(unit_text)
    if latin is None:
        return ""
    try:
        read_units(latin, expected)
    except AnswerError:
        return ""
    return f": units are written with SI's symbols in Latin letters; did you mean {latin.strip()}?"
