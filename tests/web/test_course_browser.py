"""A course run in Chromium as people would: an instructor signs in, makes a course, imports a roster
of 30, builds two assignments of three problems (one due two hours ago, with a late penalty), makes the
sign-in links; students sign in by their links (a phone and a desktop, several tabs, no key asked),
see only their assignments, and answer; a late answer loses its penalty, an extension lifts it for
one student (regrading the answers given, as the teacher ticks); the gradebook page and its CSV agree with the submissions. axe-core on every page,
screenshots at 1280 and 390 px in artifacts/course-*.png. (The LMS side, deep linking an assignment
and its scores sent once each, runs against the test platform in tests/lti/test_assignment_links.py.)
"""

from __future__ import annotations

import csv
import io
import re
import shutil
from collections.abc import Callable, Iterator
from datetime import UTC, datetime, timedelta
from typing import Any

import pytest

from app.grading.pool import GradingPool
from app.main import create_app
from app.settings import Settings
from problems.loader import BANK_DIR
from tests.bank import bank_documents
from tests.browser import FIRST_USE_MS, WIDTHS, LiveServer, check_page, serve

pytestmark = [pytest.mark.browser, pytest.mark.slow]
HOMEWORK_1 = ["atwood", "projectile", "simple-pendulum"]
HOMEWORK_2 = ["skier-friction", "yo-yo", "mass-spring"]  # due two hours ago: one day late, 10 % off
BANK = bank_documents()
ROSTER = "id,name,email\n" + "".join(f"s{n:03d},Student {n:02d},s{n:03d}@uni.example\n" for n in range(1, 31))
UNASSIGNED = "moving-wedge"  # in the bank, in no assignment
RIGHT = "tan(alpha)"  # skier-friction's friction_coefficient: coasting at constant speed


@pytest.fixture(scope="module")
def live_server(
    tmp_path_factory: pytest.TempPathFactory, page_grading_pool: GradingPool
) -> Iterator[LiveServer]:
    """The real app on SQLite with a bank of the six problems the course uses."""
    bank = tmp_path_factory.mktemp("course-bank")
    for problem_id in [*HOMEWORK_1, *HOMEWORK_2, UNASSIGNED]:
        shutil.copytree(BANK_DIR / problem_id, bank / problem_id)
    folder = tmp_path_factory.mktemp("course-live")
    settings = Settings(
        database_url=f"sqlite:///{folder / 'physcheck.db'}",
        secret="course-page-secret-0123456789",
        check_workers=1,
        bank_dir=bank,
        warm_up=False,  # a problem compiles when first answered (only skier-friction here)
    )
    app = create_app(settings, pool=page_grading_pool)
    for url in serve(app):
        yield LiveServer(url, app)


def _local(moment: datetime) -> str:
    return moment.strftime("%Y-%m-%dT%H:%M")


def _build(page: Any, title: str, problems: list[str], opens: datetime, due: datetime, late: bool) -> None:
    from playwright.sync_api import expect

    page.get_by_role("link", name="New assignment").click()
    expect(page.get_by_role("heading", level=1)).to_have_text("New assignment")
    for position, problem_id in enumerate(problems, start=1):
        name = BANK[problem_id].title
        page.get_by_label(name, exact=True).check()
        page.get_by_label(f"Order of {name}", exact=True).fill(str(position))
    page.get_by_label("Title", exact=True).fill(title)
    page.get_by_label(re.compile(r"^Opens")).fill(_local(opens))
    page.get_by_label(re.compile(r"^Due")).fill(_local(due))
    if late:
        page.get_by_label("Late work").select_option("penalty")
        page.get_by_label("Penalty per day late (%)").fill("10")
        page.get_by_label("At most (%)").fill("50")
    page.get_by_role("button", name="Save the assignment").click()
    expect(page.get_by_role("rowheader", name=title, exact=True)).to_be_visible()


def _sign_in_student(browse: Callable[..., Any], url: str, width: int) -> Any:
    from playwright.sync_api import expect

    page = browse(url, width=width)
    page.get_by_role("button", name="Sign in").click()
    expect(page.get_by_role("heading", level=1)).to_have_text("Your courses")
    return page


def _answer(page: Any, problem_title: str) -> None:
    from playwright.sync_api import expect

    page.get_by_role("link", name=problem_title).click()
    expect(page.get_by_role("heading", level=1)).to_have_text(problem_title)
    expect(page.locator(".assignment-banner")).to_contain_text("Homework 2")
    expect(page.locator(".assignment-banner")).to_contain_text("Late work loses 10 %")
    box = page.locator("#part-friction_coefficient input[name=answer]")
    box.press_sequentially(RIGHT)
    box.press("Enter")
    expect(page.locator("#part-friction_coefficient .verdict")).to_have_text(
        re.compile(r"^Correct\."), timeout=FIRST_USE_MS
    )


