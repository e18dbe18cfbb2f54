"""Checks per second and p50/p99 latency of physcheck's checker against the naive way, in one run.

The naive way is what many graders do: `parse_expr` on both texts and `simplify(a - b) == 0`. Both are
timed in this process on the same typical physics answers (correct and wrong ones mixed); physcheck's
reference preparation is cached as it is in a worker, and the cache warm-up is not timed; a second
physcheck line reads and prepares the reference again for every check.

    .venv/bin/python bench/check_bench.py [--rounds 30]
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Callable

import sympy
from sympy.parsing.sympy_parser import parse_expr, standard_transformations

from physics.checking import SymbolDecl, run_job
from physics.symbolic.judge import REMEMBERED
from problems.kinds.symbolic import SymbolicJob, adhoc_part, adhoc_tree_question

ANGLE = SymbolDecl("theta", "1", range=("0", "pi/2"))
KG = "kg"
ACC = "m/s^2"

# (answer, expected, symbols): typical answers from the bank's problems, a third of them wrong.
CASES: list[tuple[str, str, tuple[SymbolDecl, ...]]] = [
    (
        "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)**2)",
        "-m*g*tan(theta)/(M*(1 + tan(theta)**2) + m*tan(theta)**2)",
        (SymbolDecl("m", KG), SymbolDecl("M", KG), SymbolDecl("g", ACC), ANGLE),
    ),
    (
        "(M + m)*g*sin(theta)/(M + m*sin(theta)**2)",
        "(M + m)*g*sin(theta)/(M + m*sin(theta)**2)",
        (SymbolDecl("m", KG), SymbolDecl("M", KG), SymbolDecl("g", ACC), ANGLE),
    ),
    (
        "M*m*g*cos(theta)/(M + m*sin(theta)**2)",
        "M*m*g*sin(theta)/(M + m*sin(theta)**2)",
        (SymbolDecl("m", KG), SymbolDecl("M", KG), SymbolDecl("g", ACC), ANGLE),
    ),
    (
        "g*r**2/(r**2 + k**2)",
        "g/(1 + k**2/r**2)",
        (SymbolDecl("g", ACC), SymbolDecl("r", "m"), SymbolDecl("k", "m")),
    ),
    (
        "m*g*k**2/(r**2 + k**2)",
        "m*g*r**2/(r**2 + k**2)",
        (SymbolDecl("m", KG), SymbolDecl("g", ACC), SymbolDecl("r", "m"), SymbolDecl("k", "m")),
    ),
    (
        "12*U0/r0*((r0/r)**13 - (r0/r)**7)",
        "-(U0*(-12*r0**12/r**13 + 12*r0**6/r**7))",
        (SymbolDecl("U0", "J"), SymbolDecl("r0", "m"), SymbolDecl("r", "m")),
    ),
    (
        "12*sqrt(U0/m)/r0",
        "sqrt(144*U0/(m*r0**2))",
        (SymbolDecl("U0", "J"), SymbolDecl("r0", "m"), SymbolDecl("m", KG)),
    ),
    (
        "(m + M)/m*sqrt(2*g*L*(1 - cos(theta)))",
        "2*(m + M)/m*sqrt(g*L)*sin(theta/2)",
        (SymbolDecl("m", KG), SymbolDecl("M", KG), SymbolDecl("g", ACC), SymbolDecl("L", "m"), ANGLE),
    ),
    (
        "g*(sin(alpha) - mu*cos(alpha))",
        "g*(sin(alpha) + mu*cos(alpha))",
        (SymbolDecl("g", ACC), SymbolDecl("mu", "1"), SymbolDecl("alpha", "1", range=("0", "pi/2"))),
    ),
    (
        "(m2 - m1*sin(theta))*g/(m1 + m2)",
        "g*(m2 - m1*sin(theta))/(m2 + m1)",
        (SymbolDecl("m1", KG), SymbolDecl("m2", KG), SymbolDecl("g", ACC), ANGLE),
    ),
]


def physcheck_check(answer: str, expected: str, symbols: tuple[SymbolDecl, ...]) -> bool:
    """A check whose reference is prepared and whose answer is new to this process: a judgement the
    worker remembers per answer expression would otherwise serve every round after the first."""
    REMEMBERED.clear()
    return run_job(SymbolicJob(answer=answer, expected=expected, symbols=symbols)).outcome.value == "correct"


def physcheck_new_reference(answer: str, expected: str, symbols: tuple[SymbolDecl, ...]) -> bool:
    """The same, with the reference read and prepared again for every check (a reference never seen)."""
    adhoc_part.cache_clear()
    adhoc_tree_question.cache_clear()
    return physcheck_check(answer, expected, symbols)


def naive_check(answer: str, expected: str, symbols: tuple[SymbolDecl, ...]) -> bool:
    table = {s.name: sympy.Symbol(s.name, positive=True) for s in symbols}
    a = parse_expr(answer, local_dict=table, transformations=standard_transformations)
    b = parse_expr(expected, local_dict=table, transformations=standard_transformations)
    return bool(sympy.simplify(a - b) == 0)


def measure(check: Callable[[str, str, tuple[SymbolDecl, ...]], bool], rounds: int) -> list[float]:
    timings = []
    for _ in range(rounds):
        for answer, expected, symbols in CASES:
            started = time.perf_counter()
            check(answer, expected, symbols)
            timings.append(time.perf_counter() - started)
    return timings


def summary(name: str, timings: list[float]) -> tuple[float, float]:
    ordered = sorted(timings)
    p50 = statistics.median(ordered)
    p99 = ordered[min(len(ordered) - 1, int(0.99 * len(ordered)))]
    print(
        f"{name:<24} {len(timings) / sum(timings):>10.0f} checks/s   p50 {p50 * 1e3:8.2f} ms   p99 {p99 * 1e3:8.2f} ms"
    )
    return p50, p99


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--rounds", type=int, default=30)
    parser.add_argument("--naive-rounds", type=int, default=3, help="the naive way is slow; fewer rounds")
    args = parser.parse_args()

    disagreements = [c for c in CASES if physcheck_check(*c) != naive_check(*c)]  # also warms caches
    print(f"{len(CASES)} typical answers; the two ways disagree on {len(disagreements)} of them")
    for answer, expected, _ in disagreements:
        print(f"  disagree: {answer}  vs  {expected}")
    ours = summary("physcheck", measure(physcheck_check, args.rounds))
    summary("physcheck, new reference", measure(physcheck_new_reference, args.rounds))
    naive = summary("parse_expr + simplify", measure(naive_check, args.naive_rounds))
    print(f"ratio (naive / physcheck): p50 {naive[0] / ours[0]:.0f}x   p99 {naive[1] / ours[1]:.0f}x")


if __name__ == "__main__":
    main()
