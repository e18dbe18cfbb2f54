"""A database outage is a 503 with Retry-After on a live connection, never a 500 or an exit; it heals itself."""

from __future__ import annotations

import http.client
import json
import threading
import time
from pathlib import Path

import httpx
import pytest
from sqlalchemy.engine import make_url

from app.db.database import Database
from app.db.migrate import migrate
from app.keys import create_key
from tests.service.live import LiveServer, free_port
from tests.service.tcp_proxy import TcpProxy

pytestmark = [pytest.mark.slow, pytest.mark.postgres]

DEADLINE = 90  # only so that a server that never recovers fails the test instead of hanging it


@pytest.fixture
def proxied(postgres_server, tmp_path: Path):
    """A migrated database with a key, reached by the server only through a proxy the test controls."""
    url = postgres_server.create_database()
    migrate(url)
    database = Database(url)
    try:
        key = create_key(database, "instructor", "prof")[0]
    finally:
        database.dispose()
    real = make_url(url)
    proxy = TcpProxy((real.host or "127.0.0.1", real.port or 5432), free_port())
    through_proxy = real.set(host="127.0.0.1", port=proxy.port).render_as_string(hide_password=False)
    yield proxy, through_proxy, key
    proxy.down()
    postgres_server.drop_database(url)


def _get(connection: http.client.HTTPConnection, path: str, key: str) -> tuple[int, dict[str, str], dict]:
    connection.request("GET", path, headers={"Authorization": f"Bearer {key}"})
    response = connection.getresponse()
    body = json.loads(response.read())
    return response.status, {k.lower(): v for k, v in response.getheaders()}, body


def test_an_outage_answers_503_on_the_same_connection_and_heals(proxied, tmp_path: Path):
    proxy, url, key = proxied
    proxy.up()
    server = LiveServer(url, tmp_path / "server.log", warm_up="false").start()
    try:
        connection = http.client.HTTPConnection("127.0.0.1", server.port, timeout=30)
        assert _get(connection, "/v1/problems", key)[0] == 200
        socket_before = connection.sock

        proxy.down()
        status, headers, body = _get(connection, "/v1/problems", key)
        assert status == 503, body
        assert int(headers["retry-after"]) > 0
        assert body["error"]["code"] == "unavailable" and set(body["error"]) == {"code", "message", "details"}
        assert headers.get("connection", "").lower() != "close"
        assert connection.sock is socket_before, "the keep-alive connection was closed"
        assert httpx.get(f"{server.url}/ready", timeout=30).status_code == 503

        proxy.up()
        deadline = time.monotonic() + DEADLINE
        while (status := _get(connection, "/v1/problems", key)[0]) != 200:
            assert status == 503
            assert time.monotonic() < deadline, "did not recover"
            time.sleep(0.2)
        assert connection.sock is socket_before
        assert httpx.get(f"{server.url}/ready", timeout=30).status_code == 200
        connection.close()
    finally:
        server.kill()


def test_a_server_started_during_an_outage_waits_for_the_database(proxied, tmp_path: Path):
    proxy, url, key = proxied  # the proxy is down: nothing listens on its port yet
    log = tmp_path / "server.log"
    server = LiveServer(url, log, warm_up="false")
    started: list[BaseException | None] = []
    starting = threading.Thread(target=lambda: started.append(_start(server)), daemon=True)
    starting.start()
    try:
        deadline = time.monotonic() + DEADLINE
        while "waiting for the database" not in (log.read_text() if log.exists() else ""):
            assert time.monotonic() < deadline, "no log line says the server is waiting"
            assert not started, f"the server gave up: {started}"
            time.sleep(0.2)
        assert server.process is not None and server.process.poll() is None, "the server exited"
        proxy.up()
        starting.join(timeout=DEADLINE)
        assert started == [None], started
        response = httpx.get(f"{server.url}/v1/problems", headers={"Authorization": f"Bearer {key}"})
        assert response.status_code == 200
    finally:
        server.kill()


def _start(server: LiveServer) -> BaseException | None:
    try:
        server.start(timeout=DEADLINE)
    except BaseException as error:
        return error
    return None
