"""Letters typed raised or lowered, as a phone's keyboard or a "superscript generator" gives them: a
raised run with a letter in it is an exponent (`e⁻ʷᵗ` is e^(-wt), as `e^(-wt)`), and a lowered run
after a name is its subscript (`vₘₐₓ` is v_max, as LaTeX's `v_{max}`). A run of raised digits alone
stays the power the tokenizer reads (`s⁻²`). One character for one, so positions stay those typed."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from physics.mathinput.tokentypes import Kind, SpelledWord, Token
from physics.mathinput.vocabulary import (
    SUBSCRIPT_LETTERS,
    SUPERSCRIPT_DIGITS,
    SUPERSCRIPT_PLAIN,
    SUPERSCRIPT_SIGNS,
)


def raised_end(chars: list[str], i: int) -> int:
    """The end of the run of raised characters that starts at i."""
    while i < len(chars) and chars[i] in SUPERSCRIPT_PLAIN:
        i += 1
    return i


def is_raised_power(chars: list[str], start: int, end: int) -> bool:
    """Whether the raised run is a sign and digits only (`⁻²`): a power as typed, not an exponent to read."""
    return all(c in SUPERSCRIPT_DIGITS or c in SUPERSCRIPT_SIGNS for c in chars[start:end])


def raised_exponent(
    chars: list[str], start: int, end: int, space: bool, read: Callable[[str], list[Token]]
) -> list[Token]:
    """The tokens of `^(…)` for the raised run from start to end, its inside read by `read` (the
    tokenizer) as the plain characters it raises; brackets and caret at the run's ends, zero-width."""
    inside = read("".join(SUPERSCRIPT_PLAIN[c] for c in chars[start:end]))[:-1]  # without its END
    return [
        Token(Kind.OP, "^", start, start, space),
        Token(Kind.LPAREN, "(", start, start),
        *(_moved(token, start) for token in _raised_divisor_bracketed(inside)),
        Token(Kind.RPAREN, ")", end, end),
    ]


# What a raised slash's divisor may hold to be taken whole: numbers and names, a product.
_FACTORS = (Kind.NUM, Kind.WORD, Kind.CONST)


def _raised_divisor_bracketed(inside: list[Token]) -> list[Token]:
    """`⁻ᵇᵗᐟ²ᵐ`: the product after a raised slash, to the run's end, is its divisor, bracketed (zero
    width): −bt/(2m). A raised run has no room for the brackets a student would type on a line, and
    raised characters on both sides of the slash say the fraction is all of the exponent. Only one
    slash, with factors alone after it; any other run is read as typed."""
    slashes = [k for k, token in enumerate(inside) if token.kind is Kind.OP and token.text == "/"]
    if len(slashes) != 1 or slashes[0] == 0:
        return inside
    k = slashes[0]
    divisor = inside[k + 1 :]
    if not divisor or any(token.kind not in _FACTORS for token in divisor):
        return inside
    opening, closing = inside[k].end, divisor[-1].end
    return [
        *inside[: k + 1],
        Token(Kind.LPAREN, "(", opening, opening),
        *divisor,
        Token(Kind.RPAREN, ")", closing, closing),
    ]


def _moved(token: Token, by: int) -> Token:
    moved = replace(token, pos=token.pos + by, end=token.end + by)
    if isinstance(moved, SpelledWord):
        moved.char_positions = tuple(at + by for at in moved.char_positions)
    return moved


def word_before_raised(chars: list[str], start: int, end: int) -> int:
    """Where the word typed from start ends: before its first raised letter (`xʸ` is x, then ʸ)."""
    for at in range(start + 1, end):
        if chars[at] in SUPERSCRIPT_PLAIN:
            return at
    return end


def lowered_word(chars: list[str], start: int, end: int, space: bool) -> tuple[SpelledWord, int] | None:
    """The word typed from start to end, up to the end of its first run of subscript letters, spelled as
    LaTeX's `v_{max}` is (the subscript never split into a product); None if it has no subscript letter
    after its first character."""
    first = next((at for at in range(start + 1, end) if chars[at] in SUBSCRIPT_LETTERS), None)
    if first is None:
        return None
    run_end = first
    while run_end < end and (chars[run_end] in SUBSCRIPT_LETTERS or chars[run_end].isdigit()):
        run_end += 1
    base = "".join(chars[start:first])
    positions = list(range(start, first))
    if not base.endswith("_"):
        base += "_"
        positions.append(first)
    text = base + "".join(SUBSCRIPT_LETTERS.get(c, c) for c in chars[first:run_end])
    positions.extend(range(first, run_end))
    word = SpelledWord(
        Kind.WORD,
        text,
        start,
        run_end,
        space,
        char_positions=(*positions, run_end),
        unsplittable=((len(base), len(text)),),
    )
    return word, run_end
