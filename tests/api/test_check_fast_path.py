"""The common `POST /v1/check` is answered by CheckFastPath byte for byte as the route answers it, and
everything else reaches the route with its body intact."""

from __future__ import annotations

import json
from typing import Any

import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient
from starlette.types import Receive, Scope, Send

from app.check_fast_path import CheckFastPath
from app.middleware import RequestContext
from tests.api.conftest import key_headers
from tests.api.test_check_endpoint import WEDGE_SYMBOLS, choice, numeric, symbolic

JSON = {"Content-Type": "application/json"}


def body(payload: Any) -> bytes:
    return json.dumps(payload).encode()


# (id, request body, content-type): what a course script sends, good and bad.
REQUESTS = [
    ("correct", body(symbolic("-m g sin(θ)cos(θ)/(M + m sin^2 θ)")), "application/json"),
    ("sign-error", body(symbolic("m g sin(θ)cos(θ)/(M + m sin^2 θ)")), "application/json"),
    ("unreadable-answer", body(symbolic("-m g sin(θ")), "application/json"),
    ("numeric", body(numeric("4.58 m/s^2")), "application/json; charset=utf-8"),
    ("choice", body(choice("A")), "application/json"),
    ("bad-reference", body(symbolic("m", expected="m +* g")), "application/json"),
    ("unknown-unit", body(numeric("4.58 m/s^2", units="furlongs per blip")), "application/json"),
    ("bad-tolerance", body(numeric("4.58 m/s^2", tolerance={"relative": -1})), "application/json"),
    ("no-kind", body({"answer": "m", "expected": "m", "symbols": WEDGE_SYMBOLS}), "application/json"),
    ("not-json", b'{"kind": "symbolic", "answer": ', "application/json"),
    ("not-utf8", b'{"kind": "\xff"}', "application/json"),
    ("a-list", b"[1, 2]", "application/json"),
    ("empty", b"", "application/json"),
    ("text-plain", body(symbolic("m g")), "text/plain"),
]


class Inner:
    """Stands for the app behind the fast path: records what reached it and answers 299."""

    def __init__(self) -> None:
        self.seen: list[bytes] = []

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        received = b""
        while True:
            message = await receive()
            received += message.get("body", b"")
            if not message.get("more_body", False):
                break
        self.seen.append(received)
        await send({"type": "http.response.start", "status": 299, "headers": []})
        await send({"type": "http.response.body", "body": b""})


def route_only(app: FastAPI) -> TestClient:
    """The same app (and services) without the fast path: FastAPI's own stack behind RequestContext."""
    stack = FastAPI.build_middleware_stack(app)

    async def as_the_app_calls_it(scope: Scope, receive: Receive, send: Send) -> None:
        scope["app"] = app  # what FastAPI.__call__ sets before its stack runs
        await stack(scope, receive, send)

    return TestClient(RequestContext(as_the_app_calls_it, max_bytes=2 * 1024 * 1024))


def fast_path_over(inner: Inner, app: FastAPI) -> TestClient:
    return TestClient(RequestContext(CheckFastPath(inner, app), max_bytes=2 * 1024 * 1024))


@pytest.fixture
def known_key(client: TestClient) -> dict[str, str]:
    """A key the server has just authenticated (so held in memory, as a busy course script's is)."""
    headers = key_headers(client, "instructor", "script")
    assert client.post("/v1/check", json=numeric("4.58 m/s^2"), headers=headers).status_code == 200
    return headers


@pytest.mark.parametrize(("content", "content_type"), [r[1:] for r in REQUESTS], ids=[r[0] for r in REQUESTS])
def test_the_fast_path_answers_every_request_as_the_route_does(client, known_key, content, content_type):
    headers = {**known_key, "Content-Type": content_type}
    fast = client.post("/v1/check", content=content, headers=headers)
    slow = route_only(client.app).post("/v1/check", content=content, headers=headers)
    assert (fast.status_code, fast.headers["content-type"]) == (
        slow.status_code,
        slow.headers["content-type"],
    )
    assert fast.json() == slow.json()
    assert fast.headers["x-request-id"] and slow.headers["x-request-id"]


