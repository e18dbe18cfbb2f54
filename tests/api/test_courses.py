"""Courses over the API: rosters, personal sign-in links, assignments with due dates and late
policies, extensions and the gradebook; and the access rules: no instructor reaches another course's
students, no student a problem outside their assignments."""

from __future__ import annotations

import csv
import io
import re
from datetime import UTC, datetime, timedelta
from unittest.mock import ANY

import pytest
from fastapi.testclient import TestClient

from tests.api.conftest import key_headers

ROSTER = "id,name,email\ns001,Ada Lovelace,ada@uni.example\ns002,Alan Turing,alan@uni.example\ns003,Emmy Noether,\n"
RIGHT = ("skier-friction", "friction_coefficient", "tan(alpha)")
WRONG = "sin(alpha)"


def _iso(moment: datetime) -> str:
    return moment.isoformat()


def _course(client: TestClient, headers: dict[str, str], title: str = "Mechanics") -> int:
    made = client.post("/v1/courses", json={"title": title, "timezone": "Europe/Paris"}, headers=headers)
    assert made.status_code == 201, made.text
    return int(made.json()["id"])


def _roster(client: TestClient, headers: dict[str, str], course: int, text: str = ROSTER) -> dict:
    response = client.post(
        f"/v1/courses/{course}/roster", content=text, headers={**headers, "Content-Type": "text/csv"}
    )
    assert response.status_code == 200, response.text
    return response.json()


def _assignment(client, headers, course, *, problems=("skier-friction", "yo-yo"), **changes) -> dict:
    now = datetime.now(UTC)
    body = {
        "title": "Homework 1",
        "problems": list(problems),
        "opens_at": _iso(now - timedelta(days=1)),
        "due_at": _iso(now + timedelta(days=6)),
    } | changes
    response = client.post(f"/v1/courses/{course}/assignments", json=body, headers=headers)
    assert response.status_code == 201, response.text
    return response.json()


def _links(client, headers, course) -> dict[str, str]:
    response = client.post(f"/v1/courses/{course}/sign-in-links", json={}, headers=headers)
    assert response.status_code == 200, response.text
    return {link["student"]: link["url"] for link in response.json()}


def _signed_in(client: TestClient, url: str) -> tuple[TestClient, dict[str, str]]:
    """A new browser following a personal link: its client (with the cookie) and the CSRF header."""
    browser = TestClient(client.app)
    path = url.removeprefix("http://testserver")
    assert browser.get(path).status_code == 200  # the page only offers a button: nothing spent
    signed = browser.post(path, follow_redirects=False)
    assert signed.status_code == 303 and signed.headers["location"] == "/courses"
    cookie = signed.headers["set-cookie"]
    assert "HttpOnly" in cookie and "SameSite=lax" in cookie
    page = browser.get("/p/skier-friction")
    token = re.search(r'name="csrf-token" content="([^"]+)"', page.text)
    return browser, {"X-CSRF-Token": token.group(1) if token else ""}


@pytest.fixture
def teacher(client):
    return key_headers(client, "instructor", "Prof A")


@pytest.fixture
def other_teacher(client):
    return key_headers(client, "instructor", "Prof B")


def test_reimporting_a_roster_updates_names_and_never_duplicates(client, teacher):
    course = _course(client, teacher)
    assert _roster(client, teacher, course) == {"added": 3, "updated": 0, "unchanged": 0}
    again = _roster(
        client, teacher, course, "s001,Ada King,ada@uni.example\ns004,Lise Meitner,lise@uni.example\n"
    )
    assert again == {"added": 1, "updated": 1, "unchanged": 0}
    names = [s["name"] for s in client.get(f"/v1/courses/{course}/roster", headers=teacher).json()]
    assert names == ["Ada King", "Alan Turing", "Emmy Noether", "Lise Meitner"]


def test_a_roster_with_bad_lines_imports_nothing_and_names_each_line(client, teacher):
    course = _course(client, teacher)
    response = client.post(
        f"/v1/courses/{course}/roster",
        content="s001,Ada,ada@x\ns 2,Bob,\ns3,,\n",
        headers={**teacher, "Content-Type": "text/csv"},
    )
    assert response.status_code == 422
    assert [d["path"] for d in response.json()["error"]["details"]] == ["line 2", "line 3"]
    assert client.get(f"/v1/courses/{course}/roster", headers=teacher).json() == []


