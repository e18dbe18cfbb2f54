"""The instructor's course pages: make a course, import a roster, make sign-in links, build an
assignment, read the gradebook; and another instructor sees none of it."""

from __future__ import annotations

import csv
import html
import io
import re
from datetime import UTC, datetime
from zoneinfo import ZoneInfo

import pytest
from fastapi.testclient import TestClient
from httpx import Response

from app.courses.records import StaffRole
from app.db.records import Role
from app.storage import Stores
from tests.instructor.conftest import csrf_of, new_key, sign_in

ROSTER = "id,name,email\ns001,Ada Lovelace,ada@uni.example\ns002,Alan Turing,alan@uni.example\n"


def _given_values(html: str) -> list[str]:
    return re.findall(r'<td class="value">([^<]*)</td>', html)


def _make_course(client: TestClient) -> int:
    form = client.get("/instructor/courses")
    assert form.status_code == 200
    made = client.post(
        "/instructor/courses",
        data={"csrf": csrf_of(form.text), "title": "Mechanics", "timezone": "Europe/Paris"},
    )
    assert made.status_code == 303
    return int(made.headers["location"].rsplit("/", 1)[1])


def _answered_yo_yo(stores: Stores, *students: str) -> None:
    """Each student's right answer to the yo-yo's acceleration, filed as a graded submission."""
    from tests.db.helpers import CORRECT

    version = stores.problems.get("yo-yo").version
    for student in students:
        stores.submissions.file(
            problem_id="yo-yo",
            problem_version=version,
            part_id="acceleration",
            student=student,
            answer="g",
            verdict=CORRECT,
            max_attempts=None,
        )


def test_a_course_is_made_its_roster_imported_twice_without_duplicates(signed_in: TestClient, stores: Stores):
    course = _make_course(signed_in)
    page = signed_in.get(f"/instructor/courses/{course}")
    for _ in range(2):
        done = signed_in.post(
            f"/instructor/courses/{course}/roster", data={"csrf": csrf_of(page.text), "roster": ROSTER}
        )
        assert done.status_code == 200
    assert "0 added, 0 updated, 2 unchanged" in done.text
    assert [e.name for e in stores.courses.roster(course)] == ["Ada Lovelace", "Alan Turing"]
    bad = signed_in.post(
        f"/instructor/courses/{course}/roster", data={"csrf": csrf_of(page.text), "roster": "x y,,\n"}
    )
    assert bad.status_code == 422 and "Line 1" in bad.text


def test_sign_in_links_are_shown_once_and_sign_a_student_in(signed_in: TestClient, stores: Stores):
    course = _make_course(signed_in)
    page = signed_in.get(f"/instructor/courses/{course}")
    signed_in.post(
        f"/instructor/courses/{course}/roster", data={"csrf": csrf_of(page.text), "roster": ROSTER}
    )
    links = signed_in.post(f"/instructor/courses/{course}/links", data={"csrf": csrf_of(page.text)})
    urls = re.findall(r'<code class="sign-in-link">http://testserver(/s/[^<]+)</code>', links.text)
    assert len(urls) == 2
    student = TestClient(signed_in.app, follow_redirects=False)
    assert student.post(urls[0]).status_code == 303
    assert "Your courses" in student.get("/courses").text


def test_the_assignment_builder_saves_problems_in_the_chosen_order_and_dates_in_the_course_zone(
    signed_in: TestClient, stores: Stores
):
    course = _make_course(signed_in)
    form = signed_in.get(f"/instructor/courses/{course}/assignments/new", params={"q": "yo"})
    assert form.status_code == 200 and "yo-yo" in form.text
    saved = signed_in.post(
        f"/instructor/courses/{course}/assignments/new",
        data={
            "csrf": csrf_of(form.text),
            "problem": ["yo-yo"],
            "order-yo-yo": "1",
            "title": "Homework 1",
            "opens_at": "2026-03-01T09:00",
            "due_at": "2026-03-08T23:59",
            "late": "penalty",
            "per_day": "10",
            "limit": "50",
            "max_attempts": "3",
            "solutions": "after_due",
        },
    )
    assert saved.status_code == 303, saved.text
    listed = signed_in.get(saved.headers["location"]).text
    assert "Assignment saved." in listed  # said, not silent
    # the course's list says each assignment's attempts and when its solutions open, not only its dates
    assert re.search(r"<td[^>]*>3</td><td[^>]*>After the due date\b", listed), "attempts, then solutions"
    [made] = stores.courses.assignments(course)
    assert made.problems == ("yo-yo",) and made.spec.max_attempts == 3
    assert made.spec.due_at.isoformat() == "2026-03-08T22:59:00+00:00"  # 23:59 in Paris (CET)
    assert made.spec.late.per_day == 0.1
    edit = signed_in.get(f"/instructor/assignments/{made.id}/edit")
    assert 'value="2026-03-08T23:59"' in edit.text
    assert '<option value="after_due" selected>After the due date</option>' in edit.text
    refused = signed_in.post(
        f"/instructor/courses/{course}/assignments/new",
        data={"csrf": csrf_of(form.text), "title": "", "opens_at": "", "due_at": ""},
    )
    assert refused.status_code == 422 and "Pick at least one problem" in refused.text


def test_a_due_date_moved_before_the_opening_date_is_refused_saying_both_dates_and_what_to_move(
    signed_in: TestClient,
):
    # moving an open assignment's due date into the past met "The due date is before the opening date."
    from app.courses.policy import shown

    course = _make_course(signed_in)
    form = signed_in.get(f"/instructor/courses/{course}/assignments/new")
    refused = signed_in.post(
        f"/instructor/courses/{course}/assignments/new",
        data={
            "csrf": csrf_of(form.text),
            "problem": ["yo-yo"],
            "title": "Homework 1",
            "opens_at": "2026-03-08T09:00",
            "due_at": "2026-03-07T23:59",
        },
    )
    assert refused.status_code == 422
    assert (
        f"The due date, {shown(datetime(2026, 3, 7, 22, 59, tzinfo=UTC), 'Europe/Paris')}, is before the"
        f" opening date, {shown(datetime(2026, 3, 8, 8, 0, tzinfo=UTC), 'Europe/Paris')}: set Opens earlier"
        " too, or the due date later." in html.unescape(refused.text)
    )