@pytest.mark.parametrize(
    ("name", "content", "content_type"),
    [r for r in REQUESTS if r[0] in {"correct", "sign-error", "unreadable-answer", "numeric", "choice"}],
)
def test_a_readable_check_from_a_known_key_never_reaches_the_app(
    client, known_key, name, content, content_type
):
    inner = Inner()
    response = fast_path_over(inner, client.app).post(
        "/v1/check", content=content, headers={**known_key, "Content-Type": content_type}
    )
    assert response.status_code == 200, name
    assert response.json()["verdict"] in {"correct", "incorrect", "invalid"}
    assert inner.seen == []


def test_a_key_not_held_in_memory_is_looked_up_and_its_check_stays_on_the_fast_path(client):
    """As when the memory of a busy script's key expires: its requests are not handed to the app."""
    fresh = key_headers(client, "instructor", "fresh")  # made, never used: not in memory yet
    inner = Inner()
    response = fast_path_over(inner, client.app).post(
        "/v1/check", content=body(numeric("4.58 m/s^2")), headers={**fresh, **JSON}
    )
    assert response.status_code == 200
    assert response.json()["verdict"] == "correct"
    assert inner.seen == []


UNUSUAL = [
    ("no-key", {}, body(numeric("4.58 m/s^2"))),
    ("unknown-key", {"Authorization": "Bearer not-a-key"}, body(numeric("4.58 m/s^2"))),
    ("not-bearer", {"Authorization": "Basic dXNlcjpwYXNz"}, body(numeric("4.58 m/s^2"))),
    ("malformed", None, b'{"kind": "numeric", "answer": 4.58}'),
    ("not-json", None, b"kind=numeric"),
]


@pytest.mark.parametrize(("name", "auth", "content"), UNUSUAL, ids=[u[0] for u in UNUSUAL])
def test_anything_unusual_goes_on_to_the_app_with_its_body_intact(client, known_key, name, auth, content):
    inner = Inner()
    headers = {**(known_key if auth is None else auth), **JSON}
    response = fast_path_over(inner, client.app).post("/v1/check", content=content, headers=headers)
    assert response.status_code == 299, name
    assert inner.seen == [content]


def test_other_routes_and_methods_are_not_the_fast_paths(client, known_key):
    inner = Inner()
    fast = fast_path_over(inner, client.app)
    assert fast.get("/v1/check", headers=known_key).status_code == 299
    assert (
        fast.post("/v1/check/", content=body(numeric("1 m")), headers={**known_key, **JSON}).status_code
        == 299
    )
    assert len(inner.seen) == 2


def test_the_rate_limit_applies_on_the_fast_path(client, grading_pool, settings, backend):
    from tests.api.conftest import make_app

    limited = settings.model_copy(update={"rate_limit_per_minute": 3})
    with TestClient(make_app(limited, backend, pool=grading_pool)) as small:
        headers = {**key_headers(small, "instructor", "script"), **JSON}
        statuses = [
            small.post("/v1/check", content=body(numeric("4.58 m/s^2")), headers=headers).status_code
            for _ in range(5)
        ]
        refused = small.post("/v1/check", content=body(numeric("4.58 m/s^2")), headers=headers)
    assert statuses == [200, 200, 200, 429, 429]
    assert refused.json()["error"]["code"] == "rate_limited"
    assert int(refused.headers["retry-after"]) >= 1


def test_a_body_sent_again_is_answered_from_its_remembered_job_and_the_memory_stays_bounded(
    client, known_key, monkeypatch
):
    monkeypatch.setattr("app.check_fast_path.REMEMBERED_BODIES", 3)
    fast = CheckFastPath(Inner(), client.app)
    over = TestClient(RequestContext(fast, max_bytes=2 * 1024 * 1024))
    headers = {**known_key, **JSON}
    first = body(symbolic("m g sin(θ)cos(θ)/(M + m sin^2 θ)"))
    verdicts = [over.post("/v1/check", content=first, headers=headers).json() for _ in range(2)]
    assert verdicts[0] == verdicts[1] and verdicts[0]["reason"] == "sign_error"
    for n in range(5):
        over.post("/v1/check", content=body(numeric(f"{n} m/s^2")), headers=headers)
    assert len(fast._jobs) == 3
    assert first not in fast._jobs
    huge = body(symbolic("m" + " " * 5000))
    assert over.post("/v1/check", content=huge, headers=headers).status_code == 200
    assert huge not in fast._jobs