def test_a_personal_link_signs_in_once_and_the_session_works_without_a_key(client, teacher):
    course = _course(client, teacher)
    _roster(client, teacher, course)
    _assignment(client, teacher, course)
    links = _links(client, teacher, course)
    url = links[f"course:{course}:s001"]
    browser, csrf = _signed_in(client, url)
    assert [c["id"] for c in browser.get("/v1/courses").json()] == [course]
    assert browser.get("/courses").status_code == 200
    # A second browser with the same link is refused, and the first stays signed in.
    other = TestClient(client.app)
    assert other.post(url.removeprefix("http://testserver"), follow_redirects=False).status_code == 400
    assert other.get("/v1/courses").status_code == 401
    problem, part, answer = RIGHT
    filed = browser.post(
        f"/v1/problems/{problem}/parts/{part}/submissions", json={"answer": answer}, headers=csrf
    )
    assert filed.status_code == 201, filed.text
    # Without the page's CSRF token a state change is refused.
    assert (
        browser.post(f"/v1/problems/{problem}/parts/{part}/submissions", json={"answer": answer}).status_code
        == 401
    )


def test_a_new_link_replaces_the_unused_one(client, teacher):
    course = _course(client, teacher)
    _roster(client, teacher, course)
    first = _links(client, teacher, course)[f"course:{course}:s002"]
    second = _links(client, teacher, course)[f"course:{course}:s002"]
    browser = TestClient(client.app)
    assert browser.post(first.removeprefix("http://testserver"), follow_redirects=False).status_code == 400
    assert browser.post(second.removeprefix("http://testserver"), follow_redirects=False).status_code == 303


def test_a_student_sees_only_the_problems_of_their_open_assignments(client, teacher):
    course = _course(client, teacher)
    _roster(client, teacher, course)
    _assignment(client, teacher, course, problems=["skier-friction"])
    later = datetime.now(UTC) + timedelta(days=3)
    _assignment(
        client,
        teacher,
        course,
        problems=["yo-yo"],
        opens_at=_iso(later),
        due_at=_iso(later + timedelta(days=7)),
    )
    browser, csrf = _signed_in(client, _links(client, teacher, course)[f"course:{course}:s001"])
    assert [p["id"] for p in browser.get("/v1/problems").json()] == ["skier-friction"]
    for hidden in ("yo-yo", "moving-wedge"):
        assert browser.get(f"/v1/problems/{hidden}").status_code == 404
        assert browser.get(f"/p/{hidden}").status_code == 404
        assert browser.get(f"/p/{hidden}/solution").status_code == 404
        submitted = browser.post(
            f"/v1/problems/{hidden}/parts/acceleration/submissions", json={"answer": "g"}, headers=csrf
        )
        assert submitted.status_code == 404
        previewed = browser.post(
            f"/v1/problems/{hidden}/parts/acceleration/preview", json={"answer": "g"}, headers=csrf
        )
        assert previewed.status_code == 404
    assert browser.get("/p/skier-friction").status_code == 200
    home = browser.get("/problems", follow_redirects=False)  # the bank is not a course student's home
    assert home.status_code == 303 and home.headers["location"] == "/courses"
    assert "/p/yo-yo" not in browser.get("/problems/content", headers=csrf).text


