"""Where a server's CPU goes on one bench/targets.py phase: the server process against its workers.

    .venv/bin/python bench/server_cpu.py [--phase new] [--duration 8] [--concurrency 16] [--py-spy DIR]

Starts its own physcheck server (bench/load.py's OwnServer), sends the phase's bodies with wrk for
`--duration` seconds after a warm-up on other texts, and prints the CPU milliseconds per request that
the server process and the grading workers spent (from /proc, every process of the server's group).
With `--py-spy DIR` (py-spy installed), the collapsed stacks of the server process and of one worker, each
sampled for the phase's duration, are written to DIR (bench/stacks.py sums them by function).
"""

from __future__ import annotations

import argparse
import contextlib
import subprocess
import sys
import tempfile
from pathlib import Path

from load import Call, OwnServer
from ready_time import TICKS
from targets import (
    WARM_UP_FIRST,
    distinct_checks,
    identical_check,
    new_reference_checks,
    renamed_checks,
    same_checks,
    wrk_measure,
)

MAKERS = {
    "distinct": distinct_checks,
    "identical": lambda first=0: identical_check(),  # the verdict cache: the server alone
    "same": same_checks,
    "new": new_reference_checks,
    "renamed": renamed_checks,
}


def group_processes(group: int) -> dict[int, tuple[int, float, float, float]]:
    """pid -> (parent pid, user and system CPU seconds so far, CPU seconds of its children that have
    exited and been waited for) of every live process of the group: the fork server's children are
    workers, so the workers replaced during a phase (every `worker_max_tasks` jobs) count there."""
    found = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        with contextlib.suppress(OSError):
            fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            if int(fields[2]) == group:
                user, system, children_user, children_system = (int(f) / TICKS for f in fields[11:15])
                found[int(entry.name)] = (int(fields[1]), user, system, children_user + children_system)
    return found


def role(parent: int, pid: int, server: int) -> str:
    """The server, its fork server (its child), or a grading worker (the fork server's children)."""
    if pid == server:
        return "server"
    return "fork server" if parent == server else "workers"


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--phase", choices=sorted(MAKERS), default="new")
    parser.add_argument("--duration", type=float, default=8.0)
    parser.add_argument("--concurrency", type=int, default=16)
    parser.add_argument("--py-spy", type=Path, help="write flame graphs of the server and a worker here")
    args = parser.parse_args()
    make = MAKERS[args.phase]
    with tempfile.TemporaryDirectory(prefix="physcheck-server-cpu-") as tmp:
        server = OwnServer(Path(tmp), None)
        server.env["PHYSCHECK_WARM_UP"] = "false"
        try:
            key = server.create_key()
            server.start()
            server.wait_ready()
            assert server.process is not None
            pid = server.process.pid
            options = argparse.Namespace(threads=1, concurrency=args.concurrency, warmup=0, duration=2.0)
            warm: list[Call] = make(WARM_UP_FIRST)[:5000]
            wrk_measure(server.url, key, "(warm-up)", warm, options, Path(tmp))
            before = group_processes(pid)
            spies = []
            if args.py_spy is not None:
                args.py_spy.mkdir(parents=True, exist_ok=True)
                worker = next(p for p, (parent, *_) in before.items() if role(parent, p, pid) == "workers")
                for who, target in (("server", pid), ("worker", worker)):
                    out = args.py_spy / f"{args.phase}-{who}.txt"
                    spies.append(
                        subprocess.Popen(
                            [
                                str(Path(sys.executable).parent / "py-spy"),
                                "record",
                                "-p",
                                str(target),
                                "-d",
                                str(int(args.duration)),
                                "-o",
                                str(out),
                                "--format",
                                "raw",
                            ],
                            stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL,
                        )
                    )
            options.duration = args.duration
            result = wrk_measure(server.url, key, args.phase, make(), options, Path(tmp))
            after = group_processes(pid)
            for spy in spies:
                spy.wait()
        finally:
            server.stop()
    # The kernel's share (system time: sockets, pipes, waking processes) apart from the program's own.
    spent: dict[str, tuple[float, float]] = {}
    for p, (parent, user, system, children) in after.items():
        name = role(parent, p, pid)
        _, user_before, system_before, children_before = before.get(p, (parent, 0.0, 0.0, 0.0))
        so_far = spent.get(name, (0.0, 0.0))
        spent[name] = (so_far[0] + user - user_before, so_far[1] + system - system_before)
        if name == "fork server":  # workers that exited during the phase (user and system together)
            gone = spent.get("workers", (0.0, 0.0))
            spent["workers"] = (gone[0] + children - children_before, gone[1])
    for name, (user, system) in sorted(spent.items()):
        per = 1e3 / result.requests
        print(
            f"{name:<12}{(user + system) * per:8.3f} ms CPU per request "
            f"(user {user * per:.3f}, system {system * per:.3f})"
        )
    sys.stdout.flush()


if __name__ == "__main__":
    main()
