"""LaTeX as equation editors paste it, read into the tokens of the plain text it means.

`-\\frac{m g \\sin\\theta}{M}` gives the tokens of `-((m g sin θ)/(M))`, `\\sqrt[3]{x}` those of
`((x)^(1/3))`, `\\theta_{0}` the word theta_0. Tokens keep the positions of what was typed (a bracket,
`/` or `^` that a command stands for sits, zero-width, at its command or brace), so an error still points
at the right character. Only the commands of `vocabulary.LATEX_*` are read; any other is a ParseError
at its backslash that names it and says how to type it in plain text.

Braces are a stack of frames: a plain `{` is a bracket, as in plain text; the brace of a command's
argument closes with what the command needs (`\\frac`'s numerator with the `/` and the denominator).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import Literal

from physics.errors import ParseError
from physics.latex_words import LATEX_FRACTIONS, LATEX_SPACES, LATEX_TEXT_WRAPPERS
from physics.mathinput.tokentypes import Kind, SpelledWord, Token
from physics.mathinput.vocabulary import (
    FUNCTIONS,
    GREEK_LETTERS,
    LATEX_BRACKETS,
    LATEX_FUNCTION_COMMANDS,
    LATEX_HINTS,
    LATEX_LETTERS,
    LATEX_OPERATORS,
    LATEX_PLAIN_TEXT_HINT,
    LATEX_SIZES,
)

FrameKind = Literal["group", "argument", "numerator", "denominator", "radicand"]
# Operator names that a subscript may hold as its word: equation editors turn a typed `max` into `\max`.
_SUBSCRIPT_OPERATOR_WORDS = frozenset({"max", "min"})
_MAX_ROOT_INDEX_DIGITS = 3
_SHOWN_NAME_LENGTH = 24  # of an unknown command quoted back
_BRACKET_KINDS = {"(": Kind.LPAREN, "[": Kind.LPAREN, "{": Kind.LPAREN, ")": Kind.RPAREN, "]": Kind.RPAREN}
# What each argument is called in a message.
_PART = {
    "argument": "argument",
    "numerator": "numerator",
    "denominator": "denominator",
    "radicand": "argument",
}


# Spacing, and plain TeX's roman font switch (`v_{\rm max}`): nothing of a subscript's name.
_SKIPPED_IN_SUBSCRIPTS = LATEX_SPACES | {"rm"}


@dataclass(frozen=True, slots=True)
class _Frame:
    kind: FrameKind
    command: str  # as typed, `\frac`; "" for a plain brace
    start: int  # of the command (of the brace for a plain one)
    brace: int
    index: Token | None = None  # the n of \sqrt[n]{…}
    over: bool = False  # an \over has split it: its denominator's bracket closes with it


def _zero_width(kind: Kind, text: str, pos: int, value: Fraction | None = None) -> Token:
    return Token(kind, text, pos, pos, value=value)


def _is_command_letter(ch: str) -> bool:
    return ch.isascii() and ch.isalpha()


def _is_word_char(ch: str) -> bool:
    return ch.isalpha() or ch in "0123456789_"


class LatexReader:
    """The LaTeX of one text: the tokenizer hands it every backslash and brace, and `^\\circ`."""

    def __init__(
        self,
        chars: list[str],
        units_in_fonts: bool = False,
        velocities: bool = False,
        tokens: list[Token] | None = None,
    ) -> None:
        self._chars = chars
        self._tokens = [] if tokens is None else tokens  # what the tokenizer has read: `\over` splits it
        self._over_at: int | None = None  # an `\over` outside any brace: the whole text is its fraction
        self._n = len(chars)
        self._units_in_fonts = units_in_fonts
        self._velocities = velocities  # `\dot{x}` is the word x_dot (velocities.py)
        self._frames: list[_Frame] = []
        # Only in a text written in LaTeX is `~` a space and `{}` nothing (`~x` stays refused).
        self.active = "\\" in chars

    # -- braces --------------------------------------------------------------------------------
    def open_brace(self, i: int) -> tuple[list[Token], int]:
        if self.active:
            j = self._skip_spaces(i + 1)
            if j < self._n and self._chars[j] == "}":  # `{}^{\circ}`: an empty group is nothing in TeX
                return [], j + 1
        self._frames.append(_Frame("group", "", i, i))
        return [Token(Kind.LPAREN, "{", i, i + 1)], i + 1

    def close_brace(self, i: int) -> tuple[list[Token], int]:
        closing = Token(Kind.RPAREN, "}", i, i + 1)
        if not self._frames:
            return [closing], i + 1  # the parser says that no bracket opens it
        frame = self._frames.pop()
        emitted, after = self._close(frame, closing, i + 1)
        if frame.over:  # `{a \over b}`: the denominator's bracket closes with the brace
            emitted.insert(0, _zero_width(Kind.RPAREN, ")", i))
        return emitted, after

    def finish(self) -> None:
        """Refuse a command's brace left open (a plain brace left open is the parser's to report); close
        the denominator of an `\\over` outside any brace."""
        if self._over_at is not None:
            self._tokens.append(_zero_width(Kind.RPAREN, ")", self._n))
        if all(frame.kind == "group" for frame in self._frames):
            return
        frame = self._frames[-1]
        if frame.kind == "group":
            raise ParseError("Unbalanced bracket: this '{' is never closed.", frame.brace)
        raise ParseError(f"Unbalanced brace: the '{{' of {frame.command} is never closed.", frame.brace)

    def _close(self, frame: _Frame, closing: Token, i: int) -> tuple[list[Token], int]:
        """The closing bracket of an argument, and what its command adds after it."""
        if frame.kind == "numerator":
            slash = _zero_width(Kind.OP, "/", self._skip_spaces(i))
            denominator, i = self._argument(frame.command, frame.start, i, "denominator")
            return [closing, slash, *denominator], i
        if frame.kind == "denominator":
            return [closing, _zero_width(Kind.RPAREN, ")", closing.end)], i
        if frame.kind == "radicand":
            assert frame.index is not None
            at = frame.start  # a size error about the root points at its \sqrt
            power = [
                _zero_width(Kind.OP, "^", at),
                _zero_width(Kind.LPAREN, "(", at),
                _zero_width(Kind.NUM, "1", at, Fraction(1)),
                _zero_width(Kind.OP, "/", at),
                frame.index,
                _zero_width(Kind.RPAREN, ")", closing.end),
                _zero_width(Kind.RPAREN, ")", closing.end),
            ]
            return [closing, *power], i
        return [closing], i

    # -- commands ------------------------------------------------------------------------------
    def command(self, i: int) -> tuple[list[Token], int]:
        """The tokens for the command whose backslash is at `i`, and where reading goes on; no tokens
        for a spacing command (the tokenizer takes it as a space)."""
        name, end = self._command_name(i)
        if name in LATEX_SPACES:
            return [], end
        if name == "over":
            return self._over(i, end), end
        if name in LATEX_FRACTIONS:
            opened = Token(Kind.LPAREN, "(", i, end)
            numerator, after = self._argument("\\" + name, i, end, "numerator")
            return [opened, *numerator], after
        if name == "sqrt":
            return self._root(i, end)
        if name in LATEX_FUNCTION_COMMANDS:
            token, after = self._function(i, name, end)
            return [token], after
        if name in LATEX_LETTERS:
            token, after = self._letter(i, name, end)
            return [token], after
        if name in LATEX_OPERATORS:
            return [Token(Kind.OP, LATEX_OPERATORS[name], i, end)], end
        if name in LATEX_SIZES:
            token, after = self._delimiter(i, name, end)
            return [token], after
        if name in LATEX_BRACKETS:
            return [_bracket(LATEX_BRACKETS[name], i, end)], end
        if name in LATEX_TEXT_WRAPPERS and self._units_in_fonts:
            units = self._units(i, name, end)
            return [units], units.end
        if name in LATEX_TEXT_WRAPPERS:
            text, positions, after = self._braced_name(name, end)
            token, after = self._word_on(text, positions, ((0, len(text)),), i, after, digits=False)
            return [token], after
        if name == "%":
            return [Token(Kind.POSTFIX, "%", i, end)], end
        if name == "degree":
            return [Token(Kind.POSTFIX, "°", i, end)], end
        if name == "dot" and self._velocities:
            return self._dotted(i, end)
        raise self._unknown(i, name)

    def _over(self, i: int, end: int) -> list[Token]:
        """`{a \\over b}`, as plain TeX writes a/b: what its brace holds before the command is the
        numerator, what follows it the denominator; outside any brace, the whole text is split so."""
        twice = ParseError(r"Two \over in one brace: write each fraction as \frac{a}{b}.", i)
        if self._frames:
            frame = self._frames[-1]
            if frame.over:
                raise twice
            opened = next(
                at
                for at in range(len(self._tokens) - 1, -1, -1)
                if self._tokens[at].kind is Kind.LPAREN and self._tokens[at].pos == frame.brace
            )
            if opened == len(self._tokens) - 1:  # `mg{\over m+M}`: the numerator left before the brace
                raise self._no_numerator(i)
            self._tokens.insert(opened + 1, _zero_width(Kind.LPAREN, "(", frame.brace + 1))
            self._frames[-1] = replace(frame, over=True)
        else:
            if self._over_at is not None:
                raise twice
            if not self._tokens:
                raise self._no_numerator(i)
            self._tokens.insert(0, _zero_width(Kind.LPAREN, "(", 0))
            self._over_at = i
        return [
            _zero_width(Kind.RPAREN, ")", i),
            Token(Kind.OP, "/", i, end),
            _zero_width(Kind.LPAREN, "(", end),
        ]

    @staticmethod
    def _no_numerator(i: int) -> ParseError:
        return ParseError(
            r"\over has nothing before it: put the numerator before it in the same brace, as in {m g \over m + M}, "
            r"or write \frac{m g}{m + M}.",
            i,
        )

    def _dotted(self, i: int, end: int) -> tuple[list[Token], int]:
        """`\\dot{x}`, `\\dot x`, `\\dot{\\theta}`: the velocity's word `x_dot`, `theta_dot`."""
        j = self._skip_spaces(end)
        braced = j < self._n and self._chars[j] == "{"
        k = self._skip_spaces(j + 1) if braced else j
        single = self._single(k)
        if single is None or single[0].kind is not Kind.WORD:
            raise ParseError("\\dot needs a coordinate, as in \\dot{x} or \\dot{\\theta}.", i)
        word, after = single[0].text, single[1]
        if braced:
            while after < self._n and _is_word_char(self._chars[after]):  # \dot{phi2}
                word += self._chars[after]
                after += 1
            after = self._skip_spaces(after)
            if after >= self._n or self._chars[after] != "}":
                raise ParseError("\\dot{…} holds one coordinate, as in \\dot{x}.", i)
            after += 1
        text = word + "_dot"
        return [
            SpelledWord(
                Kind.WORD,
                text,
                i,
                after,
                char_positions=(i,) * len(text) + (after,),
                unsplittable=((0, len(text)),),
            )
        ], after

    def degree_end(self, i: int) -> int | None:
        """The end of `\\circ` or `{\\circ}` after the `^` ending at i (`30^\\circ` is 30°), or None."""
        j = self._skip_spaces(i)
        braced = j < self._n and self._chars[j] == "{"
        if braced:
            j = self._skip_spaces(j + 1)
        if self._text(j, j + 5) != "\\circ" or (j + 5 < self._n and _is_command_letter(self._chars[j + 5])):
            return None
        j += 5
        if not braced:
            return j
        j = self._skip_spaces(j)
        return j + 1 if j < self._n and self._chars[j] == "}" else None

    def subscripted_word(self, start: int, i: int) -> tuple[Token, int]:
        """The word typed from `start` whose `_` ends at i and is followed by `{` or a command."""
        text = "".join(self._chars[start:i])
        return self._word_on(text, list(range(start, i)), (), start, i, digits=False)

    # -- pieces --------------------------------------------------------------------------------
    def _text(self, start: int, end: int) -> str:
        return "".join(self._chars[start:end])

    def _skip_spaces(self, i: int) -> int:
        while i < self._n and self._chars[i].isspace():
            i += 1
        return i

    def _command_name(self, i: int) -> tuple[str, int]:
        """`frac` for `\\frac`, `,` for `\\,`: the name after the backslash at i, and its end."""
        j = i + 1
        if j >= self._n:
            raise ParseError("A '\\' ends the answer: finish its command, or remove it.", i)
        if not _is_command_letter(self._chars[j]):
            return self._chars[j], j + 1
        while j < self._n and _is_command_letter(self._chars[j]):
            j += 1
        return self._text(i + 1, j), j

    def _unknown(self, i: int, name: str) -> ParseError:
        named = _MATHEMATICA_CHARACTER.match(self._text(i, min(self._n, i + _SHOWN_NAME_LENGTH + 3)))
        if named is not None:  # `Sin[\[Theta]]`, as Mathematica copies a Greek letter as plain text
            return ParseError(_mathematica_character_message(named.group(), named.group(1)), i)
        shown = name if len(name) <= _SHOWN_NAME_LENGTH else name[:_SHOWN_NAME_LENGTH] + "…"
        hint = LATEX_HINTS.get(name, LATEX_PLAIN_TEXT_HINT)
        # `\sinx`, `\thetat`: TeX reads the letters after a command as part of its name.
        glued = [known for known in (*LATEX_FUNCTION_COMMANDS, *LATEX_LETTERS) if name.startswith(known)]
        if glued and name not in LATEX_HINTS:
            known = max(glued, key=len)
            hint = f"put a space after \\{known}, as in \\{known} {shown[len(known) :]}"
        return ParseError(f"Unknown LaTeX command \\{shown}: {hint}.", i)

    def _argument(
        self, command: str, start: int, i: int, kind: FrameKind, index: Token | None = None
    ) -> tuple[list[Token], int]:
        """A command's argument from i: a brace (closed later by `close_brace`) or one character."""
        j = self._skip_spaces(i)
        example = r"\frac{a}{b}" if command[1:] in LATEX_FRACTIONS else command + "{x}"
        if j < self._n and self._chars[j] == "{":
            k = self._skip_spaces(j + 1)
            if k < self._n and self._chars[k] == "}":
                raise ParseError(
                    f"{command} has an empty {_PART[kind]}: write it inside the braces, as in {example}.", j
                )
            self._frames.append(_Frame(kind, command, start, j, index))
            return [Token(Kind.LPAREN, "{", j, j + 1)], j + 1
        single = self._single(j)
        if single is None:
            article = "an" if _PART[kind][0] == "a" else "a"
            raise ParseError(
                f"{command} needs {article} {_PART[kind]} in braces, as in {example}.", min(j, self._n)
            )
        token, end = single
        following, end = self._close(
            _Frame(kind, command, start, j, index), _zero_width(Kind.RPAREN, ")", end), end
        )
        return [_zero_width(Kind.LPAREN, "(", j), token, *following], end

    def _single(self, j: int) -> tuple[Token, int] | None:
        """An argument without braces, as TeX reads one: a letter, a digit or a letter command (`\\frac12`)."""
        if j >= self._n:
            return None
        ch = self._chars[j]
        if ch.isascii() and ch.isdigit():
            return Token(Kind.NUM, ch, j, j + 1, value=Fraction(int(ch))), j + 1
        if _is_command_letter(ch):
            return Token(Kind.WORD, ch, j, j + 1), j + 1
        if ch == "\\":
            name, end = self._command_name(j)
            if name in LATEX_LETTERS:
                word = LATEX_LETTERS[name]
                return SpelledWord(
                    Kind.WORD,
                    word,
                    j,
                    end,
                    char_positions=(j,) * len(word) + (end,),
                    unsplittable=((0, len(word)),),
                ), end
        return None

    def _root(self, start: int, i: int) -> tuple[list[Token], int]:
        j = self._skip_spaces(i)
        if j < self._n and self._chars[j] == "[":
            index, after = self._root_index(j)
            rest, end = self._argument(r"\sqrt", start, after, "radicand", index)
            return [Token(Kind.LPAREN, "(", start, after), *rest], end
        rest, end = self._argument(r"\sqrt", start, i, "argument")
        return [Token(Kind.SQRT, "√", start, i), *rest], end

    def _root_index(self, j: int) -> tuple[Token, int]:
        """The whole number n of `\\sqrt[n]`, and the end of its `]`."""
        k = self._skip_spaces(j + 1)
        e = k
        while e < self._n and self._chars[e].isascii() and self._chars[e].isdigit():
            e += 1
        close = self._skip_spaces(e)
        if e == k or e - k > _MAX_ROOT_INDEX_DIGITS or close >= self._n or self._chars[close] != "]":
            raise ParseError(
                r"Write a root's index as a whole number, as in \sqrt[3]{x}; for any other root write a "
                "power, as in x^(1/n).",
                j,
            )
        digits = self._text(k, e)
        if int(digits) < 2:
            raise ParseError(r"A root's index is 2 or more, as in \sqrt[3]{x}.", k)
        return Token(Kind.NUM, digits, k, e, value=Fraction(int(digits))), close + 1

    def _function(self, i: int, name: str, end: int) -> tuple[Token, int]:
        if name != "log" or end >= self._n or self._chars[end] != "_":
            return Token(Kind.FUNC, FUNCTIONS[name], i, end), end
        stop = self._base_ten_end(end)
        if stop is None:
            raise ParseError(
                r"Write a logarithm to another base b as ln(x)/ln(b); \log_{10} is read as log10.", end
            )
        return Token(Kind.FUNC, "log10", i, stop), stop

    def _base_ten_end(self, j: int) -> int | None:
        """The end of `_10` or `_{10}` at j (after `\\log`), or None: no other base has a name."""
        if self._text(j, j + 3) == "_10" and not self._text(j + 3, j + 4).isdigit():
            return j + 3
        if self._text(j, j + 2) != "_{":
            return None
        k = self._skip_spaces(j + 2)
        close = self._skip_spaces(k + 2)
        return close + 1 if self._text(k, k + 2) == "10" and self._text(close, close + 1) == "}" else None

    def _letter(self, i: int, name: str, end: int) -> tuple[Token, int]:
        word = LATEX_LETTERS[name]
        return self._word_on(word, [i] * len(word), ((0, len(word)),), i, end, digits=True)

    def _word_on(
        self,
        text: str,
        positions: list[int],
        unsplittable: tuple[tuple[int, int], ...],
        start: int,
        j: int,
        digits: bool,
    ) -> tuple[Token, int]:
        """The word `text` (typed at `positions`) continued at j by a subscript: `\\theta_0`, `\\theta0`
        (with `digits`), `v_{0}`, `v_\\theta`, `\\mathrm{v}_{max}`."""
        if j < self._n and (self._chars[j] == "_" or (digits and self._chars[j].isdigit())):
            while j < self._n and _is_word_char(self._chars[j]):
                text += self._chars[j]
                positions.append(j)
                j += 1
        if text.endswith("_") and j < self._n and self._chars[j] in "{\\":
            subscript, sub_positions, j = self._subscript(j)
            unsplittable = (*unsplittable, (len(text), len(text) + len(subscript)))
            text += subscript
            positions.extend(sub_positions)
        return SpelledWord(
            Kind.WORD, text, start, j, char_positions=(*positions, j), unsplittable=unsplittable
        ), j

    def _subscript(self, j: int) -> tuple[str, list[int], int]:
        """The subscript at j, after a `_`: `{0}`, `{max}`, `{\\text{max}}`, `\\theta`."""
        refusal = r"A subscript holds letters and digits, as in v_{0}, v_{max} or v_\theta."
        if self._chars[j] == "\\":
            return self._subscript_command(j, refusal)
        text, positions = "", []
        k = j + 1
        while True:
            k = self._skip_spaces(k)
            if k >= self._n:
                raise ParseError("Unbalanced brace: the '{' of this subscript is never closed.", j)
            ch = self._chars[k]
            if ch == "}":
                break
            if _is_word_char(ch):
                text += ch
                positions.append(k)
                k += 1
            elif ch == "\\" and self._command_name(k)[0] in _SKIPPED_IN_SUBSCRIPTS:
                k = self._command_name(k)[1]
            elif ch == "\\":
                piece, piece_positions, k = self._subscript_command(k, refusal)
                text += piece
                positions.extend(piece_positions)
            else:
                raise ParseError(refusal, k)
        if not text:
            raise ParseError("An empty subscript: write v_{0}, or the name without _.", j)
        return text, positions, k + 1

    def _subscript_command(self, j: int, refusal: str) -> tuple[str, list[int], int]:
        name, end = self._command_name(j)
        if name in LATEX_LETTERS:
            word = LATEX_LETTERS[name]
            return word, [j] * len(word), end
        if name in LATEX_TEXT_WRAPPERS:
            return self._braced_name(name, end)
        if name in _SUBSCRIPT_OPERATOR_WORDS:  # `v_{\max}`: an editor (MathQuill) sets max as an operator
            return name, list(range(j + 1, end)), end
        raise ParseError(refusal, j)

    def _units(self, i: int, name: str, end: int) -> Token:
        """`\\mathrm{m/s^2}` in a numeric answer: units, as one WORD spelled as typed (never arithmetic)
        for the numeric reader to hand to the unit reader."""
        j = self._skip_spaces(end)
        if j >= self._n or self._chars[j] != "{":
            raise ParseError(f"\\{name} needs braces after it, as in \\{name}{{m/s}}.", min(j, self._n))
        depth = 0
        for k in range(j, self._n):
            depth += {"{": 1, "}": -1}.get(self._chars[k], 0)
            if depth == 0:
                return Token(Kind.WORD, self._text(i, k + 1), i, k + 1)
        raise ParseError(f"Unbalanced brace: the '{{' of \\{name} is never closed.", j)

    def _braced_name(self, name: str, i: int) -> tuple[str, list[int], int]:
        """The name in `\\mathrm{…}` from i (after the command): its text, positions and end."""
        example = f"\\{name}{{max}}"
        j = self._skip_spaces(i)
        if j >= self._n or self._chars[j] != "{":
            raise ParseError(f"\\{name} needs a name in braces, as in {example}.", min(j, self._n))
        k = self._skip_spaces(j + 1)
        begin = k
        while k < self._n and _is_word_char(self._chars[k]):
            k += 1
        text, stop = self._text(begin, k), self._skip_spaces(k)
        if not text or stop >= self._n or self._chars[stop] != "}":
            where = min(stop, self._n) if text else begin
            raise ParseError(f"\\{name}{{…}} may only hold a name here, as in {example}.", where)
        return text, list(range(begin, k)), stop + 1

    def _delimiter(self, i: int, name: str, end: int) -> tuple[Token, int]:
        """The bracket after `\\left`, `\\right`, `\\big`…: `\\left(` is `(`, `\\left\\lvert` is `|`."""
        j = self._skip_spaces(end)
        if j < self._n and self._chars[j] in "()[]|":
            return _bracket(self._chars[j], i, j + 1), j + 1
        if j < self._n and self._chars[j] == "\\":
            bracket, after = self._command_name(j)
            if bracket in LATEX_BRACKETS:
                return _bracket(LATEX_BRACKETS[bracket], i, after), after
        if j < self._n and self._chars[j] == ".":
            raise ParseError(
                f"\\{name}. (a bracket left blank) is not read: write brackets that match, as in "
                r"\left( x \right).",
                i,
            )
        raise ParseError(f"\\{name} needs a bracket after it, as in \\left( x \\right).", i)


