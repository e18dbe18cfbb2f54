"""SQLite locked by another writer past the database timeout: the request is 503 with Retry-After (the
lock is someone else's, a retry will do), nothing is filed, and it succeeds once the lock is gone."""

from __future__ import annotations

import sqlite3

import pytest
from fastapi.testclient import TestClient
from sqlalchemy.engine import make_url

from app.grading.pool import GradingPool
from app.settings import Settings
from tests.api.conftest import key_headers, make_app

SUBMIT = "/v1/problems/atwood/parts/acceleration/submissions"


@pytest.mark.parametrize("backend", ["sqlite"])
def test_a_write_behind_another_writers_lock_is_503_then_succeeds(
    settings: Settings, backend: str, grading_pool: GradingPool
):
    settings = settings.model_copy(update={"database_timeout_seconds": 0.5})
    with TestClient(make_app(settings, backend, pool=grading_pool)) as client:
        headers = key_headers(client, "student", "ada", student="ada")
        assert client.get("/v1/problems/atwood", headers=headers).status_code == 200
        other = sqlite3.connect(make_url(settings.database_url).database or "", isolation_level=None)
        try:
            other.execute("BEGIN IMMEDIATE")  # another process's write, in the middle of its transaction
            response = client.post(SUBMIT, json={"answer": "g (m2 - m1)/(m1 + m2)"}, headers=headers)
            assert response.status_code == 503, response.text
            assert int(response.headers["retry-after"]) > 0
            assert response.json()["error"]["code"] == "unavailable"
        finally:
            other.execute("ROLLBACK")
            other.close()
        response = client.post(SUBMIT, json={"answer": "g (m2 - m1)/(m1 + m2)"}, headers=headers)
        assert response.status_code == 201, response.text
        assert response.json()["attempts_used"] == 1
