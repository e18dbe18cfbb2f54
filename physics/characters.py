"""Fullwidth forms, as East Asian input methods type them (`４.５８ ｍ／ｓ＾２`), read as the ASCII
characters they stand for; the degree sign's look-alikes (`30º`, option-0 on a Mac keyboard) as the
degree sign; the mathematical italic and bold letters that an equation copied from Word or a PDF is
made of (`𝑚𝑔ℎ`, `𝜃`) as the plain letters they show. One character for one, so a position in the read
text is one in the typed text.

Characters that show nothing (a zero-width space from a web page, the direction marks of a right-to-left
keyboard, a byte-order mark) are taken out, as the student sees the text without them: `Visible` keeps
where each remaining character was typed. Free of sympy: the number and unit readers use it as well as
the math reader."""

from __future__ import annotations

import unicodedata
from dataclasses import dataclass
from types import MappingProxyType
from typing import Final

# U+FF01…U+FF5E are U+0021…U+007E, shifted (Unicode's Halfwidth and Fullwidth Forms block).
FULLWIDTH: Final = MappingProxyType({chr(code + 0xFEE0): chr(code) for code in range(0x21, 0x7F)})
# The masculine ordinal indicator and the ring above, typed for the degree sign.
DEGREE_LOOKALIKES: Final = MappingProxyType({"º": "°", "˚": "°"})


def _math_letter(code: int) -> str | None:
    """The plain letter or digit a mathematical alphanumeric symbol (U+1D400…U+1D7FF) is a style of."""
    char = chr(code)
    if unicodedata.category(char)[0] not in "LN":
        return None
    plain = unicodedata.normalize("NFKC", char)
    return plain if len(plain) == 1 else None


# 𝑚, 𝒎, 𝐅, 𝜃, 𝟐 as m, m, F, θ, 2; and the two letters Word's equation editor takes from the letterlike
# block instead: ℎ (its italic h) and ℯ (a script e, Euler's number in some typefaces); and ℓ.
MATH_LETTERS: Final = MappingProxyType(
    {
        **{chr(code): plain for code in range(0x1D400, 0x1D800) if (plain := _math_letter(code))},
        "ℎ": "h",
        "ℯ": "e",
        "ℓ": "l",  # the script l that `\ell` sets for a length
    }
)
# What Word's equation editor puts between a function and its argument (function application, in
# `sin⁡θ`) and between factors (invisible times): a gap, as a space is.
INVISIBLE_GAPS: Final = MappingProxyType({"\u2061": " ", "\u2062": " "})
# Dots and stars typed for a product: the bullet operator, the bullet (option-8 on a Mac keyboard), and
# the asterisk operator (Word's symbol menu), as the middle dot and the asterisk they look like.
TIMES_LOOKALIKES: Final = MappingProxyType({"∙": "·", "•": "·", "∗": "*"})
# The modifier letter circumflex, which a Mac's option-i and some phones type for a caret: `m/sˆ2`.
CARET_LOOKALIKES: Final = MappingProxyType({"ˆ": "^"})
# The digits of Arabic script, as an Arabic (U+0660…) or Persian (U+06F0…) keyboard types them, and its
# decimal separator: the same digits and point (`٤٫٥٨` is 4.58). Its thousands separator, ٬, is kept:
# unlike a comma it is no decimal one, and the readers of numbers refuse it by its own name.
ARABIC_DIGITS: Final = MappingProxyType(
    {
        **{chr(0x0660 + digit): str(digit) for digit in range(10)},
        **{chr(0x06F0 + digit): str(digit) for digit in range(10)},
        "٫": ".",
    }
)
_PLAIN: Final = MappingProxyType(
    {
        **FULLWIDTH,
        **DEGREE_LOOKALIKES,
        **MATH_LETTERS,
        **INVISIBLE_GAPS,
        **TIMES_LOOKALIKES,
        **CARET_LOOKALIKES,
        **ARABIC_DIGITS,
    }
)

# Characters that show nothing and mean nothing in an answer: zero-width space, non-joiner and joiner,
# word joiner, byte-order mark, soft hyphen, the direction marks, embeddings and isolates, and the
# variation selectors a phone's keyboard puts after a character it also has as an emoji (`²️`).
ZERO_WIDTH: Final = frozenset(
    "\u200b\u200c\u200d\u2060\ufeff\u00ad\u200e\u200f\u061c\ufe0e\ufe0f"
    + "".join(map(chr, range(0x202A, 0x202F)))
    + "".join(map(chr, range(0x2066, 0x206A)))
)


