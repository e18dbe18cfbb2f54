"""A coordinate's velocity as students write it, read as the word `<name>_dot` (the name a part declares
for it): `x'`, `ẋ` (precomposed or with a combining dot), `\\dot{x}`, `dx/dt`, `\\frac{dx}{dt}`, beside
`xdot` and `x_dot`, which the name table already reads.

Only when a part asks for it (`velocities=True`): elsewhere a prime or a dot is refused as before. The
rewriting is of tokens, never of text handed to anything that evaluates it; each word keeps where every
character was typed, so an error still points at the right one.
"""

from __future__ import annotations

import unicodedata
from collections.abc import Sequence

from physics.mathinput.tokentypes import Kind, SpelledWord, Token

SUFFIX = "_dot"
PRIMES = frozenset("'′’")
COMBINING_DOT = "\u0307"


def undotted(ch: str) -> str | None:
    """`x` for `ẋ` (a letter with a dot above, precomposed), else None."""
    if ch.isascii():
        return None
    parts = unicodedata.normalize("NFD", ch)
    return parts[0] if len(parts) == 2 and parts[1] == COMBINING_DOT and parts[0].isalpha() else None


def is_word_mark(ch: str) -> bool:
    """A character a velocity may add inside a word: a combining dot above."""
    return ch == COMBINING_DOT


def dotted_word(chars: Sequence[str], start: int, end: int, space: bool) -> Token:
    """The word typed in chars[start:end] (ending in a prime, or with dotted letters) with each dotted
    letter, and a final prime's letter, spelled `<letter>_dot`."""
    text: list[str] = []
    positions: list[int] = []
    keep: list[tuple[int, int]] = []
    for i in range(start, end):
        ch = chars[i]
        base = undotted(ch)
        if ch == COMBINING_DOT or ch in PRIMES:
            if not text:
                continue
            keep.append((len(text) - 1, len(text) + len(SUFFIX)))
            text.extend(SUFFIX)
            positions.extend([i] * len(SUFFIX))
        elif base is not None:
            keep.append((len(text), len(text) + 1 + len(SUFFIX)))
            text.append(base)
            text.extend(SUFFIX)
            positions.extend([i] * (1 + len(SUFFIX)))
        else:
            text.append(ch)
            positions.append(i)
    return SpelledWord(
        Kind.WORD,
        "".join(text),
        start,
        end,
        space,
        char_positions=(*positions, end),
        unsplittable=tuple(keep),
    )


def needs_spelling(chars: Sequence[str], start: int, end: int) -> bool:
    return any(ch == COMBINING_DOT or ch in PRIMES or undotted(ch) is not None for ch in chars[start:end])


def _derivative(tokens: Sequence[Token], i: int) -> tuple[Token, int] | None:
    """`dx/dt` (or `(dx)/(dt)`, as `\\frac{dx}{dt}` reads) at tokens[i]: the word `x_dot` and the index
    after it, else None."""
    j = i
    opened = tokens[j].kind is Kind.LPAREN
    if opened:
        j += 1
    top = tokens[j] if j < len(tokens) else None
    if top is None or top.kind is not Kind.WORD or len(top.text) < 2 or top.text[0] != "d":
        return None
    j += 1
    if opened:
        if tokens[j].kind is not Kind.RPAREN:
            return None
        j += 1
    if tokens[j].kind is not Kind.OP or tokens[j].text != "/":
        return None
    j += 1
    closed = tokens[j].kind is Kind.LPAREN
    if closed:
        j += 1
    bottom = tokens[j]
    if bottom.kind is not Kind.WORD or bottom.text != "dt":
        return None
    j += 1
    if closed:
        if tokens[j].kind is not Kind.RPAREN:
            return None
        j += 1
    if tokens[j].kind is Kind.OP and tokens[j].text == "^":
        return None  # `dx/dt^2` is no velocity
    name = top.text[1:]
    first = tokens[i]
    end = tokens[j - 1].end
    word = SpelledWord(
        Kind.WORD,
        name + SUFFIX,
        first.pos,
        end,
        first.space_before,
        char_positions=(*(top.position_in_text(k) for k in range(1, len(top.text))), *[bottom.pos] * 4, end),
        unsplittable=((0, len(name) + len(SUFFIX)),),
    )
    return word, j


def derivatives_read(tokens: list[Token]) -> list[Token]:
    """The tokens with every `dx/dt` made the one word `x_dot`."""
    if not any(t.kind is Kind.WORD and t.text == "dt" for t in tokens):
        return tokens
    out: list[Token] = []
    i = 0
    while i < len(tokens):
        found = _derivative(tokens, i) if tokens[i].kind in (Kind.WORD, Kind.LPAREN) else None
        if found is None:
            out.append(tokens[i])
            i += 1
        else:
            out.append(found[0])
            i = found[1]
    return out
