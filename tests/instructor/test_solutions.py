"""Worked solutions: instructors always see them (on the problem page and as a hand-out to print); a
student sees one only once it is released to them (app/web/solution_access.py, the one gate)."""

from __future__ import annotations

import html
import re

import pytest
from fastapi.testclient import TestClient

from app.storage import Stores
from app.web.solution_access import solution_release
from app.web.student_work import PartWork, ProblemWork
from tests.bank import bank_documents
from tests.instructor.conftest import csrf_of, new_key
from tests.instructor.test_pages import FREE_FALL, RIGHT, file_submissions

PARTS = ("acceleration", "tension", "acceleration_numeric")


def _work(**parts: PartWork) -> ProblemWork:
    return ProblemWork({part: parts.get(part, PartWork()) for part in PARTS})


DONE = PartWork(used=1, best=1.0)
OUT_OF_ATTEMPTS = PartWork(used=3, limit=3, best=0.0)
TRYING = PartWork(used=1, limit=3, best=0.0)

RELEASES = [
    # (what, the document's `solutions`, the student's work, released?)
    ("nothing tried", "after_attempts", _work(), False),
    ("every part solved", "after_attempts", _work(**dict.fromkeys(PARTS, DONE)), True),
    (
        "solved or out of attempts",
        "after_attempts",
        _work(acceleration=OUT_OF_ATTEMPTS, tension=DONE, acceleration_numeric=DONE),
        True,
    ),
    (
        "one part still has attempts",
        "after_attempts",
        _work(acceleration=TRYING, tension=DONE, acceleration_numeric=DONE),
        False,
    ),
    ("released by the document", "always", _work(), True),
    ("never, however done", "never", _work(**dict.fromkeys(PARTS, DONE)), False),
]


@pytest.mark.parametrize(("what", "policy", "work", "released"), RELEASES, ids=[r[0] for r in RELEASES])
def test_the_gate_releases_a_solution_only_as_the_problem_says(
    what: str, policy: str, work: ProblemWork, released: bool
) -> None:
    doc = bank_documents()["yo-yo"].model_copy(update={"solutions": policy})
    release = solution_release(doc, work)
    assert release.released is released, what
    assert release.why  # the student is told why, either way


def _student(stores: Stores, name: str) -> dict[str, str]:
    return {"Authorization": "Bearer " + new_key(stores, "student", name, student=name)}


def test_a_student_sees_no_solution_before_it_is_released(client: TestClient, stores: Stores) -> None:
    page = client.get("/p/yo-yo/solution/content", headers=_student(stores, "ada"))
    assert page.status_code == 200
    assert "Not released yet" in page.text and "parts 1, 2, 3 still open" in page.text
    assert (
        "Lagrange" not in page.text and "The methods compared" not in page.text and "<math" not in page.text
    )


def test_a_student_who_has_solved_every_part_sees_the_solution_with_their_values(
    client: TestClient, stores: Stores
) -> None:
    file_submissions(stores, [("bo", part, "x", RIGHT) for part in PARTS])
    page = client.get("/p/yo-yo/solution/content", headers=_student(stores, "bo"))
    assert page.status_code == 200
    text = html.unescape(page.text)
    assert "Not released yet" not in text
    for said in (
        "The methods compared",
        "Newton's laws",
        "Lagrange's equations",
        "Which method, and why",
        "Set-up",
        "Count:",
        "Answers",
    ):
        assert said in text, said
    assert "Check with the values of this variant" in text  # the method's result at bo's values


def test_the_solution_needs_a_student(client: TestClient) -> None:
    assert client.get("/p/yo-yo/solution/content").status_code == 401
    page = client.get("/p/yo-yo/solution")  # no session: the page asks for a key, shows nothing
    assert page.status_code == 200 and 'id="key-form"' in page.text and "<math" not in page.text
    assert 'data-content="/p/yo-yo/solution/content"' in page.text


def test_an_unknown_problem_has_no_solution(client: TestClient, stores: Stores) -> None:
    assert client.get("/p/no-such/solution/content", headers=_student(stores, "cy")).status_code == 404


def test_an_instructor_has_the_hand_out_and_the_link_to_post(signed_in: TestClient) -> None:
    problem = signed_in.get("/instructor/problems/yo-yo").text
    assert 'href="/instructor/problems/yo-yo/solution"' in problem
    assert 'href="/p/yo-yo/solution"' in problem
    hand_out = signed_in.get("/instructor/problems/yo-yo/solution")
    assert hand_out.status_code == 200
    assert "The methods compared" in hand_out.text and "Forces on each body" in hand_out.text
    assert "answered every part correctly or used its last attempt" in hand_out.text


def test_the_problem_page_shows_the_comparison_and_numbered_equations(signed_in: TestClient) -> None:
    page = signed_in.get("/instructor/problems/yo-yo").text
    assert '<section class="comparison"' in page
    assert '<span class="eqno">(1.1)</span>' in page
    assert "lambda" not in page and "y_yoyo" not in page and "g_k" not in page