# Cyrillic and Greek letters that look like Latin ones, as a keyboard set to another alphabet types
# them: `mс²` with a Cyrillic с shows as mc². Never read as the Latin letters (a Greek ν is a frequency),
# but named where the word they make is unknown and its Latin look-alike is known.
LATIN_LOOKALIKES: Final = MappingProxyType(
    dict(
        zip(
            "аеѕіјкорсухһԁАВЕЅІЈКМНОРСТХΑΒΕΖΗΙΚΜΝΟΡΤΥΧοκνρυχ",
            "aesijkopcyxhdABESIJKMHOPCTXABEZHIKMNOPTYXokvpux",
            strict=True,
        )
    )
)


def as_latin(word: str) -> str | None:
    """The word with its Cyrillic and Greek look-alikes of Latin letters in Latin, or None if it has none."""
    if word.isascii() or LATIN_LOOKALIKES.keys().isdisjoint(word):
        return None
    return "".join(LATIN_LOOKALIKES.get(char, char) for char in word)


def lookalike_hint(word: str) -> str:
    """A sentence naming the first letter of `word` that is Cyrillic or Greek but looks Latin."""
    char = next(char for char in word if char in LATIN_LOOKALIKES)
    script = "Cyrillic" if "CYRILLIC" in unicodedata.name(char, "") else "Greek"
    return (
        f" Its {char} is a {script} letter that looks like the Latin {LATIN_LOOKALIKES[char]}: type the Latin "
        "letter (the keyboard may be set to another alphabet)."
    )


def fullwidth_as_ascii(text: str) -> str:
    """The text with fullwidth forms and Arabic script's digits as ASCII, the degree sign's, the times
    signs' and the caret's look-alikes as those signs, mathematical letters as plain ones, and Word's invisible operators
    as spaces."""
    if text.isascii():
        return text
    return "".join(_PLAIN.get(ch, ch) for ch in text)


@dataclass(frozen=True)
class Visible:
    """A text without its zero-width characters, and where each character left was typed."""

    text: str
    typed_at: tuple[int, ...]
    typed_length: int

    def typed_position(self, position: int) -> int:
        """Where the character at `position` of the visible text was typed (its end: the typed end)."""
        return self.typed_at[position] if position < len(self.typed_at) else self.typed_length


def without_zero_width(text: str) -> Visible | None:
    """The text without its zero-width characters, or None if it has none."""
    if text.isascii() or ZERO_WIDTH.isdisjoint(text):
        return None
    typed_at = tuple(at for at, ch in enumerate(text) if ch not in ZERO_WIDTH)
    return Visible("".join(text[at] for at in typed_at), typed_at, len(text))


# The delimiters that wrap LaTeX math in a document or a web page: `$…$`, `$$…$$`, `\(…\)`, `\[…\]`; and
# what a chatbot wraps an answer in: markdown's bold `**…**`, LaTeX's `\boxed{…}`.
_MATH_DELIMITERS: Final = (
    ("**", "**"), ("$$", "$$"), ("$", "$"), ("\\(", "\\)"), ("\\[", "\\]"), ("\\boxed{", "}"),
)  # fmt: skip


def may_be_wrapped(text: str) -> bool:
    """Whether `without_math_delimiters` may find something to leave out: a cheap test first."""
    return "$" in text or "\\(" in text or "\\[" in text or "\\boxed" in text or "**" in text[:4]


def without_math_delimiters(text: str) -> str:
    """The text with the delimiters of LaTeX math around all of it (`$\\frac{mg}{k}$`, copied from a
    document) as spaces, so that positions stay those typed, each layer in turn (`**$\\boxed{…}$**`); any
    other text as it is."""
    for _ in range(len(_MATH_DELIMITERS)):
        unwrapped = _unwrapped(text)
        if unwrapped is None:
            break
        text = unwrapped
    return text


def _unwrapped(text: str) -> str | None:
    stripped = text.strip()
    for opening, closing in _MATH_DELIMITERS:
        inner = stripped[len(opening) : -len(closing)]
        if (
            len(stripped) > len(opening) + len(closing)
            and stripped.startswith(opening)
            and stripped.endswith(closing)
            and _wraps_all(opening, inner)
        ):
            start = text.index(stripped)
            end = start + len(stripped)
            return text[:start] + " " * len(opening) + inner + " " * len(closing) + text[end:]
    return None


def _wraps_all(opening: str, inner: str) -> bool:
    """Whether the opening and its closing wrap all of the text, not two parts of it (`$a$ + $b$`)."""
    if opening == "**":
        return "**" not in inner
    if opening.endswith("{"):
        return _balanced(inner)
    return "$" not in inner


def _balanced(text: str) -> bool:
    """Whether every brace in `text` closes within it: `\\boxed{a}{b}` does not wrap all of it."""
    depth = 0
    for char in text:
        depth += {"{": 1, "}": -1}.get(char, 0)
        if depth < 0:
            return False
    return depth == 0
