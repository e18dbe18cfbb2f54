"""The one renderer: Markdown with TeX to HTML with MathML, escaped, and its cleanliness check."""

from __future__ import annotations

from html.parser import HTMLParser

import pytest

from app.web.rendering import render_inline, render_issues, render_markdown, tex_to_mathml
from tests.bank import bank_documents


def test_inline_maths_becomes_mathml_with_its_tex_kept_for_assistive_technology() -> None:
    html = render_inline(r"This uses $N = mg\cos\theta$.")
    assert '<math display="inline" alttext="N = mg\\cos\\theta">' in html
    assert '<mi>cos</mi><mspace width="0.1667em"></mspace><mi>θ</mi>' in html  # TeX's thin space
    assert "$" not in html and "\\cos" not in html.replace('alttext="N = mg\\cos\\theta"', "")


def test_display_maths_inside_a_paragraph_is_a_block_formula_and_prose_after_it_stays_prose() -> None:
    text = "The potential\n$$U(r) = U_0\\left(\\frac{r_0}{r}\\right)^{12},$$\nwhere $U_0 > 0$ is a constant."
    html = render_markdown(text)
    assert '<math display="block"' in html
    assert "<mfrac>" in html
    after = html.split("</math>", 1)[1]
    assert "where" in after and "<mi>w</mi>" not in html


def test_backticks_are_code_and_markdown_is_rendered() -> None:
    html = render_markdown("Write $m_1$ as `m1`, *not* `m_1`.")
    assert "<code>m1</code>" in html and "<em>not</em>" in html and "`" not in html


class _Markup(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.tags: list[str] = []
        self.attributes: list[tuple[str, str]] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append(tag)
        self.attributes.extend((name, value or "") for name, value in attrs)


@pytest.mark.parametrize(
    "text",
    [
        "<script>alert(1)</script>",
        r"$\text{<script>alert(1)</script>}$",
        r'$\text{<mi onclick="alert(1)">x</mi>}$',
        "[click](javascript:alert(1))",
    ],
)
def test_nothing_in_the_text_becomes_markup(text: str) -> None:
    found = _Markup()
    found.feed(render_markdown(text))
    assert "script" not in found.tags and "mi" not in found.tags
    assert not [name for name, value in found.attributes if name.startswith("on") or "javascript" in value]


@pytest.mark.parametrize(
    ("text", "why"),
    [
        (r"an $\unknowncommand x$ here", "unknown command"),
        (r"a $\frac{a}$ here", "mfrac needs 2 arguments"),
        ("an unclosed $x formula", "stray $"),
        ("an unclosed `code span", "stray $ or `"),
        (r"$\text{<b>x</b>}$", "markup inside the formula"),
    ],
)
def test_unclean_text_is_reported(text: str, why: str) -> None:
    issues = render_issues(text)
    assert issues and why in issues[0]


def test_unclean_tex_is_shown_as_the_authors_code_not_half_a_formula() -> None:
    assert str(tex_to_mathml(r"\frac{a}")) == r'<code class="tex">\frac{a}</code>'


def test_dollar_amounts_are_not_maths() -> None:
    assert render_issues("It costs $5 and $6.") == []


def test_every_bank_text_renders_cleanly() -> None:
    from app.web.document_text import render_problems

    problems = {doc.id: render_problems(doc) for doc in bank_documents().values()}
    assert {pid: issues for pid, issues in problems.items() if issues} == {}
