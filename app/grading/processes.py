"""Killable worker processes, each behind its own pipe, and one supervisor thread for them all.

A caller's thread pickles a job and writes it straight to an idle worker's pipe, or to a busy lane's
(`lanes`: one job waiting in its pipe behind the running one), or queues it, and gets a
`concurrent.futures.Future` (`schedule`), or awaits the answer on its own event loop
(`run`, which spares the server a thread-safe future and its chaining per check). The supervisor thread
waits on every worker's pipe, with the nearest deadline as its timeout: it resolves futures, hands
queued jobs to freed workers, kills a worker whose job overran (`TimeoutError`), notices one that died
(`WorkerDied`), retires one after `max_tasks` jobs, and starts a replacement for each. When no worker is
left and none can be started (the fork server is gone or reloading), `ready` is False and `schedule`
raises `PoolUnavailable` until one starts again (tried every second).

    PoolError
     ├── PoolUnavailable   no worker can take the job now (down, or the pool is closing)
     └── WorkerDied        the worker running the job died (killed from outside, crashed)

A worker's messages: an empty one when it is ready for jobs (so a job's time limit starts when the
worker can start it, not while it is still starting); then the pool sends `pickle((function, args))`
and the worker answers with `pickle((True, result))` or `pickle((False, exception))`, until its pipe
closes, when it exits. Each is framed by its length and written in one `write`, so that one `read`
usually takes it whole (one read may hold two: a lane's two answers, its two jobs): a system call fewer
each way than `Connection.recv_bytes`.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import os
import pickle
import select
import selectors
import signal
import threading
import time
from collections import deque
from collections.abc import Callable, Sequence
from concurrent.futures import Future, InvalidStateError
from concurrent.futures import TimeoutError as FutureTimeout
from dataclasses import dataclass, field
from multiprocessing.connection import Connection
from multiprocessing.context import ForkServerContext
from multiprocessing.process import BaseProcess
from typing import Any

log = logging.getLogger("physcheck.grading")

RETRY_SECONDS = 1.0  # between attempts to start a worker when starting one failed
START_SECONDS = 60.0  # for the first workers to be ready (the fork server may be loading the checker)
CLOSE_SECONDS = 10.0
# The supervisor wakes at least this often, so that a job sent while it sleeps needs no wake-up write
# unless its deadline is nearer (with the service's 2 s limit, never).
IDLE_WAKE_SECONDS = 1.0
# A lane (a worker that takes a second job) holds one job more in its pipe, so that it starts it the
# moment it answers the one before, with its caches warm, instead of sleeping until the supervisor hands
# it one; with one lane per core and the other workers asleep, grading under load cost a tenth less CPU
# (bench/server_cpu.py). A job waiting behind one that has run this long goes back to the queue for
# another worker (the copy left in the pipe is answered to nobody), and the stuck lane's place is taken
# by a worker that was asleep, so a slow answer delays no other check by more than this.
WAITING_BEHIND_SECONDS = 0.05


class PoolError(Exception):
    """The pool could not run the job; never the job's own fault."""


class PoolUnavailable(PoolError):
    """No worker can take work now: none could be started, or the pool is closing."""


class WorkerDied(PoolError):
    """The worker running the job died before answering (the OOM killer, an operator, a crash)."""

    def __init__(self, exitcode: int | None):
        super().__init__(f"the worker died (exit code {exitcode})")
        self.exitcode = exitcode


_HEADER = 4  # bytes of a message's length, big-endian
_CHUNK = 1 << 16


def _framed(payload: bytes) -> bytes:
    return len(payload).to_bytes(_HEADER, "big") + payload


def _send(fd: int, message: bytes) -> None:
    """Write a framed message (blocking: a worker reads its pipe whenever a message is due)."""
    view = memoryview(message)
    while view:
        view = view[os.write(fd, view) :]


