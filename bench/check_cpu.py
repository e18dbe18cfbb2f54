"""CPU milliseconds per check in this process, prepared reference and new reference: medians of rounds.

    .venv/bin/python bench/check_cpu.py [--rounds 20] [--tree DIR]

CPU time (not wall time) so that a loaded machine moves the figures less. `--tree DIR` grades with the
code of another checkout (e.g. `git archive <commit> | tar -x -C DIR`), to compare before and after in
the same minutes: run the two alternately. The checks are bench/check_bench.py's ten typical answers.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any


def per_check_ms(check: Callable[..., bool], cases: list[Any], rounds: int) -> list[float]:
    out = []
    for _ in range(rounds):
        started = time.process_time()
        for case in cases:
            check(*case)
        out.append((time.process_time() - started) / len(cases) * 1e3)
    return out


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--rounds", type=int, default=20)
    parser.add_argument("--tree", type=Path, help="grade with the code of this checkout")
    args = parser.parse_args()
    if args.tree is not None:
        sys.path[:0] = [str(args.tree), str(args.tree / "bench")]
    from check_bench import CASES, physcheck_check, physcheck_new_reference

    for case in CASES:  # warm-up: imports and the tables built on first use
        physcheck_check(*case)
    prepared = per_check_ms(physcheck_check, CASES, args.rounds)
    new = per_check_ms(physcheck_new_reference, CASES, max(3, args.rounds // 2))
    print(
        f"prepared reference {statistics.median(prepared):.3f} ms   "
        f"new reference {statistics.median(new):.3f} ms   (CPU per check, medians)"
    )


if __name__ == "__main__":
    main()
