"""Fullwidth forms, as East Asian input methods type them (`４.５８ ｍ／ｓ＾２`), read as the ASCII
characters they stand for, and the degree sign's look-alikes (`30º`, option-0 on a Mac keyboard) as the
degree sign. One character for one, so a position in the read text is one in the typed text. Free of
sympy: the number and unit readers use it as well as the math reader."""

from __future__ import annotations

from types import MappingProxyType
from typing import Final

# U+FF01…U+FF5E are U+0021…U+007E, shifted (Unicode's Halfwidth and Fullwidth Forms block).
FULLWIDTH: Final = MappingProxyType({chr(code + 0xFEE0): chr(code) for code in range(0x21, 0x7F)})
# The masculine ordinal indicator and the ring above, typed for the degree sign.
DEGREE_LOOKALIKES: Final = MappingProxyType({"º": "°", "˚": "°"})
_PLAIN: Final = MappingProxyType({**FULLWIDTH, **DEGREE_LOOKALIKES})


def fullwidth_as_ascii(text: str) -> str:
    """The text with fullwidth forms as ASCII, and the degree sign's look-alikes as the degree sign."""
    if text.isascii():
        return text
    return "".join(_PLAIN.get(ch, ch) for ch in text)