def test_no_instructor_reaches_another_courses_students(client, teacher, other_teacher):
    course = _course(client, teacher)
    _roster(client, teacher, course)
    _assignment(client, teacher, course)
    student = f"course:{course}:s001"
    for path in (
        f"/v1/courses/{course}",
        f"/v1/courses/{course}/roster",
        f"/v1/courses/{course}/assignments",
        f"/v1/courses/{course}/gradebook",
        f"/v1/courses/{course}/gradebook.csv",
        f"/v1/problems/yo-yo?student={student}",
        f"/v1/submissions?student={student}",
        f"/v1/student-data?student={student}",
    ):
        assert client.get(path, headers=other_teacher).status_code == 404, path
    assert client.delete(f"/v1/student-data?student={student}", headers=other_teacher).status_code == 404
    assert (
        client.post(f"/v1/courses/{course}/sign-in-links", json={}, headers=other_teacher).status_code == 404
    )
    on_behalf = {"answer": "g", "student": student}
    assert (
        client.post(
            "/v1/problems/yo-yo/parts/acceleration/submissions", json=on_behalf, headers=other_teacher
        ).status_code
        == 404
    )
    assert client.get("/v1/courses", headers=other_teacher).json() == []
    # The course's own instructor files for the student, and the other never sees it in a listing.
    assert (
        client.post(
            "/v1/problems/skier-friction/parts/friction_coefficient/submissions",
            json={"answer": WRONG, "student": student},
            headers=teacher,
        ).status_code
        == 201
    )
    assert [i["student"] for i in client.get("/v1/submissions", headers=teacher).json()["items"]] == [student]
    assert client.get("/v1/submissions", headers=other_teacher).json()["items"] == []
    # The course's instructor exports the student's roster entry with their work, and erases it all.
    exported = client.get(f"/v1/student-data?student={student}", headers=teacher).json()
    assert [e["course_id"] for e in exported["enrolments"]] == [course] and len(exported["submissions"]) == 1
    erased = client.delete(f"/v1/student-data?student={student}", headers=teacher).json()["erased"]
    assert (erased["submissions"], erased["enrolments"]) == (1, 1)
    assert student not in [
        s["student"] for s in client.get(f"/v1/courses/{course}/roster", headers=teacher).json()
    ]


def _ta(client: TestClient, teacher: dict[str, str], course: int) -> tuple[dict[str, str], int]:
    """A new key made the course's teaching assistant: its headers and its id."""
    ta = key_headers(client, "instructor", "Tess")
    ta_id = client.app.state.services.stores.keys.list()[-1].id
    staffed = client.put(
        f"/v1/courses/{course}/staff", json={"member": f"key:{ta_id}", "role": "ta"}, headers=teacher
    )
    assert staffed.status_code == 200
    return ta, ta_id


HOMEWORK = {
    "title": "HW",
    "problems": ["yo-yo"],
    "opens_at": "2026-01-01T09:00:00Z",
    "due_at": "2026-01-08T09:00:00Z",
}
# What only a course's instructors may do, and the words a TA is refused with.
TA_REFUSED = [
    ("PUT", "/v1/courses/{course}/staff", {"json": {"member": "key:77", "role": "ta"}}, "change its staff"),
    ("DELETE", "/v1/courses/{course}/staff/key:77", {}, "change its staff"),
    ("POST", "/v1/courses/{course}/roster", {"content": ROSTER}, "import its roster"),
    ("POST", "/v1/courses/{course}/join-code", {"json": {"enabled": True}}, "change its join code"),
    ("POST", "/v1/courses/{course}/assignments", {"json": HOMEWORK}, "add assignments"),
    ("PUT", "/v1/assignments/{assignment}", {"json": HOMEWORK}, "change its assignments"),
    ("DELETE", "/v1/assignments/{assignment}", {}, "delete its assignments"),
]


@pytest.mark.parametrize(("method", "path", "body", "action"), TA_REFUSED)
def test_a_ta_asking_what_only_instructors_may_do_is_forbidden_saying_so(
    client, teacher, method, path, body, action
):
    # a TA sees the course: the 404 a stranger gets told them it did not exist
    course = _course(client, teacher)
    homework = _assignment(client, teacher, course)
    ta, _ = _ta(client, teacher, course)
    headers = {**ta, "Content-Type": "text/csv"} if "content" in body else ta
    url = path.format(course=course, assignment=homework["id"])
    refused = client.request(method, url, headers=headers, **body)
    assert refused.status_code == 403
    assert refused.json()["error"] == {
        "code": "forbidden",
        "message": f"Only the course's instructors may {action}; you are its teaching assistant.",
        "details": [],
    }


