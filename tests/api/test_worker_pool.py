"""The grading pool's own processes: overrun jobs are killed, dead and worn workers replaced, nothing lost."""

from __future__ import annotations

import asyncio
import os
import signal
import time
from collections.abc import Iterator
from concurrent.futures import TimeoutError as FutureTimeout
from contextlib import contextmanager

import pytest

from app.grading import forkserver
from app.grading.processes import PoolUnavailable, WorkerDied, WorkerPool

DEADLINE = 60  # only so that a broken pool fails the test instead of hanging it


@contextmanager
def started(workers: int = 1, max_tasks: int = 100, lanes: int = 0) -> Iterator[WorkerPool]:
    pool = WorkerPool("test", forkserver.context(), workers=workers, max_tasks=max_tasks, lanes=lanes)
    pool.start()
    try:
        yield pool
    finally:
        pool.close()


def pid(pool: WorkerPool) -> int:
    answer = pool.schedule(os.getpid, (), DEADLINE).result(DEADLINE)
    assert isinstance(answer, int)
    return answer


def gone(process: int) -> bool:
    """Dead (or a zombie of the fork server's, not yet reaped): never running a job again."""
    try:
        with open(f"/proc/{process}/stat") as stat:
            return stat.read().rsplit(")", 1)[1].split()[0] in {"Z", "X"}
    except FileNotFoundError:
        return True


def test_a_job_past_its_deadline_is_killed_and_its_worker_replaced():
    with started() as pool:
        overrunner = pid(pool)
        with pytest.raises(FutureTimeout):
            pool.schedule(time.sleep, (DEADLINE,), 0.2).result(DEADLINE)
        assert pid(pool) != overrunner
        deadline = time.monotonic() + DEADLINE
        while not gone(overrunner):
            assert time.monotonic() < deadline, "the overrunning worker was not killed"
            time.sleep(0.05)


def test_a_worker_is_recycled_after_max_tasks_and_no_job_is_lost():
    with started(max_tasks=2) as pool:
        one_by_one = [pid(pool) for _ in range(6)]
        assert len(set(one_by_one)) == 3
        assert one_by_one[0] == one_by_one[1] != one_by_one[2] == one_by_one[3] != one_by_one[4]
        at_once = [pool.schedule(os.getpid, (), DEADLINE) for _ in range(9)]
        assert len({future.result(DEADLINE) for future in at_once}) == 5


def test_a_worker_killed_mid_job_fails_that_job_and_is_replaced():
    with started() as pool:
        victim = pid(pool)
        running = pool.schedule(time.sleep, (DEADLINE,), DEADLINE)  # sent to the idle victim at once
        os.kill(victim, signal.SIGKILL)
        with pytest.raises(WorkerDied) as died:
            running.result(DEADLINE)
        assert died.value.exitcode == -signal.SIGKILL
        assert pid(pool) != victim


@pytest.mark.parametrize("lanes", [0, 1, 2])
def test_more_jobs_than_workers_are_queued_and_all_answered(lanes: int):
    with started(workers=2, lanes=lanes) as pool:
        futures = [pool.schedule(pow, (n, 2), DEADLINE) for n in range(20)]
        assert [future.result(DEADLINE) for future in futures] == [n * n for n in range(20)]


def test_an_exception_in_a_job_is_its_futures_exception():
    with started() as pool:
        with pytest.raises(ValueError, match="invalid literal"):
            pool.schedule(int, ("x",), DEADLINE).result(DEADLINE)
        assert pool.schedule(int, ("7",), DEADLINE).result(DEADLINE) == 7


def test_closing_fails_the_running_and_queued_jobs_and_refuses_new_ones():
    with started() as pool:
        pending = [pool.schedule(time.sleep, (DEADLINE,), DEADLINE) for _ in range(4)]
        pool.close()
        for future in pending:
            with pytest.raises(PoolUnavailable):
                future.result(DEADLINE)
        assert not pool.ready
        with pytest.raises(PoolUnavailable):
            pool.schedule(os.getpid, (), DEADLINE)


def test_a_worker_that_cannot_start_fails_the_pools_start():
    pool = WorkerPool(
        "test", forkserver.context(), workers=1, max_tasks=100, initializer=os._exit, initargs=(3,)
    )
    try:
        with pytest.raises(PoolUnavailable, match="did not start"):
            pool.start()
        assert not pool.ready
    finally:
        pool.close()


def test_run_answers_on_the_awaiting_event_loop_as_schedule_does():
    async def both() -> tuple[int, BaseException]:
        answer = await pool.run(pow, (7, 2), DEADLINE)
        with pytest.raises(FutureTimeout) as overran:
            await pool.run(time.sleep, (DEADLINE,), 0.2)
        return answer, overran.value

    with started() as pool:
        answer, overran = asyncio.run(both())
        assert answer == 49 and isinstance(overran, FutureTimeout)


def test_a_job_whose_caller_went_away_leaves_the_pool_answering():
    """A request cancelled while its job runs, its event loop closed before the answer comes back."""

    async def abandon() -> None:
        waiting = asyncio.ensure_future(pool.run(time.sleep, (0.3,), DEADLINE))
        await asyncio.sleep(0.05)
        waiting.cancel()

    with started() as pool:
        worker = pid(pool)
        asyncio.run(abandon())
        queued = [pool.schedule(pow, (n, 3), DEADLINE) for n in range(3)]
        assert [future.result(DEADLINE) for future in queued] == [0, 1, 8]
        assert pid(pool) == worker  # answered, not killed: the job ran out its 0.3 s


def test_a_lane_answers_each_of_the_jobs_sent_into_its_pipe_in_turn():
    # One lane, no other worker: every job after the first waits in its pipe or the queue, and a read
    # may hold two answers.
    with started(workers=1, lanes=1) as pool:
        futures = [pool.schedule(pow, (n, 3), DEADLINE) for n in range(200)]
        assert [future.result(DEADLINE) for future in futures] == [n**3 for n in range(200)]


def test_a_job_waiting_behind_a_slow_one_is_answered_by_a_worker_at_rest():
    with started(workers=2, lanes=1) as pool:
        lane = pid(pool)
        slow = pool.schedule(time.sleep, (DEADLINE / 4,), DEADLINE)
        behind = pool.schedule(os.getpid, (), DEADLINE)  # into the lane's pipe, behind the slow job
        answered_by = behind.result(DEADLINE / 8)
        assert not slow.done()
        assert answered_by != lane


def test_a_job_waiting_behind_an_overrun_is_answered_after_it_and_not_lost():
    with started(workers=1, lanes=1) as pool:
        overrunner = pid(pool)
        overrun = pool.schedule(time.sleep, (DEADLINE,), 0.5)
        behind = pool.schedule(os.getpid, (), DEADLINE)
        with pytest.raises(FutureTimeout):
            overrun.result(DEADLINE)
        assert behind.result(DEADLINE) != overrunner  # by the worker that replaced it


def test_a_lanes_death_sends_the_job_waiting_behind_to_another_worker():
    with started(workers=2, lanes=1) as pool:
        victim = pid(pool)
        running = pool.schedule(time.sleep, (DEADLINE,), DEADLINE)
        behind = pool.schedule(os.getpid, (), DEADLINE)
        os.kill(victim, signal.SIGKILL)
        with pytest.raises(WorkerDied):
            running.result(DEADLINE)
        assert behind.result(DEADLINE) != victim
