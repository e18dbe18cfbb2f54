"""The tokens the tokenizer makes: each keeps its 0-based position in the original text."""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from fractions import Fraction


class Kind(Enum):
    NUM = "number"
    WORD = "word"  # a run of letters/digits/underscores, resolved by the name table
    NAME = "name"  # a declared name (canonical spelling in `text`)
    CONST = "constant"  # pi or e
    FUNC = "function"  # canonical function name in `text`
    OP = "operator"  # one of + - * / ^
    LPAREN = "opening bracket"
    RPAREN = "closing bracket"
    BAR = "|"
    SUP = "superscript"
    POSTFIX = "postfix"  # ! % ° (and the word deg, after resolution)
    SQRT = "√"
    END = "end"


# Tokens are made by the dozen for every answer and never changed once made. They are not declared
# frozen: a frozen dataclass's __init__ sets each field through object.__setattr__, four times the cost
# of a plain one (a sixth of tokenizing). unsafe_hash keeps the hash that frozen gave (equal tokens
# hash alike), so nothing that compares or keys on tokens changes.
@dataclass(slots=True, unsafe_hash=True)
class Token:
    kind: Kind
    text: str  # normalized: "^" for ** as well, "*" for × · ⋅, "-" for −; "°" for the word deg
    pos: int
    end: int
    space_before: bool = False
    value: Fraction | None = None  # NUM and SUP only

    @property
    def is_integer_literal(self) -> bool:
        return self.kind is Kind.NUM and self.text.isdigit()

    def position_in_text(self, offset: int) -> int:
        """Where the character at `offset` in this token's text was typed (`len(text)`: the end)."""
        return self.pos + offset


@dataclass(slots=True, unsafe_hash=True)
class SpelledWord(Token):
    """A WORD read from LaTeX, not spelled as typed (`\\theta_{0}` is the word theta_0): where each of its
    characters (and its end) was typed, and the stretches a reading may not split (a command's name, a
    braced subscript). A subclass, so that the plain tokens stay as cheap to make as before."""

    char_positions: tuple[int, ...] = ()
    unsplittable: tuple[tuple[int, int], ...] = ()

    def position_in_text(self, offset: int) -> int:
        return self.char_positions[offset]
