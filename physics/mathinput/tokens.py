"""Tokenizer: splits math text into tokens that carry their 0-based position in the original text.

Nothing here interprets names; words are resolved later by `names.NameTable`. Size limits on the
text, the token count and number literals are enforced here, before any value is built. Backslashes
and braces go to `latex.LatexReader`, which makes of pasted LaTeX the tokens of the plain text it means.
"""

from __future__ import annotations

import re
import unicodedata
from collections.abc import Callable
from dataclasses import replace
from fractions import Fraction

from physics import separators
from physics.characters import may_be_wrapped, without_math_delimiters, without_zero_width
from physics.errors import AnswerError, LikelySlip, ParseError, TooLarge
from physics.mathinput.latex import LatexReader
from physics.mathinput.limits import InputLimits
from physics.mathinput.mixed_numbers import mixed_number_slip
from physics.mathinput.scripts import (
    is_raised_power,
    lowered_word,
    raised_end,
    raised_exponent,
    word_before_raised,
)
from physics.mathinput.sentences import equals_sign
from physics.mathinput.tokentypes import Kind, SpelledWord, Token
from physics.mathinput.velocities import PRIMES, derivatives_read, dotted_word, is_word_mark, needs_spelling
from physics.mathinput.vocabulary import (
    CHARACTER_VARIANTS,
    CLOSERS,
    FUNCTIONS,
    GREEK_LETTERS,
    GREEK_NAMES,
    OPENERS,
    ROOT_SIGNS,
    SUPERSCRIPT_DIGITS,
    SUPERSCRIPT_PLAIN,
    SUPERSCRIPT_SIGNS,
    VULGAR_FRACTIONS,
)
from physics.wording import TRAILING_SEMICOLON

__all__ = ["Kind", "Token", "tokenize"]

# More exponent digits than this is refused before int() is asked to read them.
_MAX_SCI_EXPONENT_DIGITS = 6


# What may follow the first letter of a word, besides letters.
_WORD_MARKS = frozenset("0123456789_")


