"""The OpenAPI document tells the truth: every status it documents for an endpoint is provoked here, and
the body the endpoint answers validates against the documented schema (jsonschema, the document's own
components). A status documented without a way to provoke it below fails too: add one."""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from datetime import timedelta
from typing import Any

import httpx
import jsonschema
import pytest
import yaml
from fastapi.testclient import TestClient
from sqlalchemy.exc import OperationalError

from app.auth import Role
from app.courses.records import AssignmentSpec, RosterRow, StaffRole
from app.db import problems as problem_repository
from app.db.database import Database
from app.db.types import utc_now
from app.keys import create_key
from app.lti.sessions import CSRF_HEADER, SESSION_COOKIE, open_session
from app.main import create_app
from app.ratelimit import MemoryRateLimiter
from app.settings import Settings
from app.storage import sql_stores
from tests.api.conftest import _headers
from tests.cli.test_commands import BANK
from tests.lti.fake_lms import register_fake_lms

pytestmark = pytest.mark.slow
CHECK = {"kind": "numeric", "answer": "4.58 m/s^2", "expected": 4.58, "units": "m/s^2"}
OWNED, LIMITED = "oa-owned", "oa-limited"
STUDENT = "course:1:s001"
ROSTER_CSV = "id,name,email\ns001,Ada,ada@x.org\ns002,Alan,alan@x.org\n"
STAFF = {"member": "key:98", "role": "ta"}
ASSIGNMENT = {
    "title": "HW2",
    "problems": ["yo-yo"],
    "opens_at": "2026-01-01T09:00:00+01:00",
    "due_at": "2026-01-08T09:00:00+01:00",
    "late": {"kind": "penalty", "per_day": 0.1, "limit": 0.5},
}
EXTENSION = {"due_at": "2099-01-01T00:00:00Z"}
COURSE_BODIES: dict[tuple[str, str], Any] = {
    ("put", "/v1/courses/{course_id}/staff"): STAFF,
    ("post", "/v1/courses/{course_id}/assignments"): ASSIGNMENT,
    ("put", "/v1/assignments/{assignment_id}"): ASSIGNMENT,
    ("put", "/v1/assignments/{assignment_id}/extensions/{student}"): EXTENSION,
    ("put", "/v1/problems/{problem_id}/shared"): {"shared": True},
}


def atwood(problem_id: str, **changes: Any) -> dict[str, Any]:
    doc = yaml.safe_load((BANK / "atwood" / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK / "atwood" / "model.yaml").read_text())
    return {**doc, "id": problem_id, **changes}


@dataclass
class Api:
    client: TestClient
    settings: Settings
    instructor: dict[str, str]
    student: dict[str, str]
    lms_instructor: dict[str, str]  # an LMS session's cookie and CSRF token

    def key(self, role: str = "instructor") -> dict[str, str]:
        return _headers(self.settings, role, "fresh")

    @property
    def services(self) -> Any:
        return self.client.app.state.services  # type: ignore[attr-defined]


@pytest.fixture
def api(db: Database, grading_pool: Any) -> Iterator[Api]:
    settings = Settings(database_url=db.url, secret="test-secret-0123456789", warm_up=False)
    register_fake_lms(db)
    instructor_key, instructor = create_key(db, "instructor", "prof")
    session_id, record = open_session(
        sql_stores(db).lti_sessions,
        platform_id=1,
        sub="prof",
        role=Role.INSTRUCTOR,
        name="Prof",
        now=utc_now(),
    )
    _seed_course(db, instructor.id)
    with db.session() as session:
        for problem_id, limit in ((OWNED, None), (LIMITED, 1)):
            document = atwood(problem_id, max_attempts=limit)
            problem_repository.create_problem(session, problem_id, document, owner_key_id=instructor.id)
    with TestClient(create_app(settings, pool=grading_pool), raise_server_exceptions=False) as client:
        yield Api(
            client,
            settings,
            {"Authorization": f"Bearer {instructor_key}"},
            _headers(settings, "student", "ada"),
            {"Cookie": f"{SESSION_COOKIE}={session_id}", CSRF_HEADER: record.csrf_token},
        )


