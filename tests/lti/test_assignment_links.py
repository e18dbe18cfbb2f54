# ruff: noqa: F811 - the fixtures imported below are parameters by name
"""An assignment over LTI: the instructor's first launch makes the course from the LMS context, they
build an assignment on the course pages in their launch session, deep-link it as one resource link
with one line item, students launch it, and each graded answer sends the assignment's total to the
LMS, in order, exactly once; the instructor's launch of the link opens the course's gradebook."""

from __future__ import annotations

import re
from datetime import UTC, datetime, timedelta
from html import unescape
from typing import Any

import pytest

from tests.lti.conftest import platform_launch
from tests.lti.fake_lms import INSTRUCTOR, LEARNER, TOOL, NextLaunch
from tests.lti.test_end_to_end import (  # noqa: F401 - the journey's fixtures
    LINEITEM,
    PROBLEM,
    RIGHT,
    SQL_BACKENDS,
    WRONG,
    Sites,
    backend,
    deliver,
    e2e_settings,
    field,
    meta,
    sites,
)

pytestmark = pytest.mark.anyio
CONTEXT = "physics-101"
CSRF = re.compile(r'name="csrf" value="([^"]+)"')


async def _instructor_launch(sites: Sites, **changes: Any) -> Any:
    sites.lms.next_launch = NextLaunch(
        **{"user": "teacher-1", "roles": [INSTRUCTOR], "problem": None, "lineitem": None, "context": CONTEXT}
        | changes
    )
    return await platform_launch(sites.browser)


async def _build_assignment(sites: Sites, **fields: str) -> int:
    """In the instructor's launch session: the course the launch made, and an assignment on it."""
    courses = await sites.browser.get(f"{TOOL}/instructor/courses")
    assert courses.status_code == 200, courses.text
    found = re.search(r'href="/instructor/courses/(\d+)"', courses.text)
    assert found and f"Physics ({CONTEXT})" in courses.text
    course = int(found.group(1))
    form = await sites.browser.get(f"{TOOL}/instructor/courses/{course}/assignments/new")
    csrf = CSRF.search(form.text)
    assert csrf
    now = datetime.now(UTC)
    saved = await sites.browser.post(
        f"{TOOL}/instructor/courses/{course}/assignments/new",
        data={
            "csrf": unescape(csrf.group(1)),
            "problem": [PROBLEM],
            "title": "Homework 3",
            "opens_at": (now - timedelta(days=1)).strftime("%Y-%m-%dT%H:%M"),
            "due_at": (now + timedelta(days=6)).strftime("%Y-%m-%dT%H:%M"),
            "late": "closed",
            "solutions": "after_due",
        }
        | fields,
    )
    assert saved.status_code == 303, saved.text
    return course


async def _deep_link_assignment(sites: Sites) -> dict[str, Any]:
    picker = await _instructor_launch(sites, deep_linking=True)
    assert picker.status_code == 200, picker.text
    offered = re.findall(r'name="problem" value="([^"]+)"', picker.text)
    assignment = next(value for value in offered if value.startswith("assignment:"))
    action = re.search(r'<form method="post" action="([^"]+)"', picker.text)
    assert action
    answer = await sites.browser.post(
        TOOL + unescape(action.group(1)),
        data={"csrf_token": field(picker.text, "csrf_token"), "problem": assignment},
    )
    assert answer.status_code == 200, answer.text
    config = sites.lms.config()
    config.get_registration()
    [item] = config.validate_deeplinking_resp({"JWT": field(answer.text, "JWT")})
    return dict(item)


async def _student_opens(sites: Sites, item: dict[str, Any], user: str, context: str = CONTEXT) -> Any:
    sites.lms.next_launch = NextLaunch(
        user=user,
        roles=[LEARNER],
        problem=None,
        custom=dict(item["custom"]),
        lineitem=LINEITEM,
        context=context,
    )
    return await platform_launch(sites.browser)


async def _answer(sites: Sites, answer: str) -> None:
    page = await sites.browser.get(f"{TOOL}/p/{PROBLEM}")
    assert page.status_code == 200 and "Homework 3" in page.text  # the assignment, its due date and policy
    filed = await sites.browser.post(
        f"{TOOL}/v1/problems/{PROBLEM}/parts/acceleration/submissions",
        json={"answer": answer},
        headers={"X-CSRF-Token": meta(page.text, "csrf-token")},
    )
    assert filed.status_code == 201, filed.text