def test_the_hand_outs_caption_points_to_blue_arrows_only_when_the_figure_draws_them(
    signed_in: TestClient, monkeypatch: pytest.MonkeyPatch
) -> None:
    # the caption had promised blue coordinate arrows under every figure; most draw none
    said = "Blue arrows mark the coordinates"
    assert said in signed_in.get("/instructor/problems/yo-yo/solution").text  # the yo-yo's y, drawn
    catalog = signed_in.app.state.services.catalog  # type: ignore[attr-defined]
    plain = '<svg xmlns="http://www.w3.org/2000/svg" role="img"><desc>A block on a slope.</desc></svg>'
    monkeypatch.setattr(catalog, "figure", lambda problem_id, student: plain)
    hand_out = signed_in.get("/instructor/problems/yo-yo/solution").text
    assert "A block on a slope." in hand_out and said not in hand_out


def test_a_course_students_solution_page_leads_back_to_their_courses(
    signed_in: TestClient, stores: Stores
) -> None:
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec

    made = signed_in.post(
        "/instructor/courses",
        data={"csrf": csrf_of(signed_in.get("/instructor/courses").text), "title": "Mechanics"},
    )
    course = int(made.headers["location"].rsplit("/", 1)[1])
    now = datetime.now(UTC)
    stores.courses.create_assignment(
        course, AssignmentSpec("HW 1", ("yo-yo",), now - timedelta(days=1), now + timedelta(days=1))
    )
    page = signed_in.get(f"/instructor/courses/{course}")
    signed_in.post(
        f"/instructor/courses/{course}/join-code", data={"csrf": csrf_of(page.text), "enabled": "1"}
    )
    student = TestClient(signed_in.app, follow_redirects=False)
    student.post(f"/join/{stores.courses.get_course(course).join_code}", data={"name": "Ada"})
    nav = student.get("/p/yo-yo/solution").text.split("<main", 1)[0]
    assert 'href="/courses"' in nav and 'href="/problems"' not in nav  # as the problem page's nav
    keyed = TestClient(signed_in.app).get("/p/yo-yo/solution").text  # a key's student: their problems
    assert 'href="/problems"' in keyed.split("<main", 1)[0]


def test_the_problem_page_says_when_the_solution_is_released_and_after_the_answer_that_releases_it(
    client: TestClient, stores: Stores
) -> None:
    # the link had kept saying "shown once it is released" after it was
    headers = _student(stores, "di")
    assert "shown once it is released" in client.get("/p/yo-yo/content", headers=headers).text
    file_submissions(stores, [("di", part, "x", RIGHT) for part in PARTS])
    page = client.get("/p/yo-yo/content", headers=headers).text
    assert 'id="solution-link"' in page and "released to you" in page and "shown once" not in page
    work = client.get("/p/yo-yo/parts/tension/work", headers=headers).text  # fetched after an answer
    assert 'id="solution-link"' in work and "released to you" in work


def _late_course_student(
    signed_in: TestClient, stores: Stores, max_attempts: int | None = None
) -> tuple[TestClient, int, str]:
    """A course whose assignment (yo-yo, solutions after the due date) is past due and still takes
    late work, and a student who joined it: (their browser, the course id, their identity)."""
    from datetime import UTC, datetime, timedelta

    from app.courses.records import AssignmentSpec, LateKind, LatePolicy

    made = signed_in.post(
        "/instructor/courses",
        data={"csrf": csrf_of(signed_in.get("/instructor/courses").text), "title": "Mechanics"},
    )
    course = int(made.headers["location"].rsplit("/", 1)[1])
    now = datetime.now(UTC)
    late = LatePolicy(LateKind.PENALTY, 0.1, 0.5)
    stores.courses.create_assignment(
        course,
        AssignmentSpec(
            "HW 1", ("yo-yo",), now - timedelta(days=2), now - timedelta(hours=1), late, max_attempts
        ),
    )
    page = signed_in.get(f"/instructor/courses/{course}")
    signed_in.post(
        f"/instructor/courses/{course}/join-code", data={"csrf": csrf_of(page.text), "enabled": "1"}
    )
    student = TestClient(signed_in.app, follow_redirects=False)
    student.post(f"/join/{stores.courses.get_course(course).join_code}", data={"name": "Ada"})
    [enrolment] = stores.courses.roster(course)
    return student, course, enrolment.student