def _seed_course(db: Database, instructor_id: int) -> None:
    """Course 1, taught by the fixture's instructor (with a TA, key:99), its roster (student STUDENT)
    and assignments 1 and 2 on yo-yo."""
    courses = sql_stores(db).courses
    course = courses.create_course("Mechanics", owner=f"key:{instructor_id}")
    courses.add_staff(course.id, "key:99", StaffRole.TA)
    courses.import_roster(course.id, [RosterRow("s001", "Ada", "ada@x.org")])
    now = utc_now()
    for title in ("HW1", "HW1b"):  # 1 is deleted among the cases; 2 keeps its extensions' cases apart
        courses.create_assignment(
            course.id, AssignmentSpec(title, ("yo-yo",), now - timedelta(days=1), now + timedelta(days=6))
        )


# ---- how to call each endpoint, and how to make it answer each status ---------------------------

Call = Callable[[Api, dict[str, str]], httpx.Response]


def _json(method: str, url: str, body: Any) -> Call:
    return lambda api, headers: api.client.request(method, url, json=body, headers=headers)


CALLS: dict[tuple[str, str], tuple[int, Call]] = {
    ("get", "/health"): (200, lambda api, h: api.client.get("/health")),
    ("get", "/ready"): (200, lambda api, h: api.client.get("/ready")),
    ("post", "/v1/check"): (200, _json("POST", "/v1/check", CHECK)),
    ("get", "/v1/problems"): (200, lambda api, h: api.client.get("/v1/problems", headers=h)),
    ("get", "/v1/problems/{problem_id}"): (200, lambda api, h: api.client.get("/v1/problems/yo-yo", headers=h)),
    ("post", "/v1/problems/{problem_id}/parts/{part_id}/submissions"): (
        201,
        _json("POST", "/v1/problems/yo-yo/parts/acceleration/submissions", {"answer": "g"}),
    ),
    ("post", "/v1/problems/{problem_id}/parts/{part_id}/preview"): (
        200,
        _json("POST", "/v1/problems/yo-yo/parts/acceleration/preview", {"answer": "g/2"}),
    ),
    ("get", "/v1/submissions"): (200, lambda api, h: api.client.get("/v1/submissions", headers=h)),
    ("post", "/v1/problems"): (201, _json("POST", "/v1/problems", atwood("oa-new"))),
    ("put", "/v1/problems/{problem_id}"): (200, _json("PUT", f"/v1/problems/{OWNED}", atwood(OWNED, title="New"))),
    ("delete", "/v1/problems/{problem_id}"): (
        204,
        lambda api, h: api.client.delete(f"/v1/problems/{OWNED}", headers=h),
    ),
    ("get", "/v1/problems/{problem_id}/solution"): (
        200,
        lambda api, h: api.client.get("/v1/problems/yo-yo/solution", headers=h),
    ),
    ("get", "/v1/problems/{problem_id}/results"): (
        200,
        lambda api, h: api.client.get("/v1/problems/yo-yo/results", headers=h),
    ),
    ("post", "/v1/courses"): (201, _json("POST", "/v1/courses", {"title": "Optics"})),
    ("get", "/v1/courses"): (200, lambda api, h: api.client.get("/v1/courses", headers=h)),
    ("get", "/v1/courses/{course_id}"): (200, lambda api, h: api.client.get("/v1/courses/1", headers=h)),
    ("get", "/v1/courses/{course_id}/staff"): (200, lambda api, h: api.client.get("/v1/courses/1/staff", headers=h)),
    ("put", "/v1/courses/{course_id}/staff"): (200, _json("PUT", "/v1/courses/1/staff", STAFF)),
    ("delete", "/v1/courses/{course_id}/staff/{member}"): (
        204,
        lambda api, h: api.client.delete("/v1/courses/1/staff/key:99", headers=h),
    ),
    ("get", "/v1/courses/{course_id}/roster"): (200, lambda api, h: api.client.get("/v1/courses/1/roster", headers=h)),
    ("post", "/v1/courses/{course_id}/roster"): (
        200,
        lambda api, h: api.client.post(
            "/v1/courses/1/roster", content=ROSTER_CSV, headers={**h, "Content-Type": "text/csv"}
        ),
    ),
    ("post", "/v1/courses/{course_id}/sign-in-links"): (200, _json("POST", "/v1/courses/1/sign-in-links", {})),
    ("post", "/v1/courses/{course_id}/join-code"): (200, _json("POST", "/v1/courses/1/join-code", {})),
    ("post", "/v1/courses/{course_id}/assignments"): (201, _json("POST", "/v1/courses/1/assignments", ASSIGNMENT)),
    ("get", "/v1/courses/{course_id}/assignments"): (
        200,
        lambda api, h: api.client.get("/v1/courses/1/assignments", headers=h),
    ),
    ("get", "/v1/assignments/{assignment_id}"): (200, lambda api, h: api.client.get("/v1/assignments/1", headers=h)),
    ("put", "/v1/assignments/{assignment_id}"): (200, _json("PUT", "/v1/assignments/1", ASSIGNMENT)),
    ("delete", "/v1/assignments/{assignment_id}"): (
        204,
        lambda api, h: api.client.delete("/v1/assignments/1", headers=h),
    ),
    ("get", "/v1/assignments/{assignment_id}/extensions"): (
        200,
        lambda api, h: api.client.get("/v1/assignments/2/extensions", headers=h),
    ),
    ("put", "/v1/assignments/{assignment_id}/extensions/{student}"): (
        200,
        _json("PUT", f"/v1/assignments/2/extensions/{STUDENT}", EXTENSION),
    ),
    ("delete", "/v1/assignments/{assignment_id}/extensions/{student}"): (
        204,
        lambda api, h: api.client.delete(f"/v1/assignments/2/extensions/{STUDENT}", headers=h),
    ),
    ("get", "/v1/courses/{course_id}/gradebook"): (
        200,
        lambda api, h: api.client.get("/v1/courses/1/gradebook", headers=h),
    ),
    ("get", "/v1/courses/{course_id}/gradebook.csv"): (
        200,
        lambda api, h: api.client.get("/v1/courses/1/gradebook.csv", headers=h),
    ),
    ("put", "/v1/problems/{problem_id}/shared"): (200, _json("PUT", f"/v1/problems/{OWNED}/shared", {"shared": True})),
    ("get", "/v1/lti/delivery-problems"): (
        200,
        lambda api, h: api.client.get("/v1/lti/delivery-problems", headers=h),
    ),
    ("get", "/v1/student-data"): (
        200,
        lambda api, h: api.client.get("/v1/student-data", params={"student": "eve"}, headers=h),
    ),
    ("delete", "/v1/student-data"): (
        200,
        lambda api, h: api.client.delete("/v1/student-data", params={"student": "eve"}, headers=h),
    ),
}  # fmt: skip


