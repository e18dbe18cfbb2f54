"""Turning WORD tokens into names, constants, functions and the postfix word `deg`.

A glued run (`mgsin`) becomes several tokens, each with its own position in the original text.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from fractions import Fraction

from physics.characters import as_latin, lookalike_hint
from physics.errors import AmbiguousInput, TooLarge, UnknownFunction, UnknownSymbol
from physics.mathinput.names import NameTable, Part
from physics.mathinput.sentences import refuse_a_named_answer, refuse_a_remark, refuse_leading_sentence
from physics.mathinput.tokentypes import Kind, SpelledWord, Token
from physics.mathinput.vocabulary import DEGREE_WORD, FUNCTIONS, LISTED_FUNCTIONS, MAX_WORD_LENGTH, TIMES_WORD

_ENDS_OPERAND = frozenset({Kind.NUM, Kind.NAME, Kind.CONST, Kind.RPAREN, Kind.POSTFIX, Kind.SUP})
_PART_KINDS = {"name": Kind.NAME, "const": Kind.CONST, "func": Kind.FUNC}


def reading_text(reading: tuple[Part, ...]) -> str:
    return "*".join(part.canonical for part in reading)


def _keeps_whole(reading: tuple[Part, ...], tok: SpelledWord) -> bool:
    """Whether no part of the reading starts inside a stretch typed as one (`\\theta`, `x_{mg}`)."""
    return not any(low < part.start < high for part in reading for low, high in tok.unsplittable)


def resolve_words(tokens: list[Token], table: NameTable, text: str) -> list[Token]:
    """Replace every WORD token of `text`; raise on the first word that is unknown or reads two ways."""
    out: list[Token] = []
    tokens = _latex_letters_joined(tokens, table)
    for index, tok in enumerate(tokens):
        if tok.kind is not Kind.WORD:
            out.append(tok)
            continue
        word = tok.text
        prev = out[-1] if out else None
        nxt = tokens[index + 1]
        if word == DEGREE_WORD and not table.is_declared(word) and prev and prev.kind in _ENDS_OPERAND:
            out.append(Token(Kind.POSTFIX, "°", tok.pos, tok.end, tok.space_before))
            continue
        if word == TIMES_WORD and prev is not None and prev.kind is Kind.NUM and nxt.kind is Kind.NUM:
            if table.is_declared(word):  # `2 x 10^3 x`: a calculator's times sign as much as the symbol
                raise _times_or_symbol(word, prev.text, nxt.text, tok.pos)
            out.append(Token(Kind.OP, "*", tok.pos, tok.end, tok.space_before))
            continue
        if (
            word in _TIMES_TEN
            and prev is not None
            and prev.kind is Kind.NUM
            and _raised(nxt)
            and not table.resolve(word).readings  # x_10 declared: 2x10^3 is 2·x_10³
        ):
            # `2x10^3`: a calculator's power of ten, the times sign glued to the 10
            if table.is_declared(word[0]):
                raise _times_or_symbol(word[0], prev.text, "10", tok.pos)
            ten = tok.position_in_text(1)
            out.append(Token(Kind.OP, "*", tok.pos, ten, tok.space_before))
            out.append(Token(Kind.NUM, "10", ten, tok.end, False, Fraction(10)))
            continue
        if len(word) > MAX_WORD_LENGTH and not table.is_declared(word):
            raise TooLarge(
                f"A run of {len(word)} letters is too long to read (at most {MAX_WORD_LENGTH}); "
                "put spaces or * between the names.",
                tok.pos,
            )
        readings = table.resolve(word).readings
        spelled = isinstance(tok, SpelledWord)
        if isinstance(tok, SpelledWord):
            readings = tuple(r for r in readings if _keeps_whole(r, tok))
        if len(readings) == 1:
            _refuse_degree_function(word, readings[0], tokens[index + 1 :], text, tok.pos)
            space = tok.space_before
            for part in readings[0]:
                if spelled:
                    start, end = tok.position_in_text(part.start), tok.position_in_text(part.end)
                else:  # typed as it is read: each character where it stands
                    start, end = tok.pos + part.start, tok.pos + part.end
                out.append(Token(_PART_KINDS[part.kind], part.canonical, start, end, space))
                space = False
            continue
        if not readings and not spelled:
            split = _function_number_split(word, table)
            if split is None and nxt.kind is not Kind.LPAREN:
                split = _number_ending(word, table, degrees=nxt.kind is Kind.POSTFIX and nxt.text == "°")
            if split is not None:  # `sin2θ`: sin, 2, θ, which the parser reads as sin(2θ)
                out.extend(_split_tokens(split, tok))
                continue
        if readings:
            texts = [reading_text(r) for r in readings]
            raise AmbiguousInput(
                f'"{word}" can be read as {texts[0]} or {texts[1]}. '
                "Write * or a space between the names you mean.",
                tok.pos,
                texts,
            )
        if nxt.kind is Kind.LPAREN:
            lowered = word.lower()  # `Sin(θ)`, `SQRT(x)`: a phone's capital, or caps lock
            meant = (
                f" Did you mean {lowered}? Function names are in small letters."
                if lowered in FUNCTIONS
                else other_names_hint(word, degree_function_argument(tokens[index + 1 :], text))
                or root_hint(word, tokens[index + 1 :], text)
                or _glued_capital_function_hint(word, table)
            )
            raise UnknownFunction(
                f'Unknown function "{word}".{meant} Functions you can use: {", ".join(LISTED_FUNCTIONS)}.',
                tok.pos,
                word,
                LISTED_FUNCTIONS,
            )
        refuse_a_remark(tokens, index, table, text)
        if prev is None:
            refuse_leading_sentence(tokens, table, text)
        elif index == 1:
            refuse_a_named_answer(tokens, table, text)
        allowed = table.declared
        listed = ", ".join(allowed) if allowed else "none"
        constants = "the constants pi and e" if table.euler_available else "the constant pi"
        raise UnknownSymbol(
            f'Unknown symbol "{word}". Symbols you can use: {listed} (and {constants}).'
            + _greek_stand_in_hint(word, allowed)
            + _letter_o_hint(word, allowed, table)
            + capital_pi_hint(word)
            + _spaced_name_hint(word, nxt, table)
            + _lookalike_hint(word, table)
            + glued_angle_hint(word)
            + _digits_as_power_hint(word, table)
            + _case_hint(word, allowed, table)
            + _subscript_hint(word, allowed, table)
            + _times_letter_hint(word, prev, nxt)
            + _spaced_exponent_hint(word, prev)
            + other_names_hint(word, degree_function_argument(tokens[index + 1 :], text))
            + root_hint(word, tokens[index + 1 :], text),
            tok.pos,
            word,
            allowed,
        )
    return out


_TIMES_TEN = frozenset({"x10", "X10"})


def _raised(token: Token) -> bool:
    return token.kind is Kind.SUP or (token.kind is Kind.OP and token.text == "^")


def _times_or_symbol(letter: str, before: str, after: str, position: int) -> AmbiguousInput:
    return AmbiguousInput(
        f"Is the {letter} between {before} and {after} a times sign or your symbol {letter}? Write × or * for "
        f"a times sign, or * on both sides of the symbol ({before}*{letter}*{after}).",
        position,
        (f"{before}*{after}", f"{before}*{letter}*{after}"),
    )


def _latex_letters_joined(tokens: list[Token], table: NameTable) -> list[Token]:
    """`\\Delta x` as the word Δx it shows (the space ending a command is no gap), where `Delta` alone is
    no name and the two together read one way only (`Delta_x` declared); other tokens as they are."""
    joined: list[Token] = []
    k = 0
    while k < len(tokens):
        tok = tokens[k]
        nxt = tokens[k + 1] if k + 1 < len(tokens) else None
        if (
            isinstance(tok, SpelledWord)
            and nxt is not None
            and nxt.kind is Kind.WORD
            and not nxt.space_before
            and not table.resolve(tok.text).readings
        ):
            word = SpelledWord(
                Kind.WORD,
                tok.text + nxt.text,
                tok.pos,
                nxt.end,
                tok.space_before,
                char_positions=(
                    *tok.char_positions[:-1],
                    *(nxt.position_in_text(at) for at in range(len(nxt.text) + 1)),
                ),
                unsplittable=tok.unsplittable,
            )
            readings = [r for r in table.resolve(word.text).readings if _keeps_whole(r, word)]
            if len(readings) == 1:
                joined.append(word)
                k += 2
                continue
        joined.append(tok)
        k += 1
    return joined


# A word that reads no way as it stands, but does with a number after a function split out: `sin2θ`.
_FUNCTION_NUMBER = re.compile(r"(\D+?)(\d+)(\D.*)")


def _function_number_split(word: str, table: NameTable) -> list[Part | tuple[str, int, int]] | None:
    """`sin2θ`, `mgsin2θ`, `cos2ωt`, `sin2θcos2θ` as physics types `sin 2θ`: the parts before the first
    digits (ending with a function), the digits (as text, start, end), and what follows, split the
    same way where it reads no way as it stands; None unless every piece has exactly one reading."""
    found = _FUNCTION_NUMBER.fullmatch(word)
    if found is None:
        return None
    before = table.resolve(found.group(1)).unique
    if before is None or before[-1].kind != "func":
        return None
    start, end = found.span(2)
    rest = found.group(3)
    resolved = table.resolve(rest)
    after: list[Part | tuple[str, int, int]] | None
    if resolved.readings:  # one reading, or two: ambiguous, so no split is safe
        after = list(resolved.unique) if resolved.unique is not None else None
    else:
        after = _function_number_split(rest, table)
    if after is None:
        return None
    shifted = [_shifted(piece, end) for piece in after]
    return [*before, (found.group(2), start, end), *shifted]


# A word ending in a number that is the argument of `ln` or `sqrt` before it, as `ln2` and `sqrt2` are
# typed (not `log2`, which may name a base, nor `sin30`, which would be 30 radians); and of a function
# of an angle where a degree sign follows (`sin30°`).
_NUMBER_ENDING = re.compile(r"(\D*(?:ln|sqrt))(\d+)")
_DEGREES_ENDING = re.compile(r"(\D*(?:sin|cos|tan|sec|csc|cot))(\d+)")


def _number_ending(word: str, table: NameTable, *, degrees: bool) -> list[Part | tuple[str, int, int]] | None:
    """`ln2`, `mln2`, `sqrt2`, `sin30` before a degree sign: the parts before the number (ending with the
    function), and the number; None unless they read exactly one way. Not before a bracket: `ln2(x)`
    says nothing of what is meant."""
    found = (_DEGREES_ENDING if degrees else _NUMBER_ENDING).fullmatch(word)
    if found is None:
        return None
    before = table.resolve(found.group(1)).unique
    if before is None or before[-1].kind != "func":
        return None
    return [*before, (found.group(2), *found.span(2))]


def _shifted(piece: Part | tuple[str, int, int], by: int) -> Part | tuple[str, int, int]:
    if isinstance(piece, Part):
        return Part(piece.kind, piece.canonical, piece.start + by, piece.end + by)
    return (piece[0], piece[1] + by, piece[2] + by)


def _split_tokens(pieces: list[Part | tuple[str, int, int]], tok: Token) -> list[Token]:
    tokens = []
    for k, piece in enumerate(pieces):
        space = tok.space_before if k == 0 else False
        if isinstance(piece, Part):
            start, end = tok.position_in_text(piece.start), tok.position_in_text(piece.end)
            tokens.append(Token(_PART_KINDS[piece.kind], piece.canonical, start, end, space))
        else:
            digits, low, high = piece
            start, end = tok.position_in_text(low), tok.position_in_text(high)
            tokens.append(Token(Kind.NUM, digits, start, end, space, Fraction(int(digits))))
    return tokens


# Latin letters students type for a Greek one that looks alike: `wt` for ωt, `u` for μ.
_STAND_INS = {"w": ("omega", "ω"), "u": ("mu", "μ"), "a": ("alpha", "α")}


# π as a calculator, a spreadsheet (`PI()`) or Mathematica (`Pi`) spells it, and the capital letter
_CAPITAL_PIS = frozenset({"PI", "Pi", "pI", "Π"})


def capital_pi_hint(word: str) -> str:
    """A sentence for `PI`, `Pi`, `Π` (not declared, or the word would be read), or ""."""
    if word in _CAPITAL_PIS or (word[:2] in _CAPITAL_PIS and len(word) > 2) or word[:1] == "Π":
        return " If you mean the number π, type pi or π (in small letters)."
    return ""


def _letter_o_hint(word: str, declared: Sequence[str], table: NameTable) -> str:
    """A sentence for `vo` typed with the letter o where `v_0` is declared (an initial value), or "";
    also for a Greek letter (`θ_o` for theta_0) and the subscript letter o (`θₒ`)."""
    base = word[:-1].rstrip("_")
    if len(word) > 1 and word[-1] in "oOₒ" and (f"{base}_0" in declared or _one_name(f"{base}_0", table)):
        return f" If {word} is {base} with a zero, type {base}0 or {base}_0 (a zero, not the letter o)."
    return ""


def _one_name(word: str, table: NameTable) -> bool:
    """Whether the word reads as one declared name (`θ_0` as theta_0)."""
    unique = table.resolve(word).unique
    return unique is not None and len(unique) == 1 and unique[0].kind == "name"


def _spaced_name_hint(word: str, nxt: Token, table: NameTable) -> str:
    """A sentence for `Δ x` (`Delta x`) where the two words together are a declared name (`Delta_x`)."""
    if nxt.kind is not Kind.WORD or not _one_name(word + nxt.text, table):
        return ""
    return f" If {word} {nxt.text} is {word}{nxt.text}, type it without the space."


# Names of functions that Russian and some European textbooks use (and ISO 80000-2's lg, the common
# logarithm), and the name to type for each.
_OTHER_FUNCTION_NAMES = {
    "tg": "tan", "ctg": "cot", "cotg": "cot", "arctg": "atan", "arcctg": "acot", "lg": "log10",
}  # fmt: skip
_OTHER_FUNCTION_WORD = re.compile(r"(arcctg|arctg|cotg|ctg|tg|lg)(?![a-z])")


# MATLAB's functions of an angle in degrees (`sind(30)`), and the function to type with a degree sign.
_DEGREE_FUNCTION_WORD = re.compile(r"(sin|cos|tan|sec|csc|cot)d(?![a-z])")


def other_names_hint(word: str, argument: str = "") -> str:
    """A sentence for `tg θ`, `arctg(x)`: a function under its Russian or European name, or MATLAB's
    `sind(30)`, shown with its `argument` as typed where known (`sind(30)`: "write sin(30°)"); or "".
    Never read as the function: t·g where t and g are declared is read so, as before."""
    degrees = _DEGREE_FUNCTION_WORD.match(word)
    if degrees is not None:
        name = degrees.group(1)
        glued = word[degrees.end() :]  # `sind30`
        return _degree_function_hint(name, glued if glued.isdecimal() else argument.strip())
    found = _OTHER_FUNCTION_WORD.match(word)
    if found is None:
        return ""
    name = _OTHER_FUNCTION_NAMES[found.group(1)]
    return f" Did you mean {name}? Write {name} for {found.group(1)}, as in {name}(x)."


# A square root's name as students spell it out, and `sqr`, BASIC's and Pascal's square (a square root to
# many who type it).
_ROOT_SUFFIXES = ("squareroot", "sqrroot", "sqroot", "root", "sqr")  # the longest that ends a word first


def root_hint(word: str, following: list[Token], text: str) -> str:
    """A sentence for `root(L/g)`, `squareroot(L/g)`: "Did you mean sqrt(L/g)?", and with what is glued
    before the name kept, `2πroot(L/g)`: "Did you mean π sqrt(L/g)?"; for `sqr(x)`, asking which of the
    square root and the square is meant; or "". `following`: the tokens after the word."""
    lowered = word.lower()
    name = next((n for n in _ROOT_SUFFIXES if lowered.endswith(n)), None)
    if name is None:
        return ""
    head = word[: -len(name)] + " " if len(word) > len(name) else ""
    argument = _bracketed_text(following, text) or "…"
    if name == "sqr":
        return (
            f" Did you mean the square root, {head}sqrt({argument}), or the square, {head}({argument})^2? "
            "Write one of them; sqr is not read."
        )
    return f" Did you mean {head}sqrt({argument})? Write a square root as sqrt(…) or √(…)."


_NUMBER_OF_DEGREES = re.compile(r"\d+(?:\.\d*)?\s*°?")


def _glued_capital_function_hint(word: str, table: NameTable) -> str:
    """A sentence for `MmgCos(θ)`, declared names and then a function in a phone's capital: "Did you
    mean Mmg cos(…)?"; or ""."""
    for name in sorted(FUNCTIONS, key=len, reverse=True):
        head, tail = word[: -len(name)], word[-len(name) :]
        if head and tail != name and tail.lower() == name:
            names = table.resolve(head).unique
            if names is not None and all(part.kind == "name" for part in names):
                return f" Did you mean {head} {name}(…)? Function names are in small letters."
    return ""


