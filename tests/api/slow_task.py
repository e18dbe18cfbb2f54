"""A grading task that hangs on request, to prove the pool kills workers that overrun."""

from __future__ import annotations

import os
import signal
import time

from app.authoring import Vetted
from app.grading.worker import GraderCrash, SpecProblem, grade, guarded, read_only
from physics.checking import CheckJob, Preview, run_job
from physics.errors import SpecError
from physics.verdict import Verdict


def hanging_grade(job: CheckJob) -> Verdict | SpecProblem | GraderCrash:
    if job.answer == "hang":
        while True:
            time.sleep(1)
    return grade(job)


def _faulty_run(job: CheckJob) -> Verdict:
    if job.answer == "recurse":
        raise RecursionError("maximum recursion depth exceeded")
    if job.answer == "overflow":
        raise OverflowError("int too large to convert to float")
    if job.answer == "nomemory":
        raise MemoryError
    if job.answer == "spec":
        raise SpecError("the reference does not parse", ("parts", 0, "answer"))
    return run_job(job)


def pid_or_grade(job: CheckJob) -> Verdict | SpecProblem | GraderCrash | int:
    """`pid` answers with the worker's process id (to kill it); `die` kills the worker mid-check;
    `recurse`, `overflow`, `nomemory` and `spec` raise inside grading, through the worker's own guard."""
    if job.answer == "pid":
        return os.getpid()
    if job.answer == "die":
        os.kill(os.getpid(), signal.SIGKILL)
    return guarded(_faulty_run, job)


def slow_vet(source: bytes, fmt: str) -> Vetted:
    """Vetting that takes `sleep` forever (until the pool's time limit, or a test, kills it); `pid`
    answers with the worker's process id (to kill it)."""
    if source == b"sleep":
        while True:
            time.sleep(1)
    if source == b"pid":
        return Vetted(None, [("pid", str(os.getpid()))])
    return Vetted(None, [("", "vetted")])


def spec_failing_preview(job: CheckJob) -> Preview | SpecProblem | GraderCrash:
    """A preview whose reference cannot be read, for `spec`; the worker's own preview otherwise."""
    if job.answer == "spec":
        return SpecProblem("the reference does not parse", ("parts", 0, "answer"))
    return read_only(job)


def counted_grade(tally: str, job: CheckJob) -> Verdict | SpecProblem | GraderCrash:
    """`grade`, appending a line to the file `tally` each time a worker runs it."""
    with open(tally, "a") as out:
        out.write(job.answer + "\n")
    return grade(job)
