"""Seconds from `physcheck serve` to a 200 from `/ready`: cold (nothing persisted) and warm (restarts).

    .venv/bin/python bench/ready_time.py [--cold-runs 2] [--warm-runs 5] [--directory DIR]

Starts its own servers (bench/load.py's OwnServer: a free 127.0.0.1 port, its own process group, a
SQLite database in a temporary directory). Each cold start is on a fresh database: it stores the bank
from the shipped bank (`physcheck bank build`, app/shipped_bank.py) when one was built for this code,
else (or with `--derive`) derives the whole bank in worker processes, and persists it. The warm starts
are restarts on the last cold start's database, which load the compiled bank instead. Python compiles
every module it imports that has no bytecode yet: with PYTHONDONTWRITEBYTECODE set (this machine's
environment) a checkout never keeps any, so time a checkout after `python -m compileall -q app physics
problems`, as a package install (pip, the Docker image) leaves it. Printed: every time with the median of each, in wall seconds and in CPU seconds
(all the server's processes up to the 200: the server, the workers' fork server, the workers and a
cold start's derivation processes; on a
loaded machine wall time is mostly waiting for a core, CPU time is not). /ready is polled every 20 ms.

With `--directory DIR` the database is kept in DIR (created if missing): a later run on the same DIR
skips the cold starts (the bank is persisted there already) and times only warm starts, so that code
changes to start-up can be compared before and after without deriving the bank again.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import shutil
import statistics
import tempfile
import time
from pathlib import Path

import httpx
from load import OwnServer

POLL = 0.02
READY_TIMEOUT = 900.0  # a cold start derives the whole bank: minutes on a busy machine
TICKS = os.sysconf("SC_CLK_TCK")


def group_cpu(group: int) -> float:
    """CPU seconds (user and system) used so far by the live processes of a process group and by the
    children they have waited for (a cold start's derivation processes, which have exited by then)."""
    total = 0
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        with contextlib.suppress(OSError):
            # After the command name (in parentheses, may hold spaces): state, ppid, pgrp, ... utime,
            # stime, cutime and cstime at fields 14 to 17 of the whole line.
            fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            if int(fields[2]) == group:
                total += sum(int(field) for field in fields[11:15])
    return total / TICKS


def time_to_ready(server: OwnServer) -> tuple[float, float]:
    """(wall, CPU) seconds from starting the server to its first 200 from /ready."""
    started = time.perf_counter()
    server.start()
    assert server.process is not None
    try:
        with httpx.Client(trust_env=False, timeout=2) as client:
            while time.perf_counter() - started < READY_TIMEOUT:
                if server.process.poll() is not None:
                    raise RuntimeError(f"the server exited:\n{server.log_tail()}")
                with contextlib.suppress(httpx.HTTPError):
                    if client.get(f"{server.url}/ready").status_code == 200:
                        return time.perf_counter() - started, group_cpu(server.process.pid)
                time.sleep(POLL)
        raise RuntimeError(f"not ready in {READY_TIMEOUT:g} s:\n{server.log_tail()}")
    finally:
        server.stop()


def report(label: str, runs: list[tuple[float, float]]) -> None:
    walls = ", ".join(f"{wall:.2f}" for wall, _ in runs)
    cpus = ", ".join(f"{cpu:.2f}" for _, cpu in runs)
    print(
        f"{label}: wall median {statistics.median(w for w, _ in runs):.2f} s of {walls}; "
        f"CPU median {statistics.median(c for _, c in runs):.2f} s of {cpus}",
        flush=True,
    )


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--cold-runs", type=int, default=2)
    parser.add_argument("--warm-runs", type=int, default=5)
    parser.add_argument("--directory", type=Path, help="keep the database here (reused when present)")
    parser.add_argument("--derive", action="store_true", help="cold starts derive the bank (no shipped bank)")
    args = parser.parse_args()
    with contextlib.ExitStack() as stack:
        if args.directory is None:
            root = Path(stack.enter_context(tempfile.TemporaryDirectory(prefix="physcheck-ready-")))
        else:
            root = args.directory
            root.mkdir(parents=True, exist_ok=True)
        directory = root
        cold: list[tuple[float, float]] = []
        if not (root / "bench.db").exists():
            for run in range(args.cold_runs):
                last = run == args.cold_runs - 1
                directory = root if last else Path(tempfile.mkdtemp(prefix="physcheck-cold-"))
                server = OwnServer(directory, check_workers=None)
                if args.derive:
                    server.env["PHYSCHECK_SHIPPED_BANK"] = "false"
                try:
                    cold.append(time_to_ready(server))
                finally:
                    if not last:
                        shutil.rmtree(directory)
            report("cold (nothing persisted)", cold)
        server = OwnServer(directory, check_workers=None)
        report("warm (restart, bank persisted)", [time_to_ready(server) for _ in range(args.warm_runs)])


if __name__ == "__main__":
    main()
