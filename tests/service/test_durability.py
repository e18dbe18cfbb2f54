"""Nothing acknowledged is lost: submissions answered 201 survive a SIGKILL of the server."""

from __future__ import annotations

import threading
from pathlib import Path

import httpx
import pytest

from app.db.database import Database
from app.db.migrate import migrate
from app.keys import create_key
from tests.service.live import LiveServer

pytestmark = pytest.mark.slow

ANSWERS = [
    "-m g sin(θ)cos(θ)/(M + m sin^2 θ)",
    "0",
    "m g",
    "m g +",
]  # correct, wrong, wrong dimension, invalid


def _keys(url: str) -> tuple[str, str]:
    migrate(url)
    database = Database(url)
    try:
        return create_key(database, "instructor", "prof")[0], create_key(database, "student", "ada")[0]
    finally:
        database.dispose()


def _all_submission_ids(server: LiveServer, key: str) -> set[str]:
    ids, cursor = set(), None
    while True:
        params = {"limit": 1000} | ({"cursor": cursor} if cursor else {})
        page = httpx.get(
            f"{server.url}/v1/submissions", params=params, headers={"Authorization": f"Bearer {key}"}
        ).json()
        ids |= {item["submission_id"] for item in page["items"]}
        cursor = page["next"]
        if cursor is None:
            return ids


def test_acknowledged_submissions_survive_sigkill(database_url: str, tmp_path: Path):
    instructor, student = _keys(database_url)
    # Load from four clients: the student's own per-minute budget and two-check share would only slow it.
    server = LiveServer(
        database_url,
        tmp_path / "server.log",
        warm_up="false",
        student_rate_limit_per_minute="100000",
        student_checks_in_flight="8",
    ).start()
    acknowledged: list[str] = []
    lock, stop = threading.Lock(), threading.Event()

    def client(n: int) -> None:
        # Generous timeout: the first requests wait while the server compiles the problem (no warm-up).
        with httpx.Client(
            base_url=server.url, headers={"Authorization": f"Bearer {student}"}, timeout=60
        ) as http:
            i = n
            while not stop.is_set():
                i += 1
                try:
                    response = http.post(
                        "/v1/problems/moving-wedge/parts/wedge_acceleration/submissions",
                        json={"answer": ANSWERS[i % len(ANSWERS)]},
                    )
                except httpx.TransportError:
                    return  # the server is gone; anything unacknowledged may be lost
                if response.status_code == 201:
                    with lock:
                        acknowledged.append(response.json()["submission_id"])

    threads = [threading.Thread(target=client, args=(n,)) for n in range(4)]
    for thread in threads:
        thread.start()
    try:
        while len(acknowledged) < 40 and all(t.is_alive() for t in threads):
            threading.Event().wait(0.05)
        server.kill()
    finally:
        stop.set()
        for thread in threads:
            thread.join(timeout=20)
        server.kill()
    assert len(acknowledged) >= 40
    restarted = LiveServer(database_url, tmp_path / "server.log", port=server.port, warm_up="false").start()
    try:
        stored = _all_submission_ids(restarted, instructor)
    finally:
        restarted.stop()
    assert set(acknowledged) <= stored