def test_late_work_earns_nothing_once_the_student_has_opened_the_worked_solution(
    signed_in: TestClient, stores: Stores
) -> None:
    # a solution open "after the due date" with late work accepted had been read and copied for credit
    student, course, who = _late_course_student(signed_in, stores)
    asked = student.get("/p/yo-yo/solution").text
    assert "stays as it is now" in asked and 'id="solution-answers"' not in asked  # asked first
    assert '<p class="actions"><button type="submit">Open the worked solution' in asked  # apart from "Back"
    file_submissions(stores, [(who, "acceleration", "g", RIGHT)])  # before opening: counts, late
    assert student.post("/p/yo-yo/solution", data={"csrf": "forged"}).status_code == 403
    assert stores.courses.solutions_opened(who) == {}
    opened = student.post("/p/yo-yo/solution", data={"csrf": csrf_of(asked)})
    assert opened.status_code == 303 and "yo-yo" in stores.courses.solutions_opened(who)
    shown = student.get("/p/yo-yo/solution").text
    assert 'id="solution-answers"' in shown and "You opened this worked solution on" in shown
    file_submissions(stores, [(who, "tension", "g", RIGHT)])  # after: checked, earns nothing

    problem = student.get("/p/yo-yo").text
    # on every part, the one solved late before opening too: it stays at its late score
    assert problem.count("Your grade on this part is frozen") == 3
    assert "Your grade on this part is frozen at 0.9 of 1" in problem
    book = signed_in.get(f"/instructor/courses/{course}/gradebook").text
    assert "solution read" in book
    csv_text = signed_in.get(f"/instructor/courses/{course}/gradebook.csv").text
    assert ",0.9,0.9," in csv_text and "HW 1: grade frozen, worked solution opened (yo-yo at" in csv_text


def test_a_solution_with_nothing_left_to_earn_opens_at_once_recorded_and_costing_nothing(
    signed_in: TestClient, stores: Stores
) -> None:
    # out of attempts on every part (a part solved late is not "nothing left": test_assignment_credit)
    student, _, who = _late_course_student(signed_in, stores, max_attempts=1)
    file_submissions(stores, [(who, part, "g", FREE_FALL) for part in PARTS])
    before = re.search(r"Your score: <strong>[^<]*</strong>", student.get("/p/yo-yo").text)
    shown = student.get("/p/yo-yo/solution").text
    assert 'id="solution-answers"' in shown and "stays as it is now" not in shown  # not asked first
    assert "yo-yo" in stores.courses.solutions_opened(who)  # every opening is kept (an extension may follow)
    after = student.get("/p/yo-yo").text
    assert before is not None and before.group(0) in after


def test_after_an_answer_the_attempts_are_said_once_in_the_verdict_and_shown_in_the_standing(
    client: TestClient, stores: Stores
) -> None:
    # a screen reader heard "Attempts: 1 used" twice: in the verdict's live region and the standing
    headers = _student(stores, "ed")
    fresh = client.get("/p/yo-yo/content", headers=headers).text
    assert '<span class="attempts">Attempts: 0 used' in fresh  # no verdict yet: the standing says it
    file_submissions(stores, [("ed", "tension", "x", RIGHT)])
    work = client.get("/p/yo-yo/parts/tension/work", headers=headers).text
    assert '<span class="visually-hidden">Attempts: 1 used.</span>' in work  # said with the verdict
    assert '<span class="attempts" aria-hidden="true">Attempts: 1 used' in work  # and only shown here


def test_the_comparison_names_the_parts_each_method_answers_by_their_numbers(signed_in: TestClient) -> None:
    # A hand-out's reader sees the answers numbered 1, 2, …, never the parts' ids
    hand_out = signed_in.get("/instructor/problems/yo-yo/solution").text
    comparison = hand_out[hand_out.index('<section class="comparison"') :]
    comparison = comparison[: comparison.index("</table>")]
    answered = re.findall(r'data-label="Parts it answers"><span>([^<]*)</span>', comparison)
    assert answered and "acceleration" not in comparison
    assert all(re.fullmatch(r"\d(, \d)*", cell) for cell in answered), answered
    # Newton's laws give the acceleration and the tension, parts 1 and 2; the energy the acceleration
    assert {"1, 2", "1"} <= set(answered), answered


def test_the_checks_at_the_variants_values_name_each_part_by_its_number(signed_in: TestClient) -> None:
    # they named the part by its id, `acceleration_numeric`, which a hand-out's reader never sees
    hand_out = signed_in.get("/instructor/problems/yo-yo/solution").text
    checks = re.findall(r'<ul class="checks">(.*?)</ul>', hand_out, re.S)
    assert checks and "acceleration_numeric" not in hand_out
    assert all(re.findall(r"<li>Part 3: ", found) for found in checks), (
        checks
    )  # acceleration_numeric is third


def test_why_a_method_answers_no_part_names_the_parts_by_their_numbers_saying_each_reason_once() -> None:
    # "slow_frequency: Cartesian normal modes …", then the same for fast_frequency and slow_shape: the
    # engine's names for its quantities, which a hand-out's reader never sees, and one reason thrice
    from app.instructor.described import describe
    from problems.compiled import compile_problem

    described = describe(compile_problem(bank_documents()["double-pendulum"]))
    newton = next(m for m in described.methods if m.name == "newton")
    assert newton.notes == (
        "Parts 1, 2, 3 and 4: Cartesian normal modes are done here only without constraints",
    )
