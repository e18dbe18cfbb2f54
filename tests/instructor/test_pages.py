"""The instructor pages through the real app: who may sign in and how (a signed cookie, CSRF on every
POST), scoping (an LMS instructor session acts only for itself), and what each page shows."""

from __future__ import annotations

import csv
import html
import io
import re
import shutil
from datetime import timedelta
from pathlib import Path

import pytest
import yaml
from fastapi.testclient import TestClient

from app.db.records import Role
from app.db.types import utc_now
from app.grading.pool import GradingPool
from app.instructor.router import yaml_text
from app.instructor.session import COOKIE
from app.lti import outbox
from app.lti.sessions import SESSION_COOKIE, open_session
from app.settings import Settings
from app.storage import Stores
from physics.numeric import round_sigfigs
from physics.verdict import Outcome, ReadAs, Reason, Verdict
from problems.loader import BANK_DIR
from problems.variants import format_quantity
from tests.instructor.conftest import csrf_of, make_app, new_key, sign_in, stores_of
from tests.lti.fake_lms import register_fake_lms

PROBLEM = "yo-yo"


def upload_text(problem_id: str = "my-yoyo", title: str = "My yo-yo") -> str:
    doc = yaml.safe_load((BANK_DIR / "yo-yo" / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK_DIR / "yo-yo" / "model.yaml").read_text())
    doc["id"], doc["title"] = problem_id, title
    return yaml_text(doc)


def lms_session(stores: Stores, role: Role, sub: str = "lee") -> str:
    register_fake_lms(stores)
    [platform] = stores.platforms.list()
    cookie, _ = open_session(
        stores.lti_sessions, platform_id=platform.id, sub=sub, role=role, name="Lee", now=utc_now()
    )
    return cookie


def file_submissions(stores: Stores, rows: list[tuple[str, str, str, Verdict]]) -> None:
    for student, part, answer, verdict in rows:
        stores.submissions.file(
            problem_id=PROBLEM,
            problem_version=1,
            part_id=part,
            student=student,
            answer=answer,
            verdict=verdict,
            max_attempts=None,
        )


RIGHT = Verdict(Outcome.CORRECT, 1.0, Reason.EQUIVALENT, "Correct.", ReadAs("g", "g"))
FREE_FALL = Verdict(
    Outcome.INCORRECT,
    0.0,
    Reason.KNOWN_MISTAKE,
    "The string pulls up on the yo-yo, so its centre falls more slowly than in free fall.",
    ReadAs("g", "g"),
)


# ---- signing in ---------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "path", ["/instructor/problems", "/instructor/problems/yo-yo", "/instructor/submissions"]
)
def test_without_a_session_every_page_sends_the_browser_to_sign_in(client: TestClient, path: str):
    response = client.get(path)
    assert response.status_code == 303
    assert response.headers["location"].startswith("/instructor/sign-in?next=")


def test_instructor_key_signs_in_with_a_signed_httponly_strict_cookie(
    client: TestClient, instructor_key: str
):
    response = sign_in(client, instructor_key, "/instructor/problems/yo-yo")
    assert response.status_code == 303
    assert response.headers["location"] == "/instructor/problems/yo-yo"
    cookie = next(c for c in response.headers.get_list("set-cookie") if c.startswith(COOKIE + "="))
    assert "HttpOnly" in cookie and "SameSite=strict" in cookie and "Path=/instructor" in cookie
    assert instructor_key not in cookie
    assert client.get("/instructor/problems").status_code == 200


def test_a_new_instructor_lands_on_their_courses_with_a_guide_to_begin(
    client: TestClient, instructor_key: str
):
    form = client.get("/instructor/sign-in")  # as typed: no page asked for first
    response = client.post("/instructor/sign-in", data={"key": instructor_key, "csrf": csrf_of(form.text)})
    assert response.status_code == 303 and response.headers["location"] == "/instructor/courses"
    assert client.get("/instructor").headers["location"] == "/instructor/courses"
    first = client.get("/instructor/courses").text
    assert "Start here" in first and "Create the course" in first and "Add an assignment" in first
    client.post("/instructor/courses", data={"csrf": csrf_of(first), "title": "Mechanics", "timezone": "UTC"})
    assert "Start here" not in client.get("/instructor/courses").text  # once there is a course, its card


