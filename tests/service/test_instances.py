"""Two `physcheck serve` processes on one PostgreSQL database behave as one service."""

from __future__ import annotations

import json
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import httpx
import pytest
import yaml

from app.db.database import Database
from app.db.migrate import migrate
from app.keys import create_key
from tests.service.live import LiveServer

pytestmark = [pytest.mark.slow, pytest.mark.postgres]
BANK = Path(__file__).resolve().parents[2] / "problems" / "bank"
LIMIT = 3


def _limited_atwood() -> dict:
    doc = yaml.safe_load((BANK / "atwood" / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK / "atwood" / "model.yaml").read_text())
    doc.update(id="limited-atwood", max_attempts=LIMIT)
    return doc


@pytest.fixture
def two_servers(postgres_server, tmp_path: Path):
    url = postgres_server.create_database()
    migrate(url)
    database = Database(url)
    try:
        keys = {role: create_key(database, role, role)[0] for role in ("instructor", "student")}
    finally:
        database.dispose()
    servers = [LiveServer(url, tmp_path / f"server-{i}.log", warm_up="false") for i in range(2)]
    try:
        for server in servers:
            server.start()
        yield servers, keys
    finally:
        for server in servers:
            server.stop()


def test_attempt_limits_and_submissions_are_shared_across_instances(two_servers):
    (a, b), keys = two_servers
    instructor = {"Authorization": f"Bearer {keys['instructor']}", "content-type": "application/json"}
    student = {"Authorization": f"Bearer {keys['student']}"}
    student_id = httpx.get(f"{a.url}/v1/problems/atwood", headers=student).json()["student"]
    created = httpx.post(
        f"{a.url}/v1/problems", content=json.dumps(_limited_atwood()), headers=instructor, timeout=120
    )
    assert created.status_code == 201, created.text

    def wrong_answer(i: int) -> int:
        # Filed by the instructor's key for the student: a student's own key may have only two checks
        # in flight per instance, and this is about the attempt limit, not that share.
        server = (a, b)[i % 2]
        response = httpx.post(
            f"{server.url}/v1/problems/limited-atwood/parts/acceleration/submissions",
            json={"answer": f"{i + 1} g", "student": student_id},
            headers=instructor,
            timeout=60,
        )
        return response.status_code

    with ThreadPoolExecutor(max_workers=8) as pool:
        statuses = list(pool.map(wrong_answer, range(10)))
    assert sorted(statuses) == [201] * LIMIT + [409] * (10 - LIMIT)

    # An unreadable answer uses no attempt, so it is still accepted and filed on either instance.
    invalid = httpx.post(
        f"{b.url}/v1/problems/limited-atwood/parts/acceleration/submissions",
        json={"answer": "g +"},
        headers=student,
        timeout=60,
    )
    assert (invalid.status_code, invalid.json()["verdict"]) == (201, "invalid")

    listings = [
        httpx.get(
            f"{server.url}/v1/submissions", params={"problem": "limited-atwood"}, headers=student
        ).json()
        for server in (a, b)
    ]
    assert listings[0] == listings[1]
    assert len(listings[0]["items"]) == LIMIT + 1
