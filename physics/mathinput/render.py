"""Reading an answer back to the student, from the parse tree (not from sympy's reordered result).

Text is in the contract's style (`-m*g*sin(theta)/(M + m*sin(theta)**2)`: explicit `*`, `**`, declared
spellings, only the parentheses the grouping needs) and parses back to the same expression; LaTeX uses
`\\frac`, `\\sin`, `\\theta`. STUDENT_STYLE (`^`, `·`) writes the readings of an ambiguous answer.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache

from physics.mathinput.tree import (
    Call,
    Const,
    Group,
    Name,
    Neg,
    Node,
    Num,
    Power,
    Product,
    Sum,
    ungroup,
)
from physics.mathinput.vocabulary import GREEK_LETTERS, GREEK_NAMES, LATEX_FUNCTIONS, LATIN_LOOKING_CAPITALS

# Binding strength of what a rendered piece is, to decide where parentheses are needed.
_SUM, _PRODUCT, _POWER, _ATOM = 1, 2, 3, 4

_TRAILING_DIGITS = re.compile(r"^([^\W\d_]+)(\d+)$")


@dataclass(frozen=True)
class TextStyle:
    power: str
    times: str


CONTRACT_STYLE = TextStyle(power="**", times="*")
STUDENT_STYLE = TextStyle(power="^", times="·")


def render_text(node: Node, style: TextStyle = CONTRACT_STYLE) -> str:
    return _text(node, style)[0]


def in_student_style(text: str) -> str:
    """A text in the contract's style (`m*v/(q*B)`, `e**(-omega*t)`) in STUDENT_STYLE (`m·v/(q·B)`,
    `e^(-omega·t)`): how a note tells a student what was read, in words that stay as they are where the
    note is shown as Markdown (the student page), where `*` would turn to emphasis."""
    return text.replace("**", STUDENT_STYLE.power).replace("*", STUDENT_STYLE.times)


def render_latex(node: Node) -> str:
    return _latex(node)[0]


def _wrap(piece: tuple[str, int], needs: bool) -> str:
    return f"({piece[0]})" if needs else piece[0]


def _text(node: Node, style: TextStyle) -> tuple[str, int]:
    if isinstance(node, Group):
        return _text(node.inner, style)
    if isinstance(node, Num):
        return node.literal, _ATOM
    if isinstance(node, Name):
        return node.name, _ATOM
    if isinstance(node, Const):
        return node.which, _ATOM
    if isinstance(node, Neg):
        operand = _text(node.operand, style)
        return "-" + _wrap(operand, operand[1] < _PRODUCT or _is_neg(node.operand)), _PRODUCT
    if isinstance(node, Sum):
        parts = [_text(node.first, style)[0]]
        for sign, term in node.rest:
            piece = _text(term, style)
            needs = _is_neg(term) or (sign == "-" and piece[1] < _PRODUCT)
            parts.append(f" {sign} {_wrap(piece, needs)}")
        return "".join(parts), _SUM
    if isinstance(node, Product):
        first = _text(node.first, style)
        out = _wrap(first, first[1] < _PRODUCT)
        for operator, factor in node.rest:
            piece = _text(factor, style)
            if operator == "*":
                out += style.times + _wrap(piece, piece[1] < _PRODUCT or _is_neg(factor))
            else:
                out += "/" + _wrap(piece, piece[1] <= _PRODUCT)
        return out, _PRODUCT
    if isinstance(node, Power):
        base = _text(node.base, style)
        exponent = _text(node.exponent, style)
        return (
            _wrap(base, base[1] < _ATOM) + style.power + _wrap(exponent, exponent[1] < _POWER),
            _POWER,
        )
    if isinstance(node, Call):
        return f"{node.func}({_text(node.arg, style)[0]})", _ATOM
    operand = _text(node.operand, style)
    if node.kind == "factorial":
        return f"factorial({operand[0]})", _ATOM
    suffix = "/100" if node.kind == "percent" else f"{style.times}pi/180"
    return _wrap(operand, operand[1] < _PRODUCT) + suffix, _PRODUCT


def _is_neg(node: Node) -> bool:
    return isinstance(ungroup(node), Neg)


@lru_cache(maxsize=1024)  # a few declared names, met in every answer
def latex_name(name: str) -> str:
    if name.endswith("_dot") and len(name) > len("_dot"):  # a coordinate's velocity (velocities.py)
        return rf"\dot{{{latex_name(name[: -len('_dot')])}}}"
    if "_" in name and not name.startswith("_"):
        base, sub = name.split("_", 1)
    elif match := _TRAILING_DIGITS.match(name):
        base, sub = match.group(1), match.group(2)
    else:
        base, sub = name, ""
    out = _latex_word(base)
    return f"{out}_{{{_latex_word(sub)}}}" if sub else out


def _latex_word(word: str) -> str:
    if word in GREEK_NAMES:
        word = GREEK_NAMES[word]
    if word in GREEK_LETTERS:
        if word in LATIN_LOOKING_CAPITALS:
            return word[0]
        return "o" if word == "omicron" else "\\" + word
    if len(word) <= 1 or word.isdigit():
        return word
    return r"\mathrm{" + word + "}"


def _paren(piece: tuple[str, int], needs: bool) -> str:
    return rf"\left({piece[0]}\right)" if needs else piece[0]


def _latex_number(literal: str) -> tuple[str, int]:
    if "e" in literal:
        mantissa, exponent = literal.split("e")
        return rf"{mantissa} \cdot 10^{{{exponent}}}", _PRODUCT
    return literal, _ATOM


def _latex(node: Node) -> tuple[str, int]:
    if isinstance(node, Group):
        return _latex(node.inner)
    if isinstance(node, Num):
        return _latex_number(node.literal)
    if isinstance(node, Name):
        return latex_name(node.name), _ATOM
    if isinstance(node, Const):
        return (r"\pi" if node.which == "pi" else "e"), _ATOM
    if isinstance(node, Neg):
        operand = _latex(node.operand)
        return "-" + _paren(operand, operand[1] < _PRODUCT or _is_neg(node.operand)), _PRODUCT
    if isinstance(node, Sum):
        parts = [_latex(node.first)[0]]
        for sign, term in node.rest:
            piece = _latex(term)
            parts.append(f" {sign} {_paren(piece, _is_neg(term) or (sign == '-' and piece[1] < _PRODUCT))}")
        return "".join(parts), _SUM
    if isinstance(node, Product):
        return _latex_product(node), _PRODUCT
    if isinstance(node, Power):
        return _latex_power(node), _POWER
    if isinstance(node, Call):
        return _latex_call(node.func, node.arg, None), _ATOM
    operand = _latex(node.operand)
    if node.kind == "factorial":
        return _paren(operand, operand[1] < _ATOM) + "!", _ATOM
    if node.kind == "percent":
        return _paren(operand, operand[1] < _PRODUCT) + r"\%", _PRODUCT
    return _paren(operand, operand[1] < _ATOM) + r"^{\circ}", _POWER


def _latex_product(node: Product) -> str:
    first = _latex(node.first)
    bare = first[0]  # the numerator without brackets while it is a single factor
    out = _paren(first, first[1] < _PRODUCT)
    for operator, factor in node.rest:
        piece = _latex(factor)
        if operator == "/":
            out = rf"\frac{{{bare}}}{{{piece[0]}}}"
            bare = out
            continue
        text = _paren(piece, piece[1] < _PRODUCT or _is_neg(factor))
        separator = r" \cdot " if text[:1].isdigit() else " "
        out = out + separator + text
        bare = out
    return out


def _latex_power(node: Power) -> str:
    base = ungroup(node.base)
    exponent = _latex(node.exponent)[0]
    # \sin^{2} x, but never \sin^{-1} x: that is how arcsin is written.
    positive = isinstance(ungroup(node.exponent), Num)
    if isinstance(base, Call) and base.func in LATEX_FUNCTIONS and base.func != "log10" and positive:
        return _latex_call(base.func, base.arg, exponent)
    piece = _latex(node.base)
    return _paren(piece, piece[1] < _ATOM) + f"^{{{exponent}}}"


def _latex_call(func: str, arg: Node, power: str | None) -> str:
    inner = _latex(arg)[0]
    if func == "sqrt":
        body = rf"\sqrt{{{inner}}}"
    elif func == "exp":
        body = rf"e^{{{inner}}}"
    elif func == "abs":
        body = rf"\left|{inner}\right|"
    elif func == "factorial":
        piece = _latex(arg)
        body = _paren(piece, piece[1] < _ATOM) + "!"
    else:
        name = LATEX_FUNCTIONS[func]
        head = f"{name}^{{{power}}}" if power is not None else name
        return rf"{head}\left({inner}\right)"
    return rf"\left({body}\right)^{{{power}}}" if power is not None else body
