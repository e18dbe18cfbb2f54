"""What latex2mathml leaves for the browser to typeset worse than TeX (and MathJax) would, made right:
before conversion, sympy's TeX in a textbook's style; after it, the MathML tree in MathML Core's terms.

- `\\sin{\\left(\\theta \\right)}` (sympy) is written `\\sin\\theta`, and `\\sin{\\left(2 \\theta \\right)}`
  `\\sin 2\\theta`, as books do; an argument with an operator keeps its parentheses.
- `\\mathrm{d}` stays upright (latex2mathml drops the upright of one letter), so the d of d/dt is no
  italic d; `\\mathrm{block}` is one upright word, not five letters.
- accents (the dots of ẋ) are marked as accents, so they sit on the letter, not above it as a script.
- a function name (sin, cos, ln, …) gets TeX's thin spaces from what it follows and what follows it
  (MathML Core leaves operator spacing to the operator dictionary, which names no `<mi>`).

The page's stylesheet does the rest: a math font with an OpenType MATH table (Latin Modern Math,
shipped under /static/fonts) for stretchy brackets and TeX's script positions, and display formulas
centred at display size.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET  # only latex2mathml's own output is parsed

MATHML_NS = "{http://www.w3.org/1998/Math/MathML}"
FUNCTIONS = frozenset(
    [
        "sin",
        "cos",
        "tan",
        "cot",
        "sec",
        "csc",
        "sinh",
        "cosh",
        "tanh",
        "coth",
        "arcsin",
        "arccos",
        "arctan",
        "ln",
        "log",
        "exp",
        "det",
        "lim",
        "max",
        "min",
    ]
)
_ACCENTS = frozenset("\u00a8\u02d9\u02c6\u005e\u007e\u02dc\u00af\u2192\u20d7\u0307\u0308")
# accents as the spacing characters MathML Core expects (the font's MATH table places them)
_SPACING = {"\u0308": "\u00a8", "\u0307": "\u02d9", "\u005e": "\u02c6", "\u007e": "\u02dc"}
_THIN = "0.1667em"
# elements whose children are a row (scripts and fractions have a fixed number of children)
_ROWS = frozenset({"math", "mrow", "mtd", "msqrt", "mstyle", "mpadded", "mphantom", "menclose", "merror"})
# \sin{\left(ARG \right)} with ARG an atom or a number times an atom: \sin\theta, \sin 2\theta
_ATOM = r"(?:\\[A-Za-z]+|[A-Za-z0-9])(?:_\{[^{}]*\}|_[A-Za-z0-9])?"
_SIMPLE_ARG = re.compile(
    r"\\(" + "|".join(sorted(FUNCTIONS, key=len, reverse=True)) + r")(\^\{[^{}]*\})?"
    r"\{\\left\(\s*((?:\d+\s*)?" + _ATOM + r")\s*\\right\)\}"
)
_ONE_LETTER_ROMAN = re.compile(r"\\mathrm\{([A-Za-z])\}")


def textbook_tex(tex: str) -> str:
    """sympy's TeX in a textbook's style (see the module docstring); other TeX unchanged."""
    tex = _SIMPLE_ARG.sub(lambda m: rf"\{m.group(1)}{m.group(2) or ''} {m.group(3).strip()}", tex)
    # latex2mathml turns \mathrm{d} into an italic d; \operatorname keeps it upright (an <mo>, made an
    # upright <mi> by polish)
    return _ONE_LETTER_ROMAN.sub(r"\\operatorname{\1}", tex)


def _tag(element: ET.Element) -> str:
    return element.tag.removeprefix(MATHML_NS)


def _make(tag: str, attributes: dict[str, str] | None = None, text: str | None = None) -> ET.Element:
    element = ET.Element(MATHML_NS + tag, attributes or {})
    element.text = text
    return element


def _is_function(element: ET.Element) -> bool:
    if _tag(element) == "mi" and (element.text or "") in FUNCTIONS:
        return True
    return _tag(element) in ("msup", "msub", "msubsup") and len(element) > 0 and _is_function(element[0])


def _opens_fence(element: ET.Element) -> bool:
    first = element
    while _tag(first) in ("mrow", "msup", "msub") and len(first) > 0:
        first = first[0]
    return (_tag(first) == "mo" and first.get("fence") == "true") or (first.text or "") in "([{"


def _is_operator(element: ET.Element) -> bool:
    return _tag(element) == "mo" or _tag(element) == "mspace"


def polish(root: ET.Element) -> None:
    """Fix latex2mathml's tree in place (see the module docstring)."""
    for parent in list(root.iter()):
        _merge_upright_letters(parent)
        for child in parent:
            tag = _tag(child)
            if tag == "mo" and (child.text or "").isalpha():  # \operatorname{d}: an upright name
                child.tag = MATHML_NS + "mi"
                child.attrib.clear()
                if len(child.text or "") == 1:
                    child.set("mathvariant", "normal")
            elif tag == "mo" and child.text == "/":  # TeX's slash is an ordinary symbol: no space around it
                child.set("lspace", "0")
                child.set("rspace", "0")
            elif tag == "mover" and len(child) == 2 and (child[1].text or "") in _ACCENTS:
                child.set("accent", "true")  # on the letter, by the font's accent attachment
                child[1].text = _SPACING.get(child[1].text or "", child[1].text)
    for parent in list(root.iter()):
        if _tag(parent) in _ROWS:
            _unary_signs(parent)
            _space_functions(parent)
        if _tag(parent) == "mrow" and _fenced(parent):
            for fence in (parent[0], parent[-1]):
                if not _tall(parent):  # TeX's delimiter shortfall: no taller bracket
                    fence.set("stretchy", "false")
                else:  # cover the content's height and depth, not twice the larger of them about the axis
                    fence.set("symmetric", "false")


