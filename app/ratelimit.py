"""Per-caller request budgets over a sliding one-minute window, answering how long to wait when spent.

One instance counts in memory; several instances share their counts through Redis when
`PHYSCHECK_REDIS_URL` is set, so a caller's budget is the same whichever instance it reaches.
"""

from __future__ import annotations

import logging
import math
import threading
import time
import uuid
from collections import deque
from collections.abc import Callable
from typing import Any, Protocol

log = logging.getLogger("physcheck.ratelimit")
WINDOW_SECONDS = 60


class RateLimiter(Protocol):
    def retry_after(self, caller: str) -> int | None:
        """Record a request; None if allowed, else the whole seconds until one more would be."""


class MemoryRateLimiter:
    def __init__(self, per_minute: int, clock: Callable[[], float] = time.monotonic):
        self._per_minute = per_minute
        self._clock = clock
        self._hits: dict[str, deque[float]] = {}
        self._lock = threading.Lock()

    def retry_after(self, caller: str) -> int | None:
        now = self._clock()
        with self._lock:
            hits = self._hits.setdefault(caller, deque())
            while hits and hits[0] <= now - WINDOW_SECONDS:
                hits.popleft()
            if len(hits) >= self._per_minute:
                return max(1, math.ceil(hits[0] + WINDOW_SECONDS - now))
            hits.append(now)
            if len(self._hits) > 100_000:  # forget idle callers rather than grow without bound
                self._hits = {k: v for k, v in self._hits.items() if v and v[-1] > now - WINDOW_SECONDS}
            return None


# One round trip, atomic: drop hits older than the window, then either refuse (with the wait until the
# oldest hit leaves the window) or record this one.
_SLIDING_WINDOW = """
local key, now, window, limit, member = KEYS[1], tonumber(ARGV[1]), tonumber(ARGV[2]), tonumber(ARGV[3]), ARGV[4]
redis.call('ZREMRANGEBYSCORE', key, '-inf', now - window)
if redis.call('ZCARD', key) >= limit then
  local oldest = redis.call('ZRANGE', key, 0, 0, 'WITHSCORES')
  return math.max(1, math.ceil((tonumber(oldest[2]) + window - now) / 1000))
end
redis.call('ZADD', key, now, member)
redis.call('PEXPIRE', key, window)
return 0
"""


class RedisRateLimiter:
    """The same window, kept in Redis; if Redis cannot be reached the request is allowed (and logged):
    a limiter outage must not take the service down with it."""

    def __init__(self, client: Any, per_minute: int, prefix: str, clock: Callable[[], float] = time.time):
        self._per_minute = per_minute
        self._prefix = prefix
        self._clock = clock
        self._script = client.register_script(_SLIDING_WINDOW)

    def retry_after(self, caller: str) -> int | None:
        import redis

        now_ms = int(self._clock() * 1000)
        try:
            wait = int(
                self._script(
                    keys=[f"{self._prefix}:{caller}"],
                    args=[now_ms, WINDOW_SECONDS * 1000, self._per_minute, f"{now_ms}:{uuid.uuid4().hex}"],
                )
            )
        except redis.RedisError as error:
            log.error("rate limiter unavailable, allowing the request: %s", error)
            return None
        return wait or None


def rate_limiters(redis_url: str | None, per_key: int, per_student: int) -> tuple[RateLimiter, RateLimiter]:
    """The per-key and per-student limiters: shared through Redis when a URL is given."""
    if redis_url is None:
        return MemoryRateLimiter(per_key), MemoryRateLimiter(per_student)
    import redis

    client = redis.Redis.from_url(redis_url, socket_timeout=0.5, socket_connect_timeout=0.5)
    return (
        RedisRateLimiter(client, per_key, "physcheck:rate:key"),
        RedisRateLimiter(client, per_student, "physcheck:rate:student"),
    )
