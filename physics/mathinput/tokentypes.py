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


@dataclass(frozen=True, slots=True)
class Token:
    kind: Kind
    text: str  # normalized: "^" for ** as well, "*" for × · ⋅, "-" for −; "°" for the word deg
    pos: int
    end: int
    space_before: bool = False
    value: Fraction | None = None  # NUM and SUP only
    # A WORD read from LaTeX (`\theta_{0}` is the word theta_0) is not spelled as typed: where each of
    # its characters (and its end) was typed, and the stretches a reading may not split (a command's
    # name, a braced subscript).
    char_positions: tuple[int, ...] | None = None
    unsplittable: tuple[tuple[int, int], ...] = ()

    @property
    def is_integer_literal(self) -> bool:
        return self.kind is Kind.NUM and self.text.isdigit()

    def position_in_text(self, offset: int) -> int:
        """Where the character at `offset` in this WORD's text was typed (`len(text)`: the end)."""
        if self.char_positions is not None:
            return self.char_positions[offset]
        return self.pos + offset
