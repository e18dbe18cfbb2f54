"""All configuration, read once from `PHYSCHECK_*` environment variables (or passed in by tests)."""

from __future__ import annotations

import os
from functools import lru_cache
from pathlib import Path

from pydantic import Field, model_validator
from pydantic_settings import BaseSettings, SettingsConfigDict

DEVELOPMENT_SECRET = "dev-secret-change-me"  # noqa: S105 - refused wherever it would matter


def cores() -> int:
    """The cores this process may run on."""
    found = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    return found or 1


def default_check_workers() -> int:
    """Two more grading workers than cores: one lane per core (`check_lanes`) and two at rest, which
    stand in for lanes stuck on slow answers (a hostile answer holds its worker until the time limit).
    A worker at rest holds about 20 MB of its own; the rest is shared."""
    return cores() + 2


class Settings(BaseSettings):
    model_config = SettingsConfigDict(env_prefix="PHYSCHECK_", extra="ignore")

    database_url: str = "sqlite:///./physcheck.db"
    # Every wait on the database (a connection, a lock, a statement, a server that never answers) ends
    # after about this long with 503 + Retry-After rather than holding the request.
    database_timeout_seconds: float = Field(default=5.0, gt=0, le=300)
    # Server secret for per-student variants and session cookies; a fresh one per start is safe
    # for development only, since variants would change between restarts.
    secret: str = Field(default=DEVELOPMENT_SECRET, min_length=8)
    base_url: str = "http://127.0.0.1:8000"

    # Bounded work: every check runs in a killable worker process.
    check_timeout_seconds: float = Field(default=2.0, gt=0)
    check_memory_mb: int = Field(default=1024, ge=128)
    check_workers: int = Field(default_factory=default_check_workers, ge=1)
    # Workers that take the next check while grading one, so that they start it at once instead of
    # sleeping until the server hands it over (app/grading/processes.py); 0: each takes one at a time.
    check_lanes: int = Field(default_factory=cores, ge=0)
    check_queue_size: int = Field(default=64, ge=1)
    # Checks one student (or LMS session) may have running at once; instructor API keys are not limited.
    student_checks_in_flight: int = Field(default=2, ge=1)
    # Recycling bounds a slow leak, but a new worker must compile again the references it had cached:
    # at 500, workers under load were replaced every second or two and stalled checks for 100+ ms.
    worker_max_tasks: int = Field(default=10_000, ge=1)

    # Deriving and self-testing one upload in the vetting worker; also one problem's derivation in a
    # derivation worker (what is not stored yet), killed past it.
    upload_timeout_seconds: float = Field(default=120.0, gt=0)
    # Uploads waiting for the one vetting worker before 503 + Retry-After (one per instructor key at most).
    upload_queue_size: int = Field(default=4, ge=0)

    # Above the answer limit on purpose: an over-long answer gets an `invalid` verdict, not a 413.
    max_body_bytes: int = Field(default=2 * 1024 * 1024, ge=1024)
    max_answer_chars: int = Field(default=2000, ge=10)

    # Shared rate-limit counts for several instances (redis://host:6379/0); unset: per instance.
    redis_url: str | None = None
    # Start of every Redis key, so that several deployments can share one Redis.
    redis_prefix: str = Field(default="physcheck", min_length=1, max_length=64, pattern=r"^[A-Za-z0-9_.-]+$")
    rate_limit_per_minute: int = Field(default=600, ge=1)
    student_rate_limit_per_minute: int = Field(default=60, ge=1)
    # Instructor sign-in attempts (the pages' form) from one address, and at one key prefix.
    sign_in_attempts_per_minute: int = Field(default=10, ge=1)
    # Live previews while typing, per student (or key), counted apart from the budgets above: a student
    # typing at any human pace is never limited, a script hammering the parser still is.
    preview_rate_limit_per_minute: int = Field(default=600, ge=1)

    # An LTI launch whose id_token was issued longer ago than this is refused (a replayed old token).
    lti_max_token_age_seconds: int = Field(default=3600, ge=60)

    bank_dir: Path | None = None
    # Use the derived bank built with the program (`physcheck bank build`, app/shipped_bank.py) for
    # what is not stored yet: a first start then loads the bank instead of deriving it.
    shipped_bank: bool = True
    # Compile every problem at start-up (seconds of sympy) before /ready says yes; off for quick dev runs.
    warm_up: bool = True
    # Worker processes that derive what is not stored yet (a first start, new code), side by side, each
    # under the upload limits (time and memory): about a minute for the bank on one core. The server
    # process itself never derives; an upload is stored with what its vetting derived.
    derive_jobs: int = Field(default_factory=cores, ge=1)
    log_level: str = "INFO"
    # Students' answers are personal data: the log names the submission (problem, part, student,
    # verdict) but not what was typed, unless an operator turns this on (to debug a reading, say).
    log_answers: bool = False
    # On SIGTERM, requests in progress get this long to finish (below `docker stop`'s 10 s); then they are
    # cancelled and every worker process is killed, so that the server has exited before a SIGKILL.
    shutdown_timeout_seconds: int = Field(default=8, ge=1)

    @model_validator(mode="after")
    def no_public_secret_in_production(self) -> Settings:
        # With the published default anyone could compute every student's numbers.
        if self.secret == DEVELOPMENT_SECRET and self.base_url.startswith("https://"):
            raise ValueError(
                "set PHYSCHECK_SECRET: the default secret is public and only fit for development"
            )
        return self


@lru_cache
def get_settings() -> Settings:
    return Settings()
