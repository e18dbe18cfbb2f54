"""Deriving problems in killable worker processes: the server process never derives a model.

A derivation (the engine's methods and simulation, each part's prepared reference) is seconds of sympy
on a document an author wrote, so, like an upload's vetting, it runs in a worker forked from the fork
server under a hard time limit and the workers' memory limit. What comes back is the compiled problem
as the store keeps it: pickled bytes, which only this service's own workers produce and which
`app.catalog.CompiledStore` seals under the server's secret before they reach the database.

Used for what is not stored yet: a first start's bank, a problem whose stored compilation was made by
other code, one whose row went. An upload arrives compiled by its vetting worker.
"""

from __future__ import annotations

import dataclasses
import pickle
import threading
import traceback
from collections import OrderedDict
from collections.abc import Mapping
from concurrent.futures import Future
from typing import Any

from app.grading import forkserver
from app.grading.processes import PoolUnavailable, WorkerPool
from app.grading.worker import limit_memory
from problems.compiled import CompiledProblem, compile_problem
from problems.errors import ProblemInvalid
from problems.loader import parse_problem

# A derivation leaves sympy's caches behind: a fresh worker from the clean fork server after this many.
DERIVATIONS_PER_WORKER = 20
# Derived payloads kept in this process by document hash: several apps in one process (tests, each on
# a fresh database) share what is a pure function of the document and the code.
REMEMBERED = 256


class DerivationFailed(Exception):
    """The document did not derive (its traceback's text, or why the worker stopped)."""


class DerivationRefused(DerivationFailed):
    """The running engine refuses the document's model or parts, though it was vetted when stored (by
    older code: the engine now refuses what it once verified, such as a period at a wide swing). The
    message has one line per fault, at its path, as an upload's refusal lists them for the author."""


class DerivationTimedOut(DerivationFailed):
    """Killed at the time limit: perhaps only because the machine was busy, so tried again when asked."""


def pack(compiled: CompiledProblem) -> bytes:
    """The compiled problem as the store keeps it (sympy trees pickle; they have no other faithful
    format). Only bytes made by this service are ever unpickled: see `app.catalog.CompiledStore`."""
    return pickle.dumps(compiled, protocol=pickle.HIGHEST_PROTOCOL)


def unpack(payload: bytes, version: int) -> CompiledProblem | None:
    """A packed compiled problem, as `version` (None if it is not one). For bytes this service made
    alone: a worker's answer over its own pipe, or a row whose seal verifies (`CompiledStore`)."""
    compiled = pickle.loads(payload)  # noqa: S301 - this service's own bytes (above)
    if not isinstance(compiled, CompiledProblem):
        return None
    # The same document may be stored as several versions: the content is shared, not the number.
    return dataclasses.replace(compiled, version=version)


def derived_payload(document: dict[str, Any]) -> bytes:
    """The worker's task: the stored (already vetted) document compiled, prepared and packed.

    A failure comes back as DerivationFailed with the traceback's text: the bank's own errors take
    arguments that pickle's rebuilding of an exception does not pass."""
    try:
        doc = parse_problem(document, "json", check_meaning=False)
        return pack(compile_problem(doc).prepare())
    except ProblemInvalid as error:
        raise DerivationRefused(
            "\n".join(f"{path}: {message}" if path else message for path, message in error.errors)
        ) from None
    except MemoryError:
        raise DerivationFailed("deriving ran out of memory (the workers' memory limit)") from None
    except Exception:
        raise DerivationFailed(traceback.format_exc()) from None


_remembered: OrderedDict[str, bytes] = OrderedDict()
_remembered_lock = threading.Lock()


def _remember(key: str, payload: bytes) -> None:
    with _remembered_lock:
        _remembered[key] = payload
        while len(_remembered) > REMEMBERED:
            _remembered.popitem(last=False)


def forget_derived() -> None:
    """Forget every payload derived in this process (tests that count derivations)."""
    with _remembered_lock:
        _remembered.clear()


