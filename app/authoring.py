"""Vetting an instructor's upload: validate, derive and self-test it in a killable worker process.

An upload is untrusted text whose model the engine must derive (sympy-heavy), so it never runs in the
server process: one worker, a generous but hard time limit, the same memory limit as grading. The
worker sends back the document, its compiled problem and the findings, nothing else: what the pages
show of it (the instructor's description, texts that will not render, the figure) is built there.
"""

from __future__ import annotations

import asyncio
import logging
import threading
from collections.abc import Callable
from concurrent.futures import TimeoutError as FutureTimeout
from dataclasses import dataclass, field, replace
from typing import Any, Literal

from app.derivation import pack
from app.errors import Busy, Unavailable
from app.grading import forkserver
from app.grading.processes import PoolUnavailable, WorkerDied, WorkerPool
from app.grading.worker import limit_memory
from problems.compiled import compile_problem
from problems.locate import locate
from problems.shape import shape_errors
from problems.texts import readable_texts
from problems.vetting import vet_document

log = logging.getLogger("physcheck.authoring")
UPLOAD_SELFTEST_VARIANTS = 5
UPLOAD_RETRY_AFTER = 10  # seconds: a vetting takes seconds to minutes
# A derivation leaves sympy's caches and the compiled models behind in the worker: a fresh one, forked
# from the clean fork server, after this many vettings keeps the worker's memory from creeping up.
VETTINGS_PER_WORKER = 50


@dataclass(frozen=True)
class Vetted:
    """The outcome of vetting: a clean document (JSON-ready) with its compiled problem, packed as the
    store keeps it (`app.derivation.pack`: the upload is stored with it and never derived again), or
    every error found with its path; and the line each path is on (the errors', and every text's that
    people read, for the pages' notes on texts that will not render cleanly)."""

    document: dict[str, Any] | None
    errors: list[tuple[str, str]] = field(default_factory=list)
    compiled: bytes | None = None
    lines: dict[str, int] = field(default_factory=dict)


def vet(source: bytes, fmt: Literal["json", "yaml"]) -> Vetted:
    """Every fault of an upload with its path, or its compiled problem; and the line each path is on."""
    too_large = shape_errors(source, fmt)  # the pool checked already; the command line's import did not
    if too_large:
        return Vetted(None, too_large)
    try:
        vetted, paths = _vet(source, fmt)
    except MemoryError:
        # The worker's RLIMIT_AS is the size limit of one upload's derivation, as for answers.
        return Vetted(None, [("model", "deriving and self-testing ran out of memory")])
    if not paths:
        return vetted
    try:
        text = source.decode("utf-8")
    except UnicodeDecodeError:
        return vetted
    return replace(vetted, lines=locate(text, paths))


def _vet(source: bytes, fmt: Literal["json", "yaml"]) -> tuple[Vetted, list[str]]:
    """Every stage that can run (shape, meaning, derivation, self-test), every error at once; and the
    paths to locate in the text."""
    vetting = vet_document(source, fmt, UPLOAD_SELFTEST_VARIANTS)
    doc = vetting.document
    if doc is None:
        return Vetted(None, vetting.errors), [path for path, _ in vetting.errors]
    # Compiled (and cached) by the vetting's derivation stage: prepared and packed, it is what is stored.
    compiled = pack(compile_problem(doc).prepare())
    return Vetted(doc.model_dump(mode="json"), compiled=compiled), [path for path, _ in readable_texts(doc)]


class AuthoringPool:
    """One vetting worker with a bounded queue in front of it, and at most one upload per instructor
    key in it at a time: a vetting may take minutes, so one instructor must not make all others wait."""

    def __init__(self, timeout: float, memory_mb: int, queue_size: int = 4):
        self._timeout = timeout
        self._memory_mb = memory_mb
        self._capacity = 1 + queue_size
        self._in_flight = 0
        self._owners: set[str] = set()
        self._starting = threading.Lock()  # two first uploads at once start one pool
        self._pool: WorkerPool | None = None

    # The function the worker runs (tests put a slow one here).
    _task: Callable[[bytes, Literal["json", "yaml"]], Vetted] = staticmethod(vet)

    def start(self) -> None:
        """Start the vetting worker and wait until it is ready (a no-op when it is already started)."""
        with self._starting:
            if self._pool is not None:
                return
            pool = WorkerPool(
                "upload-vetting",
                forkserver.context(),
                workers=1,
                max_tasks=VETTINGS_PER_WORKER,
                initializer=limit_memory,
                initargs=(self._memory_mb,),
                tasks=(self._task,),
            )
            pool.start()
            self._pool = pool

    def close(self) -> None:
        with self._starting:
            pool, self._pool = self._pool, None
        if pool is not None:
            pool.close()

    async def vet(self, source: bytes, fmt: Literal["json", "yaml"], owner: str | None = None) -> Vetted:
        """Vet in the worker; 503 + Retry-After when the queue is full or `owner` (an instructor key)
        already has an upload being vetted, or when the worker cannot take it (being replaced).

        A document over a size or shape limit is refused here, never queued: nothing recursive reads
        it, and junk cannot hold the one vetting worker for its whole time limit."""
        too_large = await asyncio.to_thread(shape_errors, source, fmt)
        if too_large:
            return Vetted(None, too_large)
        if self._in_flight >= self._capacity:
            raise Busy("Uploads are queued to the limit; try again shortly.", retry_after=UPLOAD_RETRY_AFTER)
        if owner is not None and owner in self._owners:
            raise Busy(
                "Your previous upload is still being checked; send the next when it is done.",
                retry_after=UPLOAD_RETRY_AFTER,
            )
        self._in_flight += 1
        if owner is not None:
            self._owners.add(owner)
        try:
            return await self._vet(source, fmt)
        finally:
            self._in_flight -= 1
            self._owners.discard(owner or "")

    async def _vet(self, source: bytes, fmt: Literal["json", "yaml"]) -> Vetted:
        try:
            pool = self._pool
            if pool is None:
                # Off the event loop: the first worker takes a moment to start (and the fork server
                # longer, when it must be started again).
                await asyncio.to_thread(self.start)
                pool = self._pool
                if pool is None:  # closed meanwhile
                    raise PoolUnavailable("the upload-vetting pool was closed")
            vetted: Vetted = await pool.run(self._task, (source, fmt), self._timeout)
            return vetted
        except FutureTimeout:
            return Vetted(
                None, [("model", f"deriving and self-testing took longer than {self._timeout:.0f} s")]
            )
        except (PoolUnavailable, WorkerDied) as error:
            # A worker killed from outside, or one being replaced: not the upload's fault.
            log.error("upload vetting failed on our side: %r", error)
            raise Unavailable(
                "Checking uploads is restarting after a fault; try again in a moment.", retry_after=2
            ) from error