def tokenize(
    text: str, limits: InputLimits, *, units_in_fonts: bool = False, velocities: bool = False
) -> list[Token]:
    """Split `text` into tokens ending with an END token; raise ParseError/TooLarge with a position.

    `units_in_fonts`: a numeric answer's `\\mathrm{…}` or `\\text{…}` holds its units, and is one WORD as
    typed (`\\mathrm{m/s^2}`); elsewhere it may hold only a name, which is the word.
    `velocities`: a coordinate's velocity written `x'`, `ẋ`, `\\dot{x}` or `dx/dt` is the word `x_dot`
    (`velocities.py`).
    """
    if len(text) > limits.max_length:
        raise TooLarge(
            f"The answer is too long ({len(text)} characters; at most {limits.max_length}).",
            limits.max_length,
        )
    if may_be_wrapped(text):
        text = without_math_delimiters(text)  # `$\frac{mg}{k}$` copied from a document
    visible = without_zero_width(text)
    if visible is not None:  # read what the student sees; positions stay those of the typed text
        try:
            seen = tokenize(visible.text, limits, units_in_fonts=units_in_fonts, velocities=velocities)
        except AnswerError as error:
            if error.position is not None:
                error.position = visible.typed_position(error.position)
            raise
        return [_typed_where(token, visible.typed_position) for token in seen]
    # Every variant is a non-ASCII character: plain ASCII text has none to replace.
    typed_ascii = text.isascii()
    chars = list(text) if typed_ascii else [CHARACTER_VARIANTS.get(ch, ch) for ch in text]
    tokens: list[Token] = []
    latex = LatexReader(chars, units_in_fonts, velocities, tokens)
    n = len(chars)
    max_tokens = limits.max_tokens
    i = 0
    space = False
    while i < n:
        ch = chars[i]
        if ch.isspace() or (ch == "~" and latex.active):  # `~`: LaTeX's unbreakable space
            space = True
            i += 1
            continue
        if len(tokens) >= max_tokens:
            raise TooLarge(f"The answer has too many parts (at most {max_tokens} tokens).", i)
        start = i
        if (ch.isdigit() and ch.isascii()) or (ch == "." and i + 1 < n and chars[i + 1].isdigit()):
            try:
                token, i = _read_number(chars, i, space, limits)
            except LikelySlip as slip:
                # `atan2(3,4)`: a function of two arguments, where `sin(4,58)` may be sin(4.58)
                opened = _open_bracket(tokens)
                called = tokens[opened - 1] if opened else None
                if called is not None and called.kind is Kind.WORD and called.text.lower() in _TWO_ARGUMENTS:
                    raise ParseError(_comma_message(tokens), slip.position) from None
                raise
            if ch == "1" and token.text.startswith("10e"):
                _refuse_two_powers_of_ten(text, tokens, token)
        elif ch.isalpha() and ch not in SUPERSCRIPT_PLAIN:  # a word starts with a letter
            i += 1
            while i < n and (
                (c := chars[i]).isalpha() or c in _WORD_MARKS or (velocities and is_word_mark(c))
            ):
                i += 1
            lowered = None
            if not typed_ascii:  # `xʸ`: the word ends at a raised letter; `vₘₐₓ` is v_max
                i = word_before_raised(chars, start, i)
                lowered = lowered_word(chars, start, i, space)
            if velocities and i < n and chars[i] in PRIMES:
                i += 1
            if lowered is not None:
                token, i = lowered
            elif chars[i - 1] == "_" and i < n and chars[i] in "{\\":  # v_{0}, v_\theta
                token, i = latex.subscripted_word(start, i)
                token = replace(token, space_before=space)
            elif velocities and needs_spelling(chars, start, i):
                token = dotted_word(chars, start, i, space)
            else:
                token = Token(Kind.WORD, "".join(chars[start:i]), start, i, space)
        elif ch == "*" and i + 1 < n and chars[i + 1] == "*":
            i += 2
            token = Token(Kind.OP, "^", start, i, space)
        elif ch == "^" and (degree_end := latex.degree_end(i + 1)) is not None:  # 30^\circ
            token = Token(Kind.POSTFIX, "°", start, degree_end, space)
            i = degree_end
        elif (
            ch == "^"
            and tokens
            and tokens[-1].kind is Kind.NUM
            and (degree_end := _typed_degree_end(chars, i + 1))
        ):
            token = Token(Kind.POSTFIX, "°", start, degree_end, space)  # 30^o, as plain text writes 30°
            i = degree_end
        elif ch in "+-*/^":
            i += 1
            token = Token(Kind.OP, ch, start, i, space)
        elif ch in "\\{}":
            if ch == "\\":
                emitted, i = latex.command(i)
                # As in LaTeX, the spaces that end a control word are no gap: `\cos\omega t` shows ωt.
                if emitted and chars[i - 1].isalpha():
                    while i < n and chars[i].isspace():
                        i += 1
            else:
                emitted, i = (latex.open_brace if ch == "{" else latex.close_brace)(i)
            if not emitted:  # a spacing command, or `{}`
                space = True
                continue
            tokens.extend([replace(emitted[0], space_before=space), *emitted[1:]])
            if len(tokens) > max_tokens:
                raise TooLarge(f"The answer has too many parts (at most {max_tokens} tokens).", start)
            space = False
            continue
        elif ch in OPENERS:
            i += 1
            token = Token(Kind.LPAREN, ch, start, i, space)
        elif ch in CLOSERS:
            i += 1
            token = Token(Kind.RPAREN, ch, start, i, space)
        elif ch == "|":
            i += 1
            token = Token(Kind.BAR, ch, start, i, space)
        elif ch == "%" and (constant := _maxima_constant(chars, i)) is not None:  # `2*%pi`, `%e^x`
            i += 1 + len(constant)
            token = Token(Kind.CONST, constant, start, i, space)
        elif ch in "!%°":
            i += 1
            token = Token(Kind.POSTFIX, ch, start, i, space)
        elif ch in ROOT_SIGNS:
            i += 1
            token = Token(Kind.SQRT, ch, start, i, space)
        elif ch in SUPERSCRIPT_PLAIN and _slash_between_raised(chars, i):
            raise _unraised_slash(chars, tokens, i, raised_end(chars, i))
        elif ch in SUPERSCRIPT_DIGITS and (fraction := script_fraction(text, i)) is not None:
            # `⁵⁄₇ g sin θ`: a fraction set with raised and lowered digits, as a word processor's or a
            # "fraction generator" gives it, is the number 5/7, as `½` is
            top, bottom, end = fraction
            typed = text[i:end]
            if _ends_with_whole_number(tokens):  # `1 ⁵⁄₇`: a mixed number, as `1 ½`
                raise mixed_number_slip(
                    int(tokens[-1].text),
                    Fraction(top, bottom),
                    f"{tokens[-1].text}{' ' if space else ''}{typed}",
                    i,
                )
            if tokens and tokens[-1].kind in _FRACTION_IS_POWER_AFTER and not space:
                named = tokens[-1].text if tokens[-1].kind in (Kind.NUM, Kind.WORD, Kind.CONST) else "(…)"
                raise ParseError(
                    f"A raised fraction {typed} after {named}: write {named}^({top}/{bottom}) for a power, "
                    f"or {top}/{bottom} {named} for a product.",
                    i,
                )
            tokens.extend(_fraction_tokens(top, bottom, i, end, space))
            i = end
            space = False
            continue
        elif ch in SUPERSCRIPT_PLAIN and not is_raised_power(chars, i, end := raised_end(chars, i)):
            if chars[i] == "ᵒ" and end == i + 1 and tokens and tokens[-1].kind is Kind.NUM:
                token = Token(Kind.POSTFIX, "°", start, end, space)  # 30ᵒ, a degree as a raised o
                i = end
            else:  # `e⁻ʷᵗ`: an exponent typed raised, read as `^(-wt)`
                if tokens and tokens[-1].kind is Kind.OP and tokens[-1].text == "^" and not space:
                    space = tokens.pop().space_before  # `e^ʷᵗ`: the caret and the raised run are one power
                raised = raised_exponent(
                    chars, i, end, space, lambda plain: tokenize(plain, limits, velocities=velocities)
                )
                tokens.extend(raised)
                if len(tokens) > max_tokens:
                    raise TooLarge(f"The answer has too many parts (at most {max_tokens} tokens).", start)
                i = end
                space = False
                continue
        elif ch in SUPERSCRIPT_SIGNS and i + 1 < n and chars[i + 1] in VULGAR_FRACTIONS:
            # `(k/m)⁻½`: a raised minus, then the fraction no palette raises: the power −½
            tokens.append(Token(Kind.OP, "^", i, i, space))
            token = Token(Kind.OP, "-" if SUPERSCRIPT_SIGNS[ch] < 0 else "+", i, i + 1)
            i += 1
        elif ch in SUPERSCRIPT_DIGITS or ch in SUPERSCRIPT_SIGNS:
            token, i = _read_superscript(chars, i, space)
            if tokens and tokens[-1].kind is Kind.OP and tokens[-1].text == "^" and not space:
                tokens.pop()  # `x^²`: the caret, then the superscript from a palette, is the one power
            elif _caret_and_minus(tokens) and not space:
                # `v^-²`: the caret and the minus typed, then the digit from a palette: the power −2
                assert token.value is not None
                token = replace(token, value=-token.value, space_before=tokens[-2].space_before)
                del tokens[-2:]
        elif ch in VULGAR_FRACTIONS:
            if _ends_with_whole_number(tokens):  # `1½`, `1 ½`: one and a half, never 1·½
                typed = f"{tokens[-1].text}{' ' if space else ''}{ch}"
                raise mixed_number_slip(int(tokens[-1].text), Fraction(*VULGAR_FRACTIONS[ch]), typed, i)
            if tokens and tokens[-1].kind is Kind.NUM and not space:
                raise ParseError(f"Write a number as a fraction or a decimal, not {tokens[-1].text}{ch}.", i)
            tokens.extend(_vulgar_fraction(ch, i, space))
            i += 1
            space = False
            continue
        elif ch == ",":
            raise ParseError(_comma_message(tokens), i)
        elif ch == "." and tokens and not "".join(chars[i + 1 :]).strip():
            i += 1  # the full stop of a sentence: `√(2gh).`, as a numeric answer's `4.58 m/s^2.`
            continue
        elif ch == "." and i + 1 < n and chars[i + 1] in _ELEMENTWISE:  # MATLAB's `v.^2`, `m.*g`, `a./b`
            op = chars[i + 1]
            raise LikelySlip(
                f"Did you mean {op}? .{op} is MATLAB's element-wise {_ELEMENTWISE[op]}: type {op} alone.", i
            )
        elif (
            ch == "." and tokens and tokens[-1].text in _CODE_MODULES and i + 1 < n and chars[i + 1].isalpha()
        ):
            # `np.sqrt(2*g*h)`, `math.pi`: a name as Python code writes it
            module = tokens[-1].text
            raise LikelySlip(
                f"Leave out {module}.: type the function or constant alone, as in sqrt(x) or pi.", i
            )
        elif (
            ch == "."
            and tokens
            and tokens[-1].kind in (Kind.WORD, Kind.RPAREN)
            and i + 1 < n
            and (chars[i + 1].isalpha() or chars[i + 1] in ROOT_SIGNS or chars[i + 1] == "(")
        ):
            # `m.g`, `sin θ.cos θ`, `2π.√(L/g)`: a dot for a product, as some schools write it
            raise ParseError("Write a product with * or a space, not '.': m*g or m g.", i)
        elif ch in PRIMES and not velocities and tokens and tokens[-1].kind is Kind.WORD:
            raise ParseError(
                f"A prime ({tokens[-1].text}{ch}) is not read here: an answer is in the problem's symbols, "
                "as they are listed (a derivative or a velocity only where the part asks for one).",
                i,
            )
        elif ch == ";" and not "".join(chars[i + 1 :]).strip():
            # `m g sin θ;`: a command's end in Maxima or MATLAB; refused at the end, as STACK refuses it
            raise ParseError(TRAILING_SEMICOLON, i)
        elif ch == "$":  # what is left of LaTeX's math delimiters, when they wrap only part of it
            raise ParseError(
                "Leave out the $ signs: type the expression alone (or all of it between two $).", i
            )
        elif ch in "=≈":  # `a = g sin θ`, `≈ 2g`, as written on paper
            raise equals_sign("".join(chars), i)
        elif ch == ":":  # `a: m*g`, Maxima's assignment; `Answer: 2g`, as a sentence introduces it
            raise ParseError("Give the expression alone, without ':' (nor what comes before it).", i)
        elif unicodedata.combining(ch) and tokens and tokens[-1].kind is Kind.WORD and not space:
            # `v⃗`, `v̄`, `x̂`: a mark set over a letter, as a vector or a mean is written on paper (a dot is
            # a velocity only where a part asks for one: velocities.py)
            raise ParseError(
                f"A mark over {tokens[-1].text[-1]} (an arrow, a bar, a hat, a dot) is not read: type the symbol as "
                "the problem lists it, without the mark.",
                i,
            )
        elif ch in _GREEK_LOOKALIKE_SIGNS:  # `sin ∝`: a phone's symbols offer ∝ where α is meant
            letter = _GREEK_LOOKALIKE_SIGNS[ch]
            raise ParseError(
                f"{ch} is the sign for 'proportional to', not read here: for {letter} type {letter} or "
                f"{GREEK_NAMES[letter]}.",
                i,
            )
        elif ch in _OPENING_QUOTES and not tokens:  # `"m*g"`, as an instruction quoted how to type it
            raise LikelySlip("Leave out the quotation marks: type the answer alone.", i)
        elif ch in _LONG_DASHES:  # `—mg`: a phone's long dash, or the one `--` turns into; never guessed
            raise LikelySlip(f"{ch} is a dash, which is not read here: for a minus sign, type -.", i)
        else:
            raise ParseError(f"Unexpected character {text[i]!r}.", i)
        tokens.append(token)
        space = False
    latex.finish()
    tokens.append(Token(Kind.END, "", n, n, space))
    if _MAYBE_POWER_ZERO.search(text):  # the walk over the tokens only where a 0 can be a power
        _refuse_powers_zero_for_degrees(tokens)
    return derivatives_read(tokens) if velocities else tokens


