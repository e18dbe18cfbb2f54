"""The worked solution in Chromium: printed to PDF on A4 and Letter, nothing is cut by the page's width
(every formula and figure fits); at 1280 and 390 px every formula has the size MathJax gives the same
TeX (measured, where MathJax is installed: `npm install --prefix .mathjax mathjax-full@3.2.2`)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from tests.browser import WIDTHS, LiveServer, artifacts_dir, check_page
from tests.instructor.test_pages_browser import signed_in_page
from tests.web.side_by_side import mathjax_dir, swap_in_mathjax

pytestmark = [pytest.mark.browser, pytest.mark.slow]

# Widths of what would be cut on the printed page: formulas and figures wider than their box.
_CUT = """() => {
  const cut = [];
  for (const el of document.querySelectorAll('math[display="block"], figure svg, table')) {
    const box = el.getBoundingClientRect();
    if (el.scrollWidth > el.clientWidth + 1 || box.right > document.documentElement.clientWidth + 1)
      cut.push((el.getAttribute('alttext') || el.tagName).slice(0, 60));
  }
  return cut;
}"""
# each formula's ink box, in page order: [width, height] (a display formula's content, not its block)
_BOXES = """() => Array.from(document.querySelectorAll('math, mjx-container > svg')).map(el => {
  const b = (el.tagName === 'math' && el.firstElementChild ? el.firstElementChild : el).getBoundingClientRect();
  return [b.width, b.height]; })"""


@pytest.mark.parametrize(("paper", "width_px"), [("A4", 718), ("Letter", 745)])
def test_the_printed_solution_fits_the_page(
    live_server: LiveServer, browse: Callable[..., Any], paper: str, width_px: int
) -> None:
    page = signed_in_page(live_server, browse, "/instructor/problems/yo-yo/solution", WIDTHS["desktop"])
    page.emulate_media(media="print")
    page.set_viewport_size({"width": width_px, "height": 1000})  # the paper's width less its margins
    assert page.evaluate(_CUT) == []
    pdf = artifacts_dir() / f"solution-yo-yo-{paper}.pdf"
    page.pdf(path=str(pdf), format=paper, print_background=False)
    assert pdf.stat().st_size > 10_000
    assert page.locator(".site-header").is_hidden() and page.locator("form").first.is_hidden()


@pytest.mark.parametrize("device", WIDTHS)
def test_the_solution_reads_cleanly_at_desktop_and_phone_widths(
    live_server: LiveServer, browse: Callable[..., Any], device: str
) -> None:
    from playwright.sync_api import expect

    page = signed_in_page(live_server, browse, "/instructor/problems/yo-yo/solution", WIDTHS[device])
    expect(page.get_by_role("heading", name="The methods compared")).to_be_visible()
    expect(page.get_by_role("table", name="What each method needed for this problem")).to_be_visible()
    check_page(page, f"solution-yo-yo-{device}")


@pytest.mark.skipif(mathjax_dir() is None, reason="MathJax (npm mathjax-full) is not installed")
@pytest.mark.parametrize("device", WIDTHS)
def test_formulas_have_the_size_mathjax_gives_them(
    live_server: LiveServer, browse: Callable[..., Any], device: str
) -> None:
    page = signed_in_page(live_server, browse, "/instructor/problems/yo-yo/solution", WIDTHS[device])
    page.wait_for_timeout(300)  # the math font
    ours = page.evaluate(_BOXES)
    page.screenshot(path=str(artifacts_dir() / f"typeset-yo-yo-{device}-ours.png"), full_page=True)
    assert swap_in_mathjax(page) == len(ours)
    page.wait_for_timeout(100)
    theirs = page.evaluate(_BOXES)
    page.screenshot(path=str(artifacts_dir() / f"typeset-yo-yo-{device}-mathjax.png"), full_page=True)
    # Heights (the same font size, scripts and fractions placed alike) within a quarter of MathJax's;
    # widths too, where both write the same thing (sin θ against MathJax's sin(θ) is narrower).
    far = [
        (i, o, t)
        for i, (o, t) in enumerate(zip(ours, theirs, strict=True))
        if t[1] > 0 and not 0.75 <= o[1] / t[1] <= 1.33
    ]
    assert not far, far[:5]
    wider = [
        (i, o, t)
        for i, (o, t) in enumerate(zip(ours, theirs, strict=True))
        if t[0] > 0 and o[0] > 1.25 * t[0]
    ]
    assert not wider, wider[:5]
