"""Code that runs inside a grading worker process.

Imported by the fork server before any worker exists, so each worker starts with sympy, pint and the
parser already loaded (a fresh worker after a kill is ready in milliseconds, not seconds).
"""

from __future__ import annotations

import ctypes
import os
import resource
import signal
import traceback
from collections.abc import Callable
from dataclasses import dataclass
from decimal import Decimal

from physics.checking import CheckJob, NumericJob, QuestionJob, SymbolDecl, preview, run_job
from physics.choice import Choice, ChoiceQuestion
from physics.errors import SpecError, TooLarge
from physics.numeric import NumericSpec
from physics.verdict import InputProblem, Preview, Verdict
from problems.kinds.symbolic import SymbolicJob

# One round trip through each fresh worker before its pool counts as ready: jobs whose making builds
# nothing in the server process (a numeric spec would build the unit registry there).
ROUND_TRIP_JOBS: tuple[CheckJob, ...] = (
    SymbolicJob(
        "m g sin(θ)",
        "g*m*sin(theta)",
        (SymbolDecl("m", "kg"), SymbolDecl("g", "m/s^2"), SymbolDecl("theta", "1")),
    ),
    QuestionJob("B", ChoiceQuestion((Choice("up the slope"), Choice("down the slope")), 0)),
)


def warm_up_jobs() -> tuple[CheckJob, ...]:
    """A job of each kind, touching every lazily built table (parser, unit registry, sampler) and every
    module sympy imports on first use: the fork server runs them once, so that every worker forks with
    them built. A wrong answer to a sum builds a sympy sum (`Add.flatten` imports sympy.tensor and
    sympy.combinatorics, a quarter of a CPU-second, on its first call) and runs the diagnoses."""
    angle = SymbolDecl("alpha", "1", range=("0", "pi/2"))
    incline = (SymbolDecl("g", "m/s^2"), SymbolDecl("mu", "1"), angle)
    return (
        *ROUND_TRIP_JOBS,
        NumericJob("4.58 km/h", NumericSpec(expected=Decimal("1.27"), units="m/s")),
        SymbolicJob("g(sin α - μ cos α)*3/4", "(g*(sin(alpha) + mu*cos(alpha)))*3/4", incline),
    )


@dataclass(frozen=True)
class SpecProblem:
    """A SpecError flattened for the trip back: exceptions lose their extra fields when pickled."""

    message: str
    path: tuple[str | int, ...]


@dataclass(frozen=True)
class GraderCrash:
    """An exception inside grading that no answer should cause (RecursionError, OverflowError, a bug):
    the grader's fault, sent back with its traceback to be logged, never filed as the student's verdict."""

    error: str
    traceback: str


_PR_SET_PDEATHSIG = 1


def limit_memory(megabytes: int) -> None:
    """Worker initializer: an allocation past the limit raises MemoryError instead of swapping; and the
    worker dies with the fork server that started it, rather than live on as an unsupervised orphan
    still reading tasks (its pool sees it as dead and replaces it)."""
    limit = megabytes * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    if os.uname().sysname == "Linux":
        ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)


# A MemoryError stays the student's `too_large`: RLIMIT_AS bounds the work of one answer in a worker
# that holds nothing else, so running out means this answer needed more than any answer may have
# (like the size limits checked before evaluation), and a retry would fail the same way.
TOO_LARGE = "This answer is too large to check; simplify it."


def grade(job: CheckJob) -> Verdict | SpecProblem | GraderCrash:
    return guarded(run_job, job)


def guarded(run: Callable[[CheckJob], Verdict], job: CheckJob) -> Verdict | SpecProblem | GraderCrash:
    """`run(job)`, with each exception sorted into the answer's fault or the grader's."""
    try:
        return run(job)
    except SpecError as error:
        return SpecProblem(error.message, error.path)
    except MemoryError:
        return Verdict.invalid(TooLarge(TOO_LARGE))
    except Exception as error:
        return GraderCrash(repr(error), traceback.format_exc())


def read_only(job: CheckJob) -> Preview | SpecProblem | GraderCrash:
    try:
        return preview(job)
    except SpecError as error:
        return SpecProblem(error.message, error.path)
    except MemoryError:
        return Preview(None, InputProblem("This answer is too large to read; simplify it."))
    except Exception as error:
        return GraderCrash(repr(error), traceback.format_exc())