def _degree_function_hint(name: str, argument: str) -> str:
    """MATLAB's `sind(30)`: what to type for it, sin(30°), or sin(θ) of an angle's symbol."""
    matlab = f"{name}d is MATLAB's {name} of an angle in degrees, which is not read here"
    if _NUMBER_OF_DEGREES.fullmatch(argument):
        meant = f"{name}({argument.rstrip('°').strip()}°)"
        return f" Did you mean {meant}? {matlab}: write {meant}, with the degree sign."
    if argument and not any(c.isdigit() for c in argument):  # `sind(θ)`; not `sind(90 - θ)`, 90 rad
        meant = f"{name}({argument})"
        return (
            f" Did you mean {meant}? {matlab}: write {meant} (an angle's symbol needs no degree sign; a number "
            f"of degrees does, as in {name}(30°))."
        )
    return (
        f" Did you mean {name}? {matlab}: type {name}, with a degree sign after a number of degrees, as in "
        f"{name}(30°) (an angle's symbol needs none)."
    )


def degree_function_argument(following: list[Token], text: str) -> str:
    """What is typed as the argument of a word such as `sind`: inside its bracket, or the number (with
    its degree sign) or word after it; "" where none is seen."""
    nxt = following[0]
    if nxt.kind is Kind.LPAREN:
        return _bracketed_text(following, text) or ""
    if nxt.kind in (Kind.NUM, Kind.WORD):
        end = following[1].end if following[1].kind is Kind.POSTFIX and following[1].text == "°" else nxt.end
        return text[nxt.pos : end]
    return ""


