"""CPU milliseconds per distinct check as a grading worker spends it, two checkouts compared in lockstep.

    .venv/bin/python bench/distinct_cpu.py OLD_DIR NEW_DIR [--kind all|symbolic|numeric] [--rounds 30]
        [--phase distinct|same|new|renamed]

Each checkout grades in its own process (`app.grading.worker.grade` on the jobs of a bench/targets.py
phase's bodies, read by the CheckIn schema as the server reads them: `distinct`, distinct answers to
known references; `same`, check_bench's answers in parse_expr's syntax; `new`, new references over the
usual names; `renamed`, new references under names never seen); the bodies are this checkout's, so both
sides grade the very same texts. The two take turns, one round of `--per` checks each, so a loaded
machine moves both alike. Prints each side's median CPU per check and
the median of the per-round ratios new/old. A checkout is made with `git archive <commit> | tar -x -C DIR`.
`--per-body` prints each body's median instead (one checkout: OLD_DIR only). `--old-env NAME=VALUE`
(repeatable) sets a variable for the old side only: the same checkout against itself with, say,
`MPMATH_NOGMPY=1` measures what a library's backend is worth.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

PHASES = ("distinct", "same", "new", "renamed")


def bodies(phase: str) -> list[dict[str, Any]]:
    """The phase's request bodies, as bench/targets.py sends them."""
    from targets import distinct_checks, new_reference_checks, renamed_checks, same_checks

    made = {
        "distinct": distinct_checks,
        "same": same_checks,
        "new": new_reference_checks,
        "renamed": renamed_checks,
    }[phase]
    return [json.loads(call.body or b"") for call in made()]


def child(tree: Path, kind: str, per: int, source: Path) -> None:
    """Grade `per` jobs per line read from stdin; print the CPU ms per check of each round."""
    sys.path[:0] = [str(tree), str(tree / "bench")]
    from pydantic import TypeAdapter

    from app.grading.worker import grade, warm_up_jobs
    from app.schemas.check import CheckIn

    adapter: TypeAdapter[Any] = TypeAdapter(CheckIn)
    jobs = [adapter.validate_python(body).job() for body in json.loads(source.read_text())]
    if kind != "all":
        jobs = [job for job in jobs if (type(job).__name__ == "SymbolicJob") == (kind == "symbolic")]
    for job in (*warm_up_jobs(), *jobs[:200]):  # warm-up: tables built on first use, the references
        grade(job)
    position = 200
    for _ in sys.stdin:
        if position + per > len(jobs):
            position = 0
        batch = jobs[position : position + per]
        position += per
        started = time.process_time()
        for job in batch:
            grade(job)
        print((time.process_time() - started) / per * 1e3, flush=True)


def per_body(tree: Path, rounds: int, phase: str) -> None:
    sys.path[:0] = [str(tree), str(tree / "bench")]
    from pydantic import TypeAdapter
    from targets import DISTINCT_VARIANTS

    from app.grading.worker import grade, warm_up_jobs
    from app.schemas.check import CheckIn

    adapter: TypeAdapter[Any] = TypeAdapter(CheckIn)
    made = bodies(phase)
    width = len(made) // DISTINCT_VARIANTS
    for job in warm_up_jobs():
        grade(job)
    for index in range(width):
        jobs = [adapter.validate_python(body).job() for body in made[index::width]]
        grade(jobs[0])
        timings = []
        for round_ in range(rounds):
            batch = jobs[1 + round_ * 10 : 11 + round_ * 10]
            started = time.process_time()
            for job in batch:
                grade(job)
            timings.append((time.process_time() - started) / len(batch) * 1e3)
        body = made[index]
        print(f"{statistics.median(timings):7.3f} ms  {body['kind']:9} {body['answer'].strip()[:50]!r}")


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("old", type=Path)
    parser.add_argument("new", type=Path, nargs="?")
    parser.add_argument("--kind", choices=("all", "symbolic", "numeric"), default="all")
    parser.add_argument("--phase", choices=PHASES, default="distinct")
    parser.add_argument("--rounds", type=int, default=30)
    parser.add_argument("--per", type=int, default=50, help="checks per round")
    parser.add_argument("--per-body", action="store_true")
    parser.add_argument("--old-env", action="append", default=[], metavar="NAME=VALUE")
    parser.add_argument("--child", type=Path, help=argparse.SUPPRESS)  # the bodies' file
    args = parser.parse_args()
    if args.child:
        child(args.old, args.kind, args.per, args.child)
        return
    if args.per_body:
        per_body(args.old, min(args.rounds, 30), args.phase)
        return
    if args.new is None:
        parser.error("give two checkouts (or --per-body with one)")
    trees = (args.old.resolve(), args.new.resolve())
    source = Path(tempfile.mkstemp(prefix="distinct-cpu-", suffix=".json")[1])
    source.write_text(json.dumps(bodies(args.phase)))
    command = [sys.executable, __file__, "--child", str(source), "--kind", args.kind, "--per", str(args.per)]
    old_env = {**os.environ, **dict(setting.split("=", 1) for setting in args.old_env)}
    processes = [
        subprocess.Popen(
            [*command, str(tree)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
            env=old_env if side == 0 else None,
        )
        for side, tree in enumerate(trees)
    ]
    timings: tuple[list[float], list[float]] = ([], [])
    for round_ in range(args.rounds):
        for side in (0, 1) if round_ % 2 == 0 else (1, 0):
            stdin, stdout = processes[side].stdin, processes[side].stdout
            assert stdin is not None and stdout is not None
            stdin.write("go\n")
            stdin.flush()
            timings[side].append(float(stdout.readline()))
    for process in processes:
        assert process.stdin is not None
        process.stdin.close()
        process.wait()
    source.unlink()
    for tree, found in zip(trees, timings, strict=True):
        print(f"{tree}: {statistics.median(found):.3f} ms CPU per check (median of {args.rounds} rounds)")
    ratios = sorted(new / old for old, new in zip(*timings, strict=True))
    quarter = len(ratios) // 4
    print(
        f"new/old per round: median {statistics.median(ratios):.3f} "
        f"(quartiles {ratios[quarter]:.3f} to {ratios[-1 - quarter]:.3f}; {args.kind} checks, {args.phase})"
    )


if __name__ == "__main__":
    main()
