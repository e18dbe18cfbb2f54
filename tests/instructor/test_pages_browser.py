"""The instructor pages in Chromium at desktop and phone widths, on the real app: sign in with the form,
upload a problem with an error, fix it, preview and save; class results after seeded submissions; the
submissions and LMS delivery pages. Every page: axe-core finds no serious or critical violation, nothing
scrolls sideways, and a screenshot is kept in artifacts/."""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

import httpx
import pytest
import yaml

from app.instructor.router import yaml_text
from problems.loader import BANK_DIR
from tests.browser import WIDTHS, LiveServer, check_page

pytestmark = [pytest.mark.browser, pytest.mark.slow]

# (student, part, answer): graded for real through the API, with an instructor key naming the student.
SEEDED = [
    ("s1", "acceleration", "g"),
    ("s1", "acceleration", "g r^2/(r^2 + k^2)"),
    ("s2", "acceleration", "2g/3"),
    ("s2", "acceleration", "-g r^2/(r^2 + k^2)"),
    ("s2", "acceleration", "g r^2/(r^2 + k^2)"),
    ("s3", "acceleration", "g r^2/(r^2 + k^2)"),
    ("s4", "acceleration", "g"),
    ("s4", "acceleration", "m g"),
    ("s1", "tension", "m g"),
    ("s2", "tension", "m g k^2/(r^2 + k^2)"),
]


def problem_yaml(problem_id: str) -> str:
    doc = yaml.safe_load((BANK_DIR / "yo-yo" / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK_DIR / "yo-yo" / "model.yaml").read_text())
    doc["id"], doc["title"] = problem_id, "Yo-yo, my version"
    return yaml_text(doc)


def signed_in_page(live_server: LiveServer, browse: Callable[..., Any], path: str, width: int) -> Any:
    """Open `path`, get sent to the sign-in form, type the key and press Enter: back on `path`."""
    from playwright.sync_api import expect

    page = browse(live_server.url + path, width=width)
    key = page.get_by_label("Instructor API key")
    expect(key).to_be_focused()
    page.keyboard.type(live_server.key("instructor", "Prof Ada"))
    page.keyboard.press("Enter")
    page.wait_for_url(live_server.url + path)
    return page


@pytest.mark.parametrize("device", WIDTHS)
@pytest.mark.sample(1)
def test_sign_in_then_problems_and_a_worked_solution(
    live_server: LiveServer, browse: Callable[..., Any], device: str
) -> None:
    from playwright.sync_api import expect

    form = browse(live_server.url + "/instructor", width=WIDTHS[device])
    expect(form.get_by_role("heading", level=1)).to_have_text("Instructor sign-in")
    check_page(form, f"instructor-sign-in-{device}")

    page = signed_in_page(live_server, browse, "/instructor/problems", WIDTHS[device])
    expect(page.get_by_role("link", name="Yo-yo unwinding from a fixed string", exact=True)).to_be_visible()
    check_page(page, f"instructor-problems-{device}")

    page.get_by_role("link", name="Yo-yo unwinding from a fixed string", exact=True).click()
    expect(page.get_by_role("heading", name="Worked solutions")).to_be_visible()
    expect(page.locator("math").first).to_be_visible()
    page.get_by_label("Student").fill("s1")
    page.get_by_role("button", name="Show their variant").click()
    expect(page.get_by_text("Showing the variant of s1")).to_be_visible()
    expect(page.get_by_role("table", name="Given values in this variant")).to_be_visible()
    check_page(page, f"instructor-problem-{device}")


@pytest.mark.parametrize("device", WIDTHS)
def test_the_problem_pages_actions_are_one_row_and_the_students_link_a_line_of_its_own(
    live_server: LiveServer, browse: Callable[..., Any], device: str
) -> None:
    page = signed_in_page(live_server, browse, "/instructor/problems/yo-yo", WIDTHS[device])
    actions = page.locator(".actions")
    printed = actions.get_by_role("link", name="Worked solution to print")
    as_student = actions.get_by_role("button", name="View as a student")
    students_link = page.get_by_text("Students' link to the solution:")
    for shown in (printed, as_student, students_link):
        shown.wait_for()
    row, link = actions.bounding_box(), students_link.bounding_box()
    assert link["y"] >= row["y"] + row["height"]  # below the row, not run on after its last link
    if device == "desktop":  # room for all of them: one row
        tops = [box["y"] + box["height"] / 2 for box in (printed.bounding_box(), as_student.bounding_box())]
        first = actions.get_by_role("link", name="Class results").bounding_box()
        assert max(tops) - min(tops) < 6 and abs(tops[0] - (first["y"] + first["height"] / 2)) < 6


