"""Where a worker's CPU goes on a bench/targets.py phase: cProfile over its jobs, graded as a worker does.

    .venv/bin/python bench/profile_phase.py [--phase new] [--checks 2000] [--top 40] [--sort tottime]

The phase's bodies (`distinct`, `same`, `new`, `renamed`) are read by the CheckIn schema as the server
reads them and graded with `app.grading.worker.grade` after the worker's own warm-up; only the grading is
profiled. Prints the CPU ms per check (without the profiler) and the profile's top functions.
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import time
from typing import Any

from distinct_cpu import PHASES, bodies


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--phase", choices=PHASES, default="new")
    parser.add_argument("--checks", type=int, default=2000)
    parser.add_argument("--top", type=int, default=40)
    parser.add_argument("--sort", default="tottime")
    parser.add_argument("--kind", choices=("all", "symbolic"), default="symbolic")
    args = parser.parse_args()
    from pydantic import TypeAdapter

    from app.grading.worker import grade
    from app.schemas.check import CheckIn

    adapter: TypeAdapter[Any] = TypeAdapter(CheckIn)
    made = bodies(args.phase)
    if args.kind == "symbolic":
        made = [body for body in made if body["kind"] == "symbolic"]
    jobs = [adapter.validate_python(body).job() for body in made]
    import app.grading.preload  # noqa: F401 - the fork server's warm-up, as a worker inherits it

    for job in jobs[-200:]:
        grade(job)
    half = args.checks // 2
    started = time.process_time()
    for job in jobs[:half]:
        grade(job)
    plain = (time.process_time() - started) / half * 1e3
    profile = cProfile.Profile()
    profile.enable()
    for job in jobs[half : args.checks]:
        grade(job)
    profile.disable()
    print(f"{args.phase}: {plain:.3f} ms CPU per {args.kind} check (without the profiler)")
    pstats.Stats(profile).sort_stats(args.sort).print_stats(args.top)


if __name__ == "__main__":
    main()
