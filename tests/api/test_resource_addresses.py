"""A resource's address: a number no record can have is a malformed request, never a fault, and a method
it does not serve is 405 naming every method it does."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from tests.instructor.conftest import csrf_of

TOO_LARGE = str(2**63)  # one past the largest id either database can store


@pytest.mark.parametrize(
    ("method", "path"),
    [
        ("GET", f"/v1/assignments/{TOO_LARGE}"),
        ("DELETE", f"/v1/assignments/{TOO_LARGE}"),
        ("GET", f"/v1/assignments/{TOO_LARGE}/extensions"),
        ("GET", f"/v1/courses/{TOO_LARGE}"),
        ("GET", f"/v1/courses/{TOO_LARGE}/gradebook"),
        ("GET", f"/v1/courses/{TOO_LARGE}/roster"),
        ("GET", "/v1/courses/38763184901533556736"),
        ("GET", "/v1/assignments/0"),
        ("GET", "/v1/courses/-1"),
    ],
)
def test_an_id_no_record_can_have_is_malformed_not_a_fault(
    client: TestClient, instructor_headers: dict[str, str], method: str, path: str
):
    response = client.request(method, path, headers=instructor_headers)
    assert response.status_code == 422, response.text
    assert response.json()["error"]["code"] == "malformed_request"


@pytest.mark.parametrize(
    ("method", "path", "allowed"),
    [
        ("OPTIONS", "/v1/assignments/1", "GET, HEAD, PUT, DELETE"),
        ("PATCH", "/v1/assignments/1", "GET, HEAD, PUT, DELETE"),
        ("DELETE", "/v1/courses", "GET, HEAD, POST"),
        ("GET", "/v1/check", "POST"),
    ],
)
def test_a_method_not_served_is_405_naming_every_method_that_is(
    client: TestClient, instructor_headers: dict[str, str], method: str, path: str, allowed: str
):
    response = client.request(method, path, headers=instructor_headers)
    assert response.status_code == 405, response.text
    assert response.headers["Allow"] == allowed
    assert response.json()["error"]["code"] == "method_not_allowed"


@pytest.mark.parametrize(
    "path",
    [
        f"/instructor/courses/{TOO_LARGE}",
        f"/instructor/courses/{TOO_LARGE}/gradebook",
        f"/instructor/assignments/{TOO_LARGE}/results",
        f"/instructor/assignments/{TOO_LARGE}/edit",
    ],
)
def test_an_instructor_page_at_an_id_no_record_can_have_is_no_fault(
    client: TestClient, instructor_headers: dict[str, str], path: str
):
    form = client.get("/instructor/sign-in")
    key = instructor_headers["Authorization"].removeprefix("Bearer ")
    signed = client.post(
        "/instructor/sign-in", data={"key": key, "csrf": csrf_of(form.text)}, follow_redirects=False
    )
    assert signed.status_code == 303, signed.text
    assert client.get(path, follow_redirects=False).status_code == 422