def test_a_ta_reads_the_gradebook_until_they_leave_the_staff(client, teacher):
    course = _course(client, teacher)
    ta, ta_id = _ta(client, teacher, course)
    assert client.get(f"/v1/courses/{course}/gradebook", headers=ta).status_code == 200
    assert client.delete(f"/v1/courses/{course}/staff/key:{ta_id}", headers=teacher).status_code == 204
    assert client.get(f"/v1/courses/{course}/gradebook", headers=ta).status_code == 404


def _late_homework(client, teacher, course: int, now: datetime) -> dict:
    """An assignment due 30 hours ago (two days started late), 0.1 off a day, at most 0.5."""
    return _assignment(
        client,
        teacher,
        course,
        problems=["skier-friction"],
        opens_at=_iso(now - timedelta(days=5)),
        due_at=_iso(now - timedelta(hours=30)),
        late={"kind": "penalty", "per_day": 0.1, "limit": 0.5},
    )


def test_late_work_loses_its_penalty_an_extension_spares_new_answers_and_the_csv_agrees(client, teacher):
    course = _course(client, teacher)
    _roster(client, teacher, course)
    now = datetime.now(UTC)
    homework = _late_homework(client, teacher, course, now)
    links = _links(client, teacher, course)
    problem, part, answer = RIGHT
    path = f"/v1/problems/{problem}/parts/{part}/submissions"
    browsers = {}
    for roster_id in ("s001", "s002"):
        browsers[roster_id] = browser, csrf = _signed_in(client, links[f"course:{course}:{roster_id}"])
        assert browser.post(path, json={"answer": answer}, headers=csrf).status_code == 201
    book = client.get(f"/v1/courses/{course}/gradebook", headers=teacher).json()
    cells = {row["student"]["roster_id"]: row["assignments"][0] for row in book["students"]}
    assert cells["s001"]["score"] == pytest.approx(0.8) and cells["s001"]["late"]
    assert cells["s003"]["score"] == 0 and cells["s003"]["status"] == "late"
    extended = client.put(
        f"/v1/assignments/{homework['id']}/extensions/course:{course}:s002",
        json={"due_at": _iso(now + timedelta(days=1))},
        headers=teacher,
    )
    assert extended.status_code == 200 and extended.json()["granted_at"] is not None
    book = client.get(f"/v1/courses/{course}/gradebook", headers=teacher).json()
    cells = {row["student"]["roster_id"]: row["assignments"][0] for row in book["students"]}
    # the answer graded before the extension keeps its penalty: the extension is for new answers
    assert cells["s002"]["score"] == pytest.approx(0.8) and cells["s002"]["extended"]
    browser, csrf = browsers["s002"]
    assert browser.post(path, json={"answer": answer}, headers=csrf).status_code == 201
    book = client.get(f"/v1/courses/{course}/gradebook", headers=teacher).json()
    cells = {row["student"]["roster_id"]: row["assignments"][0] for row in book["students"]}
    assert cells["s002"]["score"] == 1.0 and not cells["s002"]["late"] and cells["s002"]["extended"]
    assert cells["s001"]["score"] == pytest.approx(0.8)
    exported = client.get(f"/v1/courses/{course}/gradebook.csv", headers=teacher)
    assert exported.headers["content-type"].startswith("text/csv")
    rows = {r[0]: r for r in csv.reader(io.StringIO(exported.text))}
    assert rows["Student ID"][3] == "Homework 1 (out of 4)" or rows["Student ID"][3].startswith(
        "Homework 1 (out of"
    )
    assert float(rows["s001"][3]) == pytest.approx(0.8) and "late penalty" in rows["s001"][-1]
    assert float(rows["s002"][3]) == 1.0 and "extended" in rows["s002"][-1]
    assert rows["s003"][3] == "" and not cells["s003"]["attempted"]  # nothing answered: no grade
    assert cells["s001"]["attempted"] and not cells["s001"]["solution_opened"]


