"""A sample of many like cases (every bank problem's page, say), a new sample each day.

A check over many like cases runs on `sampled(cases, k)` in the default suite, so that the whole
suite stays within its time on a slow machine; every case is covered within a few days' runs. The
sample is drawn from a seed: PHYSCHECK_TEST_SEED when set, else the day's number, fixed once per run
in the controller (`fix_seed`, from conftest's pytest_configure) so that every xdist worker collects
the same tests. pytest's summary prints the seed, which draws a failing run's sample again;
PHYSCHECK_TEST_ALL=1 runs every case.

A parametrized test too costly to run every case of each time is marked `@pytest.mark.sample(k)`:
`k` of its cases (its databases, widths, models...) run, drawn the same way (conftest deselects the rest).
"""

from __future__ import annotations

import datetime
import os
import random
from collections.abc import Callable, Sequence
from typing import TypeVar

SEED_ENV = "PHYSCHECK_TEST_SEED"
ALL_ENV = "PHYSCHECK_TEST_ALL"
T = TypeVar("T")


def fix_seed() -> None:
    """The run's seed, put in the environment before the xdist workers start: they inherit it."""
    os.environ.setdefault(SEED_ENV, str(datetime.date.today().toordinal()))


def described() -> str:
    """pytest's summary line: how to draw this run's sample again, or run every case."""
    if os.environ.get(ALL_ENV):
        return f"sampled checks: every case ({ALL_ENV} is set)"
    seed = os.environ[SEED_ENV]
    return (
        f"sampled checks: seed {seed} ({SEED_ENV}={seed} draws the same sample; {ALL_ENV}=1 runs every case)"
    )


def sampled(cases: Sequence[T], k: int, name: str) -> list[T]:
    """`k` of `cases` (in their order), drawn from the run's seed and `name` (each check its own draw)."""
    if os.environ.get(ALL_ENV) or len(cases) <= k:
        return list(cases)
    fix_seed()
    chosen = set(random.Random(f"{os.environ[SEED_ENV]}:{name}").sample(range(len(cases)), k))
    return [case for index, case in enumerate(cases) if index in chosen]


def sample_marked(
    items: Sequence[T], k_of: Callable[[T], int | None], test_of: Callable[[T], str]
) -> list[T]:
    """The collected items to run: of each test whose `k_of` is a number (its `sample` mark), `k` of its
    parametrized cases, drawn as `sampled` draws them (by the test's own name); every other item."""
    groups: dict[str, list[T]] = {}
    for item in items:
        if k_of(item) is not None:
            groups.setdefault(test_of(item), []).append(item)
    kept = {id(item) for test, cases in groups.items() for item in sampled(cases, k_of(cases[0]) or 0, test)}
    return [item for item in items if k_of(item) is None or id(item) in kept]
