"""Units written in LaTeX, as equation editors paste them: `\\mathrm{m/s^2}`, `\\text{ m/s}^2`,
`\\mu\\mathrm{m}`, `\\mathrm{kg}\\cdot\\mathrm{m}\\,\\mathrm{s}^{-2}`, `^{\\circ}\\mathrm{C}`, `\\frac{m}{s}`.

`plain_units` gives the plain unit text they show, with where each of its characters was typed, so the
lexer reads it and its positions still point into what was typed. Each command is looked up in a
whitelist; any other is a ParseError at its backslash. TeX prints side by side what is typed side by
side, so `\\mu\\mathrm{m}` is μm and `\\mathrm{k}\\Omega` kΩ, while `\\,` and spaces separate.
"""

from __future__ import annotations

from physics.errors import ParseError
from physics.latex_words import LATEX_FRACTIONS, LATEX_SPACES, LATEX_TEXT_WRAPPERS

_SYMBOLS = {"mu": "µ", "Omega": "Ω", "circ": "°", "degree": "°", "cdot": "·", "times": "×"}
_TEXT_FONT_HINT = "write the units in plain text, as in m/s^2, or in \\mathrm{…}"


def _command_name(text: str, i: int) -> tuple[str, int]:
    """The name after the backslash at i (`mathrm`, or one character such as `,`) and its end."""
    j = i + 1
    if j >= len(text):
        raise ParseError(f"A '\\' ends the units: {_TEXT_FONT_HINT}", i)
    if not (text[j].isascii() and text[j].isalpha()):
        return text[j], j + 1
    while j < len(text) and text[j].isascii() and text[j].isalpha():
        j += 1
    return text[i + 1 : j], j


def _skip_spaces(text: str, i: int) -> int:
    while i < len(text) and text[i].isspace():
        i += 1
    return i


def _degree_end(text: str, i: int) -> int | None:
    """The end of `^\\circ` or `^{\\circ}` at the `^` at i (a degree sign), or None."""
    j = _skip_spaces(text, i + 1)
    braced = text.startswith("{", j)
    if braced:
        j = _skip_spaces(text, j + 1)
    if not text.startswith("\\circ", j) or text[j + 5 : j + 6].isalpha():
        return None
    j += 5
    if not braced:
        return j
    j = _skip_spaces(text, j)
    return j + 1 if text.startswith("}", j) else None


def _opening_brace(text: str, i: int, command: str) -> int:
    """The position of the `{` that must follow `command` (typed at i)."""
    j = _skip_spaces(text, i)
    if not text.startswith("{", j):
        raise ParseError(f"{command} needs braces after it, as in {command}{{m/s}}", min(j, len(text)))
    return j


def plain_units(text: str) -> tuple[str, list[int]]:
    """The plain units LaTeX `text` shows, and where each of their characters (and their end) was typed."""
    out: list[str] = []
    where: list[int] = []
    frames: list[tuple[str, int]] = []  # what each open brace is ("font", "group", "numerator", …), where

    def put(piece: str, position: int) -> None:
        out.extend(piece)
        where.extend([position] * len(piece))

    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch == "\\":
            name, end = _command_name(text, i)
            if name in LATEX_SPACES:
                put(" ", i)
            elif name == "rm":  # plain TeX's roman, `{\rm m/s^2}`: a font switch, no units
                end = _skip_spaces(text, end)
            elif name in _SYMBOLS:
                put(_SYMBOLS[name], i)
                if name.isalpha():  # TeX drops the spaces that end a command's name: `\mu m` is µm
                    end = _skip_spaces(text, end)
            elif name in LATEX_TEXT_WRAPPERS:
                brace = _opening_brace(text, end, "\\" + name)
                frames.append(("font", brace))
                end = brace + 1
            elif name in LATEX_FRACTIONS:
                brace = _opening_brace(text, end, "\\" + name)
                put("((", i)
                frames.append(("numerator", brace))
                end = brace + 1
            else:
                raise ParseError(f"Unknown LaTeX command \\{name[:24]} in the units: {_TEXT_FONT_HINT}", i)
            i = end
        elif ch == "^" and (degree_end := _degree_end(text, i)) is not None:
            put("°", i)
            i = degree_end
        elif ch == "{" and text.startswith("}", _skip_spaces(text, i + 1)):  # `{}^{\circ}`: nothing
            i = _skip_spaces(text, i + 1) + 1
        elif ch == "{":
            frames.append(("group", i))
            put("(", i)
            i += 1
        elif ch == "}":
            if not frames:
                raise ParseError("Unmatched '}' in the units", i)
            kind, _ = frames.pop()
            i += 1
            if kind == "group":
                put(")", i - 1)
            elif kind == "numerator":
                brace = _opening_brace(text, i, "\\frac{…}")
                put(")/(", brace)
                frames.append(("denominator", brace))
                i = brace + 1
            elif kind == "denominator":
                put("))", i - 1)
        elif ch == "~":
            put(" ", i)
            i += 1
        else:
            put(ch, i)
            i += 1
    if frames:
        raise ParseError("Unbalanced brace: this '{' is never closed in the units", frames[-1][1])
    where.append(n)
    return "".join(out), where