@pytest.mark.parametrize(
    ("role", "status", "message"),
    [("student", 403, "This is a student key"), (None, 401, "unknown or revoked")],
)
def test_student_or_unknown_key_is_refused_at_sign_in(
    client: TestClient, stores: Stores, role: str | None, status: int, message: str
):
    key = new_key(stores, role, "bob", student="bob") if role else "pck_not-a-key"
    response = sign_in(client, key)
    assert response.status_code == status
    assert message in response.text
    assert COOKIE not in client.cookies
    assert client.get("/instructor/problems").status_code == 303


def test_sign_in_without_the_forms_token_is_refused(client: TestClient, instructor_key: str):
    client.get("/instructor/sign-in")
    forged = client.post("/instructor/sign-in", data={"key": instructor_key, "csrf": "0" * 64})
    assert forged.status_code == 403
    missing = client.post("/instructor/sign-in", data={"key": instructor_key})
    assert missing.status_code == 403
    assert COOKIE not in client.cookies


def test_a_cookie_altered_to_name_another_key_is_no_session(signed_in: TestClient, stores: Stores):
    other = new_key(stores, "instructor", "someone else")
    assert other
    value = signed_in.cookies[COOKIE]
    key_id, rest = value.split(".", 1)
    signed_in.cookies.set(COOKIE, f"{int(key_id) + 1}.{rest}", path="/instructor")
    assert signed_in.get("/instructor/problems").status_code == 303


def test_revoking_the_key_signs_its_browser_out(signed_in: TestClient, stores: Stores):
    key_id = int(signed_in.cookies[COOKIE].split(".")[0])
    stores.keys.revoke(key_id)
    assert signed_in.get("/instructor/problems").status_code == 303


def test_every_post_needs_the_sessions_csrf_token(signed_in: TestClient):
    page = signed_in.get("/instructor/problems/new")
    token = csrf_of(page.text)
    for data in ({"source": upload_text(), "action": "save"}, {"csrf": "x" * 64, "source": upload_text()}):
        refused = signed_in.post("/instructor/problems/new", data=data)
        assert refused.status_code == 403
        assert "Form expired" in refused.text
    assert signed_in.post("/instructor/sign-out", data={}).status_code == 403
    assert signed_in.get("/instructor/problems").status_code == 200  # still signed in
    out = signed_in.post("/instructor/sign-out", data={"csrf": token})
    assert out.status_code == 303
    assert signed_in.get("/instructor/problems").status_code == 303


# ---- scoping: LMS sessions ----------------------------------------------------------------------------


def test_lms_instructor_session_sees_problems_but_no_students_work(client: TestClient, stores: Stores):
    client.cookies.set(SESSION_COOKIE, lms_session(stores, Role.INSTRUCTOR))
    listing = client.get("/instructor/problems")
    assert listing.status_code == 200
    assert "Lee (from your LMS)" in listing.text and "Sign out" not in listing.text
    assert "/instructor/problems/new" not in listing.text  # no upload link
    own = client.get("/instructor/problems/yo-yo")
    assert own.status_code == 200 and "Worked solutions" in own.text
    for path in (
        "/instructor/problems/yo-yo?student=ada",
        "/instructor/problems/yo-yo/results",
        "/instructor/submissions",
        "/instructor/submissions.csv",
        "/instructor/deliveries",
        "/instructor/problems/new",
    ):
        response = client.get(path)
        assert response.status_code == 403, path
        assert "API key" in response.text


def test_lms_student_session_is_refused(client: TestClient, stores: Stores):
    client.cookies.set(SESSION_COOKIE, lms_session(stores, Role.STUDENT, sub="stu"))
    response = client.get("/instructor/problems")
    assert response.status_code == 403
    assert "For instructors only" in response.text


# ---- problems -----------------------------------------------------------------------------------------


