"""A deeply nested upload to a real server is a 422 naming the path, and the keep-alive connection it
came on goes on serving (a 500 from a RecursionError used to close it)."""

from __future__ import annotations

import http.client
import json
from pathlib import Path

import pytest

from app.db.database import Database
from app.db.migrate import migrate
from app.keys import create_key
from tests.service.live import LiveServer

pytestmark = pytest.mark.slow

BODIES = [
    ("application/json", b'{"id": "deep", "model": ' + b'{"a": ' * 600 + b"1" + b"}" * 601),
    ("application/yaml", b"id: deep\nmodel: " + b"[" * 600 + b"1" + b"]" * 600),
]


def test_a_deeply_nested_upload_is_422_and_the_connection_goes_on(tmp_path: Path):
    url = f"sqlite:///{tmp_path / 'live.db'}"
    migrate(url)
    database = Database(url)
    try:
        key = create_key(database, "instructor", "prof")[0]
    finally:
        database.dispose()
    server = LiveServer(url, tmp_path / "server.log", warm_up="false").start()
    try:
        connection = http.client.HTTPConnection("127.0.0.1", server.port, timeout=60)
        headers = {"Authorization": f"Bearer {key}"}
        connection.request("GET", "/v1/problems", headers=headers)
        assert connection.getresponse().read() and connection.sock is not None
        socket_before = connection.sock
        for media, body in BODIES:
            connection.request("POST", "/v1/problems", body=body, headers={**headers, "Content-Type": media})
            response = connection.getresponse()
            answer = json.loads(response.read())
            assert response.status == 422, answer
            [detail] = answer["error"]["details"]
            assert detail["path"].startswith("model") and "nested more than" in detail["message"]
            assert connection.sock is socket_before, "the keep-alive connection was closed"
        connection.request("GET", "/v1/problems", headers=headers)
        assert connection.getresponse().status == 200
        assert connection.sock is socket_before
        connection.close()
    finally:
        server.kill()