def success(api: Api, method: str, path: str) -> httpx.Response:
    return CALLS[(method, path)][1](api, api.instructor)


def unauthenticated(api: Api, method: str, path: str) -> httpx.Response:
    return CALLS[(method, path)][1](api, {})


def forbidden(api: Api, method: str, path: str) -> httpx.Response:
    if path == "/v1/problems/{problem_id}":  # an LMS session acts only for its own user
        return api.client.get("/v1/problems/yo-yo", params={"student": "bob"}, headers=api.lms_instructor)
    if path.endswith("/submissions") and method == "post":
        url = "/v1/problems/yo-yo/parts/acceleration/submissions"
        return api.client.post(url, json={"answer": "g", "student": "bob"}, headers=api.lms_instructor)
    if path == "/v1/submissions":
        return api.client.get("/v1/submissions", params={"student": "bob"}, headers=api.student)
    return CALLS[(method, path)][1](api, api.student)  # instructors' routes


def not_found(api: Api, method: str, path: str) -> httpx.Response:
    url = path.replace("{problem_id}", "no-such-problem").replace("{part_id}", "a")
    url = url.replace("{course_id}", "999").replace("{assignment_id}", "999").replace("{student}", STUDENT)
    url = url.replace("{member}", "key:99")
    if path == "/v1/submissions":  # a student of a course the caller does not teach
        return api.client.get("/v1/submissions", params={"student": STUDENT}, headers=api.key())
    if path == "/v1/student-data":  # the same, for their personal data
        return api.client.request(method.upper(), path, params={"student": STUDENT}, headers=api.key())
    if (method, path) == ("post", "/v1/courses/{course_id}/roster"):
        headers = {**api.instructor, "Content-Type": "text/csv"}
        return api.client.post(url, content=ROSTER_CSV, headers=headers)
    if path.startswith(("/v1/courses", "/v1/assignments")) or path.endswith("/shared"):
        body = COURSE_BODIES.get((method, path), {})
        return api.client.request(method.upper(), url, json=body, headers=api.instructor)
    body = {"answer": "g"} if method == "post" else atwood("no-such-problem") if method == "put" else None
    return api.client.request(method.upper(), url, json=body, headers=api.instructor)


