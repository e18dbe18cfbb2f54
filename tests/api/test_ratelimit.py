"""Sliding one-minute budgets, in memory for one instance and in Redis shared by several."""

from __future__ import annotations

import os
import uuid

import pytest

from app.ratelimit import MemoryRateLimiter, RedisRateLimiter

REDIS_URL = os.environ.get("PHYSCHECK_TEST_REDIS_URL", "redis://127.0.0.1:6379/0")


class Clock:
    def __init__(self, now: float = 1_000_000.0):
        self.now = now

    def __call__(self) -> float:
        return self.now


@pytest.fixture
def redis_client():
    redis = pytest.importorskip("redis")
    client = redis.Redis.from_url(REDIS_URL, socket_timeout=1, socket_connect_timeout=1)
    try:
        client.ping()
    except redis.RedisError as error:
        pytest.skip(f"Redis not reachable at {REDIS_URL}; set PHYSCHECK_TEST_REDIS_URL ({error})")
    yield client
    client.close()


def _limiters(kind: str, clock: Clock, request: pytest.FixtureRequest) -> list:
    """Two limiters with one budget of 3 a minute: two instances sharing Redis, or one in memory."""
    if kind == "memory":
        one = MemoryRateLimiter(3, clock)
        return [one, one]
    client = request.getfixturevalue("redis_client")
    prefix = f"physcheck:test:{uuid.uuid4().hex}"
    return [RedisRateLimiter(client, 3, prefix, clock), RedisRateLimiter(client, 3, prefix, clock)]


@pytest.mark.parametrize("kind", ["memory", "redis"])
def test_budget_is_spent_then_refilled_as_old_requests_leave_the_window(kind, request):
    clock = Clock()
    first, second = _limiters(kind, clock, request)
    assert [first.retry_after("ada"), second.retry_after("ada"), first.retry_after("ada")] == [None] * 3
    clock.now += 20
    assert second.retry_after("ada") == 40  # the oldest request leaves the window in 40 s
    assert first.retry_after("bob") is None  # budgets are per caller
    clock.now += 40.5
    assert second.retry_after("ada") is None


def test_an_unreachable_redis_allows_requests_rather_than_failing_them():
    redis = pytest.importorskip("redis")
    client = redis.Redis.from_url("redis://127.0.0.1:1/0", socket_timeout=0.2, socket_connect_timeout=0.2)
    limiter = RedisRateLimiter(client, 1, "physcheck:test:down")
    assert [limiter.retry_after("ada") for _ in range(3)] == [None, None, None]