def _refuse_degree_function(
    word: str, reading: tuple[Part, ...], following: list[Token], text: str, at: int
) -> None:
    """`m g sind θ`, `m g sind(θ)` where a symbol d is declared: sin(d)·θ to the grammar, but MATLAB's sine
    of an angle in degrees as typed; refused, saying what to type for each (never graded as sin(d)·θ).
    `following`: the tokens after the word, whose first argument is shown as typed."""
    if len(reading) < 2 or reading[-2].kind != "func" or reading[-1].kind != "name":
        return
    function, symbol = reading[-2], reading[-1]
    degrees = _DEGREE_FUNCTION_WORD.fullmatch(word[function.start : symbol.end])
    if degrees is None or word[symbol.start : symbol.end] != "d":
        return
    name = degrees.group(1)
    nxt = following[0]
    if nxt.kind in (Kind.WORD, Kind.NUM):
        after = text[nxt.pos : nxt.end] or nxt.text
        applied, times, typed_times = f"{name} {after}", f"{name}(d)·{after}", f"{name}(d) {after}"
    else:
        after = _bracketed_text(following, text) or "…"
        applied, times, typed_times = f"{name}({after})", f"{name}(d)·({after})", f"{name}(d) ({after})"
    raise AmbiguousInput(
        f"Did you mean {applied} or {times}? {name}d is MATLAB's {name} of an angle in degrees, "
        f"which is not read here: for {name} of {after}, type {applied} (an angle's symbol needs no degree "
        f"sign; a number of degrees does, as in {name}(30°)); for {name} of your symbol d times {after}, "
        f"type {typed_times}.",
        at + function.start,
        (f"{name}({after})", times.replace("·", "*")),
    )


