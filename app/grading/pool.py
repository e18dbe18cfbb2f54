"""A pool of killable worker processes with a bounded queue in front of it."""

from __future__ import annotations

import logging
from collections import OrderedDict
from collections.abc import Callable
from concurrent.futures import TimeoutError as FutureTimeout
from typing import TypeVar

from app.errors import Busy, GraderFault, Unavailable
from app.grading import forkserver
from app.grading.processes import PoolUnavailable, WorkerDied, WorkerPool
from app.grading.worker import ROUND_TRIP_JOBS, GraderCrash, SpecProblem, grade, limit_memory, read_only
from physics.checking import CheckJob
from physics.errors import CheckTimeout, SpecError, TooLarge
from physics.verdict import InputProblem, Preview, Verdict

log = logging.getLogger("physcheck.grading")
T = TypeVar("T")

TIMEOUT_MESSAGE = "Could not check this in time; simplify your answer."
RESTARTING_MESSAGE = "Grading is restarting after a fault; try again in a moment."
LOGGED_ANSWER_CHARS = 120
WARM_UP_SECONDS = 60


def _excerpt(answer: str) -> str:
    return answer if len(answer) <= LOGGED_ANSWER_CHARS else answer[:LOGGED_ANSWER_CHARS] + "…"


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
        task: Callable[[CheckJob], Verdict | SpecProblem | GraderCrash] = grade,
        preview_task: Callable[[CheckJob], Preview | SpecProblem | GraderCrash] = read_only,
        verdicts_cached: int = 4096,
        log_answers: bool = False,
        lanes: int = 0,
    ):
        self._log_answers = log_answers
        self._task = task
        self._preview_task = preview_task
        # Grading is a pure function of the job (a stored part's job names its compiled version by
        # digest), so identical jobs share a verdict. Only verdicts a worker returned are kept, never a
        # timeout or a fault, which depend on the moment.
        self._verdicts: OrderedDict[str, Verdict] = OrderedDict()
        self._verdicts_cached = verdicts_cached
        self._max_answer_chars = max_answer_chars
        self._per_owner = per_owner
        self._owners: dict[str, int] = {}
        self._workers = workers
        self._timeout = timeout
        self._memory_mb = memory_mb
        self._max_tasks = max_tasks
        self._lanes = min(lanes, workers)
        self._capacity = workers + queue_size
        self._in_flight = 0
        self._pool: WorkerPool | None = None

    def _answer(self, job: CheckJob) -> dict[str, str]:
        """The answer's start for a log line, when answers may be logged (PHYSCHECK_LOG_ANSWERS)."""
        return {"answer": _excerpt(job.answer)} if self._log_answers else {}

    def start(self) -> None:
        pool = self._new_pool()
        pool.start()
        try:
            self._warm(pool)
        except BaseException:
            pool.close()
            raise
        self._pool = pool

    def _new_pool(self) -> WorkerPool:
        # forkserver: workers fork from a clean, pre-warmed process, not from the threaded server.
        # A fork server that died is started again by multiprocessing on the next worker it must fork.
        return WorkerPool(
            "grading",
            forkserver.context(),
            workers=self._workers,
            max_tasks=self._max_tasks,
            initializer=limit_memory,
            initargs=(self._memory_mb,),
            tasks=(self._task, self._preview_task),
            lanes=self._lanes,
        )

    def _warm(self, pool: WorkerPool) -> None:
        # One small job per worker: every worker is forked and answering before the pool counts as
        # ready (they fork warm from the preloaded fork server, so this takes milliseconds). The first
        # jobs go one to each idle worker.
        warm = [
            pool.schedule(self._task, (job,), WARM_UP_SECONDS)
            for _ in range(self._workers)
            for job in ROUND_TRIP_JOBS
        ]
        for future in warm:
            future.result(timeout=WARM_UP_SECONDS)

    def close(self) -> None:
        if self._pool is not None:
            self._pool.close()
            self._pool = None

    @property
    def ready(self) -> bool:
        """Able to grade now (False while no worker is left and none can be started yet)."""
        return self._pool is not None and self._pool.ready

    @property
    def in_flight(self) -> int:
        return self._in_flight

    async def _run(
        self, task: Callable[[CheckJob], T | SpecProblem | GraderCrash], job: CheckJob, owner: str | None
    ) -> T:
        """Run in a worker within the queue's capacity, and within `owner`'s share of the workers (so
        one student's slow answers cannot hold them all). A timeout raises FutureTimeout (the answer's
        doing); a fault of the grader itself raises Unavailable (503, retry) or GraderFault (500)."""
        assert self._pool is not None, "GradingPool.start() was not called"
        if self._in_flight >= self._capacity:
            raise Busy("The grading queue is full; try again shortly.", retry_after=1)
        if owner is not None and self._owners.get(owner, 0) >= self._per_owner:
            raise Busy("Your previous answers are still being checked; try again in a moment.", retry_after=1)
        self._in_flight += 1
        if owner is not None:
            self._owners[owner] = self._owners.get(owner, 0) + 1
        try:
            outcome: T | SpecProblem | GraderCrash = await self._pool.run(task, (job,), self._timeout)
        except PoolUnavailable as error:
            log.warning("grading refused: %s", error)
            raise Unavailable(RESTARTING_MESSAGE, retry_after=2) from error
        except WorkerDied as error:
            # Killed from outside (the OOM killer, an operator) or crashed: not the answer's fault.
            log.error(
                "grading worker died during a check (exit code %s); not graded",
                error.exitcode,
                extra=self._answer(job),
            )
            raise Unavailable(RESTARTING_MESSAGE, retry_after=1) from error
        finally:
            self._in_flight -= 1
            if owner is not None:
                self._owners[owner] -= 1
                if not self._owners[owner]:
                    del self._owners[owner]
        if isinstance(outcome, SpecProblem):
            raise SpecError(outcome.message, outcome.path)
        if isinstance(outcome, GraderCrash):
            log.error(
                "grading crashed: %s; not graded\n%s",
                outcome.error,
                outcome.traceback,
                extra=self._answer(job),
            )
            raise GraderFault("Grading failed on our side; it has been logged. Nothing was recorded.")
        return outcome

    async def preview(self, job: CheckJob, owner: str | None = None) -> Preview:
        """How the answer reads, also in a worker (the parser is bounded, but not trusted to be)."""
        if len(job.answer) > self._max_answer_chars:
            return Preview(
                None, InputProblem(f"The answer is longer than {self._max_answer_chars} characters.")
            )
        try:
            return await self._run(self._preview_task, job, owner)
        except FutureTimeout:
            return Preview(None, InputProblem(TIMEOUT_MESSAGE))

    async def check(self, job: CheckJob, owner: str | None = None, *, key: str | None = None) -> Verdict:
        """Grade in a worker; a timeout is an `invalid` verdict (the answer's), never a hang; a fault of
        the grader raises Unavailable or GraderFault, never a verdict. `key` names the job in the verdict
        cache in place of `repr(job)`, when the caller has a cheaper name (it must name no other job)."""
        if len(job.answer) > self._max_answer_chars:
            # Refused before any worker sees it: the cheapest hostile answer is the longest.
            limit = self._max_answer_chars
            return Verdict.invalid(
                TooLarge(f"The answer is longer than {limit} characters; shorten it.", limit)
            )
        if key is None:
            key = repr(job)  # a part job's repr shows its digest, not its payload
        known = self._verdicts.get(key)
        if known is not None:
            self._verdicts.move_to_end(key)
            return known
        try:
            verdict: Verdict = await self._run(self._task, job, owner)
        except FutureTimeout:
            return Verdict.invalid(CheckTimeout(TIMEOUT_MESSAGE))
        if self._verdicts_cached and isinstance(verdict, Verdict):
            self._verdicts[key] = verdict
            while len(self._verdicts) > self._verdicts_cached:
                self._verdicts.popitem(last=False)
        return verdict
