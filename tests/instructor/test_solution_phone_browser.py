"""The worked solutions with the widest comparison tables and formulas (the moving wedge's four methods,
the yo-yo's) at phone width: the page itself never scrolls sideways; a wide table or formula scrolls
inside its own box."""

from __future__ import annotations

import shutil
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from app.grading.pool import GradingPool
from problems.loader import BANK_DIR
from tests.browser import WIDTHS, LiveServer, artifacts_dir, check_page
from tests.instructor.conftest import serve_bank
from tests.instructor.test_pages_browser import signed_in_page

pytestmark = [pytest.mark.browser, pytest.mark.slow]

PROBLEMS = ("moving-wedge", "yo-yo")

# Elements whose right edge passes the viewport's and that no scrolling box holds: the page would move
# sideways under a thumb, and text past the edge cannot be read.
_PAST_THE_EDGE = """() => {
  const edge = document.documentElement.clientWidth + 1;
  const past = [];
  for (const el of document.querySelectorAll('main *')) {
    const box = el.getBoundingClientRect();
    if (box.width === 0 || box.right <= edge) continue;
    let held = false;
    for (let up = el.parentElement; up && !held; up = up.parentElement) {
      held = ['auto', 'scroll', 'hidden'].includes(getComputedStyle(up).overflowX);
    }
    if (!held) past.push(el.tagName + ' ' + (el.textContent || '').trim().slice(0, 40));
  }
  return past;
}"""


@pytest.fixture(scope="module")
def live_server(
    page_grading_pool: GradingPool, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[LiveServer]:
    bank: Path = tmp_path_factory.mktemp("bank")
    for problem in PROBLEMS:
        shutil.copytree(BANK_DIR / problem, bank / problem)
    yield from serve_bank(page_grading_pool, bank, ready_within=180)


@pytest.mark.parametrize("problem", PROBLEMS)
def test_a_phone_never_scrolls_the_solution_sideways(
    live_server: LiveServer, browse: Callable[..., Any], problem: str
) -> None:
    page = signed_in_page(live_server, browse, f"/instructor/problems/{problem}/solution", WIDTHS["phone"])
    page.wait_for_timeout(300)  # the math font
    assert page.title().startswith("Worked solution")
    assert page.evaluate(_PAST_THE_EDGE) == []
    assert page.evaluate("document.documentElement.scrollWidth <= document.documentElement.clientWidth")
    # the comparison of methods is read whole, each method a card of labelled lines, with no scrolling
    table = page.locator(".comparison .table-wrap")
    assert table.evaluate("el => el.scrollWidth <= el.clientWidth + 1")
    assert "Constraint forces it names" in table.inner_text()
    check_page(page, f"solution-{problem}-phone")
    table.screenshot(path=str(artifacts_dir() / f"solution-{problem}-methods-phone.png"))
