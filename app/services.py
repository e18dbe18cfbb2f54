"""What the routes need, built once per application in the lifespan and reached through `deps`."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from sqlalchemy.orm import Session

from app.auth import KeyStore
from app.authoring import AuthoringPool
from app.catalog import Catalog
from app.db.database import Database
from app.db.records import SubmissionRecord
from app.grading.pool import GradingPool
from app.ratelimit import RateLimiter
from app.settings import Settings


@dataclass
class Services:
    settings: Settings
    database: Database
    pool: GradingPool
    keys: KeyStore
    key_limiter: RateLimiter
    student_limiter: RateLimiter
    catalog: Catalog
    authoring: AuthoringPool
    # Called inside the transaction that files each submission (LTI grade passback queues there).
    on_graded: list[Callable[[Session, SubmissionRecord], object]] = field(default_factory=list)