def test_the_gradebook_page_links_its_csv_and_another_instructor_sees_nothing(
    signed_in: TestClient, stores: Stores, client: TestClient
):
    course = _make_course(signed_in)
    page = signed_in.get(f"/instructor/courses/{course}")
    signed_in.post(
        f"/instructor/courses/{course}/roster", data={"csrf": csrf_of(page.text), "roster": ROSTER}
    )
    book = signed_in.get(f"/instructor/courses/{course}/gradebook")
    assert book.status_code == 200 and f"/instructor/courses/{course}/gradebook.csv" in book.text
    assert "Ada Lovelace" in book.text
    exported = signed_in.get(f"/instructor/courses/{course}/gradebook.csv")
    assert exported.headers["content-type"].startswith("text/csv") and "Alan Turing" in exported.text
    other = TestClient(signed_in.app, follow_redirects=False)
    assert sign_in(other, new_key(stores, "instructor", "Prof B")).status_code == 303  # type: ignore[attr-defined]
    for path in ("", "/gradebook", "/gradebook.csv", "/assignments/new"):
        response = other.get(f"/instructor/courses/{course}{path}")
        assert response.status_code == 404, path
        assert "Ada Lovelace" not in response.text
    assert "Mechanics" not in other.get("/instructor/courses").text


def _view_as_student(client: TestClient, problem: str) -> Response:
    """The instructor's "View as a student" of a problem, sent from the problem's page."""
    page = client.get(f"/instructor/problems/{problem}")
    assert "View as a student" in page.text
    return client.post(f"/instructor/problems/{problem}/as-student", data={"csrf": csrf_of(page.text)})


def test_view_as_a_student_opens_the_student_page_in_the_instructors_session(
    signed_in: TestClient, stores: Stores
):
    opened = _view_as_student(signed_in, "yo-yo")
    assert opened.status_code == 303 and opened.headers["location"] == "/p/yo-yo"
    key_id = stores.keys.list()[0].id
    assert _submitted_as(signed_in, stores, "yo-yo") == f"preview:{key_id}"  # filed apart, no key asked
    forged = signed_in.post("/instructor/problems/yo-yo/as-student", data={"csrf": "nope"})
    assert forged.status_code == 403


def test_view_as_a_student_keeps_the_browsers_course_session_signed_in(signed_in: TestClient, stores: Stores):
    # the preview's cookie had replaced the course's: the browser's student was signed out of it
    course = _make_course(signed_in)
    page = signed_in.get(f"/instructor/courses/{course}")
    signed_in.post(
        f"/instructor/courses/{course}/join-code", data={"csrf": csrf_of(page.text), "enabled": "1"}
    )
    joined = signed_in.post(f"/join/{stores.courses.get_course(course).join_code}", data={"name": "Ada"})
    assert joined.status_code == 200
    assert _view_as_student(signed_in, "yo-yo").status_code == 303
    courses = signed_in.get("/courses").text
    assert "Mechanics" in courses and "Signed in as Ada" in courses  # still the course's student there
    # the page acts as the preview, filed apart from the class
    assert _submitted_as(signed_in, stores, "yo-yo") == f"preview:{stores.keys.list()[0].id}"


def _submitted_as(client: TestClient, stores: Stores, problem: str, query: str = "") -> str:
    """Whom the browser's answer to the problem's page is filed under (the page's CSRF token sent)."""
    page = client.get(f"/p/{problem}{query}")
    assert page.status_code == 200 and 'data-mode="session"' in page.text, page.text
    token = re.search(r'name="csrf-token" content="([^"]+)"', page.text)
    assert token is not None
    filed = client.post(
        f"/v1/problems/{problem}/parts/acceleration/submissions{query}",
        json={"answer": "g"},
        headers={"X-CSRF-Token": token.group(1)},
    )
    assert filed.status_code == 201, filed.text
    return next(
        s.student for s in stores.submissions.page().items if str(s.id) == filed.json()["submission_id"]
    )