def conflict(api: Api, method: str, path: str) -> httpx.Response:
    if method == "delete" and path == "/v1/courses/{course_id}/staff/{member}":  # the last instructor
        instructor = api.client.get("/v1/courses/1/staff", headers=api.instructor).json()[0]["member"]
        return api.client.delete(f"/v1/courses/1/staff/{instructor}", headers=api.instructor)
    if method == "post" and path == "/v1/problems":
        return api.client.post("/v1/problems", json=atwood(OWNED), headers=api.instructor)
    url = f"/v1/problems/{LIMITED}/parts/acceleration/submissions"
    first = api.client.post(url, json={"answer": "g", "student": "eve"}, headers=api.instructor)
    assert first.status_code == 201, first.text
    return api.client.post(url, json={"answer": "g", "student": "eve"}, headers=api.instructor)


def too_large(api: Api, method: str, path: str) -> httpx.Response:
    url = path.replace("{problem_id}", OWNED).replace("{part_id}", "acceleration").replace("{course_id}", "1")
    body = b" " * (api.settings.max_body_bytes + 1)
    headers = {**api.instructor, "Content-Type": "application/json"}
    return api.client.request(method.upper(), url, content=body, headers=headers)


def unsupported_media_type(api: Api, method: str, path: str) -> httpx.Response:
    url = path.replace("{problem_id}", OWNED)
    headers = {**api.instructor, "Content-Type": "text/plain"}
    return api.client.request(method.upper(), url, content=b"id: x", headers=headers)


def malformed(api: Api, method: str, path: str) -> httpx.Response:
    if method in ("post", "put"):
        url = path.replace("{problem_id}", OWNED if method == "put" else "yo-yo").replace(
            "{part_id}", "acceleration"
        )
        url = url.replace("{course_id}", "1").replace("{assignment_id}", "1").replace("{student}", STUDENT)
        headers = {**api.instructor, "Content-Type": "application/json"}
        return api.client.request(method.upper(), url, content=b'{"answer": ', headers=headers)
    if path == "/v1/submissions":
        return api.client.get("/v1/submissions", params={"limit": 0}, headers=api.instructor)
    if path == "/v1/problems/{problem_id}":  # a student key cannot name a student
        return api.client.get("/v1/problems/yo-yo", params={"student": "bob"}, headers=api.student)
    if path == "/v1/student-data":  # no student named
        return api.client.request(method.upper(), path, headers=api.instructor)
    # Nothing else to get wrong in a path-only route but the path itself.
    url = path.replace("{problem_id}", "nul%00id")
    return api.client.request(method.upper(), url, headers=api.instructor)


def rate_limited(api: Api, method: str, path: str) -> httpx.Response:
    services = api.services
    saved = services.key_limiter, services.preview_limiter
    services.key_limiter = MemoryRateLimiter(1)
    services.preview_limiter = MemoryRateLimiter(1)  # previews have a budget of their own
    try:
        headers = api.key()
        assert api.client.get("/v1/problems", headers=headers).status_code == 200  # the budget: spent
        if path.endswith("/preview"):
            assert CALLS[(method, path)][1](api, headers).status_code == 200  # the preview budget: spent
        return CALLS[(method, path)][1](api, headers)
    finally:
        services.key_limiter, services.preview_limiter = saved


def unavailable(api: Api, method: str, path: str) -> httpx.Response:
    services = api.services
    if path == "/ready":
        services.catalog.warm.clear()
        try:
            return api.client.get("/ready")
        finally:
            services.catalog.warm.set()
    headers = api.key()  # created before the outage

    def down(*args: Any, **kwargs: Any) -> Any:
        raise OperationalError("SELECT 1", {}, ConnectionRefusedError("connection refused"))

    database = services.database
    database.session = down
    try:
        return CALLS[(method, path)][1](api, headers)
    finally:
        del database.session


