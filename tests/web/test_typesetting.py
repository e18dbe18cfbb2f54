"""Formulas typeset as TeX (and MathJax) would, by the MathML the server makes: sympy's TeX in a
textbook's style, upright units and the d of d/dt, words in one piece, accents on their letters, signs
without a gap, TeX's spacing around function names, and brackets no taller than their content needs."""

from __future__ import annotations

import re

import pytest

from app.web.rendering import render_inline, tex_to_mathml

CASES = [
    # (what, TeX, a fragment the MathML must hold, one it must not)
    (
        "sympy's sin of one symbol reads as a book writes it",
        r"\sin{\left(\theta \right)}",
        '<mi>sin</mi><mspace width="0.1667em"></mspace><mi>θ</mi>',
        "<mo",
    ),
    (
        "a number times a symbol needs no brackets either",
        r"\cos{\left(2 \theta \right)}",
        '<mi>cos</mi><mspace width="0.1667em"></mspace><mn>2</mn><mi>θ</mi>',
        "(",
    ),
    ("a sum keeps its brackets", r"\cos{\left(\theta + \phi \right)}", ">(</mo>", None),
    (
        "the d of d/dt is upright",
        r"\frac{\mathrm{d}}{\mathrm{d}t}",
        '<mi mathvariant="normal">d</mi>',
        "<mi>d</mi>",
    ),
    (
        "a unit of one letter is upright",
        r"4.58\,\mathrm{m}/\mathrm{s}^{2}",
        '<mi mathvariant="normal">m</mi>',
        "<mi>m</mi>",
    ),
    (
        "a word in a subscript is one upright name",
        r"x_{\mathrm{block}}",
        "<mi>block</mi>",
        'mathvariant="normal">b<',
    ),
    ("a dot is an accent on its letter", r"\ddot{x}", '<mover accent="true">', None),
    ("a sign after = has no gap", r"a = - b", '<mo form="prefix">−</mo>', None),
    ("brackets around a subscript do not stretch", r"\left(x_{1} - x_{2}\right)", 'stretchy="false"', None),
    ("brackets around a fraction stretch", r"\left(\frac{r_0}{r}\right)^{12}", 'stretchy="true"', None),
    ("a slash between units takes no space", r"\mathrm{m}/\mathrm{s}", 'lspace="0" rspace="0">/</mo>', None),
]


@pytest.mark.parametrize(("what", "tex", "holds", "lacks"), CASES, ids=[c[0] for c in CASES])
def test_formulas_are_typeset_as_tex_would(what: str, tex: str, holds: str, lacks: str | None) -> None:
    mathml = str(tex_to_mathml(tex))
    assert holds in mathml, (what, mathml)
    if lacks is not None:
        assert lacks not in mathml.split('alttext="')[0] + mathml.split('">', 1)[1], (what, mathml)


def test_display_formulas_keep_the_tex_for_assistive_technology_and_comparison() -> None:
    mathml = str(
        tex_to_mathml(
            r"U(r) = U_0\left[\left(\frac{r_0}{r}\right)^{12} - 2\left(\frac{r_0}{r}\right)^{6}\right]",
            display=True,
        )
    )
    assert mathml.startswith('<math display="block" alttext="U(r) = U_0')
    assert mathml.count('stretchy="true"') == 6  # the square brackets and both pairs of parentheses


def test_engine_feedback_is_typeset_not_ascii() -> None:
    from physics.engine.impact import RESTITUTION_SIGN

    html = str(render_inline(RESTITUTION_SIGN))
    assert "v2 - v1" not in html and "<math" in html
    assert re.search(r"<msub><mi>v</mi><mn>2</mn></msub>", html)
