"""Sign-in attempts on the instructor pages, limited per address and per key prefix.

A key cannot be guessed (256 random bits), but every attempt costs a database lookup, and the prefix
that finds a key is short: attempts from one address, or at one prefix from many addresses, are
limited to `PHYSCHECK_SIGN_IN_ATTEMPTS_PER_MINUTE` each, shared through Redis when it is configured.
"""

from __future__ import annotations

from app.db.keys import lookup_prefix
from app.ratelimit import RateLimiter, rate_limiters


class SignInLimiter:
    def __init__(self, by_address: RateLimiter, by_prefix: RateLimiter):
        self._by_address = by_address
        self._by_prefix = by_prefix

    @classmethod
    def build(cls, redis_url: str | None, per_minute: int, redis_prefix: str) -> SignInLimiter:
        by_address, by_prefix = rate_limiters(redis_url, per_minute, per_minute, f"{redis_prefix}:sign-in")
        return cls(by_address, by_prefix)

    def retry_after(self, address: str, key: str) -> int | None:
        """Spend one attempt of the address's budget and of the key prefix's; None if allowed, else the
        seconds to wait."""
        wait = self._by_address.retry_after(address)
        if wait is None and key:
            wait = self._by_prefix.retry_after(lookup_prefix(key))
        return wait