@pytest.mark.parametrize("backend", SQL_BACKENDS)
async def test_a_deep_linked_assignment_sends_one_total_per_answer_in_order_exactly_once(
    sites: Sites,
) -> None:
    first = await _instructor_launch(sites, deep_linking=True)  # the first launch makes the course
    assert first.status_code == 200, first.text
    course = await _build_assignment(sites)
    item = await _deep_link_assignment(sites)
    assert item["custom"].keys() == {"assignment"}
    assert item["lineItem"]["scoreMaximum"] == 3.0  # the yo-yo's three parts, one point each

    launched = await _student_opens(sites, item, "student-1")
    assert launched.status_code == 303, launched.text
    assert re.fullmatch(rf"/courses/{course}/assignments/\d+", launched.headers["location"])
    listing = await sites.browser.get(TOOL + launched.headers["location"])
    assert listing.status_code == 200 and f"/p/{PROBLEM}" in listing.text
    await _answer(sites, WRONG)
    [zero] = await deliver(sites)
    await _answer(sites, RIGHT)
    [_, one] = await deliver(sites)
    assert (zero.score["scoreGiven"], zero.score["scoreMaximum"]) == (0.0, 3.0)
    assert (one.score["scoreGiven"], one.score["scoreMaximum"]) == (1.0, 3.0)
    assert one.score["timestamp"] > zero.score["timestamp"]
    assert {zero.line_item_id, one.line_item_id} == {"7"}

    await _student_opens(sites, item, "student-2")
    await _answer(sites, RIGHT)
    received = await deliver(sites)
    assert [r.score["userId"] for r in received] == ["student-1", "student-1", "student-2"]
    assert len({r.score["timestamp"] + r.score["userId"] for r in received}) == 3  # each sent once
    assert all(score.status == "delivered" for score in sites.stores.outbox.scores())

    gradebook = await _instructor_launch(sites, custom=dict(item["custom"]), lineitem=LINEITEM)
    assert gradebook.status_code == 303
    assert gradebook.headers["location"] == f"/instructor/courses/{course}/gradebook"
    page = await sites.browser.get(TOOL + gradebook.headers["location"])
    assert page.status_code == 200 and "User student-1" in page.text and "User student-2" in page.text


async def test_an_assignment_link_copied_to_another_lms_course_is_refused(sites: Sites) -> None:
    await _instructor_launch(sites, deep_linking=True)
    await _build_assignment(sites)
    item = await _deep_link_assignment(sites)
    refused = await _student_opens(sites, item, "student-9", context="another-course")
    assert refused.status_code == 404, refused.text
    assert "another course" in refused.text
    assert sites.stores.outbox.scores() == []


async def test_an_extension_regrading_earlier_answers_sends_the_total_again_without_the_late_penalty(
    sites: Sites,
) -> None:
    await _instructor_launch(sites, deep_linking=True)
    past = datetime.now(UTC) - timedelta(hours=2)
    course = await _build_assignment(
        sites, due_at=past.strftime("%Y-%m-%dT%H:%M"), late="penalty", per_day="10", limit="50"
    )
    item = await _deep_link_assignment(sites)
    await _student_opens(sites, item, "student-1")
    await _answer(sites, RIGHT)
    [late] = await deliver(sites)
    assert late.score["scoreGiven"] == pytest.approx(0.9)  # a day late: 10 % off its one point
    book = await _instructor_launch(sites, custom=dict(item["custom"]), lineitem=LINEITEM)
    page = await sites.browser.get(TOOL + book.headers["location"])
    student = re.search(r'<option value="([^"]+)">User student-1</option>', page.text)
    assignment = re.search(r'name="assignment"><option value="(\d+)"', page.text)
    csrf = CSRF.search(page.text)
    assert student and assignment and csrf
    extended = await sites.browser.post(
        f"{TOOL}/instructor/courses/{course}/extensions",
        data={
            "csrf": unescape(csrf.group(1)),
            "student": unescape(student.group(1)),
            "assignment": assignment.group(1),
            "due_at": (datetime.now(UTC) + timedelta(days=2)).strftime("%Y-%m-%dT%H:%M"),
            "regrade_earlier": "on",  # else the late answer keeps its penalty: new answers are spared
        },
    )
    assert extended.status_code == 303, extended.text
    [_, lifted] = await deliver(sites)
    assert lifted.score["scoreGiven"] == 1.0 and lifted.score["timestamp"] > late.score["timestamp"]
