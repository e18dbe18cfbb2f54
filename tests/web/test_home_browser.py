"""`/` in Chromium at desktop and phone widths: readable, no sideways scrolling, no serious axe finding."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from tests.browser import WIDTHS, LiveServer, check_page

pytestmark = [pytest.mark.browser, pytest.mark.slow]


@pytest.mark.parametrize("device", WIDTHS)
def test_home_page_points_to_the_student_and_instructor_pages(
    live_server: LiveServer, browse: Callable[..., Any], device: str
) -> None:
    from playwright.sync_api import expect

    page = browse(live_server.url + "/", width=WIDTHS[device])
    expect(page.get_by_role("heading", level=1)).to_contain_text("physcheck")
    expect(page.get_by_role("link", name="see your problems")).to_have_attribute("href", "/problems")
    expect(page.get_by_role("link", name="Instructor pages")).to_have_attribute("href", "/instructor")
    check_page(page, f"home-{device}")
    # The first Tab reaches the skip link, for keyboard users.
    page.keyboard.press("Tab")
    expect(page.get_by_role("link", name="Skip to content")).to_be_focused()