def test_problem_page_renders_references_mistakes_limits_and_every_method_as_mathml(signed_in: TestClient):
    html = signed_in.get("/instructor/problems/yo-yo").text
    assert html.count("<math") > 20
    assert 'alttext="\\frac{g r^{2}}{k^{2} + r^{2}}"' in html  # the acceleration's reference
    for method in ("Lagrange", "Newton", "Conservation"):
        assert method in html
    assert "The string pulls up on the yo-yo" in html  # a known mistake's feedback
    assert "with no moment of inertia the yo-yo falls freely" in html  # a limiting case
    assert "energy balance" in html and "in a numerical simulation" in html  # the model's own checks
    assert "$" not in re.sub(r'alttext="[^"]*"', "", html)  # no TeX left as text
    figure = re.search(r'<figure class="problem-figure">\s*<svg[^>]*role="img"', html)
    assert figure, "the figure drawn from the model"


def test_problem_page_shows_the_forces_on_each_body_beside_the_worked_solutions(signed_in: TestClient):
    html = signed_in.get("/instructor/problems/yo-yo").text
    solutions = html[html.index("Worked solutions") :]
    diagrams = re.findall(
        r'<figure class="free-body">\s*<svg[^>]*role="img".*?<desc[^>]*>([^<]*)</desc>', solutions, re.S
    )
    assert len(diagrams) == 1, "one diagram per body of the model"
    assert "Forces on" in diagrams[0] and "T at 90°" in diagrams[0], diagrams  # the string pulls straight up


def test_a_rod_on_an_axle_shows_the_axle_holding_it_in_its_free_body_diagram(
    settings: Settings, pages_pool: GradingPool, tmp_path: Path
) -> None:
    """The axle's force, which the problem asks for, was missing: the diagram showed the weight alone."""
    shutil.copytree(BANK_DIR / "physical-pendulum", tmp_path / "physical-pendulum")
    with TestClient(make_app(settings.model_copy(update={"bank_dir": tmp_path}), pages_pool)) as client:
        sign_in(client, new_key(stores_of(client), "instructor", "Prof Ada"))
        html = client.get("/instructor/problems/physical-pendulum").text
    diagrams = re.findall(
        r'<figure class="free-body">\s*<svg[^>]*role="img".*?<desc[^>]*>([^<]*)</desc>', html, re.S
    )
    # the axle's force, named R as the solutions name its components R_x and R_y
    assert len(diagrams) == 1 and "R at 90°" in diagrams[0] and "mg at -90°" in diagrams[0], diagrams


def test_each_free_body_diagram_is_captioned_with_its_body_and_all_are_drawn_at_one_scale(
    settings: Settings, pages_pool: GradingPool, tmp_path: Path
) -> None:
    """Nothing said which body each diagram showed, and each was scaled to its own box, so a lone
    weight's arrow could look longer than another body's heavier load."""
    shutil.copytree(BANK_DIR / "moving-wedge", tmp_path / "moving-wedge")
    with TestClient(make_app(settings.model_copy(update={"bank_dir": tmp_path}), pages_pool)) as client:
        sign_in(client, new_key(stores_of(client), "instructor", "Prof Ada"))
        html = client.get("/instructor/problems/moving-wedge/solution").text
    figures = re.findall(
        r'<figure class="free-body">\s*<svg[^>]*viewBox="\S+ \S+ ([\d.]+) [\d.]+"[^>]*width="(\d+)"'
        r".*?</svg><figcaption>(.*?)</figcaption>",
        html,
        re.S,
    )
    # each body's words and its own mass, the symbol read by its MathML's alttext
    captions = sorted(
        re.sub(r'<math[^>]*alttext="([^"]*)".*?</math>', r"\1", c, flags=re.S) for *_, c in figures
    )
    assert captions == ["the block m", "the wedge M"], captions
    scales = {round(int(pixels) / float(units)) for units, pixels, _ in figures}
    assert len(scales) == 1, scales