def test_a_course_runs_from_roster_to_gradebook(live_server: LiveServer, browse: Callable[..., Any]) -> None:
    from playwright.sync_api import expect

    now = datetime.now(UTC)
    # The instructor: sign in, a course, its roster, two assignments, the students' links.
    teacher = browse(f"{live_server.url}/instructor/sign-in", width=WIDTHS["desktop"])
    teacher.get_by_label("Instructor API key").fill(live_server.key("instructor", "Prof Noether"))
    teacher.get_by_role("button", name="Sign in").click()
    teacher.get_by_role("link", name="Courses").click()
    teacher.get_by_label("Title", exact=True).fill("Mechanics 101")
    teacher.get_by_role("button", name="Create the course").click()
    expect(teacher.get_by_role("heading", level=1)).to_have_text("Mechanics 101")
    teacher.get_by_label("Paste a roster CSV: id, name, email").fill(ROSTER)
    teacher.get_by_role("button", name="Import the roster").click()
    expect(teacher.get_by_role("status")).to_contain_text("30 added, 0 updated")
    teacher.get_by_label("Paste a roster CSV: id, name, email").fill(ROSTER)  # again: no duplicates
    teacher.get_by_role("button", name="Import the roster").click()
    expect(teacher.get_by_role("status")).to_contain_text("0 added, 0 updated, 30 unchanged")
    expect(teacher.get_by_role("heading", name="Roster (30)")).to_be_visible()
    _build(teacher, "Homework 1", HOMEWORK_1, now - timedelta(days=1), now + timedelta(days=6), late=False)
    teacher.get_by_role("link", name="New assignment").click()
    check_page(teacher, "course-builder-desktop")
    teacher.go_back()
    _build(teacher, "Homework 2", HOMEWORK_2, now - timedelta(days=5), now - timedelta(hours=2), late=True)
    check_page(teacher, "course-desktop")
    teacher.get_by_role("button", name="Make sign-in links for everyone").click()
    expect(teacher.locator("code.sign-in-link")).to_have_count(30)  # the page after the form's answer
    links = teacher.locator("code.sign-in-link").all_inner_texts()
    check_page(teacher, "course-links-desktop")

    # Student 1 on a phone: signed in by the link, two tabs, only their assignments.
    phone = _sign_in_student(browse, links[0], WIDTHS["phone"])
    expect(phone.locator(".assignment-list > li")).to_have_count(2)
    expect(phone.locator(".assignment-list")).to_contain_text("Late")
    check_page(phone, "course-home-phone")
    second_tab = phone.context.new_page()
    second_tab.goto(f"{live_server.url}/courses")
    expect(second_tab.get_by_role("heading", level=1)).to_have_text("Your courses")  # no key, no link again
    phone.get_by_role("link", name="Homework 2").click()
    expect(phone.locator(".problem-list > li")).to_have_count(3)
    expect(phone.locator(".problem-list h2").first).to_have_text(BANK["skier-friction"].title)
    check_page(phone, "course-assignment-phone")
    _answer(phone, BANK["skier-friction"].title)
    check_page(phone, "course-problem-phone")
    outside = second_tab.goto(f"{live_server.url}/p/{UNASSIGNED}")
    assert outside is not None and outside.status == 404  # not in their assignments
    reused = browse(links[0], width=WIDTHS["desktop"])  # the link was spent
    reused.get_by_role("button", name="Sign in").click()
    expect(reused.get_by_role("alert")).to_contain_text("already been used")

    # Student 2 at a desktop, late too; then an extension that regrades the answers given lifts their
    # penalty (without the tick it counts for new answers only).
    desk = _sign_in_student(browse, links[1], WIDTHS["desktop"])
    desk.get_by_role("link", name="Homework 2").click()
    _answer(desk, BANK["skier-friction"].title)

    teacher.goto(f"{live_server.url}/instructor/courses")
    teacher.get_by_role("link", name=re.compile(r"^Gradebook\W+Mechanics 101")).click()
    teacher.get_by_label("Student", exact=True).select_option(label="Student 02 (s002@uni.example)")
    teacher.get_by_label("Assignment").select_option(label="Homework 2")
    teacher.get_by_label(re.compile(r"^New due date")).fill(_local(now + timedelta(days=2)))
    teacher.get_by_label("Also lift the late penalty on the answers already given").check()
    teacher.get_by_role("button", name="Set the extension").click()
    rows = teacher.locator("table.gradebook tbody tr")
    expect(rows).to_have_count(30)
    # Columns by due date: Homework 2 (due yesterday) first.
    expect(teacher.locator("table.gradebook thead th").nth(1)).to_contain_text("Homework 2")
    first, second = rows.nth(0), rows.nth(1)
    expect(first.locator("td").nth(0)).to_contain_text("0.9")
    expect(first.locator("td").nth(0)).to_contain_text("late")
    expect(second.locator("td").nth(0)).to_contain_text("1")
    expect(second.locator("td").nth(0)).to_contain_text("ext.")
    expect(rows.nth(2).locator("td").nth(0)).to_have_text(re.compile(r"^\s*—\s*late\b"))  # not started
    check_page(teacher, "course-gradebook-desktop")
    exported = teacher.context.request.get(teacher.url.split("?")[0] + ".csv")
    table = {row[0]: row for row in csv.reader(io.StringIO(exported.text()))}
    assert table["Student ID"][3].startswith("Homework 2 (out of ")
    assert table["Student ID"][4].startswith("Homework 1 (out of ")
    assert float(table["s001"][3]) == pytest.approx(0.9) and "late penalty" in table["s001"][-1]
    assert float(table["s002"][3]) == 1.0 and "extended" in table["s002"][-1]
    # nothing answered: an empty cell (no grade), not the 0 of a wrong answer
    assert all(table[f"s{n:03d}"][3] == "" for n in range(3, 31))
    assert all(table[f"s{n:03d}"][4] == "" for n in range(1, 31))
    teacher.get_by_role("link", name="Student 01").click()
    expect(teacher.locator("#parts")).to_contain_text("friction_coefficient")

    teacher.get_by_role("link", name="Mechanics 101").click()
    teacher.get_by_role("link", name=re.compile(r"^Results\W+Homework 2")).click()
    skier = re.escape(BANK["skier-friction"].title)
    friction = teacher.get_by_role("row", name=re.compile(rf"^{skier} friction_coefficient "))  # by title
    expect(friction.locator("td").nth(1)).to_have_text("2")  # tried (after the title's row heading, the part)
    expect(friction.locator("td").nth(2)).to_have_text("2")  # correct
    expect(friction.locator("td").nth(3)).to_have_text("1")  # late (the other had an extension)
    check_page(teacher, "course-results-desktop")
    # on a phone the course's and the results' tables are cards: the page itself had scrolled sideways,
    # widened by the visually hidden label of each row's last link
    for page_name in ("course-results-phone", "course-page-phone"):
        check_page(browse(teacher.url, width=WIDTHS["phone"], cookies=teacher.context.cookies()), page_name)
        teacher.go_back()
    phone_teacher = browse(teacher.url, width=WIDTHS["phone"], cookies=teacher.context.cookies())
    check_page(phone_teacher, "course-gradebook-phone")
    builder = browse(
        f"{live_server.url}/instructor/courses", width=WIDTHS["phone"], cookies=teacher.context.cookies()
    )
    builder.get_by_role("link", name="Mechanics 101", exact=True).click()
    builder.get_by_role("link", name="New assignment").click()
    check_page(builder, "course-builder-phone")
    home = browse(f"{live_server.url}/courses", width=WIDTHS["desktop"], cookies=desk.context.cookies())
    expect(home.locator(".assignment-list")).to_contain_text("your extension")
    check_page(home, "course-home-desktop")