# MATLAB's element-wise operators, `.^`, `.*`, `./`: each the operator after its dot.
_ELEMENTWISE = {"^": "power", "*": "product", "/": "division"}
# Modules whose functions Python code names with the module: `np.sqrt`, `math.pi`.
_CODE_MODULES = frozenset({"np", "numpy", "math", "cmath", "sp", "sympy", "scipy"})

# Signs that look like a Greek letter, and the letter: ∝ (proportional to) for α.
_GREEK_LOOKALIKE_SIGNS = {"∝": "α"}

# Quotation marks that open a quoted answer: straight, typographic, low and guillemets.
_OPENING_QUOTES = "\"'‘“„«"

# Dashes longer than the en dash that is read as a minus (CHARACTER_VARIANTS): the em dash, the
# horizontal bar, the figure dash.
_LONG_DASHES = "—―‒"


def _typed_where(token: Token, typed_position: Callable[[int], int]) -> Token:
    """The token with its positions in the typed text (of which it was read without zero-width characters)."""
    moved = replace(token, pos=typed_position(token.pos), end=typed_position(token.end))
    if isinstance(moved, SpelledWord):
        moved.char_positions = tuple(map(typed_position, moved.char_positions))
        moved.unsplittable = tuple((typed_position(a), typed_position(b)) for a, b in moved.unsplittable)
    return moved