def test_a_students_variant_shows_their_values_and_expected_numbers(signed_in: TestClient):
    services = signed_in.app.state.services  # type: ignore[attr-defined]
    record = services.catalog.get(PROBLEM)
    variant = services.catalog.variant(record, "ada")
    compiled = services.catalog.compiled(record)
    expected = compiled.parts["acceleration_numeric"].reference(variant)
    html = signed_in.get("/instructor/problems/yo-yo", params={"student": "ada"}).text
    assert "Showing the variant of <strong>ada</strong>" in html
    for name, value in variant.values.items():
        assert format_quantity(value, record.document["given"][name]["unit"]) in html
    assert format_quantity(round_sigfigs(expected, 4), "m/s^2") in html
    other = signed_in.get("/instructor/problems/yo-yo", params={"student": "bob"}).text
    assert format_quantity(round_sigfigs(expected, 4), "m/s^2") not in other or variant.values == (
        services.catalog.variant(record, "bob").values
    )


def test_unknown_problem_is_a_404_page(signed_in: TestClient):
    response = signed_in.get("/instructor/problems/no-such-thing")
    assert response.status_code == 404
    assert "No such problem" in response.text


# ---- upload and edit ----------------------------------------------------------------------------------


def test_a_new_problem_starts_from_a_built_in_ones_files_under_a_new_id_and_saves(signed_in: TestClient):
    # the upload page had offered a blank box and a file name (problems/FORMAT.md) it did not serve
    blank = signed_in.get("/instructor/problems/new")
    assert "Start a new problem from this one" in blank.text  # where to find the examples
    assert 'href="/instructor/problems/new?from=yo-yo"' in signed_in.get("/instructor/problems/yo-yo").text
    started = signed_in.get("/instructor/problems/new", params={"from": "yo-yo"})
    assert started.status_code == 200
    source = html.unescape(re.search(r"<textarea[^>]*>(.*?)</textarea>", started.text, re.S).group(1))
    assert source.startswith("id: yo-yo-copy\n") and "\nmodel:\n  " in source
    assert "  #" in source  # the model's comments, as its author wrote them
    saved = signed_in.post(
        "/instructor/problems/new", data={"csrf": csrf_of(started.text), "source": source, "action": "save"}
    )
    assert saved.status_code == 303 and saved.headers["location"] == "/instructor/problems/yo-yo-copy?saved=1"
    for missing in ("no-such", "../yo-yo", "yo-yo-copy"):  # an upload is edited as a new version instead
        assert signed_in.get("/instructor/problems/new", params={"from": missing}).status_code == 404


def test_upload_shows_every_error_with_its_path_and_line_then_previews_then_saves(signed_in: TestClient):
    token = csrf_of(signed_in.get("/instructor/problems/new").text)
    broken = (
        upload_text()
        .replace("kind: numeric", "kind: numeric\n  tolerance: {rel: -1}")
        .replace("title: My yo-yo\n", "")
    )
    response = signed_in.post(
        "/instructor/problems/new", data={"csrf": token, "source": broken, "action": "preview"}
    )
    assert response.status_code == 422
    lines = broken.splitlines()
    rel_line = next(i for i, line in enumerate(lines, 1) if "tolerance: {rel: -1}" in line)
    assert '<code class="path">title</code>' in response.text
    assert (
        f'<code class="path">parts[2].tolerance.rel</code> <a class="line" href="#source" data-line="{rel_line}">'
        in (response.text)
    )
    assert "nothing was saved" in response.text
    assert "tolerance: {rel: -1}" in response.text  # the text is kept beside its errors

    preview = signed_in.post(
        "/instructor/problems/new", data={"csrf": token, "source": upload_text(), "action": "preview"}
    )
    assert preview.status_code == 200, preview.text
    assert "Preview: no errors" in preview.text
    assert 'alttext="\\frac{g r^{2}}{k^{2} + r^{2}}"' in preview.text  # the derived answer
    assert "Lagrange" in preview.text
    assert re.search(r'<figure class="problem-figure">\s*<svg', preview.text)
    assert signed_in.get("/instructor/problems/my-yoyo").status_code == 404  # nothing stored yet

    saved = signed_in.post(
        "/instructor/problems/new", data={"csrf": token, "source": upload_text(), "action": "save"}
    )
    assert saved.status_code == 303
    assert saved.headers["location"] == "/instructor/problems/my-yoyo?saved=1"
    page = signed_in.get(saved.headers["location"])
    assert "Saved as version 1." in page.text and "Edit (new version)" in page.text