class _Messages:
    """The framed messages read from a pipe: one read may hold more than one (a worker may have its
    next job in its pipe, and answer two jobs before the supervisor reads)."""

    def __init__(self, fd: int):
        self.fd = fd
        self._data = b""

    def next(self) -> bytes | None:
        """The next message's payload (reading until it is whole), or None when the other end closed."""
        while not (end := self._end()):
            more = os.read(self.fd, _CHUNK)
            if not more:
                return None
            self._data += more
        message, self._data = self._data[_HEADER:end], self._data[end:]
        return message

    def arrived(self) -> list[bytes] | None:
        """Every message the next read completes (the pipe is readable), or None when it closed."""
        first = self.next()
        if first is None:
            return None
        messages = [first]
        while end := self._end():
            messages.append(self._data[_HEADER:end])
            self._data = self._data[end:]
        return messages

    def _end(self) -> int:
        data = self._data
        if len(data) < _HEADER:
            return 0
        end = _HEADER + int.from_bytes(data[:_HEADER], "big")
        return end if len(data) >= end else 0


def serve(
    conn: Connection,
    initializer: Callable[..., object] | None,
    initargs: Sequence[object],
    tasks: Sequence[Callable[..., object]],
    server: int | None = None,
) -> None:
    """A worker's whole life: run each job read from `conn` and answer on it, until it is closed, or
    until the `server` process ends. `tasks` are only unpickled, and so imported, before the worker says
    it is ready: a job's time limit must not pay for importing its function's module (a test's task may
    import half the app)."""
    del tasks
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the server's; the server stops its workers
    if server is not None:
        _exit_with(server)
    if initializer is not None:
        initializer(*initargs)
    fd = conn.fileno()
    _send(fd, _framed(b""))  # ready
    jobs = _Messages(fd)
    while (message := jobs.next()) is not None:
        try:
            function, args = pickle.loads(message)  # noqa: S301 (from the server, over our own pipe)
            outcome: tuple[bool, object] = (True, function(*args))
        except Exception as error:
            outcome = (False, error)
        try:
            reply = pickle.dumps(outcome, pickle.HIGHEST_PROTOCOL)
        except Exception as error:
            reply = pickle.dumps((False, PoolError(f"the answer could not be pickled: {error!r}")))
        _send(fd, _framed(reply))


def _exit_with(server: int) -> None:
    """End this worker as soon as the server process ends, even in the middle of a job: a server killed
    outright (SIGKILL, the OOM killer) cannot kill its workers, a job (an upload's vetting, a derivation)
    may run for minutes, and each worker left keeps the fork server alive too."""
    try:
        handle = os.pidfd_open(server)
    except ProcessLookupError:  # gone already
        os._exit(1)
    except (AttributeError, OSError):  # no pidfd here: the worker ends at its next read instead
        return

    def watch() -> None:
        select.select([handle], [], [])  # readable once the process has exited
        os._exit(1)

    threading.Thread(target=watch, name="exit-with-server", daemon=True).start()


@dataclass(eq=False)
class _Job:
    message: bytes
    future: Future[Any] | asyncio.Future[Any] | None  # None: a copy handed to another worker instead
    timeout: float
    deadline: float = float("inf")  # set when its worker starts it
    running: bool = False

    @property
    def started(self) -> float:
        return self.deadline - self.timeout


@dataclass(eq=False)
class _Worker:
    process: BaseProcess
    conn: Connection
    answers: _Messages
    # Sent to it, in order: the first is running, the next waits in its pipe. After its removal, the
    # job it died running (failed when it is reaped).
    jobs: deque[_Job] = field(default_factory=deque)
    done: int = 0
    ready: bool = False  # it said so: it takes jobs from now on
    broken: bool = False  # a write to its pipe failed: it died, and takes no job until it is removed


# What the supervisor's selector watches: a live worker's pipe, a gone worker's sentinel, the wake pipe.
_PIPE, _SENTINEL, _WAKE = "pipe", "sentinel", "wake"
# A future with the worker's pickled answer, or with the exception the pool raises in its stead.
_Settled = list[tuple[Future[Any] | asyncio.Future[Any], bytes | BaseException]]


