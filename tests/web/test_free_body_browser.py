"""The free-body editor in Chromium at phone width, used with the keyboard alone: the palette's buttons
add forces, each direction is typed in its own field, the list is the diagram a screen reader reads,
the answer box holds the text that is graded; no serious axe-core finding, no sideways scrolling.
Screenshot: artifacts/free-body-phone.png. The lab's data (table, plot, CSV) on the same run."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from tests.browser import FIRST_USE_MS, WIDTHS, LiveServer, check_page
from tests.web.test_student_pages_browser import open_problem

pytestmark = [pytest.mark.browser, pytest.mark.slow]


def test_forces_are_drawn_with_the_keyboard_alone_on_a_phone(
    live_server: LiveServer, browse: Callable[..., Any]
) -> None:
    from playwright.sync_api import expect

    key = live_server.key("student", "Drawer", student="drawer")
    page = open_problem(live_server, browse, "moving-wedge-lagrangian", key, WIDTHS["phone"])
    section = page.locator("#part-forces_on_block")
    section.get_by_role("button", name="+ weight").focus()
    page.keyboard.press("Enter")  # adds the weight, its direction field focused (270 by default)
    section.get_by_role("button", name="+ normal").focus()
    page.keyboard.press("Enter")
    page.keyboard.press("Control+A")
    page.keyboard.type("90")
    answer = section.get_by_label("Your answer")
    expect(answer).to_have_value("weight 270; normal 90")
    expect(section.locator(".drawn-forces li")).to_have_count(2)
    expect(section.locator(".arrows line")).to_have_count(2)
    check_page(page, "free-body-phone")
    section.get_by_role("button", name="Check answer").click()
    expect(section.locator(".verdict")).to_contain_text("perpendicular", timeout=FIRST_USE_MS)


def test_a_lab_shows_the_students_own_table_plot_and_csv(
    live_server: LiveServer, browse: Callable[..., Any]
) -> None:
    from playwright.sync_api import expect

    key = live_server.key("student", "Labber", student="labber")
    page = open_problem(live_server, browse, "incline-lab", key, WIDTHS["phone"])
    expect(page.locator("table.lab-data tbody tr")).to_have_count(7, timeout=FIRST_USE_MS)
    expect(page.locator("figure.lab-plot circle")).to_have_count(7)
    expect(page.get_by_role("link", name="Download your measurements (CSV)")).to_be_visible()
    check_page(page, "lab-data-phone")