def test_an_extension_regrades_earlier_late_answers_only_when_the_teacher_asks(client, teacher):
    course = _course(client, teacher)
    _roster(client, teacher, course)
    now = datetime.now(UTC)
    homework = _late_homework(client, teacher, course, now)
    problem, part, answer = RIGHT
    browser, csrf = _signed_in(client, _links(client, teacher, course)[f"course:{course}:s001"])
    path = f"/v1/problems/{problem}/parts/{part}/submissions"
    assert browser.post(path, json={"answer": answer}, headers=csrf).status_code == 201
    extension = f"/v1/assignments/{homework['id']}/extensions/course:{course}:s001"
    due = _iso(now + timedelta(days=1))
    scores = []
    for body in ({"due_at": due}, {"due_at": due, "regrade_earlier": True}):
        assert client.put(extension, json=body, headers=teacher).status_code == 200
        book = client.get(f"/v1/courses/{course}/gradebook", headers=teacher).json()
        (row,) = [r for r in book["students"] if r["student"]["roster_id"] == "s001"]
        scores.append(row["assignments"][0]["score"])
    assert scores == [pytest.approx(0.8), 1.0]
    listed = client.get(f"/v1/assignments/{homework['id']}/extensions", headers=teacher).json()
    assert listed == [{"student": f"course:{course}:s001", "due_at": ANY, "granted_at": None}]


def test_a_closed_assignment_refuses_answers_after_its_due_date(client, teacher):
    course = _course(client, teacher)
    _roster(client, teacher, course)
    now = datetime.now(UTC)
    _assignment(
        client,
        teacher,
        course,
        problems=["skier-friction"],
        opens_at=_iso(now - timedelta(days=5)),
        due_at=_iso(now - timedelta(minutes=1)),
    )
    browser, csrf = _signed_in(client, _links(client, teacher, course)[f"course:{course}:s001"])
    problem, part, answer = RIGHT
    refused = browser.post(
        f"/v1/problems/{problem}/parts/{part}/submissions", json={"answer": answer}, headers=csrf
    )
    assert refused.status_code == 409 and "closed" in refused.json()["error"]["message"]
    standing = browser.get(f"/v1/courses/{course}/assignments").json()
    assert standing[0]["status"] == "closed"


def test_an_assignments_attempts_per_part_override_the_problems(client, teacher):
    course = _course(client, teacher)
    _roster(client, teacher, course)
    _assignment(client, teacher, course, problems=["skier-friction"], max_attempts=1)
    browser, csrf = _signed_in(client, _links(client, teacher, course)[f"course:{course}:s001"])
    problem, part, _ = RIGHT
    path = f"/v1/problems/{problem}/parts/{part}/submissions"
    assert browser.post(path, json={"answer": WRONG}, headers=csrf).status_code == 201
    assert browser.post(path, json={"answer": WRONG}, headers=csrf).status_code == 409
    # The student is told the limit they are held to, not the problem's own.
    view = browser.get(f"/v1/problems/{problem}").json()
    assert {p["max_attempts"] for p in view["parts"]} == {1}
    page = browser.get(f"/p/{problem}").text
    assert "Attempts: 1 of 1 used" in page and "(no limit)" not in page


@pytest.mark.parametrize(
    ("method", "path"),
    [
        ("GET", "/v1/courses/{c}"),
        ("GET", "/v1/courses/{c}/roster"),
        ("GET", "/v1/courses/{c}/assignments"),
        ("GET", "/v1/courses/{c}/gradebook"),
        ("GET", "/v1/assignments/{a}"),
        ("DELETE", "/v1/assignments/{a}"),
        ("GET", "/v1/assignments/{a}/extensions"),
        ("DELETE", "/v1/assignments/{a}/extensions/course:{c}:s001"),
    ],
)
def test_another_instructors_course_or_assignment_answers_as_one_that_does_not_exist(
    client, teacher, other_teacher, method, path
):
    # an assignment of another's course had answered "no course 1", telling that it exists and where
    course = _course(client, teacher)
    _roster(client, teacher, course)
    assignment = _assignment(client, teacher, course)["id"]
    absent = {"c": course + 100, "a": assignment + 100}
    theirs = client.request(method, path.format(c=course, a=assignment), headers=other_teacher)
    missing = client.request(method, path.format(**absent), headers=other_teacher)
    assert theirs.status_code == missing.status_code == 404
    said = theirs.json()["error"]["message"]
    assert said == missing.json()["error"]["message"].replace(str(absent["c"]), str(course)).replace(
        str(absent["a"]), str(assignment)
    )
    if "{c}" not in path:
        assert f"course {course}" not in said


