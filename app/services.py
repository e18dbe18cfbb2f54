"""What the routes need, built once per application in the lifespan and reached through `deps`."""

from __future__ import annotations

from dataclasses import dataclass, field

from app.auth import KeyStore
from app.authoring import AuthoringPool
from app.catalog import Catalog
from app.db.database import Database
from app.grading.pool import GradingPool
from app.instructor.sign_in_limit import SignInLimiter
from app.ratelimit import MemoryRateLimiter, RateLimiter
from app.schemas.check import VerdictJson
from app.settings import Settings
from app.storage import Stores


@dataclass
class Services:
    settings: Settings
    database: Database | None  # SQL apps' (tests and tools use it); routes reach storage through `stores`
    stores: Stores
    pool: GradingPool
    keys: KeyStore
    key_limiter: RateLimiter
    student_limiter: RateLimiter
    catalog: Catalog
    authoring: AuthoringPool
    verdict_json: VerdictJson = field(default_factory=VerdictJson)
    sign_in_limiter: SignInLimiter | None = None  # the instructor pages' form; None: not limited
    # Live previews' own budget (settings.preview_rate_limit_per_minute), apart from the request budgets.
    preview_limiter: RateLimiter = field(default_factory=lambda: MemoryRateLimiter(600))