PROVOKE: dict[int, Callable[[Api, str, str], httpx.Response]] = {
    401: unauthenticated,
    403: forbidden,
    404: not_found,
    409: conflict,
    413: too_large,
    415: unsupported_media_type,
    422: malformed,
    429: rate_limited,
    503: unavailable,
}


def documented(spec: dict[str, Any]) -> list[tuple[str, str, int]]:
    return [
        (method, path, int(status))
        for path, item in spec["paths"].items()
        for method, operation in item.items()
        for status in operation["responses"]
    ]


def schema_error(
    spec: dict[str, Any], method: str, path: str, status: int, response: httpx.Response
) -> str | None:
    """Why the response does not match what the document says, or None."""
    if response.status_code != status:
        return f"answered {response.status_code}: {response.text[:200]}"
    documented_response = spec["paths"][path][method]["responses"][str(status)]
    content = documented_response.get("content", {}).get("application/json")
    media = response.headers.get("content-type", "").split(";")[0]
    if content is None and media in documented_response.get("content", {}):
        return None  # a documented body that is not JSON (a CSV export)
    if content is None:
        return None if not response.content else f"documents no body but got {response.text[:100]}"
    schema = {**content["schema"], "components": spec["components"]}
    try:
        jsonschema.Draft202012Validator(schema).validate(response.json())
    except jsonschema.ValidationError as error:
        return f"body does not match the schema: {error.message[:300]}"
    for header in documented_response.get("headers", {}):
        if header.lower() not in response.headers:
            return f"documented header {header} missing"
    return None


@pytest.mark.parametrize("backend", ["sqlite"])
def test_every_documented_status_is_answered_in_the_documented_shape(api: Api):
    spec = api.client.get("/openapi.json").json()
    cases = documented(spec)
    # Successes last: one retires the problem that other cases change.
    cases.sort(key=lambda case: (case[2] < 300, case[0] == "delete"))
    failures = []
    for method, path, status in cases:
        if status < 300:
            expected, _ = CALLS.get((method, path), (None, None))
            if expected != status:
                failures.append(f"{method.upper()} {path} {status}: no call in CALLS")
                continue
            response = success(api, method, path)
        elif status in PROVOKE:
            response = PROVOKE[status](api, method, path)
        else:
            failures.append(f"{method.upper()} {path} {status}: no way to provoke it in PROVOKE")
            continue
        why = schema_error(spec, method, path, status, response)
        if why:
            failures.append(f"{method.upper()} {path} {status}: {why}")
    assert not failures, "\n".join(failures)
    assert len(cases) > 60


CONTRACT_ERRORS = {401, 403, 404, 409, 413, 415, 422, 429, 503}


@pytest.mark.parametrize("backend", ["sqlite"])
def test_error_responses_use_the_error_shape_and_keyed_routes_declare_the_bearer_scheme(api: Api):
    spec = api.client.get("/openapi.json").json()
    assert spec["components"]["securitySchemes"]["bearer"] == {
        "type": "http",
        "scheme": "bearer",
        "description": spec["components"]["securitySchemes"]["bearer"]["description"],
    }
    seen: set[int] = set()
    for method, path, status in documented(spec):
        operation = spec["paths"][path][method]
        if status >= 400:
            seen.add(status)
            ref = operation["responses"][str(status)]["content"]["application/json"]["schema"]["$ref"]
            assert ref == "#/components/schemas/ErrorBody", (method, path, status)
        if path.startswith("/v1/"):
            assert operation["security"] == [{"bearer": []}], (method, path)
            assert {"401", "429", "503"} <= set(operation["responses"]), (method, path)
    assert seen == CONTRACT_ERRORS
    assert "HTTPValidationError" not in spec["components"]["schemas"]


# ---- /docs works offline -------------------------------------------------------------------------


@pytest.mark.parametrize("backend", ["sqlite"])
def test_docs_page_loads_only_same_origin_files_that_exist(api: Api):
    page = api.client.get("/docs")
    assert page.status_code == 200
    html = page.text
    urls = re.findall(r'(?:src|href)="([^"]+)"', html) + re.findall(r"url: '([^']+)'", html)
    assert len(urls) >= 4  # the script, the stylesheet, the icon and the OpenAPI document
    for url in urls:
        assert url.startswith("/") and not url.startswith("//"), url
        assert api.client.get(url).status_code == 200, url
    assert "http://" not in html and "https://" not in html
    assert '"persistAuthorization": true' in html