@pytest.mark.parametrize("device", WIDTHS)
def test_the_builders_search_filters_in_place_keeping_what_was_typed_and_ticked(
    live_server: LiveServer, browse: Callable[..., Any], device: str
) -> None:
    # the search had reloaded the page: the title and dates typed and the problems ticked were lost
    from playwright.sync_api import expect

    teacher = browse(f"{live_server.url}/instructor/sign-in", width=WIDTHS[device])
    teacher.get_by_label("Instructor API key").fill(live_server.key("instructor", "Prof Meitner"))
    teacher.get_by_role("button", name="Sign in").click()
    teacher.get_by_role("link", name="Courses").click()
    teacher.get_by_label("Title", exact=True).fill("Waves")
    teacher.get_by_role("button", name="Create the course").click()
    teacher.get_by_role("link", name="New assignment").click()
    builder = teacher.url
    expect(teacher.get_by_label(re.compile(r"^Opens"))).not_to_have_value("")  # a new one opens now
    teacher.get_by_label("Title", exact=True).fill("Homework 3")
    teacher.get_by_label(BANK["atwood"].title, exact=True).check()
    search = teacher.get_by_label("Find problems by title or topic")
    search.fill("pendulum")
    search.press("Enter")
    expect(teacher.get_by_label(BANK["simple-pendulum"].title, exact=True)).to_be_visible()
    expect(teacher.get_by_label(BANK["projectile"].title, exact=True)).to_be_hidden()
    expect(teacher.get_by_label(BANK["atwood"].title, exact=True)).to_be_checked()  # ticked: still listed
    expect(teacher.locator("#shown-count")).to_have_text("2 problems listed")
    assert teacher.url == builder
    expect(teacher.get_by_label("Title", exact=True)).to_have_value("Homework 3")
    settings, problems = teacher.get_by_label("Title", exact=True), teacher.locator("table.problem-picker")
    assert settings.bounding_box()["y"] < problems.bounding_box()["y"]  # above the long list, not below
    # a date or a number had kept the browser's small box beside the full-size title field
    heights = {
        name: round(teacher.get_by_label(label).bounding_box()["height"])
        for name, label in (
            ("text", re.compile(r"^Title$")),
            ("date", re.compile(r"^Opens")),
            ("number", re.compile(r"^Attempts per part")),
        )
    }
    assert max(heights.values()) - min(heights.values()) <= 2, heights
    # the late penalty's fields only while late work is accepted (they had shown with it closed)
    penalty = teacher.get_by_label("Penalty per day late (%)")
    expect(penalty).to_be_hidden()
    teacher.get_by_label("Late work").select_option("penalty")
    expect(penalty).to_be_visible()
    expect(teacher.get_by_label("At most (%)")).to_be_visible()
    check_page(teacher, f"course-builder-search-{device}")