class WorkerPool:
    def __init__(
        self,
        name: str,
        context: ForkServerContext,
        workers: int,
        max_tasks: int,
        initializer: Callable[..., object] | None = None,
        initargs: Sequence[object] = (),
        tasks: Sequence[Callable[..., object]] = (),
        lanes: int = 0,
    ):
        """`lanes`: how many workers take a second job while running one (0: none, every worker takes
        one job at a time); the other workers take jobs only while a lane is stuck on one."""
        self._name = name
        self._context = context
        self._wanted = workers
        self._max_tasks = max_tasks
        self._initializer = initializer
        self._initargs = tuple(initargs)
        self._tasks = tuple(tasks)
        self._lanes = lanes
        self._lock = threading.Lock()
        self._live: list[_Worker] = []
        self._gone: list[_Worker] = []  # removed, until the fork server reports their exit
        self._queue: deque[_Job] = deque()
        self._down = True  # no worker, and none could be started: refuse rather than queue
        self._closed = False
        self._retry_at = 0.0
        self._wake_at = 0.0  # when the supervisor wakes at the latest: a nearer deadline must wake it
        self._selector = selectors.DefaultSelector()
        self._wake_r, self._wake_w = os.pipe()
        os.set_blocking(self._wake_r, False)
        os.set_blocking(self._wake_w, False)
        self._selector.register(self._wake_r, selectors.EVENT_READ, (_WAKE, None))
        self._supervisor: threading.Thread | None = None

    def start(self) -> None:
        """Start every worker and wait until each is ready, then the supervisor; if a worker does not
        start, close the pool and raise."""
        try:
            for _ in range(self._wanted):
                self._add(self._spawn())
            for worker in self._live:
                if not worker.conn.poll(START_SECONDS) or worker.answers.next() is None:
                    raise PoolUnavailable(f"a {self._name} worker did not start")
                worker.ready = True
        except BaseException:
            self.close()
            raise
        self._supervisor = threading.Thread(
            target=self._supervise, name=f"{self._name}-supervisor", daemon=True
        )
        self._supervisor.start()

    @property
    def ready(self) -> bool:
        return not (self._down or self._closed)

    def schedule(self, function: Callable[..., Any], args: tuple[Any, ...], timeout: float) -> Future[Any]:
        """Run `function(*args)` in a worker, killing it if it runs longer than `timeout` seconds. The
        future raises TimeoutError then, WorkerDied if the worker dies, PoolUnavailable if the pool
        loses its last worker or closes first; `schedule` itself raises PoolUnavailable while down."""
        future: Future[Any] = Future()
        self._enqueue(function, args, timeout, future)
        return future

    async def run(self, function: Callable[..., Any], args: tuple[Any, ...], timeout: float) -> Any:
        """`schedule`'s job, awaited on the running event loop; it raises what that future would."""
        future: asyncio.Future[Any] = asyncio.get_running_loop().create_future()
        self._enqueue(function, args, timeout, future)
        return await future

    def _enqueue(
        self,
        function: Callable[..., Any],
        args: tuple[Any, ...],
        timeout: float,
        future: Future[Any] | asyncio.Future[Any],
    ) -> None:
        job = _Job(_framed(pickle.dumps((function, args), pickle.HIGHEST_PROTOCOL)), future, timeout)
        with self._lock:
            if self._closed:
                raise PoolUnavailable(f"the {self._name} pool is closing")
            if self._down:
                raise PoolUnavailable(f"the {self._name} pool has no worker (one is being started)")
            self._queue.append(job)
            self._dispatch()

    def hurry(self, future: Future[Any]) -> bool:
        """Move `schedule`'s job for `future` to the front of the queue, if it is still waiting there
        (someone waits for it now: a page asking for a problem the first start has not derived yet)."""
        with self._lock:
            job = next((job for job in self._queue if job.future is future), None)
            if job is None:
                return False
            self._queue.remove(job)
            self._queue.appendleft(job)
            return True

    def close(self) -> None:
        """Stop the supervisor, kill the workers, and fail every job not answered yet."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
            self._wake()  # locked: the supervisor closes the wake pipe on its way out, after this
        supervisor = self._supervisor
        if supervisor is not None:
            supervisor.join(CLOSE_SECONDS)
        with self._lock:
            live, self._live = self._live, []
            workers, self._gone = live + self._gone, []
            jobs = [job for worker in workers for job in worker.jobs] + list(self._queue)
            self._queue.clear()
        for worker in live:
            worker.process.kill()
            worker.conn.close()
        for worker in workers:
            worker.process.join(CLOSE_SECONDS)
            with contextlib.suppress(ValueError):  # still running after all: the OS will see to it
                worker.process.close()
        for job in jobs:
            if job.future is not None:
                _settle(job.future, PoolUnavailable(f"the {self._name} pool was closed"))
        if supervisor is None:
            self._release()  # else the supervisor releases them on its way out

    # Below: the supervisor thread's, but for `_dispatch` and `_wake`, which callers run too.

    def _dispatch(self) -> None:
        """Hand queued jobs to the workers that take them now (the lock held)."""
        now = time.monotonic()
        while self._queue:
            worker = self._taker(now)
            if worker is None:
                return
            job = self._queue.popleft()
            assert job.future is not None
            if not job.running:
                if not _running(job.future):
                    continue  # cancelled while queued
                job.running = True
            try:
                _send(worker.conn.fileno(), job.message)
            except OSError:
                # It died; its end of the pipe tells the supervisor. The job goes to the next.
                worker.broken = True
                self._queue.appendleft(job)
                continue
            worker.jobs.append(job)
            if len(worker.jobs) == 1:
                job.deadline = now + job.timeout
                if job.deadline < self._wake_at:
                    self._wake_at = job.deadline
                    self._wake()

    def _taker(self, now: float) -> _Worker | None:
        """The worker that takes the next job: an idle one; else, with lanes, the lane whose running job
        started earliest takes one more, to start when it answers. The lanes are the first `lanes` ready
        workers not stuck on a job (running longer than WAITING_BEHIND_SECONDS): the others stay asleep
        until a lane is stuck, then stand in for it."""
        lanes: list[_Worker] = []
        for worker in self._live:
            stuck = worker.jobs and worker.jobs[0].started <= now - WAITING_BEHIND_SECONDS
            if worker.ready and not worker.broken and not stuck:
                lanes.append(worker)
        if self._lanes:
            lanes = lanes[: self._lanes]
        idle = next((worker for worker in lanes if not worker.jobs), None)
        if idle is not None or not self._lanes:
            return idle
        second = [w for w in lanes if len(w.jobs) == 1 and w.done + 2 < self._max_tasks]
        return min(second, key=lambda w: w.jobs[0].started, default=None)

    def _wake(self) -> None:
        with contextlib.suppress(OSError):  # full: a wake-up is already pending
            os.write(self._wake_w, b"\0")

    def _supervise(self) -> None:
        try:
            while not self._closed:
                try:
                    self._round()
                except Exception:
                    log.exception("the %s pool's supervisor failed; going on", self._name)
                    time.sleep(RETRY_SECONDS)
        finally:
            if self._closed:
                self._release()

    def _round(self) -> None:
        """Wait for an answer, a death or a deadline; settle them, replace workers, dispatch."""
        with self._lock:
            self._wake_at = self._next_wake()
            timeout = max(0.0, self._wake_at - time.monotonic())
        events = self._selector.select(timeout)
        answers: list[tuple[_Worker, list[bytes] | None]] = []
        gone: list[_Worker] = []
        for key, _ in events:
            kind, worker = key.data
            if kind == _WAKE:
                with contextlib.suppress(BlockingIOError):
                    os.read(self._wake_r, 4096)
            elif kind == _PIPE:
                try:
                    answers.append((worker, worker.answers.arrived()))
                except OSError:
                    answers.append((worker, None))
            else:
                gone.append(worker)
        settled: _Settled = []
        with self._lock:
            if self._closed:
                return
            for worker, arrived in answers:
                if arrived is None:
                    self._lost(worker, settled)
                else:
                    for answer in arrived:
                        self._answered(worker, answer, settled)
            self._expire(time.monotonic(), settled)
            for worker in gone:
                self._reap(worker, settled)
        # Replacements first: a caller told its worker died or overran finds a live one when it retries.
        self._replenish(settled)
        with self._lock:
            self._dispatch()
        for future, outcome in settled:
            _settle(future, outcome)

    def _next_wake(self) -> float:
        now = time.monotonic()
        wake = now + IDLE_WAKE_SECONDS
        for worker in self._live:
            if worker.jobs:
                wake = min(wake, worker.jobs[0].deadline)
            if worker.jobs and self._lanes:
                # Soon enough to find a lane stuck, or a job sent meanwhile waiting behind one too long,
                # without a wake-up written for every job sent.
                wake = min(wake, now + WAITING_BEHIND_SECONDS)
            if len(worker.jobs) > 1:
                wake = min(wake, worker.jobs[0].started + WAITING_BEHIND_SECONDS)
        if len(self._live) < self._wanted:
            wake = min(wake, self._retry_at)
        return wake

    def _answered(self, worker: _Worker, answer: bytes, settled: _Settled) -> None:
        if not worker.jobs:  # a new worker, ready
            worker.ready = True
            return
        job = worker.jobs.popleft()
        if job.future is not None:
            settled.append((job.future, answer))
        worker.done += 1
        if worker.jobs:  # it has started the next one
            worker.jobs[0].deadline = time.monotonic() + worker.jobs[0].timeout
        elif worker.done >= self._max_tasks:
            # Memory hygiene: a fresh worker forks from the clean fork server; this one exits on EOF.
            self._remove(worker)

    def _lost(self, worker: _Worker, settled: _Settled) -> None:
        """Its pipe closed: it died. Its job fails once its death is reaped, with the exit code; the
        one waiting behind it goes to another worker."""
        self._requeue_waiting(worker)
        if not worker.ready:
            # Its start failed (its initializer, say): starting the next at once could loop for ever.
            log.error("a new %s worker died as it started; retrying in %g s", self._name, RETRY_SECONDS)
            self._retry_at = time.monotonic() + RETRY_SECONDS
        else:
            log.warning("a %s worker died; replacing it", self._name)
        self._remove(worker)
        if not self._live:
            self._fall_down(settled)

    def _expire(self, now: float, settled: _Settled) -> None:
        for worker in [w for w in self._live if w.jobs and w.jobs[0].deadline <= now]:
            self._requeue_waiting(worker)
            job = worker.jobs.popleft()
            if job.future is not None:
                settled.append((job.future, FutureTimeout()))
            worker.process.kill()
            self._remove(worker)
        for worker in self._live:
            if len(worker.jobs) > 1 and worker.jobs[0].started + WAITING_BEHIND_SECONDS <= now:
                self._requeue_waiting(worker)

    def _requeue_waiting(self, worker: _Worker) -> None:
        """The jobs waiting in `worker`'s pipe go back to the front of the queue; the copies it still
        holds are answered to nobody."""
        waiting = [job for job in list(worker.jobs)[1:] if job.future is not None]
        for job in reversed(waiting):
            self._queue.appendleft(job)
        running = worker.jobs.popleft() if worker.jobs else None
        worker.jobs = deque(_Job(job.message, None, job.timeout) for job in worker.jobs)
        if running is not None:
            worker.jobs.appendleft(running)

    def _remove(self, worker: _Worker) -> None:
        """Out of the pool: its pipe closed, its sentinel watched until its exit is known."""
        self._live.remove(worker)
        self._selector.unregister(worker.conn)
        worker.conn.close()
        self._gone.append(worker)
        self._selector.register(worker.process.sentinel, selectors.EVENT_READ, (_SENTINEL, worker))

    def _reap(self, worker: _Worker, settled: _Settled) -> None:
        self._gone.remove(worker)
        self._selector.unregister(worker.process.sentinel)
        worker.process.join(0)  # the sentinel is ready: this reads the exit code, never waits
        if worker.jobs and worker.jobs[0].future is not None:
            settled.append((worker.jobs[0].future, WorkerDied(worker.process.exitcode)))
        worker.process.close()

    def _fall_down(self, settled: _Settled) -> None:
        """No worker left after a fault: refuse new jobs, and fail the queued ones rather than keep them
        waiting for as long as the fork server takes to come back."""
        self._down = True
        settled += [
            (job.future, PoolUnavailable(f"the {self._name} pool lost its workers"))
            for job in self._queue
            if job.future is not None  # always: only a copy left in a pipe has none
        ]
        self._queue.clear()

    def _replenish(self, settled: _Settled) -> None:
        """Start workers up to the number wanted (unlocked: a start takes milliseconds, or seconds when
        the fork server must be started again); after a failure, try again after RETRY_SECONDS."""
        while len(self._live) < self._wanted and not self._closed and time.monotonic() >= self._retry_at:
            try:
                worker = self._spawn()
            except Exception:
                log.exception("could not start a %s worker; retrying in %g s", self._name, RETRY_SECONDS)
                self._retry_at = time.monotonic() + RETRY_SECONDS
                with self._lock:
                    if not self._live:
                        self._fall_down(settled)
                return
            with self._lock:
                if self._closed:
                    worker.process.kill()
                    worker.conn.close()
                    return
                was_down = self._down
                self._add(worker)
            if was_down:
                log.warning("the %s pool has a worker again", self._name)

    def _spawn(self) -> _Worker:
        ours, theirs = self._context.Pipe()
        process = self._context.Process(
            target=serve,
            args=(theirs, self._initializer, self._initargs, self._tasks, os.getpid()),
            name=f"{self._name}-worker",
            daemon=True,
        )
        try:
            process.start()
        except BaseException:
            ours.close()
            raise
        finally:
            theirs.close()  # the worker's end: only the worker may hold it, or its death shows no EOF
        return _Worker(process, ours, _Messages(ours.fileno()))

    def _add(self, worker: _Worker) -> None:
        """In the pool, though idle only once it says it is ready (jobs meanwhile wait in the queue)."""
        self._live.append(worker)
        self._selector.register(worker.conn, selectors.EVENT_READ, (_PIPE, worker))
        self._down = False

    def _release(self) -> None:
        with self._lock:
            self._selector.close()
            os.close(self._wake_r)
            os.close(self._wake_w)


def _running(future: Future[Any] | asyncio.Future[Any]) -> bool:
    """Marked running, unless it was cancelled while queued (an event loop's future is only read: its
    loop alone may change it)."""
    if isinstance(future, Future):
        return future.set_running_or_notify_cancel()
    return not future.cancelled()


def _settle(future: Future[Any] | asyncio.Future[Any], outcome: bytes | BaseException) -> None:
    """Resolve with a worker's pickled answer, or with the exception the pool raised in its stead."""
    ok, value = _read(outcome)
    if isinstance(future, Future):
        with contextlib.suppress(InvalidStateError):  # cancelled while queued
            _resolve(future, ok, value)
    else:
        with contextlib.suppress(RuntimeError):  # its loop has closed: nobody is waiting any more
            future.get_loop().call_soon_threadsafe(_resolve, future, ok, value)


def _read(outcome: bytes | BaseException) -> tuple[bool, Any]:
    """(True, the result) from a worker's pickled answer; else (False, the exception to raise)."""
    if not isinstance(outcome, bytes):
        return False, outcome
    try:
        ok, value = pickle.loads(outcome)  # noqa: S301 (from our own worker, over our own pipe)
    except Exception as error:
        return False, PoolError(f"the worker's answer could not be read: {error!r}")
    return ok, value


def _resolve(future: Future[Any] | asyncio.Future[Any], ok: bool, value: Any) -> None:
    if future.done():  # cancelled (the request went away), or settled by close() meanwhile
        return
    if ok:
        future.set_result(value)
    else:
        future.set_exception(value)