def test_uploaded_file_is_used_and_a_taken_id_is_reported(signed_in: TestClient):
    token = csrf_of(signed_in.get("/instructor/problems/new").text)
    response = signed_in.post(
        "/instructor/problems/new",
        data={"csrf": token, "source": "", "action": "save"},
        files={"file": ("yo.yaml", upload_text("yo-yo").encode(), "application/yaml")},
    )
    assert response.status_code == 409
    assert "this id is already taken" in response.text
    assert "title: My yo-yo" in response.text  # the file's text is now in the box


def test_edit_saves_a_new_version_through_the_same_path_as_the_api(
    signed_in: TestClient, instructor_key: str, stores: Stores
):
    token = csrf_of(signed_in.get("/instructor/problems/new").text)
    signed_in.post(
        "/instructor/problems/new", data={"csrf": token, "source": upload_text(), "action": "save"}
    )
    form = signed_in.get("/instructor/problems/my-yoyo/edit")
    assert form.status_code == 200 and "My yo-yo" in form.text
    saved = signed_in.post(
        "/instructor/problems/my-yoyo/edit",
        data={"csrf": token, "source": upload_text(title="My yo-yo, again"), "action": "save"},
    )
    assert saved.headers["location"] == "/instructor/problems/my-yoyo?saved=2"
    api = signed_in.get("/v1/problems/my-yoyo", headers={"Authorization": f"Bearer {instructor_key}"})
    assert api.json()["title"] == "My yo-yo, again" and api.json()["version"] == 2
    # Another instructor may not edit it, nor anyone the built-in bank.
    assert signed_in.get("/instructor/problems/yo-yo/edit").status_code == 403
    signed_in.cookies.clear()
    sign_in(signed_in, new_key(stores, "instructor", "Other"))
    assert signed_in.get("/instructor/problems/my-yoyo/edit").status_code == 403


# ---- class results, submissions, deliveries -----------------------------------------------------------


def test_class_results_show_counts_charts_and_tables_without_instructors_tries(
    signed_in: TestClient, stores: Stores
):
    file_submissions(
        stores,
        [
            ("ada", "acceleration", "g", FREE_FALL),
            ("ada", "acceleration", "g r^2/(r^2+k^2)", RIGHT),
            ("bob", "acceleration", "g", FREE_FALL),
            ("cy", "acceleration", "g r^2/(r^2+k^2)", RIGHT),
            ("preview:1", "acceleration", "g", FREE_FALL),
        ],
    )
    html = signed_in.get("/instructor/problems/yo-yo/results").text
    assert "2 of 3 (67 %)" in html  # the overview chart's bar for part 1
    # The overview, and three charts for the one part tried (the untried parts say so instead).
    assert html.count('role="img"') == 1 + 3
    assert html.count("No student has answered this part yet.") == 2
    assert '<title id="part-0-mistakes-title">Part 1: wrong answers by known mistake</title>' in html
    assert re.search(r"<strong>3</strong> students tried; <strong>2</strong> answered correctly", html)
    assert "Instructors' tries, not counted: 1." in html
    row = re.search(r"The string pulls up on the yo-yo[^<]*</td><td>(\d+)</td><td>(\d+)</td>", html)
    assert row and row.groups() == ("2", "2")


def test_submissions_are_filtered_by_student_and_downloaded_as_csv(signed_in: TestClient, stores: Stores):
    file_submissions(
        stores,
        [("ada", "acceleration", "g", FREE_FALL), ("bob", "tension", "m g", FREE_FALL)],
    )
    html = signed_in.get("/instructor/submissions", params={"student": "ada"}).text
    assert ">ada</a>" in html and ">bob</a>" not in html
    title = stores.problems.get(PROBLEM).document["title"]
    assert f'<a href="/instructor/problems/{PROBLEM}">{title}</a> · acceleration' in html  # by title, not id
    assert f'<option value="{PROBLEM}">{title}</option>' in html
    assert 'href="/instructor/submissions.csv?student=ada"' in html
    response = signed_in.get("/instructor/submissions.csv", params={"student": "ada"})
    assert response.headers["content-type"].startswith("text/csv")
    assert "attachment" in response.headers["content-disposition"]
    rows = list(csv.reader(io.StringIO(response.text)))
    assert rows[0][:3] == ["submission_id", "created_at", "problem"]
    assert [(r[5], r[6]) for r in rows[1:]] == [("ada", "g")]