def test_the_join_link_is_copied_with_one_click(live_server: LiveServer, browse: Callable[..., Any]) -> None:
    from playwright.sync_api import expect

    teacher = browse(f"{live_server.url}/instructor/sign-in", width=WIDTHS["desktop"])
    teacher.context.grant_permissions(["clipboard-read", "clipboard-write"], origin=live_server.url)
    teacher.get_by_label("Instructor API key").fill(live_server.key("instructor", "Prof Curie"))
    teacher.get_by_role("button", name="Sign in").click()
    teacher.get_by_role("link", name="Courses").click()
    teacher.get_by_label("Title", exact=True).fill("Optics")
    teacher.get_by_role("button", name="Create the course").click()
    teacher.get_by_role("button", name="Make a join code").click()
    link = teacher.locator("#join-link").inner_text()
    assert re.fullmatch(rf"{re.escape(live_server.url)}/join/\w+", link)
    copy = teacher.locator("button[data-copy]")  # by its name it would be lost once it says "Copied"
    expect(copy).to_have_text("Copy the join link")
    copy.click()
    expect(copy).to_have_text("Copied")
    assert teacher.evaluate("() => navigator.clipboard.readText()") == link


def test_a_late_student_is_asked_before_a_worked_solution_freezes_their_grade(
    live_server: LiveServer, browse: Callable[..., Any]
) -> None:
    # a solution open "after the due date" with late work accepted had been read and copied for credit
    from playwright.sync_api import expect

    stores = live_server.stores
    teacher_key = live_server.key("instructor", "Prof Franklin")
    owner = max(k.id for k in stores.keys.list() if k.name == "Prof Franklin")
    course = stores.courses.create_course("Lab", owner=f"key:{owner}")
    stores.courses.set_join_code(course.id, "LABJ2345")
    now = datetime.now(UTC)
    from app.courses.records import AssignmentSpec, LateKind, LatePolicy

    stores.courses.create_assignment(
        course.id,
        AssignmentSpec(
            "Lab 1",
            ("skier-friction",),
            now - timedelta(days=3),
            now - timedelta(hours=1),
            LatePolicy(LateKind.PENALTY, 0.1, 0.5),
        ),
    )
    student = browse(f"{live_server.url}/join/LABJ2345", width=WIDTHS["phone"])
    student.get_by_label("Your name").fill("Rosalind")
    student.get_by_role("button", name="Join the course").click()
    student.goto(f"{live_server.url}/courses")
    student.get_by_role("link", name="Lab 1").click()
    _answer_in(student, BANK["skier-friction"].title, "Lab 1")
    student.get_by_role("link", name="Worked solution").click()
    expect(student.locator(".confirm-solution")).to_contain_text("stays as it is now")
    check_page(student, "course-solution-ask-phone")
    student.get_by_role("button", name="Open the worked solution").click()
    expect(student.get_by_role("heading", name="Answers")).to_be_visible(timeout=FIRST_USE_MS)
    expect(student.locator(".notice.frozen")).to_contain_text("You opened this worked solution on")
    check_page(student, "course-solution-opened-phone")
    student.get_by_role("link", name="Back to the problem").first.click()
    expect(student.locator("#part-acceleration .notice.frozen")).to_contain_text("frozen")
    check_page(student, "course-problem-frozen-phone")
    wide = browse(student.url, width=WIDTHS["desktop"], cookies=student.context.cookies())
    # solved late before the solution was opened: it stays at its late score, and says so
    expect(wide.locator("#part-friction_coefficient .notice.frozen")).to_contain_text("frozen at 0.9 of 1")
    check_page(wide, "course-problem-frozen-desktop")

    teacher = browse(f"{live_server.url}/instructor/sign-in", width=WIDTHS["desktop"])
    teacher.get_by_label("Instructor API key").fill(teacher_key)
    teacher.get_by_role("button", name="Sign in").click()
    teacher.goto(f"{live_server.url}/instructor/courses/{course.id}/gradebook")
    expect(teacher.locator("table.gradebook tbody tr").first).to_contain_text("solution read")
    check_page(teacher, "course-gradebook-frozen-desktop")
    check_page(
        browse(teacher.url, width=WIDTHS["phone"], cookies=teacher.context.cookies()),
        "course-gradebook-frozen-phone",
    )
    teacher.goto(f"{live_server.url}/instructor/courses/{course.id}")
    teacher.get_by_role("button", name=re.compile(r"^Release now\W+Lab 1")).click()
    expect(teacher.get_by_role("status")).to_contain_text("Worked solutions released")
    check_page(teacher, "course-released-desktop")
    check_page(
        browse(teacher.url, width=WIDTHS["phone"], cookies=teacher.context.cookies()), "course-released-phone"
    )


