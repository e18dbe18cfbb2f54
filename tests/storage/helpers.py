"""Builders shared by the storage contract tests."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from app.storage import Stores
from app.storage.protocols import Filed
from physics.verdict import Verdict
from tests.db.helpers import DOCUMENT, INCORRECT, PART, PROBLEM


def store_problem(stores: Stores, problem_id: str = PROBLEM) -> int:
    """A built-in problem to submit against; returns its version."""
    return stores.problems.save_builtin(problem_id, {**DOCUMENT, "id": problem_id}).version


def submit(
    stores: Stores,
    version: int = 1,
    verdict: Verdict = INCORRECT,
    *,
    student: str = "s1",
    part: str = PART,
    problem: str = PROBLEM,
    answer: str = "-m g",
    max_attempts: int | None = None,
) -> Filed:
    return stores.submissions.file(
        problem_id=problem,
        problem_version=version,
        part_id=part,
        student=student,
        answer=answer,
        verdict=verdict,
        max_attempts=max_attempts,
    )


def in_parallel(count: int, work: Callable[[int], Any]) -> list[Any]:
    """Run work(i) in `count` threads started together; the results, or the exceptions raised."""
    barrier = threading.Barrier(count)
    results: list[Any] = [None] * count

    def run(index: int) -> None:
        barrier.wait()
        try:
            results[index] = work(index)
        except Exception as error:
            results[index] = error

    threads = [threading.Thread(target=run, args=(index,)) for index in range(count)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return results