def _bracket(char: str, pos: int, end: int) -> Token:
    if char == "|":
        return Token(Kind.BAR, "|", pos, end)
    if char == "}":
        return Token(Kind.RPAREN, "}", pos, end)
    return Token(_BRACKET_KINDS[char], char, pos, end)


# Mathematica's named characters, as its plain text (InputForm) writes them: `\[Theta]`, `\[CapitalOmega]`.
_MATHEMATICA_CHARACTER = re.compile(r"\\\[([A-Za-z]+)\]")
_MATHEMATICA_SIGNS = {"Degree": "°", "HBar": "ħ", "Times": "*", "Pi": "π"}


def _mathematica_character_message(typed: str, name: str) -> str:
    r"""What to type for `\[Theta]` (θ or theta), or that Mathematica's named characters are not read."""
    if name in _MATHEMATICA_SIGNS:
        return (
            f"{typed} is Mathematica's name for {_MATHEMATICA_SIGNS[name]}: type {_MATHEMATICA_SIGNS[name]}."
        )
    letter = name.removeprefix("Curly")  # `\[CurlyEpsilon]`: the letter's other form
    letter = letter.removeprefix("Capital") if letter.startswith("Capital") else letter.lower()
    if letter in GREEK_LETTERS:
        return f"{typed} is Mathematica's name for {GREEK_LETTERS[letter]}: type {GREEK_LETTERS[letter]} or {letter}."
    return f"{typed} is a Mathematica character, not read here: type the expression in plain text."
