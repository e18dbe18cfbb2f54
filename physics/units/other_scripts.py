"""Units written in Russian (`м/с²`, `кг`, `Н·м`, `км/ч`) or Chinese (`米/秒²`, `千克`), as a student whose
school writes SI's units in its own script types them. They are refused naming the Latin symbols to
type, never read as them: the spelling is the student's to fix, and the suggestion is made only where
it reads as units; other words in those scripts are refused saying units are typed in Latin letters.
A Cyrillic or Greek letter that only looks Latin (`2.01 ѕ`) is named, as in a symbolic answer."""

from __future__ import annotations

import re

from physics.characters import as_latin, lookalike_hint
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
# The Chinese names of units (Chinese textbooks write 米/秒², 千克), and of their prefixes.
_CHINESE_UNITS = {
    "米": "m", "秒": "s", "克": "g", "公斤": "kg", "公里": "km", "吨": "t", "牛": "N", "牛顿": "N", "焦": "J",
    "焦耳": "J", "瓦": "W", "瓦特": "W", "帕": "Pa", "帕斯卡": "Pa", "小时": "h", "分钟": "min", "弧度": "rad",
    "赫": "Hz", "赫兹": "Hz", "伏": "V", "伏特": "V", "安": "A", "安培": "A", "欧": "Ω", "欧姆": "Ω", "库": "C",
    "库仑": "C", "开": "K", "开尔文": "K", "升": "L", "摩尔": "mol", "度": "°",
}  # fmt: skip
_CHINESE_PREFIXES = {"千": "k", "兆": "M", "毫": "m", "微": "µ", "纳": "n", "厘": "c"}
_TABLES = ((_UNITS, _PREFIXES), (_CHINESE_UNITS, _CHINESE_PREFIXES))
# A word in Cyrillic, or in Chinese or Japanese characters (kana and the CJK ideographs).
_WORD = re.compile(r"[\u0400-\u04ff]+|[\u3040-\u30ff\u4e00-\u9fff]+")


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
    for units, prefixes in _TABLES:
        if word in units:
            return units[word]
        for prefix, latin in prefixes.items():
            if word.startswith(prefix) and word[len(prefix) :] in units:
                return latin + units[word[len(prefix) :]]
    return None


def other_script_units_hint(unit_text: str, expected: Dimension | None) -> str:
    """A sentence naming the Latin units to type for units written in Russian or Chinese, or with a letter
    that looks Latin, or saying to type SI's symbols for other words in those scripts; "" for units with none (`expected` settles the
    reading of glued Latin names, as for any units)."""
    latin = latin_units(unit_text)
    if latin is not None and _read(latin, expected):
        return f": units are written with SI's symbols in Latin letters; did you mean {latin.strip()}?"
    looks = as_latin(unit_text)
    if looks is not None and _read(looks, expected):  # `2.01 ѕ`: a Cyrillic letter that looks Latin
        return f": did you mean {looks.strip()}?{lookalike_hint(unit_text)}"
    if not _WORD.search(unit_text):
        return ""
    return ": units are written with SI's symbols in Latin letters, as in m/s^2, kg or N"


def _read(units: str, expected: Dimension | None) -> bool:
    try:
        read_units(units, expected)
    except AnswerError:
        return False
    return True