def test_a_preview_acts_only_for_the_problem_it_was_opened_for(signed_in: TestClient, stores: Stores):
    # it had been chosen for every problem page for 8 hours, the browser's own course student's too
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec

    author = stores.keys.list()[0]
    stores.problems.create(
        "my-yo-yo", {**stores.problems.get("yo-yo").document, "id": "my-yo-yo"}, owner_key_id=author.id
    )
    course = _make_course(signed_in)
    now = datetime.now(UTC)
    stores.courses.create_assignment(
        course, AssignmentSpec("HW", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    )
    page = signed_in.get(f"/instructor/courses/{course}")
    signed_in.post(f"/instructor/courses/{course}/join-code", data={"csrf": csrf_of(page.text)})
    signed_in.post(f"/join/{stores.courses.get_course(course).join_code}", data={"name": "Ada"})
    ada = stores.courses.roster(course)[0].student
    assert _view_as_student(signed_in, "my-yo-yo").status_code == 303
    assert _submitted_as(signed_in, stores, "yo-yo") == ada
    assert _submitted_as(signed_in, stores, "my-yo-yo") == f"preview:{author.id}"


def _two_courses_with_yo_yo(signed_in: TestClient, stores: Stores) -> dict[int, tuple[int, str]]:
    """A lecture and its lab, each with an open assignment of the yo-yo, and the browser joined to
    both (the lab's session its latest): per course, the assignment and the student's identity."""
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec

    now = datetime.now(UTC)
    spec = AssignmentSpec("HW", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    students = {}
    for _ in range(2):
        course = _make_course(signed_in)
        made = stores.courses.create_assignment(course, spec)
        page = signed_in.get(f"/instructor/courses/{course}")
        signed_in.post(f"/instructor/courses/{course}/join-code", data={"csrf": csrf_of(page.text)})
        signed_in.post(f"/join/{stores.courses.get_course(course).join_code}", data={"name": "Ada"})
        students[course] = (made.id, stores.courses.roster(course)[0].student)
    return students


def test_a_problem_in_two_courses_files_the_answer_in_the_course_its_page_was_opened_from(
    signed_in: TestClient, stores: Stores
):
    # the answer went to the browser's latest course that had the problem open, whichever page it came from
    for course, (assignment, student) in _two_courses_with_yo_yo(signed_in, stores).items():
        listed = signed_in.get(f"/courses/{course}/assignments/{assignment}").text
        assert f'href="/p/yo-yo?course={course}"' in listed
        assert _submitted_as(signed_in, stores, "yo-yo", f"?course={course}") == student


def test_an_api_call_from_a_browser_in_two_courses_naming_none_is_refused_naming_them(
    signed_in: TestClient, stores: Stores
):
    # it had acted as the latest course's student: an answer could be filed in the other course's place
    students = _two_courses_with_yo_yo(signed_in, stores)
    page = signed_in.get("/p/yo-yo")
    token = re.search(r'name="csrf-token" content="([^"]+)"', page.text)
    assert token is not None
    shown = re.search(r'data-course="(\d+)"', page.text)  # the page's calls name the course it shows
    assert shown is not None and int(shown.group(1)) in students
    headers = {"X-CSRF-Token": token.group(1)}
    for path, body in (
        ("/v1/problems/yo-yo/parts/acceleration/submissions", {"answer": "g"}),
        ("/v1/submissions", None),
    ):
        refused = signed_in.request("POST" if body else "GET", path, json=body, headers=headers)
        assert refused.status_code == 422, path
        error = refused.json()["error"]
        assert error["code"] == "course_required" and error["details"][0]["path"] == "course"
        assert all(f"{course}: Mechanics" in error["message"] for course in students)
        first, second = sorted(students)
        assert f"name one with ?course={first} or ?course={second}." in error["message"]
    assert stores.submissions.page().items == []  # nothing filed
    elsewhere = signed_in.get("/v1/submissions", params={"course": 999}, headers=headers)
    assert elsewhere.status_code == 404  # not the latest course's list under another's name
    for course, (_, student) in students.items():  # named, each call acts in its course
        assert _submitted_as(signed_in, stores, "yo-yo", f"?course={course}") == student
        listed = signed_in.get("/v1/submissions", params={"course": course}, headers=headers)
        assert listed.status_code == 200
        assert [item["student"] for item in listed.json()["items"]] == [student]


def test_an_assignment_read_from_a_browser_in_two_courses_acts_in_the_assignments_course(
    signed_in: TestClient, stores: Stores
):
    # it had been refused for want of ?course=, though the assignment's id names its course
    students = _two_courses_with_yo_yo(signed_in, stores)
    for course, (assignment, _) in students.items():
        read = signed_in.get(f"/v1/assignments/{assignment}")
        assert read.status_code == 200, read.text
        assert read.json()["course_id"] == course and read.json()["status"] == "not started"
    elsewhere = stores.courses.create_assignment(
        _make_course(signed_in), stores.courses.get_assignment(assignment).spec
    )
    assert signed_in.get(f"/v1/assignments/{elsewhere.id}").status_code == 404  # a course not its own


@pytest.mark.parametrize(
    ("named", "status"),
    [
        ("the lecture's student", 403),  # their own course's session: acting for students needs a key
        ("a student of neither", 403),  # whichever course: the same answer, nothing to choose
        ("a student of both", 422),  # truly ambiguous: which course's session asks matters
    ],
)
def test_student_data_from_a_browser_in_two_courses_asks_for_the_course_only_when_ambiguous(
    signed_in: TestClient, stores: Stores, named: str, status: int
):
    students = _two_courses_with_yo_yo(signed_in, stores)
    (lecture, (_, lecture_student)), (lab, _) = sorted(students.items())
    for course in (lecture, lab):
        stores.courses.enrol(course, "lti:1:both", "Both")
    student = {
        "the lecture's student": lecture_student,
        "a student of neither": "s-1024",
        "a student of both": "lti:1:both",
    }[named]
    answered = signed_in.get("/v1/student-data", params={"student": student})
    assert answered.status_code == status, answered.text
    error = answered.json()["error"]
    if status == 422:
        assert error["code"] == "course_required"
        assert f"name one with ?course={lecture} or ?course={lab}." in error["message"]
        assert (
            error["details"][0]["message"]
            == f"required: one of the courses {lecture}, {lab}, which could each take this"
        )
    else:
        assert error["code"] == "forbidden"


@pytest.mark.parametrize("problem_page", [False, True])
@pytest.mark.parametrize("enrolled_in_both", [False, True])
def test_a_course_page_the_browser_has_no_session_for_asks_to_sign_in_to_that_course(
    signed_in: TestClient, stores: Stores, enrolled_in_both: bool, problem_page: bool
):
    # the page had acted as the browser's other course's student (`choose` fell back to the latest)
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec

    now = datetime.now(UTC)
    spec = AssignmentSpec("Lab work", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    lecture, lab = _make_course(signed_in), _make_course(signed_in)
    lab_work = stores.courses.create_assignment(lab, spec)
    page = signed_in.get(f"/instructor/courses/{lecture}")
    signed_in.post(f"/instructor/courses/{lecture}/join-code", data={"csrf": csrf_of(page.text)})
    signed_in.post(f"/join/{stores.courses.get_course(lecture).join_code}", data={"name": "Ada"})
    if enrolled_in_both:  # one identity in both courses, as an LMS's is
        stores.courses.enrol(lab, stores.courses.roster(lecture)[0].student, "Ada")
    # the problem page, opened from the lab's assignment page, had shown the problem's key form
    path = f"/p/yo-yo?course={lab}" if problem_page else f"/courses/{lab}/assignments/{lab_work.id}"
    shown = signed_in.get(path)
    assert shown.status_code == 401
    assert "<h1>Sign in to this course</h1>" in shown.text and "Lab work" not in shown.text
    assert 'id="key-form"' not in shown.text
    assert signed_in.get("/courses").status_code == 200  # still signed in to the lecture


@pytest.mark.parametrize(
    ("path", "status", "shown"),
    [
        ("/p/yo-yo?course=1", 401, "You are not signed in."),
        ("/p/yo-yo", 200, 'id="key-form"'),  # a key's page, as before
    ],
)
def test_a_problem_page_of_a_course_asks_a_browser_signed_in_nowhere_to_sign_in(
    signed_in: TestClient, path: str, status: int, shown: str
):
    browser = TestClient(signed_in.app, follow_redirects=False)
    got = browser.get(path)
    assert got.status_code == status and shown in got.text


def test_the_course_page_makes_and_turns_off_a_join_code(signed_in: TestClient, stores: Stores):
    course = _make_course(signed_in)
    page = signed_in.get(f"/instructor/courses/{course}")
    assert "No join code" in page.text
    made = signed_in.post(
        f"/instructor/courses/{course}/join-code", data={"csrf": csrf_of(page.text), "enabled": "1"}
    )
    assert made.status_code == 303
    code = stores.courses.get_course(course).join_code
    shown = signed_in.get(f"/instructor/courses/{course}").text
    assert code and f"/join/{code}" in shown
    assert "link to come back" in shown and "each join is a new student" not in shown  # as joining now is
    signed_in.post(
        f"/instructor/courses/{course}/join-code", data={"csrf": csrf_of(page.text), "enabled": "0"}
    )
    assert stores.courses.get_course(course).join_code is None


def test_an_assignments_results_count_the_courses_students_only_under_the_problems_titles(
    signed_in: TestClient, stores: Stores
):
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec, RosterRow

    course = _make_course(signed_in)
    stores.courses.import_roster(course, [RosterRow("s1", "Ada", ""), RosterRow("s2", "Alan", "")])
    now = datetime.now(UTC)
    made = stores.courses.create_assignment(
        course, AssignmentSpec("HW", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    )
    _answered_yo_yo(stores, f"course:{course}:s1", "someone-outside")
    page = signed_in.get(f"/instructor/assignments/{made.id}/results")
    assert page.status_code == 200
    title = stores.problems.get("yo-yo").document["title"]
    row = re.search(
        rf'<th[^>]*><a href="/instructor/problems/yo-yo">{re.escape(title)}</a></th><td[^>]*>acceleration</td>'
        r"<td[^>]*>(\d+)</td><td[^>]*>(\d+)</td>",
        page.text,
    )
    assert row and row.groups() == ("1", "1"), "each part under its problem's title, linked to the problem"
    other = TestClient(signed_in.app, follow_redirects=False)
    sign_in(other, new_key(stores, "instructor", "Prof B"))
    assert other.get(f"/instructor/assignments/{made.id}/results").status_code == 404


def test_an_upload_is_seen_by_its_authors_courses_and_by_all_once_shared(
    signed_in: TestClient, stores: Stores
):
    author = stores.keys.list()[0]
    document = {**stores.problems.get("yo-yo").document, "id": "my-yo-yo", "title": "My yo-yo"}
    stores.problems.create("my-yo-yo", document, owner_key_id=author.id)
    other = TestClient(signed_in.app, follow_redirects=False)
    colleague_key = new_key(stores, "instructor", "Prof C")
    sign_in(other, new_key(stores, "instructor", "Prof B"))
    paths = [
        "/instructor/problems/my-yo-yo",
        "/instructor/problems/my-yo-yo/solution",
        "/instructor/problems/my-yo-yo/results",
    ]
    assert all(signed_in.get(path).status_code == 200 for path in paths)
    assert all(other.get(path).status_code == 404 for path in paths)
    assert "My yo-yo" not in other.get("/instructor/problems").text
    # A colleague on the author's course staff uses it; after sharing, everyone does.
    course = _make_course(signed_in)
    colleague_id = next(k.id for k in stores.keys.list() if k.name == "Prof C")
    stores.courses.add_staff(course, f"key:{colleague_id}", StaffRole.TA)
    colleague = TestClient(signed_in.app, follow_redirects=False)
    sign_in(colleague, colleague_key)
    assert colleague.get("/instructor/problems/my-yo-yo").status_code == 200
    stores.courses.share_problem("my-yo-yo", True)
    assert other.get("/instructor/problems/my-yo-yo").status_code == 200


def test_the_submissions_page_and_csv_show_only_the_visitors_students(signed_in: TestClient, stores: Stores):
    from app.courses.records import RosterRow

    course = _make_course(signed_in)
    stores.courses.import_roster(course, [RosterRow("s1", "Ada", "")])
    _answered_yo_yo(stores, f"course:{course}:s1", "keyed-student")
    own = signed_in.get("/instructor/submissions")
    assert f"student=course%3A{course}%3As1" in own.text and "keyed-student" in own.text  # her answers' link
    other = TestClient(signed_in.app, follow_redirects=False)
    sign_in(other, new_key(stores, "instructor", "Prof B"))
    listed = other.get("/instructor/submissions")
    assert f"course:{course}:s1" not in listed.text and "keyed-student" in listed.text
    exported = other.get("/instructor/submissions.csv")
    assert f"course:{course}:s1" not in exported.text and "keyed-student" in exported.text
    assert other.get("/instructor/submissions", params={"student": f"course:{course}:s1"}).status_code == 404


def test_the_submissions_page_names_a_courses_students_and_finds_them_by_name(
    signed_in: TestClient, stores: Stores
):
    # a joined student's work is filed as course:N:join-…, which told the instructor nothing
    from app.courses.records import RosterRow

    course = _make_course(signed_in)
    stores.courses.import_roster(
        course,
        [RosterRow("s1", "Ada Lovelace", ""), RosterRow("s2", "Alan", ""), RosterRow("s3", "Alan", "")],
    )
    _answered_yo_yo(stores, f"course:{course}:s1", f"course:{course}:s2")
    listed = signed_in.get("/instructor/submissions")
    assert '>Ada Lovelace</a><br><span class="muted identity">s1</span>' in listed.text  # name, then id
    found = signed_in.get("/instructor/submissions", params={"student": "ada lovelace"})
    assert (
        found.status_code == 200 and "Ada Lovelace" in found.text and f"course:{course}:s2" not in found.text
    )
    assert f'/instructor/submissions.csv?student=course%3A{course}%3As1"' in found.text  # the CSV: hers too
    shared = signed_in.get("/instructor/submissions", params={"student": "Alan"})
    assert shared.status_code == 422 and "Alan (s2), Alan (s3)" in shared.text
    assert ", student Alan (s3)." in signed_in.get("/instructor/submissions", params={"student": "s3"}).text
    book = signed_in.get(f"/instructor/courses/{course}/gradebook", params={"student": f"course:{course}:s1"})
    assert f'href="/instructor/submissions?student=course%3A{course}%3As1"' in book.text  # her answers
    # her variant, by name, as her problem page shows it to her
    variant = signed_in.get("/instructor/problems/yo-yo", params={"student": "Ada Lovelace"})
    assert 'Showing the variant of <strong>Ada Lovelace</strong> <span class="muted">(s1)' in (variant.text)
    by_identity = signed_in.get("/instructor/problems/yo-yo", params={"student": f"course:{course}:s1"})
    assert _given_values(variant.text) and _given_values(variant.text) == _given_values(by_identity.text)
    hand_out = signed_in.get("/instructor/problems/yo-yo/solution", params={"student": "ada lovelace"})
    assert "<strong>Ada Lovelace</strong> (s1)" in hand_out.text
    other = TestClient(signed_in.app, follow_redirects=False)
    sign_in(other, new_key(stores, "instructor", "Prof B"))
    elsewhere = other.get("/instructor/submissions", params={"student": "Ada Lovelace"})
    assert elsewhere.status_code == 200 and f"course:{course}:s1" not in elsewhere.text  # not their student


def test_a_course_students_problem_and_solution_pages_look_at_their_courses_once_each(
    signed_in: TestClient, stores: Stores, monkeypatch: pytest.MonkeyPatch
):
    from datetime import UTC, datetime, timedelta

    from app.courses import access
    from app.courses.records import AssignmentSpec

    course = _make_course(signed_in)
    now = datetime.now(UTC)
    stores.courses.create_assignment(
        course, AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    )
    page = signed_in.get(f"/instructor/courses/{course}")
    signed_in.post(
        f"/instructor/courses/{course}/join-code", data={"csrf": csrf_of(page.text), "enabled": "1"}
    )
    student = TestClient(signed_in.app, follow_redirects=False)
    code = stores.courses.get_course(course).join_code
    assert student.post(f"/join/{code}", data={"name": "Ada"}).status_code == 200  # shown their link
    calls: list[str] = []
    real = access.opening

    def counted(*args: object, **kwargs: object) -> access.Opening | None:
        calls.append("opening")
        return real(*args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(access, "opening", counted)
    for path in ("/p/yo-yo/content", "/p/yo-yo/solution/content"):
        calls.clear()
        shown = student.get(path)
        assert shown.status_code == 200, path
        assert calls == ["opening"], path
    assert "HW 1" in student.get("/p/yo-yo/content").text  # the banner still names the assignment


def test_a_refused_assignment_keeps_what_was_typed_and_a_new_one_opens_now(
    signed_in: TestClient, stores: Stores
):
    course = _make_course(signed_in)
    form = signed_in.get(f"/instructor/courses/{course}/assignments/new")
    opens = re.search(
        r'id="a-opens" name="opens_at" type="datetime-local" required value="([^"]*)"', form.text
    )
    assert opens and re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d", opens.group(1))  # now, in the course's zone
    assert form.text.index('id="a-title"') < form.text.index('class="problem-picker')  # settings first
    refused = signed_in.post(
        f"/instructor/courses/{course}/assignments/new",
        data={
            "csrf": csrf_of(form.text),
            "title": "Homework 2",
            "opens_at": "2026-03-01T09:00",
            "due_at": "2026-03-08T23:59",
            "late": "penalty",
            "per_day": "5",
            "limit": "40",
            "max_attempts": "4",
            "solutions": "never",
        },
    )
    assert refused.status_code == 422 and "Pick at least one problem" in refused.text
    for kept in (
        'value="Homework 2"',
        'value="2026-03-01T09:00"',
        'value="2026-03-08T23:59"',
        '<option value="penalty" selected',
        'name="per_day" type="number" min="0" max="100" step="any" value="5"',
        'name="limit" type="number" min="0" max="100" step="any" value="40"',
        'name="max_attempts" type="number" min="1" value="4"',
        '<option value="never" selected',
    ):
        assert kept in refused.text, kept


def _visible_text(html: str) -> str:
    """What a reader sees: the text between tags (a form's hidden student value is not read)."""
    return re.sub(r"<[^>]+>", " ", html)


def test_a_joined_student_is_shown_by_name_email_and_a_readable_id_never_by_their_filing_identity(
    signed_in: TestClient, stores: Stores
):
    from app.courses import sessions as course_sessions
    from app.db.types import utc_now

    course = _make_course(signed_in)
    stores.courses.set_join_code(course, "JOINCODE")
    joined = course_sessions.join(stores.courses, "JOINCODE", "Lise Meitner", "lise@uni.example", utc_now())
    assert isinstance(joined, course_sessions.Joined)
    student = joined.session.student
    _answered_yo_yo(stores, student)
    for path, params in [
        (f"/instructor/courses/{course}", {}),
        (f"/instructor/courses/{course}/gradebook", {"student": student}),
        ("/instructor/submissions", {}),
        ("/instructor/submissions", {"student": "lise@uni.example"}),
        ("/instructor/problems/yo-yo", {"student": "Lise Meitner"}),
    ]:
        shown = _visible_text(signed_in.get(path, params=params).text)
        assert "Lise Meitner" in shown and "lise@uni.example" in shown, path
        assert f"course:{course}:" not in shown, path
    exports = [
        list(csv.DictReader(io.StringIO(signed_in.get(f"/instructor/courses/{course}/gradebook.csv").text)))
        for _ in range(2)
    ]
    ids = [rows[0]["Student ID"] for rows in exports]
    assert re.fullmatch(r"join-[0-9a-f]{12}", ids[0]) and ids[0] == ids[1]  # readable, and the same each time
    assert exports[0][0]["Name"] == "Lise Meitner" and exports[0][0]["Email"] == "lise@uni.example"


@pytest.mark.parametrize(
    ("title", "timezone", "said"),
    [
        ("Mechanics", "Paris", "“Paris” is not a time zone name"),
        ("Mechanics", "Europe/Pariss", "“Europe/Pariss” is not a time zone name"),
        ("", "Europe/Paris", "Give the course a title."),
    ],
)
def test_a_course_with_an_unknown_time_zone_or_no_title_is_refused_saying_why_keeping_what_was_typed(
    signed_in: TestClient, stores: Stores, title: str, timezone: str, said: str
):
    form = signed_in.get("/instructor/courses")
    refused = signed_in.post(
        "/instructor/courses", data={"csrf": csrf_of(form.text), "title": title, "timezone": timezone}
    )
    assert refused.status_code == 422 and said in refused.text
    assert (
        f'value="{timezone}"' in refused.text
        and f'name="title" type="text" required maxlength="200" value="{title}"' in refused.text
    )
    assert "Start here" in refused.text  # no course was made (it had been, in UTC)


def test_a_problems_page_links_to_a_new_assignment_of_each_course_with_the_problem_ticked(
    signed_in: TestClient, stores: Stores
):
    before = signed_in.get("/instructor/problems/yo-yo", params={"saved": "1"}).text
    assert 'To assign it, <a href="/instructor/courses">create a course</a> first.' in before  # no dead end
    course = _make_course(signed_in)
    page = signed_in.get("/instructor/problems/yo-yo").text
    link = f"/instructor/courses/{course}/assignments/new?pick=yo-yo"
    assert f'<a href="{link}">a new assignment of Mechanics</a>' in page
    builder = signed_in.get(link).text
    assert re.search(r'<input type="checkbox" name="problem" value="yo-yo" id="pick-yo-yo" checked>', builder)


def test_one_students_gradebook_names_the_problems_by_title_and_sets_the_extension_form_to_them(
    signed_in: TestClient, stores: Stores
):
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec

    course = _make_course(signed_in)
    signed_in.post(
        f"/instructor/courses/{course}/roster",
        data={"csrf": csrf_of(signed_in.get(f"/instructor/courses/{course}").text), "roster": ROSTER},
    )
    now = datetime.now(UTC)
    stores.courses.create_assignment(
        course, AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    )
    alan = f"course:{course}:s002"
    page = signed_in.get(f"/instructor/courses/{course}/gradebook", params={"student": alan}).text
    title = stores.problems.get("yo-yo").document["title"]
    assert re.search(
        rf'<td[^>]*><a href="/instructor/problems/yo-yo">{re.escape(title)}</a></td>'
        r"<td[^>]*>Part 1: <code>acceleration</code></td>",
        page,
    )
    assert f'<option value="{alan}" selected>Alan Turing' in page  # not the roster's first, Ada


def _upload_retired_from_an_assignment(
    signed_in: TestClient, stores: Stores, problems: tuple[str, ...]
) -> tuple[TestClient, int, int]:
    """The instructor's upload `my-yo-yo` (a copy of the yo-yo) in an open assignment of `problems`, a
    student who joined the course by its code, then the upload retired: (the student's browser, the
    course id, the assignment id)."""
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec

    author = stores.keys.list()[0]
    document = {**stores.problems.get("yo-yo").document, "id": "my-yo-yo", "title": "My yo-yo"}
    stores.problems.create("my-yo-yo", document, owner_key_id=author.id)
    course = _make_course(signed_in)
    now = datetime.now(UTC)
    made = stores.courses.create_assignment(
        course, AssignmentSpec("HW 1", problems, now - timedelta(days=1), now + timedelta(days=1))
    )
    page = signed_in.get(f"/instructor/courses/{course}")
    signed_in.post(
        f"/instructor/courses/{course}/join-code", data={"csrf": csrf_of(page.text), "enabled": "1"}
    )
    student = TestClient(signed_in.app, follow_redirects=False)
    student.post(f"/join/{stores.courses.get_course(course).join_code}", data={"name": "Ada"})
    stores.problems.retire("my-yo-yo")
    return student, course, made.id


def test_an_assignment_whose_upload_was_retired_still_opens_for_its_students_with_its_other_problems(
    signed_in: TestClient, stores: Stores
):
    student, course, assignment = _upload_retired_from_an_assignment(signed_in, stores, ("my-yo-yo", "yo-yo"))
    shown = student.get(f"/courses/{course}/assignments/{assignment}")
    assert shown.status_code == 200, shown.text  # it had been the API's 404, "no problem 'my-yo-yo'"
    title = stores.problems.get("yo-yo").document["title"]
    assert title in shown.text and "My yo-yo" not in shown.text


@pytest.mark.parametrize("page", ["edit", "results"])
def test_another_instructors_assignment_page_answers_as_one_that_does_not_exist(
    signed_in: TestClient, stores: Stores, page: str
):
    # it had answered "There is no course 1 of yours.", telling that the assignment exists and where
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec

    now = datetime.now(UTC)
    spec = AssignmentSpec("Lab work", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    theirs = stores.courses.create_assignment(stores.courses.create_course("B", owner="key:other").id, spec)
    shown = signed_in.get(f"/instructor/assignments/{theirs.id}/{page}")
    missing = signed_in.get(f"/instructor/assignments/{theirs.id + 100}/{page}")
    assert shown.status_code == missing.status_code == 404
    assert f"There is no assignment {theirs.id} of yours." in shown.text
    assert f"There is no assignment {theirs.id + 100} of yours." in missing.text
    assert "No such assignment" in shown.text and "There is no course" not in shown.text


def test_a_refused_course_page_leads_back_to_the_courses(signed_in: TestClient):
    missing = signed_in.get("/instructor/courses/999")
    assert missing.status_code == 404 and "There is no course 999 of yours." in missing.text
    assert (
        'Back to <a href="/instructor/courses">your courses</a>' in missing.text
    )  # it offered only the problems


def test_an_assignment_is_deleted_from_its_page_and_its_answers_stay(signed_in: TestClient, stores: Stores):
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec

    course = _make_course(signed_in)
    now = datetime.now(UTC)
    made = stores.courses.create_assignment(
        course, AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    )
    _answered_yo_yo(stores, f"course:{course}:s1")
    page = signed_in.get(f"/instructor/assignments/{made.id}/edit").text
    assert "Delete “HW 1”" in page
    assert (
        signed_in.post(f"/instructor/assignments/{made.id}/delete", data={"csrf": "forged"}).status_code
        == 403
    )
    done = signed_in.post(f"/instructor/assignments/{made.id}/delete", data={"csrf": csrf_of(page)})
    assert (
        done.status_code == 303 and done.headers["location"] == f"/instructor/courses/{course}?saved=deleted"
    )
    assert "Assignment deleted" in signed_in.get(done.headers["location"]).text
    assert stores.courses.assignments(course) == []
    assert signed_in.get(f"/instructor/assignments/{made.id}/edit").status_code == 404
    assert len(stores.submissions.page(student=f"course:{course}:s1", limit=10).items) == 1


def test_the_submissions_filter_lists_no_other_instructors_private_upload(
    signed_in: TestClient, stores: Stores
):
    other = stores.keys.create(Role.INSTRUCTOR, name="Prof B")
    document = {**stores.problems.get("yo-yo").document, "id": "secret-yo-yo", "title": "Exam question 3"}
    stores.problems.create("secret-yo-yo", document, owner_key_id=other.record.id)
    page = signed_in.get("/instructor/submissions").text
    assert "Exam question 3" not in page and "secret-yo-yo" not in page


def test_the_builder_says_late_answers_earn_nothing_after_the_worked_solution_is_opened(
    signed_in: TestClient,
):
    course = _make_course(signed_in)
    form = signed_in.get(f"/instructor/courses/{course}/assignments/new").text
    penalty = form[form.index('<div id="late-penalty">') :]
    penalty = penalty[: penalty.index("</div>")]
    # inside the late penalty's fields: shown only while late work is accepted
    assert "earns nothing on its parts after" in penalty


def test_releasing_an_assignments_solutions_now_opens_them_before_the_due_date(
    signed_in: TestClient, stores: Stores
):
    from datetime import UTC, datetime, timedelta

    from app.courses.policy import solutions_released
    from app.courses.records import AssignmentSpec, SolutionRelease

    course = _make_course(signed_in)
    now = datetime.now(UTC)
    made = stores.courses.create_assignment(
        course, AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    )
    page = signed_in.get(f"/instructor/courses/{course}").text
    assert f'action="/instructor/assignments/{made.id}/release-solutions"' in page
    forged = signed_in.post(f"/instructor/assignments/{made.id}/release-solutions", data={"csrf": "forged"})
    assert forged.status_code == 403
    done = signed_in.post(
        f"/instructor/assignments/{made.id}/release-solutions", data={"csrf": csrf_of(page)}
    )
    assert done.headers["location"] == f"/instructor/courses/{course}?saved=released"
    after = signed_in.get(done.headers["location"]).text
    assert "Worked solutions released" in after and "release-solutions" not in after
    released = stores.courses.get_assignment(made.id)
    assert released.spec.solutions is SolutionRelease.RELEASED and released.spec.due_at == made.spec.due_at
    assert solutions_released(released, released.spec.due_at, now, all_parts_done=False)[0]


def test_the_gradebook_shows_not_started_apart_from_a_0_earned(signed_in: TestClient, stores: Stores):
    # both had read 0: a student who never answered and one who answered wrong
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec
    from tests.db.helpers import INCORRECT

    course = _make_course(signed_in)
    page = signed_in.get(f"/instructor/courses/{course}")
    signed_in.post(
        f"/instructor/courses/{course}/roster", data={"csrf": csrf_of(page.text), "roster": ROSTER}
    )
    now = datetime.now(UTC)
    stores.courses.create_assignment(
        course, AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    )
    stores.submissions.file(
        problem_id="yo-yo",
        problem_version=stores.problems.get("yo-yo").version,
        part_id="acceleration",
        student=f"course:{course}:s001",
        answer="-g",
        verdict=INCORRECT,
        max_attempts=None,
    )
    book = signed_in.get(f"/instructor/courses/{course}/gradebook").text
    ada, alan = (book[book.index(name) :] for name in ("Ada Lovelace", "Alan Turing"))
    assert re.search(r'data-label="HW 1 / \d+">0\b', ada)
    assert re.search(r'data-label="HW 1 / \d+"><span aria-hidden="true">—</span>', alan)
    assert '<span class="muted">not started</span>' in alan


def test_the_submissions_csv_names_each_courses_student_beside_their_identity(
    signed_in: TestClient, stores: Stores
):
    # a joined student's rows had read only course:N:join-…, with no name or email to tell who
    from app.courses.records import RosterRow

    course = _make_course(signed_in)
    stores.courses.import_roster(course, [RosterRow("s1", "Ada Lovelace", "ada@uni.example")])
    joined = f"course:{course}:join-3f2a"
    stores.courses.enrol(course, joined, "Alan Turing", "alan@uni.example")
    _answered_yo_yo(stores, f"course:{course}:s1", joined, "keyed-student")
    rows = list(csv.DictReader(io.StringIO(signed_in.get("/instructor/submissions.csv").text)))
    people = {row["student"]: (row["name"], row["email"]) for row in rows}
    assert people == {
        f"course:{course}:s1": ("Ada Lovelace", "ada@uni.example"),
        joined: ("Alan Turing", "alan@uni.example"),
        "keyed-student": ("", ""),  # in no course: no roster to name them
    }


def test_an_assignment_whose_only_problem_was_retired_says_there_is_nothing_to_answer(
    signed_in: TestClient, stores: Stores
):
    # it had said "Not started" and "Score: 0 of 0"
    student, course, assignment = _upload_retired_from_an_assignment(signed_in, stores, ("my-yo-yo",))
    for path in ("/courses", f"/courses/{course}/assignments/{assignment}"):
        shown = student.get(path).text
        assert "Nothing to answer" in shown and "0 of 0" not in shown and "Not started" not in shown, path


# What only a course's instructors may do from its pages, and the words a TA is refused with.
TA_REFUSED_PAGES = [
    ("GET", "/instructor/courses/{course}/assignments/new", "add assignments"),
    ("POST", "/instructor/courses/{course}/assignments/new", "add assignments"),
    ("POST", "/instructor/courses/{course}/roster", "import its roster"),
    ("POST", "/instructor/courses/{course}/join-code", "change its join code"),
    ("GET", "/instructor/assignments/{assignment}/edit", "change its assignments"),
    ("POST", "/instructor/assignments/{assignment}/edit", "change its assignments"),
    ("POST", "/instructor/assignments/{assignment}/delete", "delete its assignments"),
    ("POST", "/instructor/assignments/{assignment}/release-solutions", "release its worked solutions"),
]


@pytest.mark.parametrize(("method", "path", "action"), TA_REFUSED_PAGES)
def test_a_ta_asking_what_only_instructors_may_do_is_refused_saying_so(
    signed_in: TestClient, stores: Stores, method: str, path: str, action: str
):
    # a TA sees the course: "There is no course 1 of yours" told them it did not exist
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec

    course = _make_course(signed_in)
    now = datetime.now(UTC)
    homework = stores.courses.create_assignment(
        course, AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    )
    ta = TestClient(signed_in.app, follow_redirects=False)
    ta_key = new_key(stores, "instructor", "Tess")
    stores.courses.add_staff(course, f"key:{stores.keys.list()[-1].id}", StaffRole.TA)
    sign_in(ta, ta_key)
    course_page = ta.get(f"/instructor/courses/{course}")
    assert course_page.status_code == 200
    url = path.format(course=course, assignment=homework.id)
    refused = ta.request(method, url, data={"csrf": csrf_of(course_page.text)} if method == "POST" else None)
    assert refused.status_code == 403
    assert "For the course&#39;s instructors" in refused.text
    assert f"Only the course&#39;s instructors may {action}; you are its teaching assistant." in refused.text


def test_a_students_parts_in_the_gradebook_are_numbered_as_their_problem_page_numbers_them(
    signed_in: TestClient, stores: Stores
):
    # they were the engine's ids alone (acceleration_numeric), while the student asks about "part 3"
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec

    course = _make_course(signed_in)
    signed_in.post(
        f"/instructor/courses/{course}/roster",
        data={"csrf": csrf_of(signed_in.get(f"/instructor/courses/{course}").text), "roster": ROSTER},
    )
    now = datetime.now(UTC)
    stores.courses.create_assignment(course, AssignmentSpec("HW 1", ("yo-yo",), now, now + timedelta(days=1)))
    book = signed_in.get(
        f"/instructor/courses/{course}/gradebook", params={"student": f"course:{course}:s001"}
    )
    parts = re.findall(r'data-label="Part">Part (\d+): <code>(\w+)</code>', book.text)
    assert parts == [
        ("1", "acceleration"),
        ("2", "tension"),
        ("3", "acceleration_numeric"),
    ]


def test_setting_or_removing_an_extension_says_so_with_the_students_due_date_now(
    signed_in: TestClient, stores: Stores
):
    # the gradebook came back as before, its form reset to the first student: nothing said it was done
    from datetime import UTC, datetime, timedelta

    from app.courses.policy import shown
    from app.courses.records import AssignmentSpec

    course = _make_course(signed_in)
    signed_in.post(
        f"/instructor/courses/{course}/roster",
        data={"csrf": csrf_of(signed_in.get(f"/instructor/courses/{course}").text), "roster": ROSTER},
    )
    now = datetime.now(UTC).replace(second=0, microsecond=0)
    class_due = now - timedelta(days=1)
    homework = stores.courses.create_assignment(
        course, AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), class_due)
    )
    extended = now + timedelta(days=3)
    for due_at, said in (
        (f"{extended.astimezone(ZoneInfo('Europe/Paris')):%Y-%m-%dT%H:%M}", "Extension saved: Alan Turing"),
        ("", "Extension removed: Alan Turing"),
    ):
        sent = signed_in.post(
            f"/instructor/courses/{course}/extensions",
            data={
                "csrf": csrf_of(signed_in.get(f"/instructor/courses/{course}/gradebook").text),
                "student": f"course:{course}:s002",
                "assignment": str(homework.id),
                "due_at": due_at,
            },
        )
        assert sent.status_code == 303, sent.text
        book = signed_in.get(sent.headers["location"]).text
        due = shown(extended if due_at else class_due, "Europe/Paris")
        assert re.search(rf'role="status">{said} has HW 1 due {re.escape(due)}', book), book
        assert f'<option value="course:{course}:s002" selected>' in book  # the form stays on them
    assert "Extension" not in signed_in.get(f"/instructor/courses/{course}/gradebook").text.split("<h2")[0]


def test_a_tas_course_page_offers_only_what_a_ta_may_do(signed_in: TestClient, stores: Stores):
    # a TA was shown the roster's import, the join code's and the assignments' forms, each refused (403)
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec

    course = _make_course(signed_in)
    page = signed_in.get(f"/instructor/courses/{course}")
    signed_in.post(
        f"/instructor/courses/{course}/roster", data={"csrf": csrf_of(page.text), "roster": ROSTER}
    )
    now = datetime.now(UTC)
    homework = stores.courses.create_assignment(
        course, AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    )
    refused = {path.format(course=course, assignment=homework.id) for _, path, _ in TA_REFUSED_PAGES}
    ta = TestClient(signed_in.app, follow_redirects=False)
    ta_key = new_key(stores, "instructor", "Tess")
    stores.courses.add_staff(course, f"key:{stores.keys.list()[-1].id}", StaffRole.TA)
    sign_in(ta, ta_key)
    for client, teaches in ((signed_in, True), (ta, False)):
        html = client.get(f"/instructor/courses/{course}").text
        offered = set(re.findall(r'(?:href|action)="([^"]+)"', html))
        assert bool(offered & refused) is teaches, offered & refused
        # what a TA may do stays: the roster and the assignments read, sign-in links, the gradebook
        assert "Ada Lovelace" in html and "HW 1" in html
        assert f"/instructor/courses/{course}/links" in offered
        assert f"/instructor/courses/{course}/gradebook" in offered


@pytest.mark.parametrize(
    ("regrade_earlier", "since"),
    [("", ", granted {granted}"), ("on", ", covering the answers given before it too")],
)
def test_an_extension_in_the_gradebook_opens_to_when_it_was_granted_and_to_when(
    signed_in: TestClient, stores: Stores, regrade_earlier: str, since: str
):
    # its dates were a tooltip ("ext." titled with the due date alone), which no phone shows
    from datetime import UTC, datetime, timedelta

    from app.courses.policy import shown
    from app.courses.records import AssignmentSpec

    course = _make_course(signed_in)
    signed_in.post(
        f"/instructor/courses/{course}/roster",
        data={"csrf": csrf_of(signed_in.get(f"/instructor/courses/{course}").text), "roster": ROSTER},
    )
    now = datetime.now(UTC).replace(second=0, microsecond=0)
    homework = stores.courses.create_assignment(
        course, AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=2), now - timedelta(days=1))
    )
    page = signed_in.get(f"/instructor/courses/{course}/gradebook")
    due = now + timedelta(days=3)
    granted = signed_in.post(
        f"/instructor/courses/{course}/extensions",
        data={
            "csrf": csrf_of(page.text),
            "student": f"course:{course}:s002",
            "assignment": str(homework.id),
            "due_at": f"{due.astimezone(ZoneInfo('Europe/Paris')):%Y-%m-%dT%H:%M}",
            "regrade_earlier": regrade_earlier,
        },
    )
    assert granted.status_code == 303, granted.text
    extension = stores.courses.extensions(homework.id)[f"course:{course}:s002"]
    note = f"extended to {shown(due, 'Europe/Paris')}" + since.format(
        granted=shown(extension.granted_at, "Europe/Paris") if extension.granted_at else ""
    )
    book = signed_in.get(f"/instructor/courses/{course}/gradebook").text
    disclosures = re.findall(r'<details class="extension"><summary>(.*?)</summary>(.*?)</details>', book)
    assert disclosures == [
        (
            '<span class="badge" aria-hidden="true">ext.</span><span class="visually-hidden">Extension</span>',
            note,
        )
    ]