def _bracketed_text(tokens: list[Token], text: str) -> str | None:
    """What is typed inside the bracket that tokens[0] opens, or None where no bracket opens or closes."""
    if tokens[0].kind is not Kind.LPAREN:
        return None
    depth = 0
    for tok in tokens:
        depth += {Kind.LPAREN: 1, Kind.RPAREN: -1}.get(tok.kind, 0)
        if depth == 0:
            return text[tokens[0].end : tok.pos].strip()
    return None


def glued_angle_hint(word: str) -> str:
    """A sentence for `sin30`, a function of an angle with a number glued on and no degree sign: 30
    radians as typed, most often 30° meant; or ""."""
    found = _DEGREES_ENDING.fullmatch(word)
    if found is None:
        return ""
    name, number = found.group(1)[-3:], found.group(2)  # `mgsin30`: the function is the word's end
    return f" Did you mean {name}({number}°)? Write the degree sign for degrees, or {name}({number}) for radians."


_NAMES_THEN_DIGITS = re.compile(r"(\D+)(\d+)(\D*)")


def _digits_as_power_hint(word: str, table: NameTable) -> str:
    """A sentence for `mc2` (m c², its power typed as a plain digit, as a text message writes it), or
    `mω2L` (m ω² L), where the letters read one way as declared names, the last before the digits with no
    numbered subscript; or ""."""
    found = _NAMES_THEN_DIGITS.fullmatch(word)
    if found is None:
        return ""
    names = table.resolve(found.group(1)).unique
    after = table.resolve(found.group(3)).unique if found.group(3) else ()
    if names is None or after is None or any(part.kind != "name" for part in (*names, *after)):
        return ""
    last = names[-1].canonical
    if any(name[len(last) :].lstrip("_")[:1].isdigit() for name in table.declared if name.startswith(last)):
        return ""  # `v2` where v_1 is declared: a subscript mistyped, more likely than a power
    typed = " ".join(part.canonical for part in names)
    rest = "".join(f" {part.canonical}" for part in after)
    return f" Did you mean {typed}^{found.group(2)}{rest}? Write a power with ^."