# Maxima's constants, as STACK students type them: `%pi` is π and `%e` Euler's number, never a percent.
_MAXIMA_CONSTANTS = ("pi", "e")


def _maxima_constant(chars: list[str], i: int) -> str | None:
    """The constant named after the `%` at i (`%pi`, `%e`), else None."""
    for name in _MAXIMA_CONSTANTS:
        end = i + 1 + len(name)
        if "".join(chars[i + 1 : end]) == name and not (end < len(chars) and chars[end].isalnum()):
            return name
    return None


def _typed_degree_end(chars: list[str], i: int) -> int | None:
    """The end of a degree typed as a power after the `^` ending at i: `o`, `°` or `{o}` (`30^o`), else
    None. No one raises a number to a letter o."""
    n = len(chars)
    braced = i < n and chars[i] == "{"
    j = i + 1 if braced else i
    if j >= n or chars[j] not in "o°":
        return None
    j += 1
    if braced:
        return j + 1 if j < n and chars[j] == "}" else None
    return None if j < n and (chars[j].isalnum() or chars[j] == "_") else j


_MAYBE_POWER_ZERO = re.compile(r"\^[\s({]*[0.]|⁰")


def _refuse_powers_zero_for_degrees(tokens: list[Token]) -> None:
    """`30^0`, `30^{0}`, `30⁰`: a degree sign typed as a zero, or the number 1? Refused, with both: no one
    writes 1 so. (10^0 is a power of ten, as in 4.58×10^0.)"""
    for k, zero in enumerate(tokens):
        if zero.kind not in (Kind.NUM, Kind.SUP) or zero.value != 0:
            continue
        at = k
        if zero.kind is Kind.NUM:  # after `^`, or after `^(` with its bracket closed right after the 0
            bracketed = (
                tokens[k - 1].kind is Kind.LPAREN and tokens[k + 1].kind is Kind.RPAREN if k else False
            )
            caret = k - 2 if bracketed else k - 1
            if caret < 1 or tokens[caret].kind is not Kind.OP or tokens[caret].text != "^":
                continue
            at = caret
        base = tokens[at - 1] if at else None
        if base is None or base.kind is not Kind.NUM or base.text == "10":
            continue
        raise LikelySlip(
            f"Did you mean {base.text}° or {base.text} to the power 0 (which is 1)? For degrees write "
            f"{base.text}° or {base.text} deg.",
            tokens[at].pos,
        )


