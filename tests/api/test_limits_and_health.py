"""Rate limits per key and per student (429 with Retry-After), readiness, and the error shape."""

from __future__ import annotations

import io
import json
import logging
import os
import shutil
import threading
import time

import pytest
from fastapi.testclient import TestClient

from app.settings import Settings
from problems.loader import BANK_DIR
from tests.api.conftest import key_headers, make_app

BODY = {"kind": "numeric", "answer": "4.58 m/s^2", "expected": 4.58, "units": "m/s^2"}


@pytest.fixture
def limited(settings: Settings, backend: str, grading_pool) -> tuple[TestClient, Settings]:
    tight = settings.model_copy(update={"rate_limit_per_minute": 3, "student_rate_limit_per_minute": 2})
    with TestClient(make_app(tight, backend, pool=grading_pool)) as client:
        yield client, tight


def test_a_key_over_its_budget_gets_429_with_retry_after(limited):
    client, _ = limited
    headers = key_headers(client, "instructor", "busy")
    statuses = [client.post("/v1/check", json=BODY, headers=headers).status_code for _ in range(4)]
    assert statuses == [200, 200, 200, 429]
    response = client.post("/v1/check", json=BODY, headers=headers)
    assert response.json()["error"]["code"] == "rate_limited"
    assert 1 <= int(response.headers["Retry-After"]) <= 60


def test_a_students_budget_is_shared_by_all_its_keys(limited):
    client, _ = limited
    keys = [key_headers(client, "student", "ada", student="ada") for _ in range(2)]
    statuses = [client.post("/v1/check", json=BODY, headers=keys[i % 2]).status_code for i in range(3)]
    assert statuses == [200, 200, 429]


def test_ready_turns_200_once_the_problems_are_compiled(settings, backend, grading_pool, tmp_path):
    bank = tmp_path / "bank"  # two problems: the whole bank would take minutes to derive here
    for problem in ("atwood", "mass-spring"):
        shutil.copytree(BANK_DIR / problem, bank / problem)
    warming = settings.model_copy(update={"warm_up": True, "bank_dir": bank})
    with TestClient(make_app(warming, backend, pool=grading_pool)) as client:
        headers = key_headers(client, "student", "first", student="first")
        deadline = time.monotonic() + 120
        said = set()
        while (response := client.get("/ready")).status_code != 200 and time.monotonic() < deadline:
            assert response.json()["error"]["code"] == "not_ready"
            said.add(response.json()["error"]["message"])
            time.sleep(0.2)
        # Progress is told once a first problem is derived (the two derive side by side: maybe never).
        assert said <= {
            "Still compiling the problems.",
            "Still compiling the problems (1 of 2 derived).",
            "Still compiling the problems (2 of 2 derived).",
        }
        assert response.json() == {"status": "ready"}
        # Ready means graded at once, a numeric part too (its unit table may still be in the making).
        checks = [
            ("acceleration", "(m2 - m1) g/(m1 + m2)", "correct"),
            ("acceleration_numeric", "1000 m/s^2", "incorrect"),
        ]
        for part, answer, verdict in checks:
            sent = client.post(
                f"/v1/problems/atwood/parts/{part}/submissions", json={"answer": answer}, headers=headers
            )
            assert (sent.status_code, sent.json()["verdict"]) == (201, verdict), sent.json()
        catalog = client.app.state.services.catalog  # type: ignore[attr-defined]
        assert {record.id for record in catalog.list()} == {"atwood", "mass-spring"}


def test_unknown_route_answers_in_the_error_shape(client):
    response = client.get("/v1/nothing-here")
    assert response.status_code == 404
    assert set(response.json()["error"]) == {"code", "message", "details"}


def test_every_response_carries_a_request_id(client):
    assert client.get("/health").headers["x-request-id"]
    assert client.get("/health", headers={"X-Request-ID": "trace-42"}).headers["x-request-id"] == "trace-42"


