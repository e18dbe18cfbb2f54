"""A database that accepts connections but never answers: every call is a 503 with Retry-After on a
live connection (never a hung request, never a 500), and the service heals when it answers again."""

from __future__ import annotations

import http.client
import json
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import httpx
import pytest

from tests.service.live import LiveServer
from tests.service.test_database_outage import proxied  # noqa: F401 (fixture)

pytestmark = [pytest.mark.slow, pytest.mark.postgres]

# A request not answered in this long counts as hung: ten times the server's database timeout (2 s).
# Before the timeouts, such requests waited 40 s and more.
HUNG = 20
RECOVERY = 90  # only so that a server that never recovers fails the test instead of hanging it
CALLS = [
    ("GET", "/v1/problems", None),
    ("GET", "/v1/problems/atwood", None),
    ("POST", "/v1/problems/atwood/parts/acceleration/submissions", {"answer": "g (m2 - m1)/(m1 + m2)"}),
    ("GET", "/v1/submissions?problem=atwood", None),
]


def _call(connection: http.client.HTTPConnection, method: str, path: str, body: object, key: str):
    headers = {"Authorization": f"Bearer {key}", "Content-Type": "application/json"}
    connection.request(method, path, body=None if body is None else json.dumps(body), headers=headers)
    response = connection.getresponse()
    return response.status, {k.lower(): v for k, v in response.getheaders()}, json.loads(response.read())


def test_a_black_holed_database_is_503_with_retry_after_and_heals(proxied, tmp_path: Path):  # noqa: F811
    proxy, url, key = proxied
    proxy.up()
    server = LiveServer(url, tmp_path / "server.log", warm_up="false", database_timeout_seconds="2").start()
    try:
        connection = http.client.HTTPConnection("127.0.0.1", server.port, timeout=HUNG)
        assert _call(connection, "GET", "/v1/problems", None, key)[0] == 200
        socket_before = connection.sock

        proxy.black_hole()
        time.sleep(2.5)  # past the key cache, so that the key itself must be looked up too
        for method, path, body in CALLS:
            status, headers, answer = _call(connection, method, path, body, key)
            assert status == 503, (method, path, answer)
            assert int(headers["retry-after"]) > 0
            assert answer["error"]["code"] == "unavailable"
        assert connection.sock is socket_before, "the keep-alive connection was closed"
        assert httpx.get(f"{server.url}/ready", timeout=HUNG).status_code == 503

        # More callers at once than the database has connections: none waits forever for one.
        def one(n: int) -> int:
            response = httpx.get(
                f"{server.url}/v1/problems", headers={"Authorization": f"Bearer {key}"}, timeout=HUNG
            )
            return response.status_code

        with ThreadPoolExecutor(24) as callers:
            assert set(callers.map(one, range(24))) == {503}

        proxy.forward()
        deadline = time.monotonic() + RECOVERY
        while (status := one(0)) != 200:
            assert status == 503
            assert time.monotonic() < deadline, "did not recover"
            time.sleep(0.2)
        connection.close()
    finally:
        server.kill()
    assert "connection was cut" in (tmp_path / "server.log").read_text()