# Two-argument functions students know from programming or calculators, and how the answer writes them.
_TWO_ARGUMENTS = {
    "atan2": "the angle as atan(y/x)",
    "arctan2": "the angle as atan(y/x)",
    # a power or a root as code and spreadsheets write it: `pow(x, 2)`, `POWER(x, 0.5)`, `nthroot(x, 3)`
    "pow": "a power with ^, as x^2 or x^(1/2)",
    "power": "a power with ^, as x^2 or x^(1/2)",
    "nthroot": "a root as a power, as x^(1/3), or with sqrt(x)",
    "root": "a root as a power, as x^(1/3), or with sqrt(x)",
    "surd": "a root as a power, as x^(1/3), or with sqrt(x)",
}


def _comma_message(before: list[Token]) -> str:
    """Why a comma cannot be read, by where it stands: in a function's brackets (`atan2(y, x)`), in
    plain brackets (a pair), or between two expressions."""
    at = _open_bracket(before)
    if at is None:
        return "Commas are not used in answers: give one expression (a product is written with * or a space)."
    name = before[at - 1].text if at and before[at - 1].kind is Kind.WORD else None
    if name is None:
        return "Commas are not used in answers: give one expression, not a pair or a list."
    if name in FUNCTIONS:
        return f"Commas are not used in answers: {name}(…) takes one argument."
    written = _TWO_ARGUMENTS.get(name.lower())
    instead = f"; write {written}" if written else ""
    return f"Commas are not used in answers: a function of several arguments cannot be written{instead}."


