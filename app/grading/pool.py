"""A pool of killable worker processes with a bounded queue in front of it."""

from __future__ import annotations

import asyncio
import logging
import multiprocessing
from collections.abc import Callable
from concurrent.futures import TimeoutError as FutureTimeout
from typing import TypeVar

from pebble import ProcessExpired, ProcessPool

from app.errors import Busy
from app.grading.worker import WARM_UP_JOBS, SpecProblem, grade, limit_memory, read_only
from physics.checking import CheckJob, Preview
from physics.errors import CheckTimeout, SpecError, TooLarge
from physics.verdict import InputProblem, Verdict

log = logging.getLogger("physcheck.grading")
T = TypeVar("T")

TIMEOUT_MESSAGE = "Could not check this in time; simplify your answer."


class GradingPool:
    def __init__(
        self,
        workers: int,
        timeout: float,
        memory_mb: int,
        max_tasks: int,
        queue_size: int,
        max_answer_chars: int = 2000,
        per_owner: int = 2,
        task: Callable[[CheckJob], Verdict | SpecProblem] = grade,
    ):
        self._task = task
        self._max_answer_chars = max_answer_chars
        self._per_owner = per_owner
        self._owners: dict[str, int] = {}
        self._workers = workers
        self._timeout = timeout
        self._memory_mb = memory_mb
        self._max_tasks = max_tasks
        self._capacity = workers + queue_size
        self._in_flight = 0
        self._pool: ProcessPool | None = None

    def start(self) -> None:
        # forkserver: workers fork from a clean, pre-warmed process, not from the threaded server.
        context = multiprocessing.get_context("forkserver")
        context.set_forkserver_preload(["app.grading.worker"])
        self._pool = ProcessPool(
            max_workers=self._workers,
            max_tasks=self._max_tasks,
            initializer=limit_memory,
            initargs=(self._memory_mb,),
            context=context,
        )
        # One small job per worker so the first real request does not pay for lazy imports.
        warm = [self._submit(self._task, job) for _ in range(self._workers) for job in WARM_UP_JOBS]
        for future in warm:
            future.result(timeout=60)

    def close(self) -> None:
        if self._pool is not None:
            self._pool.stop()  # type: ignore[no-untyped-call]
            self._pool.join(timeout=5)
            self._pool = None

    @property
    def in_flight(self) -> int:
        return self._in_flight

    def _submit(self, task: Callable[[CheckJob], object], job: CheckJob):  # type: ignore[no-untyped-def]
        assert self._pool is not None, "GradingPool.start() was not called"
        return self._pool.schedule(task, args=(job,), timeout=self._timeout)

    async def _run(self, task: Callable[[CheckJob], T | SpecProblem], job: CheckJob, owner: str | None) -> T:
        """Run in a worker within the queue's capacity, and within `owner`'s share of the workers (so
        one student's slow answers cannot hold them all); raises FutureTimeout or ProcessExpired."""
        if self._in_flight >= self._capacity:
            raise Busy("The grading queue is full; try again shortly.", retry_after=1)
        if owner is not None and self._owners.get(owner, 0) >= self._per_owner:
            raise Busy("Your previous answers are still being checked; try again in a moment.", retry_after=1)
        self._in_flight += 1
        if owner is not None:
            self._owners[owner] = self._owners.get(owner, 0) + 1
        try:
            outcome: T | SpecProblem = await asyncio.wrap_future(self._submit(task, job))
        finally:
            self._in_flight -= 1
            if owner is not None:
                self._owners[owner] -= 1
                if not self._owners[owner]:
                    del self._owners[owner]
        if isinstance(outcome, SpecProblem):
            raise SpecError(outcome.message, outcome.path)
        return outcome

    async def preview(self, job: CheckJob, owner: str | None = None) -> Preview:
        """How the answer reads, also in a worker (the parser is bounded, but not trusted to be)."""
        if len(job.answer) > self._max_answer_chars:
            return Preview(
                None, InputProblem(f"The answer is longer than {self._max_answer_chars} characters.")
            )
        try:
            return await self._run(read_only, job, owner)
        except (FutureTimeout, ProcessExpired):
            return Preview(None, InputProblem(TIMEOUT_MESSAGE))

    async def check(self, job: CheckJob, owner: str | None = None) -> Verdict:
        """Grade in a worker; a timeout or a killed worker is an `invalid` verdict, never a hang."""
        if len(job.answer) > self._max_answer_chars:
            # Refused before any worker sees it: the cheapest hostile answer is the longest.
            limit = self._max_answer_chars
            return Verdict.invalid(
                TooLarge(f"The answer is longer than {limit} characters; shorten it.", limit)
            )
        try:
            return await self._run(self._task, job, owner)
        except FutureTimeout:
            return Verdict.invalid(CheckTimeout(TIMEOUT_MESSAGE))
        except ProcessExpired as error:
            log.error("grading worker died (exit code %s)", error.exitcode)
            return Verdict.invalid(TooLarge("This answer is too large to check; simplify it."))