def test_an_instructor_assigns_only_problems_that_are_theirs_to_use(client, teacher, other_teacher):
    course = _course(client, teacher)
    response = client.post(
        f"/v1/courses/{course}/assignments",
        json={
            "title": "HW",
            "problems": ["no-such-problem", "yo-yo"],
            "opens_at": "2026-01-01T00:00:00+01:00",
            "due_at": "2026-01-08T00:00:00+01:00",
        },
        headers=teacher,
    )
    assert response.status_code == 422
    assert [d["path"] for d in response.json()["error"]["details"]] == ["problems.0"]
    naive = client.post(
        f"/v1/courses/{course}/assignments",
        json={
            "title": "HW",
            "problems": ["yo-yo"],
            "opens_at": "2026-01-01T00:00:00",
            "due_at": "2026-01-08T00:00:00",
        },
        headers=teacher,
    )
    assert naive.status_code == 422  # a date without its zone is ambiguous


def test_a_join_code_enrols_a_new_student_and_signs_them_in(client, teacher):
    course = _course(client, teacher)
    _assignment(client, teacher, course, problems=["skier-friction"])
    made = client.post(f"/v1/courses/{course}/join-code", json={}, headers=teacher).json()
    code = made["join_code"]
    assert made["url"].endswith(f"/join/{code}")
    browser = TestClient(client.app)
    assert "Join Mechanics" in browser.get(f"/join/{code}").text
    assert browser.post(f"/join/{code}", data={"name": ""}, follow_redirects=False).status_code == 422
    joined = browser.post(
        f"/join/{code}", data={"name": "Lise", "email": "lise@x.org"}, follow_redirects=False
    )
    assert joined.status_code == 200 and "Save this link to come back" in joined.text
    assert [p["id"] for p in browser.get("/v1/problems").json()] == ["skier-friction"]
    assert [s["name"] for s in client.get(f"/v1/courses/{course}/roster", headers=teacher).json()] == ["Lise"]
    client.post(f"/v1/courses/{course}/join-code", json={"enabled": False}, headers=teacher)
    late = TestClient(client.app)
    assert late.post(f"/join/{code}", data={"name": "Otto"}, follow_redirects=False).status_code == 404


def test_a_sign_in_posted_from_another_site_is_refused_and_the_link_kept(client, teacher):
    course = _course(client, teacher)
    _roster(client, teacher, course)
    path = _links(client, teacher, course)[f"course:{course}:s001"].removeprefix("http://testserver")
    browser = TestClient(client.app)
    for headers in ({"Origin": "https://evil.example"}, {"Sec-Fetch-Site": "cross-site", "Origin": "null"}):
        forged = browser.post(path, headers=headers, follow_redirects=False)
        assert forged.status_code == 403 and "physcheck_course" not in forged.headers.get("set-cookie", "")
    same_site = browser.post(
        path, headers={"Sec-Fetch-Site": "same-origin", "Origin": "null"}, follow_redirects=False
    )
    assert same_site.status_code == 303  # the link was not spent by the refused post


@pytest.mark.parametrize(
    ("solutions", "due_in", "released"),
    [
        ("never", -timedelta(days=1), False),
        ("after_due", timedelta(days=1), False),
        ("after_due", -timedelta(days=1), True),
    ],
)
def test_worked_solutions_open_by_the_assignments_release_policy(
    client, teacher, solutions, due_in, released
):
    course = _course(client, teacher)
    _roster(client, teacher, course)
    now = datetime.now(UTC)
    _assignment(
        client,
        teacher,
        course,
        problems=["skier-friction"],
        solutions=solutions,
        opens_at=_iso(now - timedelta(days=3)),
        due_at=_iso(now + due_in),
    )
    browser, _ = _signed_in(client, _links(client, teacher, course)[f"course:{course}:s001"])
    page = browser.get("/p/skier-friction/solution")
    assert page.status_code == 200
    said = {
        "never": "does not release worked solutions for this assignment",
        "after_due": "opens after the due date",
    }
    if released:
        assert "Not released yet" not in page.text and "Solutions, method by method" in page.text
    else:
        assert "Not released yet" in page.text and said[solutions] in page.text
