"""The one renderer for text people read: Markdown with TeX (`$…$` inline, `$$…$$` display) to HTML with
MathML made on the server (markdown-it-py, its dollarmath plugin, latex2mathml). Statements, prompts,
feedback, solutions and previews all go through it, so they look alike and none shows raw TeX.

Safety: raw HTML in the source is escaped (markdown-it's `html` option is off), link schemes are
markdown-it's safe list, and the MathML latex2mathml makes is parsed and written out again here, so
no text inside a formula (`\\text{<b>}`) can become markup. Nothing is evaluated.
"""

from __future__ import annotations

import functools
import re
import xml.etree.ElementTree as ET  # parses only the MathML latex2mathml made, never input text
from collections.abc import Iterable, Sequence
from html import escape
from typing import TYPE_CHECKING, Any

from markupsafe import Markup

from app.web.typesetting import polish, textbook_tex

# latex2mathml and markdown-it are imported by the first page that renders text (a tenth of a
# CPU-second, kept off the way to /ready).
if TYPE_CHECKING:
    from markdown_it import MarkdownIt
    from markdown_it.renderer import RendererHTML
    from markdown_it.token import Token
    from markdown_it.utils import EnvType, OptionsDict

MATHML_NS = "{http://www.w3.org/1998/Math/MathML}"
MAX_TEX_CHARS = 2000
MAX_TEXT_CHARS = 50_000
# latex2mathml leaves an unknown command as an identifier with its backslash (`<mi>\foo</mi>`).
_UNKNOWN_COMMAND = re.compile(r"\\[A-Za-z]+")
# What latex2mathml makes; anything else came from text inside the TeX (`\\text{<b onclick=…>}`).
_TAGS = frozenset(
    [
        "math",
        "mrow",
        "mi",
        "mn",
        "mo",
        "mtext",
        "mspace",
        "ms",
        "msub",
        "msup",
        "msubsup",
        "mfrac",
        "msqrt",
        "mroot",
        "mover",
        "munder",
        "munderover",
        "mtable",
        "mtr",
        "mtd",
        "mstyle",
        "mpadded",
        "mphantom",
        "menclose",
        "merror",
        "semantics",
        "annotation",
    ]
)
_ATTRIBUTES = frozenset(
    [
        "display",
        "stretchy",
        "fence",
        "form",
        "mathvariant",
        "width",
        "height",
        "depth",
        "lspace",
        "rspace",
        "columnalign",
        "columnlines",
        "columnspacing",
        "rowspacing",
        "rowlines",
        "linethickness",
        "accent",
        "accentunder",
        "movablelimits",
        "separator",
        "largeop",
        "symmetric",
        "minsize",
        "maxsize",
        "displaystyle",
        "scriptlevel",
        "notation",
        "frame",
        "framespacing",
    ]
)
# Left as text, a `$` not before a digit (`$5` is money) or a backtick is an unclosed formula or code.
_STRAY = re.compile(r"\$(?!\d)|`")
_ARITY = {"mfrac": 2, "msub": 2, "msup": 2, "mroot": 2, "msubsup": 3, "munder": 2, "mover": 2}


class RenderIssue(ValueError):
    """Why a piece of TeX or Markdown does not render cleanly."""


def _serialize(element: ET.Element, out: list[str]) -> None:
    tag = element.tag.removeprefix(MATHML_NS)
    attributes = "".join(f' {name}="{escape(value)}"' for name, value in element.attrib.items())
    out.append(f"<{tag}{attributes}>")
    if element.text:
        out.append(escape(element.text))
    for child in element:
        _serialize(child, out)
        if child.tail:
            out.append(escape(child.tail))
    out.append(f"</{tag}>")


def _problems_in(element: ET.Element) -> Iterable[str]:
    for node in element.iter():
        tag = node.tag.removeprefix(MATHML_NS)
        if tag not in _TAGS or not node.tag.startswith(MATHML_NS):
            yield "markup inside the formula"
        if not set(node.attrib) <= _ATTRIBUTES | {"xmlns"}:
            yield "attributes inside the formula"
        if tag == "merror":
            yield "an error in the formula"
        if tag in _ARITY and len(node) != _ARITY[tag]:
            yield f"{tag} needs {_ARITY[tag]} arguments"
        if node.text and tag != "mtext" and (unknown := _UNKNOWN_COMMAND.search(node.text)):
            yield f"unknown command {unknown.group(0)}"