def _case_hint(word: str, declared: Sequence[str], table: NameTable) -> str:
    """A sentence for `l` where only `L` is declared, or `Mg sinθ` where m and g are (a phone's capital
    at the start of the answer), or ""; never where both cases are declared, as m and M are two masses."""
    folded = word.casefold()
    same = [name for name in declared if name.casefold() == folded]
    if len(same) == 1:
        return f" Names are case-sensitive: did you mean {same[0]}?"
    lowered = word[:1].lower() + word[1:]
    if lowered != word and table.resolve(lowered).unique is not None:
        return f" Names are case-sensitive: did you mean {lowered}?"
    return ""


def _subscript_hint(word: str, declared: Sequence[str], table: NameTable) -> str:
    """A sentence for `μ` where only `mu_k` is declared: the letter without its subscript; or ""."""
    meant = [
        f"{word}_{name.split('_', 1)[1]}"
        for name in declared
        if "_" in name and _reads_as(f"{word}_{name.split('_', 1)[1]}", name, table)
    ]
    return f" Did you mean {meant[0]}? The symbol has a subscript." if len(meant) == 1 else ""


def _reads_as(word: str, name: str, table: NameTable) -> bool:
    unique = table.resolve(word).unique
    return unique is not None and len(unique) == 1 and unique[0].canonical == name