def _open_bracket(before: list[Token]) -> int | None:
    """Where the innermost bracket still open after `before` opens, if one is."""
    depth = 0
    for at in range(len(before) - 1, -1, -1):
        kind = before[at].kind
        if kind is Kind.RPAREN:
            depth += 1
        elif kind is Kind.LPAREN:
            if not depth:
                return at
            depth -= 1
    return None


def _vulgar_fraction(ch: str, i: int, space: bool) -> list[Token]:
    """`½` as the tokens of `(1/2)`, all at the character's position."""
    return _fraction_tokens(*VULGAR_FRACTIONS[ch], i, i + 1, space)


def _fraction_tokens(top: int, bottom: int, start: int, end: int, space: bool) -> list[Token]:
    """A fraction typed as one sign (`½`, `⁵⁄₇`) as the tokens of `(5/7)`, each spanning the sign."""
    return [
        Token(Kind.LPAREN, "(", start, end, space),
        Token(Kind.NUM, str(top), start, end, False, Fraction(top)),
        Token(Kind.OP, "/", start, end),
        Token(Kind.NUM, str(bottom), start, end, False, Fraction(bottom)),
        Token(Kind.RPAREN, ")", start, end),
    ]


def _slash_between_raised(chars: list[str], i: int) -> bool:
    """Whether the raised run at i is followed by a slash and another raised run (`⁻ᵇᵗ/²ᵐ`)."""
    slash = raised_end(chars, i)
    return slash + 1 < len(chars) and chars[slash] == "/" and chars[slash + 1] in SUPERSCRIPT_PLAIN


