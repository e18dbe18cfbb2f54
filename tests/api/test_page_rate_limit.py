"""The student page's content endpoint spends the same budgets as the API: per key and per student."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from fastapi.testclient import TestClient

from app.settings import Settings
from tests.api.conftest import key_headers, make_app

BODY = {"kind": "numeric", "answer": "4.58 m/s^2", "expected": 4.58, "units": "m/s^2"}


@pytest.fixture
def limited(settings: Settings, backend: str, grading_pool) -> Iterator[tuple[TestClient, Settings]]:
    tight = settings.model_copy(update={"rate_limit_per_minute": 3, "student_rate_limit_per_minute": 2})
    with TestClient(make_app(tight, backend, pool=grading_pool)) as client:
        yield client, tight


def student_keys(client: TestClient, count: int) -> list[dict[str, str]]:
    return [key_headers(client, "student", "ada", student="ada") for _ in range(count)]


def test_content_requests_over_the_students_budget_get_429_with_retry_after(limited):
    client, _ = limited
    [headers] = student_keys(client, 1)
    responses = [client.get("/p/yo-yo/content", headers=headers) for _ in range(3)]
    assert [r.status_code for r in responses] == [200, 200, 429]
    assert 1 <= int(responses[-1].headers["Retry-After"]) <= 60


def test_content_and_api_requests_share_one_budget(limited):
    client, _ = limited
    first, second = student_keys(client, 2)
    assert client.post("/v1/check", json=BODY, headers=first).status_code == 200
    assert client.get("/p/yo-yo/content", headers=second).status_code == 200
    assert client.get("/p/yo-yo/content", headers=first).status_code == 429
    assert client.post("/v1/check", json=BODY, headers=second).status_code == 429
