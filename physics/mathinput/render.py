"""Reading an answer back to the student, from the parse tree (not from sympy's reordered result).

Text is in the contract's style (`-m*g*sin(theta)/(M + m*sin(theta)**2)`: explicit `*`, `**`, declared
spellings, only the parentheses the grouping needs) and parses back to the same expression; LaTeX uses
`\\frac`, `\\sin`, `\\theta`. STUDENT_STYLE (`^`, `·`) writes the readings of an ambiguous answer, and
AS_TYPED_STYLE those of a division whose other groupings were read one way to find it.
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
    Postfix,
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
    # Where the problem declares a symbol e (a coefficient of restitution), Euler's number is written
    # exp(1) and upright, \mathrm{e}, so that neither reads as the symbol.
    euler: str = "e"
    euler_latex: str = "e"
    # A call or a power whose reach was a choice shown as typed (`sin x/2`), not as the reading tried.
    as_typed: bool = False


CONTRACT_STYLE = TextStyle(power="**", times="*")
STUDENT_STYLE = TextStyle(power="^", times="·")
AS_TYPED_STYLE = TextStyle(power="^", times="·", as_typed=True)
_BESIDE_SYMBOL_E = TextStyle(power="**", times="*", euler="exp(1)", euler_latex=r"\mathrm{e}")


def render_text(node: Node, style: TextStyle = CONTRACT_STYLE) -> str:
    return _pieces(node, style)[0]


def in_student_style(text: str) -> str:
    """A text in the contract's style (`m*v/(q*B)`, `e**(-omega*t)`) in STUDENT_STYLE (`m·v/(q·B)`,
    `e^(-omega·t)`): how a note tells a student what was read, in words that stay as they are where the
    note is shown as Markdown (the student page), where `*` would turn to emphasis."""
    return text.replace("**", STUDENT_STYLE.power).replace("*", STUDENT_STYLE.times)


def render_latex(node: Node) -> str:
    return _pieces(node, CONTRACT_STYLE)[2]


def render_both(node: Node, *, symbol_e: bool = False) -> tuple[str, str]:
    """`render_text(node)` and `render_latex(node)`, in one walk of the tree; `symbol_e`: e is a declared
    symbol, so Euler's number is set apart from it."""
    text, _, latex, _ = _pieces(node, _BESIDE_SYMBOL_E if symbol_e else CONTRACT_STYLE)
    return text, latex


# A node's text and its LaTeX, each with the binding strength of what it is: one walk makes both.
_Pieces = tuple[str, int, str, int]


def _wrap(piece: str, needs: bool) -> str:
    return f"({piece})" if needs else piece


def _paren(piece: str, needs: bool) -> str:
    return rf"\left({piece}\right)" if needs else piece


def _is_neg(node: Node) -> bool:
    return isinstance(ungroup(node), Neg)


def _pieces(node: Node, style: TextStyle) -> _Pieces:
    # By the type, the commonest first (a chain of isinstance tests per node cost as much as the rest).
    kind = type(node)
    while kind is Group:
        node = node.inner  # type: ignore[union-attr]
        kind = type(node)
    if kind is Name:
        return node.name, _ATOM, latex_name(node.name), _ATOM  # type: ignore[union-attr]
    if kind is Num:
        return (node.literal, _ATOM, *_latex_number(node.literal))  # type: ignore[union-attr]
    if kind is Product:
        return _product(node, style)  # type: ignore[arg-type]
    if kind is Power:
        return _power(node, style)  # type: ignore[arg-type]
    if kind is Sum:
        return _sum(node, style)  # type: ignore[arg-type]
    if kind is Call:
        func = node.func  # type: ignore[union-attr]
        arg = _pieces(node.arg, style)  # type: ignore[union-attr]
        latex = _latex_call(func, arg, None, style)
        if style.as_typed and node.typed is not None:  # type: ignore[union-attr]
            return node.typed, _PRODUCT, latex, _ATOM  # type: ignore[union-attr]
        return f"{func}({arg[0]})", _ATOM, latex, _ATOM
    if kind is Neg:
        text, text_binding, latex, latex_binding = _pieces(node.operand, style)  # type: ignore[union-attr]
        neg = _is_neg(node.operand)  # type: ignore[union-attr]
        return (
            "-" + _wrap(text, text_binding < _PRODUCT or neg),
            _PRODUCT,
            "-" + _paren(latex, latex_binding < _PRODUCT or neg),
            _PRODUCT,
        )
    if kind is Const:
        if node.which == "pi":  # type: ignore[union-attr]
            return "pi", _ATOM, r"\pi", _ATOM
        return style.euler, _ATOM, style.euler_latex, _ATOM
    assert isinstance(node, Postfix)
    text, text_binding, latex, latex_binding = _pieces(node.operand, style)
    if node.kind == "factorial":
        return f"factorial({text})", _ATOM, _paren(latex, latex_binding < _ATOM) + "!", _ATOM
    suffix = "/100" if node.kind == "percent" else f"{style.times}pi/180"
    text = _wrap(text, text_binding < _PRODUCT) + suffix
    if node.kind == "percent":
        return text, _PRODUCT, _paren(latex, latex_binding < _PRODUCT) + r"\%", _PRODUCT
    return text, _PRODUCT, _paren(latex, latex_binding < _ATOM) + r"^{\circ}", _POWER