def _unraised_slash(chars: list[str], tokens: list[Token], i: int, slash: int) -> ParseError:
    """`A e⁻ᵇᵗ/²ᵐ`: an exponent typed raised, its slash typed plain, as no keyboard raises one. As typed
    the exponent ends at the slash; refused, saying how to write the whole exponent in ^( )."""
    top = "".join(SUPERSCRIPT_PLAIN[c] for c in chars[i:slash])
    bottom = "".join(SUPERSCRIPT_PLAIN[c] for c in chars[slash + 1 : raised_end(chars, slash + 1)])
    one_factor = len(bottom) == 1 or bottom.isdigit() or bottom in GREEK_LETTERS  # `t/tau`, not `t/(tau)`
    divisor = bottom if one_factor else f"({bottom})"
    base = tokens[-1].text if tokens and tokens[-1].kind in (Kind.WORD, Kind.CONST) else ""
    return ParseError(
        f"The exponent is raised but its '/' is not, so the exponent ends at the '/': write the whole "
        f"exponent in ^( ), as {base}^({top}/{divisor}).",
        slash,
    )


# After these a raised fraction (`x⁵⁄₇`) may be a power as much as a product: asked, never guessed.
_FRACTION_IS_POWER_AFTER = (Kind.NUM, Kind.WORD, Kind.CONST, Kind.RPAREN, Kind.POSTFIX, Kind.BAR)
_SUBSCRIPT_DIGITS = "₀₁₂₃₄₅₆₇₈₉"
_FRACTION_SLASHES = "⁄/∕"
_MAX_SCRIPT_DIGITS = 6  # far more than any fraction typed this way; bounds the digits read


def script_fraction(text: str, i: int) -> tuple[int, int, int] | None:
    """A fraction of raised digits over lowered ones at i (`⁵⁄₇`, `¹/₁₂`): (top, bottom, end), or None."""
    slash = i
    while slash < len(text) and text[slash] in SUPERSCRIPT_DIGITS:
        slash += 1
    if slash == len(text) or text[slash] not in _FRACTION_SLASHES:
        return None
    end = slash + 1
    while end < len(text) and text[end] in _SUBSCRIPT_DIGITS:
        end += 1
    if end == slash + 1 or max(slash - i, end - slash - 1) > _MAX_SCRIPT_DIGITS:
        return None
    top = int("".join(str(SUPERSCRIPT_DIGITS[c]) for c in text[i:slash]))
    bottom = int("".join(str(_SUBSCRIPT_DIGITS.index(c)) for c in text[slash + 1 : end]))
    return top, bottom, end