def test_each_request_is_logged_once_with_its_id_status_and_time(client, settings):
    from app.logs import JsonLogFormatter

    stream = io.StringIO()
    handler = logging.StreamHandler(stream)
    handler.setFormatter(JsonLogFormatter())
    logger = logging.getLogger("physcheck.http")
    logger.addHandler(handler)
    try:
        fine = client.get("/health")
        refused = client.post("/v1/check", content=b"x" * (settings.max_body_bytes + 1))
    finally:
        logger.removeHandler(handler)
    assert refused.status_code == 413  # the cap answers before the key is asked for
    lines = [json.loads(line) for line in stream.getvalue().splitlines()]
    assert [(line["message"], line["method"], line["path"], line["status"]) for line in lines] == [
        ("request", "GET", "/health", fine.status_code),
        ("request", "POST", "/v1/check", 413),
    ]
    assert [line["request_id"] for line in lines] == [
        fine.headers["x-request-id"],
        refused.headers["x-request-id"],
    ]
    assert fine.headers["x-request-id"] != refused.headers["x-request-id"]
    assert all(isinstance(line["ms"], float) for line in lines)


CONTRACT_PATHS = {
    ("post", "/v1/check"),
    ("get", "/v1/problems"),
    ("post", "/v1/problems"),
    ("get", "/v1/problems/{problem_id}"),
    ("put", "/v1/problems/{problem_id}"),
    ("delete", "/v1/problems/{problem_id}"),
    ("get", "/v1/problems/{problem_id}/solution"),
    ("post", "/v1/problems/{problem_id}/parts/{part_id}/submissions"),
    ("get", "/v1/submissions"),
}


def test_openapi_documents_every_contract_endpoint(client):
    spec = client.get("/openapi.json").json()
    documented = {(method, path) for path, item in spec["paths"].items() for method in item}
    assert documented >= CONTRACT_PATHS
    assert client.get("/docs").status_code == 200


def test_a_full_grading_queue_is_503_with_retry_after(settings, backend):
    from app.grading.pool import GradingPool
    from tests.api.slow_task import hanging_grade

    pool = GradingPool(workers=1, timeout=3.0, memory_mb=1024, max_tasks=10, queue_size=0, task=hanging_grade)
    pool.start()
    try:
        with TestClient(make_app(settings, backend, pool=pool)) as client:
            headers = key_headers(client, "student", "ada")
            hang = {"kind": "symbolic", "answer": "hang", "expected": "m", "symbols": {"m": {}}}
            first = threading.Thread(target=lambda: client.post("/v1/check", json=hang, headers=headers))
            first.start()
            deadline = time.monotonic() + 10
            while pool.in_flight == 0 and time.monotonic() < deadline:
                time.sleep(0.02)
            response = client.post("/v1/check", json=BODY, headers=headers)
            first.join()
    finally:
        pool.close()
    assert response.status_code == 503
    assert response.json()["error"]["code"] == "busy"
    assert response.headers["Retry-After"] == "1"


def test_the_public_default_secret_is_refused_for_an_https_deployment():
    from pydantic import ValidationError

    with pytest.raises(ValidationError, match="PHYSCHECK_SECRET"):
        Settings(base_url="https://physcheck.example.edu")
    assert Settings(base_url="https://physcheck.example.edu", secret="a-real-secret-value").secret


@pytest.mark.parametrize("expected", ["4_58", "NaN", "Infinity", "0x10", "4.5.8"])
def test_a_reference_that_is_not_a_plain_decimal_is_422(client, expected):
    headers = key_headers(client, "student", "ada")
    response = client.post("/v1/check", json={**BODY, "expected": expected}, headers=headers)
    assert response.status_code == 422


def test_an_instance_runs_two_more_grading_workers_than_it_has_cores_unless_told(monkeypatch):
    monkeypatch.delenv("PHYSCHECK_CHECK_WORKERS", raising=False)
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    assert Settings(secret="settings-test-secret").check_workers == (cores or 1) + 2
    monkeypatch.setenv("PHYSCHECK_CHECK_WORKERS", "1")
    assert Settings(secret="settings-test-secret").check_workers == 1