def _fenced(row: ET.Element) -> bool:
    return (
        len(row) >= 2
        and all(_tag(end) == "mo" and end.get("fence") == "true" for end in (row[0], row[-1]))
        and bool((row[0].text or "").strip() or (row[-1].text or "").strip())
    )


def _tall(element: ET.Element) -> bool:
    """Whether a fence around it must grow: a fraction, a root, a table or a large operator inside
    (subscripts and superscripts alone fit within an ordinary bracket, as TeX's shortfall allows)."""
    return any(
        _tag(e) in ("mfrac", "msqrt", "mroot", "mtable", "munderover") and e.get("displaystyle") != "false"
        for e in element.iter()
        if e is not element
    )


def _unary_signs(parent: ET.Element) -> None:
    """A + or − that starts a row or follows another operator (=, a bracket, a comma) is a sign:
    prefix, with no space after it (−N, not − N)."""
    previous: ET.Element | None = None
    for child in parent:
        if (
            _tag(child) == "mo"
            and (child.text or "") in ("\u2212", "+", "-", "\u00b1")
            and (previous is None or (_tag(previous) == "mo" and previous.get("form") != "postfix"))
        ):
            child.set("form", "prefix")
        if _tag(child) != "mspace":
            previous = child


def _merge_upright_letters(parent: ET.Element) -> None:
    """`<mi mathvariant="normal">b</mi><mi mathvariant="normal">l</mi>…` -> `<mi>bl…</mi>`."""
    children = list(parent)
    index = 0
    while index < len(children):
        run = index
        while (
            run < len(children)
            and _tag(children[run]) == "mi"
            and children[run].get("mathvariant") == "normal"
            and len(children[run].text or "") == 1
            and (children[run].text or "").isalpha()
            and not children[run].tail
        ):
            run += 1
        if run - index >= 2:
            first = children[index]
            first.text = "".join(c.text or "" for c in children[index:run])
            first.attrib.pop("mathvariant", None)  # a name of several letters is upright by default
            for extra in children[index + 1 : run]:
                parent.remove(extra)
            children = list(parent)
        index += 1


def _space_functions(parent: ET.Element) -> None:
    """TeX's thin space between a function name and what it follows and what follows it (not a
    bracket, not an operator, which brings its own space)."""
    children = list(parent)
    offset = 0
    for index, child in enumerate(children):
        if not _is_function(child):
            continue
        at = index + offset
        if index > 0 and not _is_operator(children[index - 1]):
            parent.insert(at, _make("mspace", {"width": _THIN}))
            offset += 1
            at += 1
        if (
            index + 1 < len(children)
            and not _is_operator(children[index + 1])
            and not _opens_fence(children[index + 1])
        ):
            parent.insert(at + 1, _make("mspace", {"width": _THIN}))
            offset += 1