def _sum(node: Sum, style: TextStyle) -> _Pieces:
    first = _pieces(node.first, style)
    texts, latexes = [first[0]], [first[2]]
    for sign, term in node.rest:
        text, text_binding, latex, latex_binding = _pieces(term, style)
        neg = _is_neg(term)
        texts.append(f" {sign} {_wrap(text, neg or (sign == '-' and text_binding < _PRODUCT))}")
        latexes.append(f" {sign} {_paren(latex, neg or (sign == '-' and latex_binding < _PRODUCT))}")
    return "".join(texts), _SUM, "".join(latexes), _SUM


def _product(node: Product, style: TextStyle) -> _Pieces:
    text, text_binding, latex, latex_binding = _pieces(node.first, style)
    out = _wrap(text, text_binding < _PRODUCT)
    bare = latex  # the LaTeX numerator without brackets while it is a single factor
    tex = _paren(latex, latex_binding < _PRODUCT)
    for operator, factor in node.rest:
        text, text_binding, latex, latex_binding = _pieces(factor, style)
        if operator == "/":
            out += "/" + _wrap(text, text_binding <= _PRODUCT)
            tex = rf"\frac{{{bare}}}{{{latex}}}"
        else:
            neg = _is_neg(factor)
            out += style.times + _wrap(text, text_binding < _PRODUCT or neg)
            latex = _paren(latex, latex_binding < _PRODUCT or neg)
            tex += (r" \cdot " if latex[:1].isdigit() else " ") + latex
        bare = tex
    return out, _PRODUCT, tex, _PRODUCT


def _power(node: Power, style: TextStyle) -> _Pieces:
    exponent = _pieces(node.exponent, style)
    base = ungroup(node.base)
    # \sin^{2} x, but never \sin^{-1} x: that is how arcsin is written.
    if (
        isinstance(base, Call)
        and base.func in LATEX_FUNCTIONS
        and base.func != "log10"
        and isinstance(ungroup(node.exponent), Num)
    ):
        arg = _pieces(base.arg, style)
        text, binding = f"{base.func}({arg[0]})", _ATOM
        latex = _latex_call(base.func, arg, exponent[2], style)
    else:
        text, binding, base_latex, base_latex_binding = _pieces(node.base, style)
        latex = _paren(base_latex, base_latex_binding < _ATOM) + f"^{{{exponent[2]}}}"
    if style.as_typed and node.typed is not None:
        return node.typed, _PRODUCT, latex, _POWER
    text = _wrap(text, binding < _ATOM) + style.power + _wrap(exponent[0], exponent[1] < _POWER)
    return text, _POWER, latex, _POWER


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


def _latex_number(literal: str) -> tuple[str, int]:
    if "e" in literal:
        mantissa, exponent = literal.split("e")
        return rf"{mantissa} \cdot 10^{{{exponent}}}", _PRODUCT
    return literal, _ATOM


def _latex_call(func: str, arg: _Pieces, power: str | None, style: TextStyle) -> str:
    inner = arg[2]
    if func == "sqrt":
        body = rf"\sqrt{{{inner}}}"
    elif func == "exp":
        body = rf"{style.euler_latex}^{{{inner}}}"
    elif func == "abs":
        body = rf"\left|{inner}\right|"
    elif func == "factorial":
        body = _paren(inner, arg[3] < _ATOM) + "!"
    else:
        name = LATEX_FUNCTIONS[func]
        head = f"{name}^{{{power}}}" if power is not None else name
        return rf"{head}\left({inner}\right)"
    return rf"\left({body}\right)^{{{power}}}" if power is not None else body