def _read_number(chars: list[str], i: int, space: bool, limits: InputLimits) -> tuple[Token, int]:
    n = len(chars)
    start = i
    while i < n and chars[i].isascii() and chars[i].isdigit():
        i += 1
    whole = "".join(chars[start:i])
    fraction = ""
    if i < n and chars[i] == ".":
        i += 1
        frac_start = i
        while i < n and chars[i].isascii() and chars[i].isdigit():
            i += 1
        fraction = "".join(chars[frac_start:i])
    if i + 1 < n and chars[i] == "," and chars[i + 1].isdigit():
        raise separators.comma_in_number("".join(chars), i)
    if "".join(chars[i : i + 3]) == separators.LATEX_COMMA and i + 3 < n and chars[i + 3].isdigit():
        raise separators.comma_in_number("".join(chars), i)
    if i + 1 < n and chars[i] == separators.ARABIC_THOUSANDS and chars[i + 1].isdigit():
        raise separators.arabic_thousands("".join(chars), i)
    digits = len(whole) + len(fraction)
    if digits > limits.max_number_digits:
        raise TooLarge(f"A number has too many digits (at most {limits.max_number_digits}).", start)
    shift = 0
    literal = (whole or "0") + ("." + fraction if fraction else "")
    if i < n and chars[i] in "eE":
        j = i + 1
        sign = ""
        if j < n and chars[j] in "+-":
            sign = chars[j]
            j += 1
        exp_start = j
        while j < n and chars[j].isascii() and chars[j].isdigit():
            j += 1
        if j > exp_start:  # otherwise the e is a name (2e is 2 times e)
            exp_digits = "".join(chars[exp_start:j])
            if len(exp_digits) > _MAX_SCI_EXPONENT_DIGITS or int(exp_digits) > limits.max_sci_exponent:
                raise TooLarge(f"A power of ten is too large (at most 10^{limits.max_sci_exponent}).", start)
            shift = int(exp_digits) * (-1 if sign == "-" else 1)
            literal += "e" + ("-" if sign == "-" else "") + exp_digits.lstrip("0").rjust(1, "0")
            i = j
    # Fraction(n) for a whole number: the value Fraction(n, 1) is, without its gcd.
    value = (
        Fraction(int(whole + fraction or "0"), 10 ** len(fraction))
        if fraction
        else Fraction(int(whole or "0"))
    )
    if shift:
        value *= Fraction(10) ** shift
    return Token(Kind.NUM, literal, start, i, space, value), i


def _refuse_two_powers_of_ten(text: str, tokens: list[Token], ten: Token) -> None:
    """`3.0×10e8`: a power of ten marked by both ×10 and e, which is 3.0×10^9 as typed; refused (as a
    numeric answer's literal is), asking which was meant."""
    if len(tokens) < 2 or tokens[-2].kind is not Kind.NUM:
        return
    times = tokens[-1]
    if times.kind is not Kind.OP or times.text != "*" or text[times.pos : times.end] == "**":
        return
    typed = text[ten.pos : ten.end]
    letter, exponent = typed[2], typed[3:]
    mantissa = text[tokens[-2].pos : tokens[-2].end]
    raise LikelySlip(
        f"Did you mean {mantissa}×10^{exponent} or {mantissa}{letter}{exponent}? ×10 and {letter} each mark a "
        "power of ten: write one of them, not both",
        ten.pos + 2,
    )


def _ends_with_whole_number(tokens: list[Token]) -> bool:
    """Whether the tokens end with a whole number that is not an exponent (`1` of `1 1/2`, not the `2`
    of `x^2 ½`), so that a fraction after it makes a mixed number."""
    if not tokens or tokens[-1].kind is not Kind.NUM or not tokens[-1].text.isdigit():
        return False
    return len(tokens) < 2 or tokens[-2].kind is not Kind.OP or tokens[-2].text != "^"


def _caret_and_minus(tokens: list[Token]) -> bool:
    """Whether the tokens end with a `^` and a minus glued to it (`v^-`)."""
    return (
        len(tokens) >= 2
        and tokens[-1].kind is Kind.OP
        and tokens[-1].text == "-"
        and not tokens[-1].space_before
        and tokens[-2].kind is Kind.OP
        and tokens[-2].text == "^"
    )


def _read_superscript(chars: list[str], i: int, space: bool) -> tuple[Token, int]:
    n = len(chars)
    start = i
    sign = 1
    while i < n and chars[i] in SUPERSCRIPT_SIGNS:
        sign *= SUPERSCRIPT_SIGNS[chars[i]]
        i += 1
    digits_start = i
    value = 0
    while i < n and chars[i] in SUPERSCRIPT_DIGITS and i - digits_start < _MAX_SCI_EXPONENT_DIGITS:
        value = value * 10 + SUPERSCRIPT_DIGITS[chars[i]]
        i += 1
    if i == digits_start:
        raise ParseError("A superscript sign needs superscript digits after it (as in s⁻²).", start)
    text = "".join(chars[start:i])
    return Token(Kind.SUP, text, start, i, space, Fraction(sign * value)), i
