"""CPU microseconds to read (or refuse) one author's number, and to validate a `POST /v1/check` body
carrying it: medians of rounds, ordinary numbers beside hostile ones.

    .venv/bin/python bench/hostile_numbers.py [--rounds 30]

The one decimal reader (physics/numeric/decimals.py) refuses by size before any arithmetic; this
shows what a refusal costs next to reading 9.81, and that the body's validation adds no more.
"""

from __future__ import annotations

import argparse
import contextlib
import statistics
import time
from collections.abc import Callable
from decimal import Decimal

from pydantic import ValidationError

from physics.numeric import NotADecimal, read_decimal
from problems.kinds.numeric import NumericCheckIn

CASES: list[tuple[str, object]] = [
    ("9.81", 9.81),
    ("6.022e23 text", "6.022e23"),
    ("4000-digit int", 10**4000),
    ("1e999999999 text", "1e999999999"),
    ("1e + 190 nines", "1e" + "9" * 190),
    ("100k-digit text", "9" * 100_000),
    ("1e-999999999999999999 Decimal", Decimal("1e-999999999999999999")),
]


def _read(value: object) -> None:
    with contextlib.suppress(NotADecimal):
        read_decimal(value)


def _validate(value: object) -> None:
    with contextlib.suppress(ValidationError):
        NumericCheckIn.model_validate({"kind": "numeric", "answer": "1", "expected": value})


def median_us(work: Callable[[object], None], value: object, rounds: int, repeat: int = 200) -> float:
    samples = []
    for _ in range(rounds):
        started = time.process_time()
        for _ in range(repeat):
            work(value)
        samples.append((time.process_time() - started) / repeat * 1e6)
    return statistics.median(samples)


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--rounds", type=int, default=30)
    args = parser.parse_args()
    print(f"{'number':32} {'read µs':>10} {'body µs':>10}   (CPU, median of {args.rounds})")
    for name, value in CASES:
        read = median_us(_read, value, args.rounds)
        body = median_us(_validate, value, args.rounds)
        print(f"{name:32} {read:10.1f} {body:10.1f}")


if __name__ == "__main__":
    main()