def _convert(tex: str, display: bool) -> ET.Element:
    """latex2mathml's tree for `tex`, typeset as TeX would (typesetting.py), or RenderIssue when it is
    not clean MathML."""
    if len(tex) > MAX_TEX_CHARS:
        raise RenderIssue(f"formula longer than {MAX_TEX_CHARS} characters")
    from latex2mathml.converter import convert

    try:
        markup = convert(textbook_tex(tex), display="block" if display else "inline")
        root = ET.fromstring(markup)  # noqa: S314 (our converter's output, not input)
    except Exception as error:  # latex2mathml raises many types on malformed TeX
        raise RenderIssue(f"TeX not understood: {type(error).__name__}: {error}") from None
    found = list(_problems_in(root))
    if found:
        raise RenderIssue("; ".join(dict.fromkeys(found)))
    polish(root)
    return root


@functools.lru_cache(maxsize=4096)
def _mathml(tex: str, display: bool) -> str:
    try:
        root = _convert(tex, display)
    except RenderIssue:
        # Shown as the TeX the author wrote rather than a half-made formula.
        return f'<code class="tex">{escape(tex)}</code>'
    root.attrib.pop("xmlns", None)
    root.set("alttext", tex)
    out: list[str] = []
    _serialize(root, out)
    return "".join(out)


def tex_to_mathml(tex: str, *, display: bool = False) -> Markup:
    """One formula as a `<math>` element (TeX kept in `alttext`); unclean TeX is shown as code."""
    return Markup(_mathml(tex.strip(), display))  # noqa: S704 (escaped by _serialize)


def tex_issues(tex: str) -> list[str]:
    try:
        _convert(tex.strip(), False)
    except RenderIssue as issue:
        return [str(issue)]
    return []


def _math_rule(display: bool) -> Any:
    def render(
        self: RendererHTML, tokens: Sequence[Token], idx: int, options: OptionsDict, env: EnvType
    ) -> str:
        return _mathml(tokens[idx].content.strip(), display)

    return render


@functools.cache
def _markdown() -> MarkdownIt:
    from markdown_it import MarkdownIt
    from mdit_py_plugins.dollarmath import dollarmath_plugin

    md = MarkdownIt("commonmark", {"html": False, "typographer": False})
    # `$5 and $6` stays text: a dollar followed by a digit does not open maths.
    dollarmath_plugin(md, allow_labels=False, allow_digits=False, double_inline=True)
    md.add_render_rule("math_inline", _math_rule(False))
    md.add_render_rule("math_inline_double", _math_rule(True))
    md.add_render_rule("math_block", _math_rule(True))
    md.add_render_rule("math_block_eqno", _math_rule(True))
    return md


def _bounded(text: str) -> str:
    return text[:MAX_TEXT_CHARS]


def render_markdown(text: str) -> Markup:
    """Paragraphs, lists, emphasis, `code` and maths, as HTML."""
    return Markup(_markdown().render(_bounded(text)))  # noqa: S704 (markdown-it escapes; html is off)


def render_inline(text: str) -> Markup:
    """One line (a prompt, a feedback sentence): inline Markdown and maths, no paragraph."""
    return Markup(_markdown().renderInline(_bounded(text).strip()))  # noqa: S704 (as above)


def render_issues(text: str) -> list[str]:
    """Why `text` does not render cleanly: TeX latex2mathml does not understand or leaves an error in,
    or a `$` or backtick left as text (an unclosed formula or code span). Empty: it renders cleanly."""
    found: list[str] = []
    for block in _markdown().parse(_bounded(text)):
        tokens = [block, *(block.children or [])]
        for token in tokens:
            if token.type.startswith("math_"):
                found.extend(f"${token.content.strip()}$: {issue}" for issue in tex_issues(token.content))
            elif token.type == "text" and _STRAY.search(token.content):
                found.append(f"stray $ or ` in {token.content.strip()!r}")
    return found
