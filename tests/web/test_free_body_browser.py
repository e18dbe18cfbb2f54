"""The free-body editor in Chromium at phone width, used with the keyboard alone: the palette's buttons
add forces, each direction is typed in its own field, the list is the diagram a screen reader reads,
the answer box holds the text that is graded; no serious axe-core finding, no sideways scrolling.
Screenshot: artifacts/free-body-phone.png. An arrow turned by dragging, with the mouse on a desktop and
with a finger (touch-sized pointer events through Chromium's own touch input) on a phone: the direction
field and the graded answer follow (free-body-drag-desktop.png, free-body-drag-phone.png). The lab's
data (table, plot, CSV) on the same run."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import pytest

from tests.browser import FIRST_USE_MS, WIDTHS, LiveServer, artifacts_dir, check_page
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


def canvas_point(canvas: Any, degrees: float, radius: float) -> tuple[float, float]:
    """The page point `radius` canvas units from the body's centre, `degrees` anticlockwise from +x."""
    box = canvas.bounding_box()
    scale = box["width"] / 220  # the canvas's viewBox is 220 units across
    rad = math.radians(degrees)
    return (
        box["x"] + box["width"] / 2 + radius * scale * math.cos(rad),
        box["y"] + box["height"] / 2 - radius * scale * math.sin(rad),
    )


def head_of(section: Any, index: int) -> tuple[float, float]:
    box = section.locator(f".force[data-index='{index}'] .handle").bounding_box()
    return box["x"] + box["width"] / 2, box["y"] + box["height"] / 2


def test_an_arrow_dragged_with_the_mouse_sets_its_direction_and_the_graded_answer(
    live_server: LiveServer, browse: Callable[..., Any]
) -> None:
    from playwright.sync_api import expect

    key = live_server.key("student", "Mouse drawer", student="mouse-drawer")
    page = open_problem(live_server, browse, "moving-wedge-lagrangian", key, WIDTHS["desktop"])
    section = page.locator("#part-forces_on_block")
    section.get_by_role("button", name="+ weight").click()
    section.get_by_role("button", name="+ normal").click()
    answer = section.get_by_label("Your answer")
    expect(answer).to_have_value("weight 270; normal 90")
    canvas = section.locator(".force-canvas")
    canvas.scroll_into_view_if_needed()
    page.mouse.move(*head_of(section, 0))
    page.mouse.down()
    page.mouse.move(*canvas_point(canvas, 40, 70), steps=5)
    expect(section.get_by_label("weight, direction (degrees)")).to_have_value("40")  # follows the pointer
    page.mouse.move(*canvas_point(canvas, 2, 70), steps=5)  # 2° snaps to 0
    page.mouse.up()
    expect(section.get_by_label("weight, direction (degrees)")).to_have_value("0")
    expect(section.get_by_label("normal, direction (degrees)")).to_have_value("90")
    expect(answer).to_have_value("weight 0; normal 90")
    section.locator(".free-body-editor").screenshot(path=str(artifacts_dir() / "free-body-drag-editor.png"))
    check_page(page, "free-body-drag-desktop")
    section.get_by_role("button", name="Check answer").click()
    expect(section.locator(".verdict")).to_contain_text("weight points straight down", timeout=FIRST_USE_MS)


def test_an_arrow_dragged_with_a_finger_on_a_phone_sets_its_direction_and_the_graded_answer(
    live_server: LiveServer, browse: Callable[..., Any]
) -> None:
    from playwright.sync_api import expect

    key = live_server.key("student", "Finger drawer", student="finger-drawer")
    page = open_problem(live_server, browse, "moving-wedge-lagrangian", key, WIDTHS["phone"])
    section = page.locator("#part-forces_on_block")
    section.get_by_role("button", name="+ weight").click()
    canvas = section.locator(".force-canvas")
    canvas.scroll_into_view_if_needed()
    canvas.evaluate(
        """c => { window.seen = [];
        c.addEventListener("pointerdown", e => window.seen.push([e.pointerType, e.width, e.height])); }"""
    )
    cdp = page.context.new_cdp_session(page)
    cdp.send("Emulation.setTouchEmulationEnabled", {"enabled": True, "maxTouchPoints": 1})

    def touch(kind: str, point: tuple[float, float] | None = None) -> None:
        points = [] if point is None else [{"x": point[0], "y": point[1], "radiusX": 12, "radiusY": 12}]
        cdp.send("Input.dispatchTouchEvent", {"type": kind, "touchPoints": points})

    touch("touchStart", head_of(section, 0))  # the weight's head, 270° by default
    for degrees in (250, 220, 200, 181):
        touch("touchMove", canvas_point(canvas, degrees, 75))
    touch("touchEnd")
    field = section.get_by_label("weight, direction (degrees)")
    answer = section.get_by_label("Your answer")
    expect(field).to_have_value("180")
    expect(answer).to_have_value("weight 180")
    touch("touchStart", canvas_point(canvas, 268, 45))  # a tap below the body, off the head: 270
    touch("touchEnd")
    expect(field).to_have_value("270")
    expect(answer).to_have_value("weight 270")
    seen = page.evaluate("window.seen")
    assert seen and all(kind == "touch" and w >= 20 and h >= 20 for kind, w, h in seen), seen
    section.locator(".free-body-editor").screenshot(
        path=str(artifacts_dir() / "free-body-drag-editor-phone.png")
    )
    check_page(page, "free-body-drag-phone")
    section.get_by_role("button", name="Check answer").click()
    verdict = section.locator(".verdict")
    expect(verdict).to_contain_text("missing", timeout=FIRST_USE_MS)  # the normal force, not drawn
    expect(verdict).not_to_contain_text("points the wrong way")


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
