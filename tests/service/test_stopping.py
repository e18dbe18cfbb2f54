"""Every way of stopping a real `physcheck serve` ends every process it started: SIGTERM in the middle of
a first start's derivation, SIGTERM or Ctrl-C while it waits for its database, and a plain SIGTERM to the
whole process group; none logs a worker's death as a fault."""

from __future__ import annotations

import contextlib
import os
import signal
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.service.live import LiveServer, free_port

pytestmark = pytest.mark.slow

# Only so that a server that never stops fails the test instead of hanging it. The server's own bound is
# PHYSCHECK_SHUTDOWN_TIMEOUT_SECONDS (8 s) for requests in progress, then every worker is killed.
DEADLINE = 60
FAULT_LINES = ("died", "replacing it", "broke", "Traceback")


def group(pgid: int) -> list[int]:
    """The live processes (zombies aside) of a process group, from /proc."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            stat = Path(f"/proc/{entry}/stat").read_text()
        except OSError:  # gone meanwhile
            continue
        state, _ppid, pgrp = stat[stat.rindex(")") + 2 :].split()[:3]
        if int(pgrp) == pgid and state != "Z":
            found.append(int(entry))
    return found


def compiled_rows(database: Path) -> int:
    """Problems stored compiled in the server's SQLite file so far (the engine's digest row aside)."""
    with contextlib.closing(sqlite3.connect(database, timeout=30)) as connection:
        try:
            (count,) = connection.execute("SELECT count(*) FROM compiled_problems").fetchone()
        except sqlite3.OperationalError:  # not migrated yet
            return 0
    return int(count) - 1


def wait_for(text: str, log: Path, server: LiveServer) -> None:
    deadline = time.monotonic() + DEADLINE
    while text not in (log.read_text() if log.exists() else ""):
        assert server.process is not None and server.process.poll() is None, log.read_text()
        assert time.monotonic() < deadline, f"the log never said {text!r}"
        time.sleep(0.1)


def stopped(server: LiveServer, sig: signal.Signals, *, whole_group: bool = False) -> list[int]:
    """Send `sig` (to the server, or to its process group); wait for the server to exit and for the
    group to empty; return the processes of the group still alive at the deadline (and kill them)."""
    assert server.process is not None
    pgid = server.process.pid  # LiveServer starts it in a session of its own
    if whole_group:
        os.killpg(pgid, sig)
    else:
        server.process.send_signal(sig)
    with contextlib.suppress(subprocess.TimeoutExpired):  # then it is among those left
        server.process.wait(timeout=DEADLINE)
    deadline = time.monotonic() + DEADLINE
    while (left := group(pgid)) and time.monotonic() < deadline:
        time.sleep(0.2)
    if left:
        os.killpg(pgid, signal.SIGKILL)
    server.kill()
    return left


def test_sigterm_during_a_first_starts_derivation_ends_the_fork_server_and_every_worker(tmp_path: Path):
    log = tmp_path / "server.log"
    database = tmp_path / "fresh.db"
    # Without the shipped bank: where `physcheck bank build` has run, a first start derives nothing.
    server = LiveServer(f"sqlite:///{database}", log, derive_jobs="2", shipped_bank="false")
    server.start_in_background()
    try:
        wait_for("deriving", log, server)  # the bank, never derived in this database
        assert server.process is not None
        deadline = time.monotonic() + DEADLINE
        # One problem derived and stored: the workers are deriving the next ones (49 in all).
        while compiled_rows(database) < 1:
            assert time.monotonic() < deadline, "no problem was derived"
            time.sleep(0.2)
        assert len(group(server.process.pid)) >= 5  # the server, fork server, grading and derivation workers
        left = stopped(server, signal.SIGTERM)
    finally:
        server.kill()
    assert left == [], f"still running after the server stopped: {left}"
    text = log.read_text()
    assert not [line for line in text.splitlines() if any(word in line for word in FAULT_LINES)], text


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT], ids=["SIGTERM", "Ctrl-C"])
@pytest.mark.sample(1)
def test_a_server_waiting_for_its_database_obeys_sigterm_and_ctrl_c(tmp_path: Path, sig: signal.Signals):
    log = tmp_path / "server.log"
    nothing_listens = f"postgresql+psycopg://postgres@127.0.0.1:{free_port()}/test"
    server = LiveServer(nothing_listens, log)
    server.start_in_background()
    try:
        wait_for("waiting for the database", log, server)
        left = stopped(server, sig, whole_group=sig is signal.SIGINT)  # a terminal's Ctrl-C: the group
    finally:
        server.kill()
    assert left == [], f"still running after the server stopped: {left}"
    assert "stopped while waiting for the database" in log.read_text()


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT], ids=["SIGTERM", "Ctrl-C"])
@pytest.mark.sample(1)
def test_a_normal_shutdown_logs_no_worker_fault(tmp_path: Path, sig: signal.Signals):
    log = tmp_path / "server.log"
    server = LiveServer(f"sqlite:///{tmp_path / 'db.sqlite'}", log, warm_up="false").start()
    try:
        left = stopped(server, sig, whole_group=True)  # systemd's way, and a terminal's: the whole group
    finally:
        server.kill()
    assert left == []
    text = log.read_text()
    assert not [line for line in text.splitlines() if any(word in line for word in FAULT_LINES)], text


# A server (this script) with one worker in the middle of an hour-long job, which prints the worker's pid.
LONG_JOB = """
import sys
import time

from app.grading.forkserver import context
from app.grading.processes import WorkerPool


def main():
    pool = WorkerPool("long-jobs", context(), workers=1, max_tasks=10, tasks=(time.sleep,))
    pool.start()
    pool.schedule(time.sleep, (3600,), 3600)
    print(*(worker.process.pid for worker in pool._live), flush=True)
    time.sleep(3600)


if __name__ == "__main__":
    main()
"""


def test_a_server_killed_outright_leaves_no_worker_behind_even_mid_job(tmp_path: Path):
    script = tmp_path / "server.py"
    script.write_text(LONG_JOB)
    server = subprocess.Popen(
        [sys.executable, str(script)], stdout=subprocess.PIPE, text=True, start_new_session=True
    )
    try:
        assert server.stdout is not None
        workers = [int(pid) for pid in server.stdout.readline().split()]
        assert workers and all(pid in group(server.pid) for pid in workers)
        server.kill()  # SIGKILL: no shutdown runs
        server.wait(timeout=DEADLINE)
        deadline = time.monotonic() + DEADLINE
        while (left := group(server.pid)) and time.monotonic() < deadline:
            time.sleep(0.2)
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(server.pid, signal.SIGKILL)
        server.wait(timeout=DEADLINE)
        if server.stdout is not None:
            server.stdout.close()
    assert left == [], f"still running after the server was killed: {left}"