def test_delivery_problems_show_what_the_lms_said(signed_in: TestClient, stores: Stores):
    register_fake_lms(stores)
    [platform] = stores.platforms.list()
    stores.outbox.add_target(
        platform, student="lti:1:ada", problem_id=PROBLEM, lineitem_url="https://lms/li/1", sub="ada"
    )
    # Due only in an hour, so the app's own outbox worker leaves it to this test to claim.
    later = utc_now() + timedelta(hours=1)
    stores.outbox.enqueue(PROBLEM, "lti:1:ada", 1.0, 3.0, later)
    [score] = stores.outbox.claim("test", later, 1)
    stores.outbox.finish(score, outbox.Outcome(outbox.FAILED, 422, "<b>Line item is closed</b>"), later)
    html = signed_in.get("/instructor/deliveries").text
    assert "HTTP 422" in html and "lti:1:ada" in html and "1 / 3" in html
    assert "&lt;b&gt;Line item is closed&lt;/b&gt;" in html  # the LMS's words, escaped


def test_problem_list_links_each_problem_and_its_results(signed_in: TestClient):
    html = signed_in.get("/instructor/problems").text
    assert 'href="/instructor/problems/yo-yo"' in html
    assert 'href="/instructor/problems/yo-yo/results"' in html
    assert "Yo-yo unwinding from a fixed string" in html


def test_pages_are_served_with_a_strict_content_security_policy(signed_in: TestClient):
    response = signed_in.get("/instructor/problems")
    assert "script-src 'self'" in response.headers["content-security-policy"]
    assert "frame-ancestors 'self'" in response.headers["content-security-policy"]


def test_preview_lists_texts_that_will_not_render_cleanly_with_their_lines(signed_in: TestClient):
    token = csrf_of(signed_in.get("/instructor/problems/new").text)
    source = upload_text().replace("Use $g$ for", r"Use $\gravity$ for")
    line = next(i for i, text in enumerate(source.splitlines(), 1) if text.startswith("statement:"))
    preview = signed_in.post(
        "/instructor/problems/new", data={"csrf": token, "source": source, "action": "preview"}
    )
    assert preview.status_code == 200
    assert "1 text will not render cleanly" in preview.text
    assert (
        f'<code class="path">statement</code> <a class="line" href="#source" data-line="{line}">line {line}</a>'
        in preview.text
    )


def test_behind_https_the_session_cookie_is_secure(settings, pages_pool):
    secure = settings.model_copy(update={"base_url": "https://physcheck.example"})
    app = make_app(secure, pages_pool)
    with TestClient(app, base_url="https://testserver", follow_redirects=False) as client:
        response = sign_in(client, new_key(stores_of(client), "instructor", "Prof"))
    cookie = next(c for c in response.headers.get_list("set-cookie") if c.startswith(COOKIE + "="))
    assert "Secure" in cookie


def test_a_limiting_case_is_not_described_by_restating_it(
    settings: Settings, pages_pool: GradingPool, tmp_path: Path
) -> None:
    """The engine describes a bare angle's limit as `θ → 0`; the page had shown "θ → 0: θ → 0"."""
    shutil.copytree(BANK_DIR / "moving-wedge", tmp_path / "moving-wedge")
    with TestClient(make_app(settings.model_copy(update={"bank_dir": tmp_path}), pages_pool)) as client:
        sign_in(client, new_key(stores_of(client), "instructor", "Prof Ada"))
        html = client.get("/instructor/problems/moving-wedge").text
    words = []
    for section in html.split("Limiting cases")[1:]:
        items = re.findall(r"<li>(.*?)</li>", section[: section.index("</ul>")], re.S)
        words += [re.sub(r"<math.*?</math>", "", item, flags=re.S).strip() for item in items]
    assert "" in words, f"a bare angle's limit is its formula alone: {words}"
    assert not any(text.endswith("→ 0") for text in words), words
    assert any(text.startswith(": ") and len(text) > 2 for text in words), (
        f"described ones keep words: {words}"
    )
