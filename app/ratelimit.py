"""Per-caller request budgets over a sliding one-minute window, answering how long to wait when spent.

One instance counts in memory; several instances share their counts through Redis when
`PHYSCHECK_REDIS_URL` is set, so a caller's budget is the same whichever instance it reaches.

Redis is asked with short timeouts and behind a circuit breaker: when it fails, each instance counts
in its own memory (a caller's budget is then at most N times the limit over N instances: limited, and
with no latency spent on a dead or hung Redis) and tries Redis again every `REDIS_RETRY_SECONDS`,
logging the outage once a minute at most.
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


REDIS_TIMEOUT_SECONDS = 0.1  # connect and read: Redis on the local network answers in well under 1 ms
REDIS_RETRY_SECONDS = 10.0
REDIS_LOG_EVERY_SECONDS = 60.0


class CircuitBreaker:
    """Closed, Redis is asked; after a failure, open: Redis is skipped for `retry_seconds`, then one
    caller may try it (the others keep skipping it) and closes the breaker if it answers."""

    def __init__(
        self,
        retry_seconds: float = REDIS_RETRY_SECONDS,
        log_every: float = REDIS_LOG_EVERY_SECONDS,
        clock: Callable[[], float] = time.monotonic,
    ):
        self._retry_seconds = retry_seconds
        self._log_every = log_every
        self._clock = clock
        self._lock = threading.Lock()
        self._open_until: float | None = None  # None: closed
        self._probing = False
        self._logged_at: float | None = None

    @property
    def closed(self) -> bool:
        return self._open_until is None

    def allow(self) -> bool:
        with self._lock:
            if self._open_until is None:
                return True
            if self._probing or self._clock() < self._open_until:
                return False
            self._probing = True
            return True

    def succeeded(self) -> None:
        with self._lock:
            if self._open_until is not None:
                log.warning("Redis answers again; rate limits are shared through it again")
            self._open_until, self._probing, self._logged_at = None, False, None

    def failed(self, error: Exception) -> None:
        with self._lock:
            now = self._clock()
            self._open_until, self._probing = now + self._retry_seconds, False
            if self._logged_at is None or now - self._logged_at >= self._log_every:
                self._logged_at = now
                log.error(
                    "Redis unavailable (%s); counting rate limits in this process, retrying every %.0f s",
                    error,
                    self._retry_seconds,
                )


class RedisRateLimiter:
    """The same window, kept in Redis; while Redis fails (see CircuitBreaker), counted in memory."""

    def __init__(
        self,
        client: Any,
        per_minute: int,
        prefix: str,
        clock: Callable[[], float] = time.time,
        breaker: CircuitBreaker | None = None,
    ):
        self._per_minute = per_minute
        self._prefix = prefix
        self._clock = clock
        self._script = client.register_script(_SLIDING_WINDOW)
        self._breaker = breaker or CircuitBreaker()
        self._fallback = MemoryRateLimiter(per_minute)

    def retry_after(self, caller: str) -> int | None:
        import redis

        if not self._breaker.allow():
            return self._fallback.retry_after(caller)
        now_ms = int(self._clock() * 1000)
        try:
            wait = int(
                self._script(
                    keys=[f"{self._prefix}:{caller}"],
                    args=[now_ms, WINDOW_SECONDS * 1000, self._per_minute, f"{now_ms}:{uuid.uuid4().hex}"],
                )
            )
        except redis.RedisError as error:
            self._breaker.failed(error)
            return self._fallback.retry_after(caller)
        self._breaker.succeeded()
        return wait or None


def rate_limiters(
    redis_url: str | None, per_key: int, per_student: int, prefix: str = "physcheck"
) -> tuple[RateLimiter, RateLimiter]:
    """The per-key and per-student limiters: shared through Redis when a URL is given, under keys that
    start with `prefix` (the deployment's name, so that several deployments can share one Redis)."""
    if redis_url is None:
        return MemoryRateLimiter(per_key), MemoryRateLimiter(per_student)
    import redis
    from redis.backoff import NoBackoff
    from redis.retry import Retry

    client = redis.Redis.from_url(
        redis_url,
        socket_timeout=REDIS_TIMEOUT_SECONDS,
        socket_connect_timeout=REDIS_TIMEOUT_SECONDS,
        retry=Retry(NoBackoff(), 0),  # redis-py retries 3 times with backoff by default: seconds per request
    )
    breaker = CircuitBreaker()  # one outage, one breaker, one log line
    return (
        RedisRateLimiter(client, per_key, f"{prefix}:rate:key", breaker=breaker),
        RedisRateLimiter(client, per_student, f"{prefix}:rate:student", breaker=breaker),
    )


def preview_limiter(redis_url: str | None, per_minute: int, prefix: str = "physcheck") -> RateLimiter:
    """The live previews' own budget, per student or key (shared through Redis when a URL is given)."""
    if redis_url is None:
        return MemoryRateLimiter(per_minute)
    import redis
    from redis.backoff import NoBackoff
    from redis.retry import Retry

    client = redis.Redis.from_url(
        redis_url,
        socket_timeout=REDIS_TIMEOUT_SECONDS,
        socket_connect_timeout=REDIS_TIMEOUT_SECONDS,
        retry=Retry(NoBackoff(), 0),
    )
    return RedisRateLimiter(client, per_minute, f"{prefix}:rate:preview")
