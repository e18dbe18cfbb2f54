"""Derivation (vetting) time of every bank problem: load its model and derive it from scratch (both
methods or more, the proofs, the simulation, the generated mistakes and limits), the median of a few
runs per problem, in this one process; then the total of the medians.

    .venv/bin/python bench/derive_times.py [--runs 3] [--problem ID ...]

Times are CPU seconds of this process (`time.process_time`), so a busy machine slows them less than it
slows wall-clock time; compare the figures of one run with each other.
"""

from __future__ import annotations

import argparse
import statistics
import time

from sympy.core.cache import clear_cache

from physics.engine import derivation, load_model
from problems.loader import load_bank
from problems.symbols import symbol_table

uncached = derivation._derive.__wrapped__  # each run derives from scratch


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--problem", action="append", help="only this problem (repeatable)")
    args = parser.parse_args()
    documents = [d for d in load_bank(check_meaning=False) if not args.problem or d.id in args.problem]
    medians: list[float] = []
    print(f"{'problem':28} {'median CPU s':>12} {'min':>7} {'max':>7}   ({args.runs} runs)")
    for doc in documents:
        table = symbol_table(doc)
        times = []
        for _ in range(args.runs):
            clear_cache()  # sympy's own cache would make later runs look faster than a first vetting
            start = time.process_time()
            uncached(load_model(doc.model or {}, table))
            times.append(time.process_time() - start)
        median = statistics.median(times)
        medians.append(median)
        print(f"{doc.id:28} {median:12.2f} {min(times):7.2f} {max(times):7.2f}")
    print(f"{'total (sum of medians)':28} {sum(medians):12.2f}   over {len(documents)} problems")
    if medians:
        print(f"{'slowest':28} {max(medians):12.2f}")


if __name__ == "__main__":
    main()
