"""A real `physcheck serve` survives SIGKILL of a grading worker and of the fork server behind them."""

from __future__ import annotations

import itertools
import os
import signal
import time
from pathlib import Path

import httpx
import pytest

from app.db.database import Database
from app.db.migrate import migrate
from app.keys import create_key
from tests.service.live import LiveServer

pytestmark = pytest.mark.slow

RECOVERY_DEADLINE = 90  # only so that a server that never recovers fails the test instead of hanging it
BODY = {
    "kind": "symbolic",
    "answer": "m g",
    "expected": "g*m",
    "symbols": {"m": {"dimension": "kg"}, "g": {"dimension": "m/s^2"}},
}


def _children(pid: int) -> list[int]:
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:
                continue
            # The command name may hold spaces and parentheses: the fields follow its last ')'.
            if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
                found.append(int(entry.name))
    return found


def _cmdline(pid: int) -> str:
    try:
        return (Path("/proc") / str(pid) / "cmdline").read_bytes().replace(b"\0", b" ").decode()
    except OSError:
        return ""


def _fork_servers(server: LiveServer) -> list[int]:
    assert server.process is not None
    return [p for p in _children(server.process.pid) if "forkserver" in _cmdline(p)]


def _fork_server(server: LiveServer) -> int:
    (found,) = _fork_servers(server)
    return found


_SPELLINGS = itertools.count(2)


def _grading_check(http: httpx.Client) -> httpx.Response:
    """A check of an answer the server has not graded yet: a remembered verdict needs no worker."""
    n = next(_SPELLINGS)
    return http.post("/v1/check", json={**BODY, "answer": f"{n} m g / {n}"})


def _recovers(server: LiveServer, http: httpx.Client) -> list[int]:
    """Poll /ready and a check until both succeed; return every status seen meanwhile."""
    seen, deadline = [], time.monotonic() + RECOVERY_DEADLINE
    while True:
        ready = httpx.get(f"{server.url}/ready", timeout=10)
        check = _grading_check(http)
        seen += [ready.status_code, check.status_code]
        for response in (ready, check):
            if response.status_code == 503:
                assert response.headers["Retry-After"], response.text
                assert set(response.json()["error"]) == {"code", "message", "details"}
        if ready.status_code == check.status_code == 200:
            assert check.json()["verdict"] == "correct"
            return seen
        assert time.monotonic() < deadline, f"not recovered; statuses {seen}"
        time.sleep(0.1)


@pytest.fixture
def served(database_url: str, tmp_path: Path):
    migrate(database_url)
    database = Database(database_url)
    try:
        key = create_key(database, "instructor", "prof")[0]
    finally:
        database.dispose()
    server = LiveServer(database_url, tmp_path / "server.log", warm_up="false", check_workers="2").start()
    try:
        with httpx.Client(
            base_url=server.url, headers={"Authorization": f"Bearer {key}"}, timeout=30
        ) as http:
            assert _grading_check(http).status_code == 200
            yield server, http
    finally:
        server.kill()


@pytest.mark.sample(1)
def test_grading_resumes_after_an_idle_worker_is_killed(served):
    server, http = served
    workers = _children(_fork_server(server))
    assert workers, "no grading workers found"
    for worker in workers:  # both: the hardest case, no worker left (503s) until a replacement starts
        os.kill(worker, signal.SIGKILL)
    seen = _recovers(server, http)
    assert set(seen) <= {200, 503}, seen
    assert not set(_children(_fork_server(server))) & set(workers)


@pytest.mark.sample(1)
def test_grading_resumes_after_the_fork_server_is_killed(served):
    server, http = served
    fork_server = _fork_server(server)
    os.kill(fork_server, signal.SIGKILL)
    seen = _recovers(server, http)
    assert set(seen) <= {200, 503}, seen
    # A worker of the killed fork server may finish a check before the pool sees it die: wait for the new one.
    deadline = time.monotonic() + 20
    while not (found := _fork_servers(server)) and time.monotonic() < deadline:
        time.sleep(0.2)
    assert found and fork_server not in found, found


@pytest.mark.sample(1)
def test_a_sigterm_to_the_whole_process_group_stops_the_server_without_losing_workers_first(served):
    """As systemd stops a service: the server shuts its workers down itself, with nothing to replace."""
    server, _ = served
    assert server.process is not None
    process, log = server.process, server._log_path
    fork_server = _fork_server(server)
    server.stop()  # SIGTERM to the group, then waits for the server to exit
    assert process.returncode in (0, -signal.SIGTERM)  # uvicorn re-raises the signal once shut down
    text = log.read_text()
    assert "worker died" not in text and "could not start" not in text, text[-2000:]
    deadline = time.monotonic() + RECOVERY_DEADLINE
    while (Path("/proc") / str(fork_server)).exists() and "Z" not in _state(fork_server):
        assert time.monotonic() < deadline, "the fork server outlived the server"
        time.sleep(0.1)


def _state(pid: int) -> str:
    try:
        return (Path("/proc") / str(pid) / "stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return "X"