def _answer_in(page: Any, problem_title: str, assignment: str) -> None:
    from playwright.sync_api import expect

    page.get_by_role("link", name=problem_title).click()
    expect(page.locator(".assignment-banner")).to_contain_text(assignment)
    box = page.locator("#part-friction_coefficient input[name=answer]")
    box.press_sequentially(RIGHT)
    box.press("Enter")
    expect(page.locator("#part-friction_coefficient .verdict")).to_have_text(
        re.compile(r"^Correct\."), timeout=FIRST_USE_MS
    )


@pytest.mark.parametrize("device", WIDTHS)
def test_a_student_in_two_courses_stays_signed_in_to_both_in_one_browser(
    live_server: LiveServer, browse: Callable[..., Any], device: str
) -> None:
    # joining the lab had signed the browser out of the physics course
    from playwright.sync_api import expect

    from app.courses.records import AssignmentSpec

    stores = live_server.stores
    now = datetime.now(UTC)
    student = browse(f"{live_server.url}/courses", width=WIDTHS[device])
    # the lab has the atwood too: the physics course's page of it had acted as the lab's student
    for title, problems in (("Physics", ("atwood",)), ("Physics lab", ("projectile", "atwood"))):
        course = stores.courses.create_course(title, owner="key:0")
        code = f"{title[-3:].upper()}{device[:4].upper()}"
        stores.courses.set_join_code(course.id, code)
        spec = AssignmentSpec(f"{title} 1", problems, now - timedelta(days=1), now + timedelta(days=6))
        stores.courses.create_assignment(course.id, spec)
        student.goto(f"{live_server.url}/join/{code}")
        student.get_by_label("Your name").fill("Chien-Shiung Wu")
        student.get_by_role("button", name="Join the course").click()
        expect(student.get_by_role("heading", level=1)).to_have_text(f"Welcome to {title}")
    student.goto(f"{live_server.url}/courses")
    expect(student.get_by_role("heading", level=2, name="Physics", exact=True)).to_be_visible()
    expect(student.get_by_role("heading", level=2, name="Physics lab", exact=True)).to_be_visible()
    check_page(student, f"course-two-courses-{device}")
    student.get_by_role("link", name="Physics 1").click()
    student.get_by_role("link", name=BANK["atwood"].title).click()
    expect(student.locator(".assignment-banner")).to_contain_text("Physics 1")
    # the page's own calls name its course (unnamed, the lab and the course could both take them)
    physics = stores.courses.course_by_join_code(f"ICS{device[:4].upper()}")
    assert physics is not None and student.url.endswith(f"/p/atwood?course={physics.id}")
    with student.expect_request(lambda request: "/preview" in request.url) as previewed:
        student.locator("#part-acceleration input[name=answer]").press_sequentially("g")
    assert previewed.value.url.endswith(f"/v1/problems/atwood/parts/acceleration/preview?course={physics.id}")
