"""The student page's content endpoint spends the same budgets as the API: per key and per student."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from fastapi.testclient import TestClient

from app.db.database import Database
from app.keys import create_key
from app.main import create_app
from app.settings import Settings

BODY = {"kind": "numeric", "answer": "4.58 m/s^2", "expected": 4.58, "units": "m/s^2"}


@pytest.fixture
def limited(settings: Settings, grading_pool) -> Iterator[tuple[TestClient, Settings]]:
    tight = settings.model_copy(update={"rate_limit_per_minute": 3, "student_rate_limit_per_minute": 2})
    with TestClient(create_app(tight, pool=grading_pool)) as client:
        yield client, tight


def student_keys(settings: Settings, count: int) -> list[dict[str, str]]:
    database = Database(settings.database_url)
    try:
        keys = [create_key(database, "student", "ada", student="ada")[0] for _ in range(count)]
    finally:
        database.dispose()
    return [{"Authorization": f"Bearer {key}"} for key in keys]


def test_content_requests_over_the_students_budget_get_429_with_retry_after(limited):
    client, settings = limited
    [headers] = student_keys(settings, 1)
    responses = [client.get("/p/yo-yo/content", headers=headers) for _ in range(3)]
    assert [r.status_code for r in responses] == [200, 200, 429]
    assert 1 <= int(responses[-1].headers["Retry-After"]) <= 60


def test_content_and_api_requests_share_one_budget(limited):
    client, settings = limited
    first, second = student_keys(settings, 2)
    assert client.post("/v1/check", json=BODY, headers=first).status_code == 200
    assert client.get("/p/yo-yo/content", headers=second).status_code == 200
    assert client.get("/p/yo-yo/content", headers=first).status_code == 429
    assert client.post("/v1/check", json=BODY, headers=second).status_code == 429