@pytest.mark.parametrize("device", WIDTHS)
@pytest.mark.sample(1)
def test_upload_with_an_error_fix_it_preview_and_save(
    live_server: LiveServer, browse: Callable[..., Any], device: str
) -> None:
    from playwright.sync_api import expect

    problem_id = f"my-yoyo-{device}"
    good = problem_yaml(problem_id)
    broken = good.replace("units: m/s^2", "units: m/s^2\n  tolerance: {rel: -1}", 1)
    page = signed_in_page(live_server, browse, "/instructor/problems/new", WIDTHS[device])
    source = page.get_by_label("Problem (YAML or JSON)")
    source.fill(broken)
    page.get_by_role("button", name="Preview").click()
    summary = page.locator("#error-summary")
    # the fault, and apart from it the self-test that could not run because of it
    expect(summary.get_by_role("heading")).to_have_text("1 error; 1 stage could not run: nothing was saved")
    expect(summary.locator("ol")).to_contain_text("parts[2].tolerance.rel")
    expect(summary.locator("ol")).not_to_contain_text("not self-tested")
    expect(summary.locator("ul.not-run")).to_contain_text("not self-tested")
    expect(summary).to_contain_text("line ")
    expect(summary).to_be_focused()
    expect(source).to_have_value(broken)  # the text stays, beside its errors
    # YAML's lines are not wrapped: a wrapped line's rest started at the left, reading as a new key
    assert source.evaluate("box => getComputedStyle(box).whiteSpace") == "pre"
    check_page(page, f"instructor-upload-error-{device}")
    # "line N" takes the keyboard to that line of the text, selected.
    summary.get_by_role("link", name=re.compile(r"^line \d+$")).first.click()
    expect(source).to_be_focused()
    selected = page.evaluate(
        "() => { const b = document.getElementById('source'); "
        "return b.value.slice(b.selectionStart, b.selectionEnd); }"
    )
    assert selected.strip() == "tolerance: {rel: -1}"

    source.fill(good)
    page.get_by_role("button", name="Preview").click()
    preview = page.locator("section.preview")
    expect(preview.get_by_role("heading", level=2)).to_have_text("Preview: no errors")
    expect(preview.locator("math").first).to_be_visible()
    check_page(page, f"instructor-upload-preview-{device}")

    page.get_by_role("button", name="Save this problem").click()
    expect(page.get_by_role("status")).to_have_text("Saved as version 1.")
    expect(page.get_by_role("heading", level=1)).to_have_text("Yo-yo, my version")
    check_page(page, f"instructor-upload-saved-{device}")


def seed_submissions(live_server: LiveServer) -> None:
    headers = {"Authorization": f"Bearer {live_server.key('instructor', 'course script')}"}
    with httpx.Client(base_url=live_server.url, headers=headers, timeout=60) as client:
        for student, part, answer in SEEDED:
            response = client.post(
                f"/v1/problems/yo-yo/parts/{part}/submissions", json={"answer": answer, "student": student}
            )
            assert response.status_code == 201, response.text


@pytest.fixture(scope="module")
def seeded(live_server: LiveServer) -> LiveServer:
    seed_submissions(live_server)
    return live_server


@pytest.mark.parametrize("device", WIDTHS)
def test_class_results_after_seeded_submissions(
    seeded: LiveServer, browse: Callable[..., Any], device: str
) -> None:
    from playwright.sync_api import expect

    page = signed_in_page(seeded, browse, "/instructor/problems/yo-yo/results", WIDTHS[device])
    overview = page.get_by_role("table", name="Per part")
    expect(overview.get_by_role("row").nth(1)).to_contain_text("4")  # four students tried part 1
    expect(page.get_by_role("img", name="Students with a correct answer, per part")).to_be_visible()
    expect(page.get_by_role("img", name="Part 1: wrong answers by known mistake")).to_be_visible()
    expect(page.locator("#part-0")).to_contain_text("4 students tried; 3 answered correctly (75 %)")
    check_page(page, f"instructor-results-{device}")

    page.goto(seeded.url + "/instructor/submissions?student=s2")
    expect(page.get_by_role("table")).to_contain_text("2g/3")
    expect(page.get_by_role("table")).not_to_contain_text("s1")
    if device == "desktop":  # side by side, the filter's fields line up
        problem, student = (
            page.get_by_label("Problem").bounding_box(),
            page.get_by_label("Student").bounding_box(),
        )
        assert abs(problem["y"] + problem["height"] - student["y"] - student["height"]) < 4
    check_page(page, f"instructor-submissions-{device}")

    page.goto(seeded.url + "/instructor/deliveries")
    expect(page.get_by_role("heading", level=1)).to_have_text("LMS delivery problems")
    expect(page.get_by_role("status")).to_contain_text("Every score has been delivered")
    check_page(page, f"instructor-deliveries-{device}")
