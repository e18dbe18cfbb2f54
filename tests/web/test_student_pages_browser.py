"""Bank problems' student pages in Chromium at phone width (a new sample each day, tests/sampling.py:
about a second each): the statement and the figure render, with no sideways scrolling and no serious
axe-core finding; on a fixed sample of problems, at desktop and phone widths, an answer is typed and
typeset, submitted and graded, and is there after a reload.
Screenshots: artifacts/student-<id>-phone.png and artifacts/student-worked-<id>-<width>.png.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

import pytest

from problems.schema import SymbolicPart
from tests.bank import bank_documents
from tests.browser import FIRST_USE_MS, WIDTHS, LiveServer, check_page
from tests.sampling import sampled

pytestmark = [pytest.mark.browser, pytest.mark.slow]
BANK = bank_documents()
# Worked through (type, preview, submit, reload) at both widths: a sample of kinds of problem, since
# each problem's first check compiles it (seconds on a busy machine). Every page is rendered above.
WORKED = [
    pid
    for pid in (
        "incline-pulley",
        "lennard-jones",
        "moving-wedge",
        "rolling-incline",
        "skier-friction",
        "yo-yo",
    )
    if pid in BANK
]


def readable_answer(problem_id: str) -> str:
    """An answer the first part can read (right or wrong): its first symbol, or a number with units."""
    doc = BANK[problem_id]
    part = doc.parts[0]
    if isinstance(part, SymbolicPart):
        return (part.symbols or list(doc.symbols))[0]
    return f"2 {part.units}" if part.units != "1" else "2"


def open_problem(
    live_server: LiveServer, browse: Callable[..., Any], problem_id: str, key: str, width: int
) -> Any:
    from playwright.sync_api import expect

    page = browse(f"{live_server.url}/p/{problem_id}", width=width)
    page.get_by_label("Your student key").fill(key)
    page.keyboard.press("Enter")
    expect(page.get_by_role("heading", level=1)).to_have_text(BANK[problem_id].title)
    expect(page.locator(".statement math").first).to_be_visible()
    expect(page.locator(".statement")).not_to_contain_text("$")
    expect(page.locator("figure.problem-figure svg title")).to_have_count(1)
    return page


@pytest.mark.parametrize("problem_id", sampled(sorted(BANK), 6, "student-page-on-a-phone"))
def test_a_bank_problems_page_renders_with_its_figure_on_a_phone(
    live_server: LiveServer, browse: Callable[..., Any], problem_id: str
) -> None:
    """Statement typeset, figure drawn, no sideways scrolling at 390 px, no serious axe finding (no
    grading here: each problem's first check compiles it, which the sampled test below pays for)."""
    key = live_server.key("student", "Reader", student="reader")
    page = open_problem(live_server, browse, problem_id, key, WIDTHS["phone"])
    check_page(page, f"student-{problem_id}-phone")


@pytest.mark.parametrize("problem_id", WORKED)
@pytest.mark.sample(3)
def test_student_works_a_bank_problem_at_desktop_and_phone_widths(
    live_server: LiveServer, browse: Callable[..., Any], problem_id: str
) -> None:
    from playwright.sync_api import expect

    key = live_server.key("student", "Student", student="student")
    page = open_problem(live_server, browse, problem_id, key, WIDTHS["desktop"])
    answer = readable_answer(problem_id)
    box = page.get_by_label("Your answer").first
    box.press_sequentially(answer)
    expect(page.locator("#preview-0 math")).to_be_visible(timeout=FIRST_USE_MS)
    box.press("Enter")
    verdict = page.locator(".verdict").first
    expect(verdict).to_have_text(re.compile(r"^(Correct|Not correct)\."), timeout=FIRST_USE_MS)
    expect(page.locator("section.part").first.locator(".attempts")).to_contain_text("Attempts: 1")
    # The verdict box (a live region) says the count too, to a screen reader only: it is shown just below.
    expect(verdict.locator(".visually-hidden")).to_have_text(re.compile(r"^Attempts: 1 "))
    page.reload()
    expect(page.get_by_role("heading", level=1)).to_be_focused()
    expect(page.get_by_label("Your answer").first).to_have_value(answer)
    expect(page.locator("section.part").first.locator(".history summary")).to_contain_text("(1)")
    check_page(page, f"student-worked-{problem_id}-desktop")
    phone = open_problem(live_server, browse, problem_id, key, WIDTHS["phone"])
    expect(phone.get_by_label("Your answer").first).to_have_value(answer)
    check_page(phone, f"student-worked-{problem_id}-phone")


@pytest.mark.parametrize("device", WIDTHS)
def test_problem_list_for_a_student_key_links_every_problem_with_the_students_score(
    live_server: LiveServer, browse: Callable[..., Any], device: str
) -> None:
    from playwright.sync_api import expect

    key = live_server.key("student", "Lister", student=f"lister-{device}")
    page = browse(f"{live_server.url}/problems", width=WIDTHS[device])
    page.get_by_label("Your student key").fill(key)
    page.get_by_role("button", name="Show my problems").click()
    expect(page.get_by_role("heading", level=1)).to_have_text("Your problems")
    cards = page.locator(".problem-list > li")
    expect(cards).to_have_count(len(BANK))
    expect(cards.first).to_contain_text("Not started")
    first = sorted(BANK.values(), key=lambda doc: (doc.title.casefold(), doc.id))[0]  # by title
    link = page.get_by_role("link", name=first.title, exact=True)
    expect(link).to_have_attribute("href", f"/p/{first.id}")
    check_page(page, f"problems-{device}")
    link.click()  # the key is kept in the tab: the problem opens without asking again
    expect(page.get_by_role("heading", level=1)).to_have_text(first.title)
    submit_box = page.get_by_label("Your answer").first
    submit_box.fill(readable_answer(first.id))
    submit_box.press("Enter")
    expect(page.locator(".verdict").first).to_have_text(
        re.compile(r"^(Correct|Not correct)\."), timeout=FIRST_USE_MS
    )
    page.go_back()
    expect(page.locator(".problem-list > li").first).to_contain_text("Score:")


def test_the_answer_that_releases_the_worked_solution_says_so_at_once(
    live_server: LiveServer, browse: Callable[..., Any]
) -> None:
    # the link at the foot of the page had said "shown once it is released" until a reload
    from playwright.sync_api import expect

    from tests.instructor.test_pages import RIGHT

    problem_id = "skier-friction"
    version = live_server.stores.problems.get(problem_id).version
    for part in ("acceleration", "friction_coefficient_numeric", "acceleration_numeric"):
        live_server.stores.submissions.file(
            problem_id=problem_id,
            problem_version=version,
            part_id=part,
            student="releaser",
            answer="x",
            verdict=RIGHT,
            max_attempts=None,
        )
    key = live_server.key("student", "Releaser", student="releaser")
    page = open_problem(live_server, browse, problem_id, key, WIDTHS["phone"])
    link = page.locator("#solution-link")
    expect(link).to_contain_text("shown once it is released")
    box = page.locator("#part-friction_coefficient input[name=answer]")
    box.press_sequentially("tan(alpha)")
    box.press("Enter")
    expect(page.locator("#part-friction_coefficient .verdict")).to_have_text(
        re.compile(r"^Correct\."), timeout=FIRST_USE_MS
    )
    expect(link).to_contain_text("released to you")
    check_page(page, "student-solution-released-phone")
