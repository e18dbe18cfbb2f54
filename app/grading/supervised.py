"""A pebble process pool that is replaced when it breaks, so one killed worker cannot end upload vetting.

pebble marks a whole pool broken for good when a worker dies while no task is running ("All workers
expired"), or when the fork server that starts workers is gone; every later `schedule` then raises.
A watcher thread notices within `interval` seconds, stops the broken pool, fails whatever was still
waiting on it, and starts (and warms) a fresh one; meanwhile `healthy` is False and `schedule` raises
`PoolUnavailable`, which the service answers with 503 and Retry-After. (Grading, where the cost per
task matters, runs on its own lighter pool, `app.grading.processes`.)
"""

from __future__ import annotations

import contextlib
import logging
import threading
from collections.abc import Callable, Iterable
from concurrent.futures import Future, InvalidStateError
from concurrent.futures.process import BrokenProcessPool
from typing import Any

from pebble import ProcessPool

from app.grading.processes import PoolUnavailable

log = logging.getLogger("physcheck.grading")


class SupervisedPool:
    def __init__(
        self,
        name: str,
        make: Callable[[], ProcessPool],
        warm: Callable[[ProcessPool], None] | None = None,
        interval: float = 0.2,
    ):
        self._name = name
        self._make = make
        self._warm = warm
        self._interval = interval
        self._lock = threading.Lock()
        self._pool: ProcessPool | None = None
        # Futures not yet resolved, with the pool that owes the result: a broken pool never resolves
        # the tasks still in its queue, so replacing it fails them instead of leaving requests hanging.
        self._pending: dict[Future[Any], ProcessPool] = {}
        self._closing = threading.Event()
        self._watcher: threading.Thread | None = None
        self.replacements = 0

    def start(self) -> None:
        self._pool = self._fresh()
        self._watcher = threading.Thread(target=self._watch, name=f"{self._name}-watcher", daemon=True)
        self._watcher.start()

    @property
    def healthy(self) -> bool:
        pool = self._pool
        return pool is not None and bool(pool.active)

    def schedule(self, task: Callable[..., Any], args: Iterable[Any], timeout: float) -> Future[Any]:
        with self._lock:
            pool = self._pool
            if pool is None or not pool.active:
                raise PoolUnavailable(f"the {self._name} pool is being replaced")
            try:
                future: Future[Any] = pool.schedule(task, args=tuple(args), timeout=timeout)
            except RuntimeError as error:  # pebble: "Unexpected error within the Pool"
                raise PoolUnavailable(f"the {self._name} pool is broken") from error
            self._pending[future] = pool
        future.add_done_callback(self._forget)
        return future

    def close(self) -> None:
        self._closing.set()
        if self._watcher is not None:
            self._watcher.join(timeout=10)
        with self._lock:
            pool, self._pool = self._pool, None
        if pool is not None:
            self._retire(pool)

    def _forget(self, future: Future[Any]) -> None:
        with self._lock:
            self._pending.pop(future, None)

    def _fresh(self) -> ProcessPool:
        pool = self._make()
        if self._warm is not None:
            try:
                self._warm(pool)
            except BaseException:
                _stop(pool)
                raise
        return pool

    def _watch(self) -> None:
        while not self._closing.wait(self._interval):
            if self._pool is not None and not self.healthy:
                self._replace()

    def _replace(self) -> None:
        with self._lock:
            broken, self._pool = self._pool, None
        log.error("the %s pool broke (a worker or the fork server died); replacing it", self._name)
        if broken is not None:
            self._retire(broken)
        while not self._closing.is_set():
            try:
                fresh = self._fresh()
            except Exception:
                log.exception("could not start a new %s pool; retrying in 1 s", self._name)
                self._closing.wait(1)
                continue
            with self._lock:
                if self._closing.is_set():
                    _stop(fresh)
                    return
                self._pool = fresh
            self.replacements += 1
            log.warning("the %s pool is back (replacement %d)", self._name, self.replacements)
            return

    def _retire(self, pool: ProcessPool) -> None:
        _stop(pool)
        with self._lock:
            orphans = [future for future, owner in self._pending.items() if owner is pool]
        for future in orphans:
            if not future.done():
                with contextlib.suppress(InvalidStateError):  # pebble resolved it meanwhile
                    future.set_exception(BrokenProcessPool(f"the {self._name} pool was replaced"))


def _stop(pool: ProcessPool) -> None:
    try:
        pool.stop()  # type: ignore[no-untyped-call]
        pool.join(timeout=5)
    except Exception:
        log.exception("stopping a pool failed")