class DerivationPool:
    """`workers` derivation processes, started on the first derivation (a restart that finds everything
    stored never starts one) and killed by `close` (a shutdown mid-derivation leaves none behind)."""

    def __init__(self, workers: int = 1, timeout: float = 120.0, memory_mb: int = 1024):
        self._workers = workers
        self._timeout = timeout
        self._memory_mb = memory_mb
        self._lock = threading.Lock()
        self._pool: WorkerPool | None = None
        self._closed = False
        self._pending: dict[str, Future[bytes]] = {}  # by document hash: one derivation per document
        self._scheduled: dict[str, Future[Any]] = {}  # the pool's own futures of those, to hurry one
        # Documents that failed (but for a timeout), by hash: the same code fails them again, so each
        # request for one is answered at once rather than holding a worker for as long again.
        self._failed: OrderedDict[str, DerivationFailed] = OrderedDict()

    @property
    def workers(self) -> int:
        return self._workers

    def submit(self, document: Mapping[str, Any], *, urgent: bool = False) -> Future[bytes]:
        """The document's payload, derived in a worker (or remembered). The future raises
        DerivationFailed (the document's doing, or its time limit), or PoolError / PoolUnavailable
        when no worker could run it (a fault or a shutdown: not the document's doing). `urgent`: a
        request waits for it, so it goes before the derivations queued for no one (a first start's
        bank, derived in order, would otherwise keep a page of its last problem waiting for them all)."""
        # Here, not at the top: the workers import this module for their task, and need no SQLAlchemy.
        from app.db.problems import document_hash

        key = document_hash(document)
        with _remembered_lock:
            payload = _remembered.get(key)
        if payload is not None:
            done: Future[bytes] = Future()
            done.set_result(payload)
            return done
        with self._lock:
            pending = self._pending.get(key)
            if pending is not None:
                scheduled = self._scheduled.get(key)
                if urgent and scheduled is not None and self._pool is not None:
                    self._pool.hurry(scheduled)
                return pending
            failed = self._failed.get(key)
            if failed is not None:
                refused: Future[bytes] = Future()
                refused.set_exception(failed)
                return refused
            future, self._scheduled[key] = self._schedule(dict(document))
            self._pending[key] = future
            if urgent and self._pool is not None:  # a problem stored after start, asked for at once
                self._pool.hurry(self._scheduled[key])
        future.add_done_callback(lambda finished: self._settled(key, finished))
        return future

    def _schedule(self, document: dict[str, Any]) -> tuple[Future[bytes], Future[Any]]:
        """Send one derivation to a worker (the lock held): the pool's own future's outcome, but for a
        timeout, which is the document's (DerivationFailed); and the pool's future, to hurry it."""
        pool = self._started()
        outer: Future[bytes] = Future()
        inner = pool.schedule(derived_payload, (document,), self._timeout)

        def relay(finished: Future[Any]) -> None:
            error = finished.exception()
            if isinstance(error, TimeoutError):
                outer.set_exception(DerivationTimedOut(f"deriving took longer than {self._timeout:.0f} s"))
            elif error is not None:
                outer.set_exception(error)
            else:
                outer.set_result(finished.result())

        inner.add_done_callback(relay)
        return outer, inner

    def _started(self) -> WorkerPool:
        """The pool, started on first use (the lock held; `close` does not take it, so that a shutdown
        during a start kills what is starting)."""
        if self._closed:
            raise PoolUnavailable("the derivation pool is closed")
        if self._pool is None:
            self._pool = pool = WorkerPool(
                "derivation",
                forkserver.context(),
                workers=self._workers,
                max_tasks=DERIVATIONS_PER_WORKER,
                initializer=limit_memory,
                initargs=(self._memory_mb,),
                tasks=(derived_payload,),
            )
            try:
                pool.start()
            except Exception as error:  # closed meanwhile, or the fork server failed: not the document's
                self._pool = None  # the next derivation tries again
                raise PoolUnavailable(f"the derivation workers did not start: {error!r}") from error
            if self._closed:  # closed while it started
                pool.close()
                raise PoolUnavailable("the derivation pool is closed")
        return self._pool

    def _settled(self, key: str, future: Future[bytes]) -> None:
        error = future.exception()
        with self._lock:
            self._pending.pop(key, None)
            self._scheduled.pop(key, None)
            if isinstance(error, DerivationFailed) and not isinstance(error, DerivationTimedOut):
                self._failed[key] = error
                while len(self._failed) > REMEMBERED:
                    self._failed.popitem(last=False)
        if error is None:
            _remember(key, future.result())

    def close(self) -> None:
        """Kill the workers; derivations not finished fail with PoolUnavailable."""
        self._closed = True
        pool = self._pool
        if pool is not None:
            pool.close()
