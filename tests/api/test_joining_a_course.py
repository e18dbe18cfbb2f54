"""A student who joins a course by its code gets a link to come back from any device; joining again
under a name or email already in the course adds nobody and says how to get back in; nobody signs in
as another student by typing their name."""

from __future__ import annotations

import re

import pytest
from fastapi.testclient import TestClient

from tests.api.conftest import key_headers
from tests.api.test_courses import RIGHT, WRONG, _assignment, _course, _roster

RETURN_LINK = re.compile(r'<code class="sign-in-link" id="return-link">http://testserver(/s/[^<]+)</code>')


@pytest.fixture
def teacher(client):
    return key_headers(client, "instructor", "Prof A")


def _join_code(client: TestClient, teacher: dict[str, str]) -> str:
    course = _course(client, teacher)
    _assignment(client, teacher, course, problems=["skier-friction"])
    return str(client.post(f"/v1/courses/{course}/join-code", json={}, headers=teacher).json()["join_code"])


def _join(client: TestClient, code: str, **form: str) -> tuple[TestClient, str]:
    """A new browser joining: the browser and the link to come back it was shown."""
    browser = TestClient(client.app, follow_redirects=False)
    joined = browser.post(f"/join/{code}", data=form)
    assert joined.status_code == 200, joined.text
    found = RETURN_LINK.search(joined.text)
    assert found, "the page after joining shows no link to come back"
    return browser, found.group(1)


def _device(client: TestClient, link: str) -> tuple[TestClient, dict[str, str]]:
    """Another device opening the link: its browser (signed in) and the CSRF header its pages carry."""
    browser = TestClient(client.app, follow_redirects=False)
    signed = browser.post(link)
    assert signed.status_code == 303 and signed.headers["location"] == "/courses", signed.text
    token = re.search(r'name="csrf-token" content="([^"]+)"', browser.get("/p/skier-friction").text)
    assert token
    return browser, {"X-CSRF-Token": token.group(1)}


def _answer(browser: TestClient, csrf: dict[str, str], answer: str) -> None:
    problem, part, _ = RIGHT
    filed = browser.post(
        f"/v1/problems/{problem}/parts/{part}/submissions", json={"answer": answer}, headers=csrf
    )
    assert filed.status_code == 201, filed.text


def test_the_link_shown_on_joining_signs_the_student_in_on_other_devices_each_time_with_their_work(
    client, teacher
):
    code = _join_code(client, teacher)
    _, link = _join(client, code, name="Lise Meitner", email="lise@uni.example")
    phone, phone_csrf = _device(client, link)
    laptop, laptop_csrf = _device(client, link)  # the same link again: not spent
    _answer(phone, phone_csrf, WRONG)
    _answer(laptop, laptop_csrf, RIGHT[2])
    students = {item["student"] for item in client.get("/v1/submissions", headers=teacher).json()["items"]}
    assert len(students) == 1  # one student, whichever device answered


def test_a_new_link_to_come_back_replaces_the_old_one(client, teacher):
    code = _join_code(client, teacher)
    browser, old = _join(client, code, name="Lise Meitner")
    page = browser.get("/courses").text
    csrf = re.search(r'name="csrf" value="([^"]+)"', page)
    assert csrf and "Make a new link to come back" in page
    made = browser.post("/courses/return-link", data={"csrf": csrf.group(1)})
    new = RETURN_LINK.search(made.text)
    assert made.status_code == 200 and new
    assert TestClient(client.app).post(old, follow_redirects=False).status_code == 400
    _device(client, new.group(1))


def test_a_new_link_to_come_back_needs_the_pages_csrf_token(client, teacher):
    code = _join_code(client, teacher)
    browser, old = _join(client, code, name="Lise Meitner")
    refused = browser.post("/courses/return-link", data={"csrf": "forged"})
    assert refused.status_code == 403 and not RETURN_LINK.search(refused.text)
    _device(client, old)  # the saved link still works


@pytest.mark.parametrize(
    ("first", "again", "says"),
    [
        (
            {"name": "Lise Meitner", "email": ""},
            {"name": "  lise   MEITNER ", "email": ""},
            "Someone has joined Mechanics with this name already",
        ),
        (
            {"name": "Lise Meitner", "email": "lise@uni.example"},
            {"name": "L. M.", "email": "LISE@uni.example"},
            "Someone has joined Mechanics with this email already",
        ),
        # on the imported roster: she never joined, so had no link to come back saved, as she was told
        (
            {"name": "Ada Lovelace", "email": ""},
            {"name": "Ada Lovelace", "email": ""},
            "on Mechanics's roster already",
        ),
    ],
)
def test_joining_under_a_name_or_email_in_the_course_adds_nobody_and_says_how_to_get_back_in(
    client, teacher, first, again, says
):
    code = _join_code(client, teacher)
    course = client.get("/v1/courses", headers=teacher).json()[0]["id"]
    _roster(client, teacher, course)  # Ada Lovelace, Alan Turing, Emmy Noether
    if first["name"] != "Ada Lovelace":
        _join(client, code, **first)
    before = client.get(f"/v1/courses/{course}/roster", headers=teacher).json()
    stranger = TestClient(client.app, follow_redirects=False)
    refused = stranger.post(f"/join/{code}", data=again)
    assert refused.status_code == 409
    assert says in refused.text
    rostered = first["name"] == "Ada Lovelace"
    assert ("personal sign-in link your" in refused.text) == rostered
    assert ("link to come back that you saved" in refused.text) != rostered
    assert "physcheck_course" not in refused.headers.get("set-cookie", "")  # nobody's session
    assert client.get(f"/v1/courses/{course}/roster", headers=teacher).json() == before


