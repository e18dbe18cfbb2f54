"""Code that runs inside a grading worker process.

Imported by the fork server before any worker exists, so each worker starts with sympy, pint and the
parser already loaded (a fresh worker after a kill is ready in milliseconds, not seconds).
"""

from __future__ import annotations

import resource
from dataclasses import dataclass
from decimal import Decimal

from physics.checking import CheckJob, NumericJob, Preview, SymbolDecl, SymbolicJob, preview, run_job
from physics.errors import SpecError, TooLarge
from physics.numeric import NumericSpec
from physics.verdict import InputProblem, Verdict

# Touch every lazily built table (parser, unit registry, sampler) before real requests arrive.
WARM_UP_JOBS: tuple[CheckJob, ...] = (
    SymbolicJob(
        "m g sin(θ)",
        "g*m*sin(theta)",
        (SymbolDecl("m", "kg"), SymbolDecl("g", "m/s^2"), SymbolDecl("theta", "1")),
    ),
    NumericJob("4.58 km/h", NumericSpec(expected=Decimal("1.27"), units="m/s")),
)


@dataclass(frozen=True)
class SpecProblem:
    """A SpecError flattened for the trip back: exceptions lose their extra fields when pickled."""

    message: str
    path: tuple[str | int, ...]


def limit_memory(megabytes: int) -> None:
    """Worker initializer: an allocation past the limit raises MemoryError instead of swapping."""
    limit = megabytes * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def grade(job: CheckJob) -> Verdict | SpecProblem:
    try:
        return run_job(job)
    except SpecError as error:
        return SpecProblem(error.message, error.path)
    except (MemoryError, RecursionError, OverflowError):
        return Verdict.invalid(TooLarge("This answer is too large to check; simplify it."))


def read_only(job: CheckJob) -> Preview | SpecProblem:
    try:
        return preview(job)
    except SpecError as error:
        return SpecProblem(error.message, error.path)
    except (MemoryError, RecursionError, OverflowError):
        return Preview(None, InputProblem("This answer is too large to read; simplify it."))
