"""The course pages in Chromium: on a phone each table row is a card of labelled lines that fits the
screen (nothing scrolls sideways, the page nor a table in its box); at desktop width they stay tables
with their column headings; and a new course's time zone is the browser's. axe-core on every page;
screenshots in artifacts/tables-*.png."""

from __future__ import annotations

from collections.abc import Callable
from datetime import UTC, datetime, timedelta
from typing import Any

import pytest

from app.courses.records import AssignmentSpec, RosterRow
from tests.browser import WIDTHS, LiveServer, check_page
from tests.db.helpers import CORRECT, INCORRECT
from tests.instructor.test_pages_browser import signed_in_page

pytestmark = [pytest.mark.browser, pytest.mark.slow]

# Long names, ids and emails: what widened the tables past a phone.
ROSTER = [
    RosterRow(
        "s-2026-000417",
        "Maria-Magdalena Wolfeschlegelsteinhausen",
        "maria.magdalena.wolfeschlegelsteinhausen@physics.uni.example",
    ),
    RosterRow("s-2026-000418", "Alan Turing", "alan.turing@physics.uni.example"),
]
# Each page's table: the builder's bank, the course's assignments, the gradebook's students and one
# student's parts, the submissions, an assignment's parts, a problem's class results per part.
PAGES = {
    "builder": ("/instructor/courses/{course}/assignments/new", "table.problem-picker"),
    "course": ("/instructor/courses/{course}", "table.stacked"),
    "gradebook": ("/instructor/courses/{course}/gradebook", "table.gradebook"),
    "student": (
        "/instructor/courses/{course}/gradebook?student=course%3A{course}%3As-2026-000417",
        "#parts table",
    ),
    "submissions": ("/instructor/submissions", "table.submissions"),
    "results": ("/instructor/assignments/{assignment}/results", "table.stacked"),
    "class-results": ("/instructor/problems/yo-yo/results", ".overview table"),
}


def _course_with_work(live_server: LiveServer, page: Any) -> dict[str, int]:
    """A course made on its page, its roster and an assignment of the yo-yo, and both students' answers."""
    page.get_by_label("Title", exact=True).fill("Mechanics, autumn term, section B (Thursdays)")
    page.get_by_role("button", name="Create the course").click()
    page.wait_for_url(f"{live_server.url}/instructor/courses/*")
    course = int(page.url.rsplit("/", 1)[1])
    stores = live_server.stores
    stores.courses.import_roster(course, ROSTER)
    now = datetime.now(UTC)
    assignment = stores.courses.create_assignment(
        course,
        AssignmentSpec(
            "Homework 1: rolling, unwinding and slipping",
            ("yo-yo",),
            now - timedelta(days=1),
            now + timedelta(days=6),
        ),
    )
    version = stores.problems.get("yo-yo").version
    for row, verdict in zip(ROSTER, (CORRECT, INCORRECT), strict=True):
        stores.submissions.file(
            problem_id="yo-yo",
            problem_version=version,
            part_id="acceleration",
            student=f"course:{course}:{row.roster_id}",
            answer="g*r^2/(r^2 + k^2) + 0*(m_1 + m_2 + m_3 + m_4 + m_5 + m_6 + m_7 + m_8)",
            verdict=verdict,
            max_attempts=None,
        )
    return {"course": course, "assignment": assignment.id}


def _layout(page: Any, table: str) -> dict[str, Any]:
    return page.evaluate(
        """(selector) => {
            const table = document.querySelector(selector);
            const box = table.closest('.table-wrap');
            const head = table.querySelector('thead');
            return {
                table: getComputedStyle(table).display,
                headingsShown: head.getBoundingClientRect().height > 1,
                overflow: box.scrollWidth - box.clientWidth,
                rows: table.querySelectorAll('tbody tr').length,
            };
        }""",
        table,
    )


@pytest.mark.parametrize("device", WIDTHS)
def test_course_tables_are_cards_on_a_phone_and_tables_on_a_desktop(
    live_server: LiveServer, browse: Callable[..., Any], device: str
) -> None:
    page = signed_in_page(live_server, browse, "/instructor/courses", WIDTHS[device])
    ids = _course_with_work(live_server, page)
    for name, (path, table) in PAGES.items():
        page.goto(live_server.url + path.format(**ids))
        shown = _layout(page, table)
        assert shown["rows"] >= 1, name
        assert shown["overflow"] <= 0, f"{name}: the table scrolls {shown['overflow']} px sideways in its box"
        if device == "phone":
            assert shown["table"] == "block" and not shown["headingsShown"], f"{name}: not cards"
        else:
            assert shown["table"] == "table" and shown["headingsShown"], f"{name}: not a table"
        check_page(page, f"tables-{name}-{device}")


def test_a_new_courses_time_zone_is_the_browsers_own(live_server: LiveServer, chromium: Any) -> None:
    from playwright.sync_api import expect

    context = chromium.new_context(timezone_id="America/Chicago")
    try:
        page = context.new_page()
        page.goto(live_server.url + "/instructor/courses")
        page.get_by_label("Instructor API key").fill(live_server.key("instructor", "Prof Chicago"))
        page.get_by_role("button", name="Sign in").click()
        expect(page.get_by_label("Time zone of its dates")).to_have_value("America/Chicago")  # not UTC
    finally:
        context.close()