def test_a_student_signed_in_to_the_course_who_opens_its_join_link_again_is_not_joined_twice(client, teacher):
    code = _join_code(client, teacher)
    browser, _ = _join(client, code, name="Lise Meitner")
    assert "You are in Mechanics already, as Lise Meitner" in browser.get(f"/join/{code}").text
    again = browser.post(f"/join/{code}", data={"name": "Lise M."})
    assert again.status_code == 303 and again.headers["location"] == "/courses"
    course = client.get("/v1/courses", headers=teacher).json()[0]["id"]
    assert [s["name"] for s in client.get(f"/v1/courses/{course}/roster", headers=teacher).json()] == [
        "Lise Meitner"
    ]


def test_signing_out_ends_the_session_and_the_link_to_come_back_still_works(client, teacher):
    code = _join_code(client, teacher)
    browser, link = _join(client, code, name="Lise Meitner")
    page = browser.get("/courses").text
    assert "Signed in as Lise Meitner" in page
    cookie = browser.cookies.get("physcheck_course")
    copy = TestClient(client.app, follow_redirects=False, cookies={"physcheck_course": cookie})
    csrf = re.search(r'name="csrf" value="([^"]+)"', page)
    assert csrf
    assert browser.post("/courses/sign-out", data={"csrf": "forged"}).status_code == 403
    out = browser.post("/courses/sign-out", data={"csrf": csrf.group(1)})
    assert out.status_code == 200 and "Signed out" in out.text
    assert browser.get("/courses").status_code == 401
    assert copy.get("/courses").status_code == 401  # the session itself is gone, not only the cookie
    _device(client, link)


def test_an_assignment_not_open_yet_says_when_it_opens_on_the_students_home(client, teacher):
    from datetime import UTC, datetime, timedelta

    code = _join_code(client, teacher)
    course = client.get("/v1/courses", headers=teacher).json()[0]["id"]
    opens = datetime(2031, 3, 2, 9, 0, tzinfo=UTC)
    _assignment(
        client,
        teacher,
        course,
        title="Homework 2",
        problems=["yo-yo"],
        opens_at=opens.isoformat(),
        due_at=(opens + timedelta(days=7)).isoformat(),
    )
    browser, _ = _join(client, code, name="Lise Meitner")
    home = browser.get("/courses").text
    assert "Opens Sun 02 Mar 2031, 10:00 CET; due Sun 09 Mar 2031, 10:00 CET." in home  # Paris time


def test_a_student_who_joins_a_second_course_in_the_same_browser_stays_in_both(client, teacher):
    # joining course B had signed the browser out of course A
    code = _join_code(client, teacher)
    mechanics = client.get("/v1/courses", headers=teacher).json()[0]["id"]
    lab = _course(client, teacher, "Optics lab")
    lab_work = _assignment(client, teacher, lab, problems=["yo-yo"], title="Lab 1")
    lab_code = client.post(f"/v1/courses/{lab}/join-code", json={}, headers=teacher).json()["join_code"]
    browser, _ = _join(client, code, name="Lise Meitner")
    assert browser.post(f"/join/{lab_code}", data={"name": "Lise Meitner"}).status_code == 200
    home = browser.get("/courses").text
    assert "Mechanics" in home and "Optics lab" in home and "to 2 courses" in home
    assert browser.get(f"/courses/{lab}/assignments/{lab_work['id']}").status_code == 200
    # each problem's page and answers act as the student of the course that assigned it
    for problem, part, answer in (RIGHT, ("yo-yo", "acceleration", "g")):
        token = re.search(r'name="csrf-token" content="([^"]+)"', browser.get(f"/p/{problem}").text)
        assert token
        path = f"/v1/problems/{problem}/parts/{part}/submissions"
        filed = browser.post(path, json={"answer": answer}, headers={"X-CSRF-Token": token.group(1)})
        assert filed.status_code == 201, filed.text
    for course in (mechanics, lab):
        [row] = client.get(f"/v1/courses/{course}/gradebook", headers=teacher).json()["students"]
        assert row["assignments"][0]["attempted"], course
    csrf = re.search(r'name="csrf" value="([^"]+)"', home)
    assert csrf
    assert browser.post("/courses/sign-out", data={"csrf": csrf.group(1)}).status_code == 200
    assert browser.get("/courses").status_code == 401  # out of both: a shared computer's next user