def _times_letter_hint(word: str, prev: Token | None, nxt: Token) -> str:
    """A sentence for `m x g`, the letter x typed for a times sign between two factors, or ""."""
    if word not in ("x", "X") or prev is None or prev.kind not in _ENDS_OPERAND:
        return ""
    if nxt.kind not in (Kind.WORD, Kind.NUM, Kind.LPAREN, Kind.FUNC, Kind.CONST, Kind.SQRT):
        return ""
    return f" If {word} is a times sign, write * or a space instead."


_EXPONENT_WORD = re.compile(r"[eE]\d+")


def _spaced_exponent_hint(word: str, prev: Token | None) -> str:
    """A sentence for `2 E3 x`, a power of ten typed apart from its number, or ""."""
    if prev is None or prev.kind is not Kind.NUM or not _EXPONENT_WORD.fullmatch(word):
        return ""
    return f" Did you mean {prev.text}{word}? Write a power of ten without a space before its {word[0]}."


def _lookalike_hint(word: str, table: NameTable) -> str:
    """A sentence for `mс` typed with a Cyrillic с, where the Latin letters it looks like are read, or ""."""
    latin = as_latin(word)
    if latin is None or table.resolve(latin).unique is None:
        return ""
    return lookalike_hint(word)


def _greek_stand_in_hint(word: str, declared: Sequence[str]) -> str:
    """A sentence for an unknown word holding a Latin stand-in for a declared Greek symbol, or ""."""
    for letter, (name, glyph) in _STAND_INS.items():
        if (
            letter in word
            and name not in word
            and letter not in declared
            and any(d.startswith(name) for d in declared)
        ):
            return f" If {letter} stands for {glyph}, type {name} or {glyph}."
    return ""
