"""Seconds from `physcheck serve` to a 200 from `/ready`: cold (nothing persisted), then warm (restarts).

    .venv/bin/python bench/ready_time.py [--warm-runs 3] [--directory DIR]

Starts its own server (bench/load.py's OwnServer: a free 127.0.0.1 port, its own process group, a fresh
SQLite database in a temporary directory). The cold start derives the whole bank and persists it; each
warm start is a restart on the same database, which should load the compiled bank instead. Printed:
the cold time and every warm time with their median. /ready is polled every 20 ms.

With `--directory DIR` the database is kept in DIR (created if missing): a later run on the same DIR
skips the cold start (the bank is persisted there already) and times only warm starts, so that code
changes to start-up can be compared before and after without deriving the bank again.
"""

from __future__ import annotations

import argparse
import contextlib
import statistics
import tempfile
import time
from pathlib import Path

import httpx
from load import OwnServer

POLL = 0.02
READY_TIMEOUT = 900.0  # a cold start derives the whole bank: minutes on a busy machine


def time_to_ready(server: OwnServer) -> float:
    started = time.perf_counter()
    server.start()
    try:
        with httpx.Client(trust_env=False, timeout=2) as client:
            while time.perf_counter() - started < READY_TIMEOUT:
                if server.process is not None and server.process.poll() is not None:
                    raise RuntimeError(f"the server exited:\n{server.log_tail()}")
                with contextlib.suppress(httpx.HTTPError):
                    if client.get(f"{server.url}/ready").status_code == 200:
                        return time.perf_counter() - started
                time.sleep(POLL)
        raise RuntimeError(f"not ready in {READY_TIMEOUT:g} s:\n{server.log_tail()}")
    finally:
        server.stop()


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--warm-runs", type=int, default=3)
    parser.add_argument("--directory", type=Path, help="keep the database here (reused when present)")
    args = parser.parse_args()
    with contextlib.ExitStack() as stack:
        if args.directory is None:
            directory = Path(stack.enter_context(tempfile.TemporaryDirectory(prefix="physcheck-ready-")))
        else:
            directory = args.directory
            directory.mkdir(parents=True, exist_ok=True)
        persisted = (directory / "bench.db").exists()
        server = OwnServer(directory, check_workers=None)
        if not persisted:
            cold = time_to_ready(server)
            print(f"cold (nothing persisted): {cold:.2f} s")
        warm = [time_to_ready(server) for _ in range(args.warm_runs)]
        shown = ", ".join(f"{t:.2f}" for t in warm)
        print(f"warm (restart, bank persisted): median {statistics.median(warm):.2f} s of {shown}")


if __name__ == "__main__":
    main()
