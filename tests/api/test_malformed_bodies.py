"""A body that cannot be read as JSON is a malformed request (422 in the error shape), never 400 or 500;
a streamed body over the cap is 413 however it is framed."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from fastapi.testclient import TestClient

from app.settings import Settings

VALID = b'{"kind": "numeric", "answer": "4.58 m/s^2", "expected": 4.58, "units": "m/s^2"}'


@pytest.mark.parametrize(
    ("body", "message"),
    [
        (b'{"kind": "numeric", "answer": "4.58 \xff\xfe", "expected": 4.58}', "UTF-8"),
        (b'{"kind": "numeric", "answer": "4", "expected": ' + b"7" * 5000 + b"}", "digits"),
        (b"[" * 100_000 + b"]" * 100_000, "nested"),
        (b'{"kind": "numeric", "answer": "4", "expected": 4, "symbols": ' + b'{"a": ' * 5000 + b"1" + b"}" * 5001, "nested"),
        (b'{"kind": "numeric", "answer": ', "JSON"),
    ],
    ids=["invalid-utf8", "5000-digit-number", "deep-array", "deep-object", "truncated"],
)  # fmt: skip
def test_unreadable_json_is_422_in_the_error_shape(
    client: TestClient, student_headers: dict[str, str], body: bytes, message: str
):
    headers = {**student_headers, "Content-Type": "application/json"}
    response = client.post("/v1/check", content=body, headers=headers)
    assert response.status_code == 422, response.text
    error = response.json()["error"]
    assert error["code"] == "malformed_request"
    assert message in error["message"] + " ".join(d["message"] for d in error["details"])


def chunks(total: int, size: int = 64 * 1024) -> Iterator[bytes]:
    while total > 0:
        yield b" " * min(size, total)
        total -= size


def test_chunked_body_over_the_cap_is_413(
    client: TestClient, student_headers: dict[str, str], settings: Settings
):
    headers = {**student_headers, "Content-Type": "application/json"}
    response = client.post("/v1/check", content=chunks(settings.max_body_bytes + 1), headers=headers)
    assert response.status_code == 413, response.text
    assert response.json()["error"]["code"] == "payload_too_large"


def test_chunked_body_under_the_cap_is_read_whole(client: TestClient, student_headers: dict[str, str]):
    headers = {**student_headers, "Content-Type": "application/json"}
    response = client.post("/v1/check", content=iter([VALID[:20], VALID[20:]]), headers=headers)
    assert response.status_code == 200, response.text
    assert response.json()["verdict"] == "correct"


UNREADABLE = [b'{"kind": "numeric", "answer": ', b"\xff\xfe not utf-8", b"[" * 100_000]
JSON_ROUTES = ["/v1/check", "/v1/problems/atwood/parts/acceleration/submissions"]


@pytest.mark.parametrize("body", UNREADABLE, ids=["truncated", "not-utf8", "deep"])
@pytest.mark.parametrize("path", JSON_ROUTES)
@pytest.mark.parametrize(
    "authorization", [None, "Bearer not-a-key", "Basic abc"], ids=["no-key", "unknown-key", "not-bearer"]
)
def test_caller_is_refused_before_an_unreadable_body_is(
    client: TestClient, path: str, body: bytes, authorization: str | None
):
    headers = {"Content-Type": "application/json"}
    if authorization is not None:
        headers["Authorization"] = authorization
    response = client.post(path, content=body, headers=headers)
    assert response.status_code == 401, response.text
    assert response.json()["error"]["code"] == "unauthenticated"


@pytest.mark.parametrize(
    ("body", "message"),
    [
        (
            {"problem": "atwood", "part": "acceleration", "answer": "g"},
            "kind is required ('symbolic', 'numeric'",
        ),
        ({"kind": "vector", "answer": "g"}, "kind must be 'symbolic', 'numeric'"),
    ],
    ids=["no-kind", "unknown-kind"],
)
def test_a_check_without_a_known_kind_says_which_kinds_there_are(
    client: TestClient, student_headers: dict[str, str], body: dict[str, str], message: str
):
    # it said "Unable to extract tag using discriminator 'kind'" at the path ""
    response = client.post("/v1/check", json=body, headers=student_headers)
    assert response.status_code == 422, response.text
    assert [(d["path"], d["message"][: len(message)]) for d in response.json()["error"]["details"]] == [
        ("kind", message)
    ]
