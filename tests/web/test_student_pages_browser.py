"""Every bank problem's student page in Chromium, at desktop and phone widths: the statement and the
figure render, an answer is typed and typeset, submitted and graded, and is there after a reload;
no sideways scrolling and no serious axe-core finding. Screenshots: artifacts/student-<id>-<width>.png.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

import pytest

from problems.loader import load_bank
from problems.schema import SymbolicPart
from tests.browser import WIDTHS, LiveServer, check_page

pytestmark = [pytest.mark.browser, pytest.mark.slow]
BANK = {doc.id: doc for doc in load_bank()}


def readable_answer(problem_id: str) -> str:
    """An answer the first part can read (right or wrong): its first symbol, or a number with units."""
    doc = BANK[problem_id]
    part = doc.parts[0]
    if isinstance(part, SymbolicPart):
        return (part.symbols or list(doc.symbols))[0]
    return f"2 {part.units}" if part.units != "1" else "2"


@pytest.mark.parametrize("device", WIDTHS)
@pytest.mark.parametrize("problem_id", sorted(BANK))
def test_student_works_a_bank_problem(
    live_server: LiveServer, browse: Callable[..., Any], problem_id: str, device: str
) -> None:
    from playwright.sync_api import expect

    key = live_server.key("student", "Student", student=f"student-{device}")
    page = browse(f"{live_server.url}/p/{problem_id}", width=WIDTHS[device])
    page.get_by_label("Your student key").fill(key)
    page.keyboard.press("Enter")
    expect(page.get_by_role("heading", level=1)).to_have_text(BANK[problem_id].title)
    expect(page.locator(".statement math").first).to_be_visible()
    expect(page.locator(".statement")).not_to_contain_text("$")
    expect(page.locator("figure.problem-figure svg title")).to_have_count(1)
    answer = readable_answer(problem_id)
    box = page.get_by_label("Your answer").first
    box.press_sequentially(answer)
    expect(page.locator("#preview-0 math")).to_be_visible()
    box.press("Enter")
    verdict = page.locator(".verdict").first
    expect(verdict).to_have_text(re.compile(r"^(Correct|Not correct)\."))
    expect(page.locator("section.part").first.locator(".attempts")).to_contain_text("Attempts: 1")
    page.reload()
    expect(page.get_by_role("heading", level=1)).to_be_focused()
    expect(page.get_by_label("Your answer").first).to_have_value(answer)
    expect(page.locator("section.part").first.locator(".history summary")).to_contain_text("(1)")
    check_page(page, f"student-{problem_id}-{device}")
