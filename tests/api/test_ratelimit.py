"""Sliding one-minute budgets, in memory for one instance and in Redis shared by several."""

from __future__ import annotations

import logging
import os
import socket
import threading
import uuid

import pytest

from app.ratelimit import CircuitBreaker, MemoryRateLimiter, RedisRateLimiter, rate_limiters
from app.settings import Settings

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


def test_an_unreachable_redis_falls_back_to_limits_counted_in_this_process():
    key_limiter, _ = rate_limiters("redis://127.0.0.1:1/0", 2, 2, prefix=f"test-{uuid.uuid4().hex}")
    waits = [key_limiter.retry_after("ada") for _ in range(3)]
    assert waits[:2] == [None, None] and waits[2] is not None and waits[2] > 0


class Blackhole:
    """A TCP port that accepts connections and never answers: a hung Redis."""

    def __init__(self) -> None:
        self.listener = socket.socket()
        self.listener.bind(("127.0.0.1", 0))
        self.listener.listen(64)
        self.port = self.listener.getsockname()[1]
        self.accepted: list[socket.socket] = []
        threading.Thread(target=self._accept, daemon=True).start()

    def _accept(self) -> None:
        while True:
            try:
                self.accepted.append(self.listener.accept()[0])
            except OSError:
                return

    def close(self) -> None:
        self.listener.close()
        for connection in self.accepted:
            connection.close()


@pytest.fixture
def blackhole():
    hole = Blackhole()
    yield hole
    hole.close()


def test_a_hung_redis_is_asked_once_then_skipped_with_one_log_line(blackhole, caplog):
    key_limiter, student_limiter = rate_limiters(
        f"redis://127.0.0.1:{blackhole.port}/0", 1000, 1000, prefix=f"test-{uuid.uuid4().hex}"
    )
    with caplog.at_level(logging.WARNING, logger="physcheck.ratelimit"):
        for n in range(50):
            assert key_limiter.retry_after(f"key{n}") is None
            assert student_limiter.retry_after(f"student{n}") is None
    # One connection for a hundred requests: the breaker opened at the first timeout, for both limiters.
    assert len(blackhole.accepted) == 1
    assert len([r for r in caplog.records if "Redis unavailable" in r.getMessage()]) == 1


class FlakyScript:
    """Stands in for the Redis client: fails while `down`, counts every call that reaches it."""

    def __init__(self) -> None:
        self.down = True
        self.calls = 0

    def register_script(self, _source: str) -> FlakyScript:
        return self

    def __call__(self, keys: list[str], args: list[object]) -> int:
        self.calls += 1
        if self.down:
            import redis

            raise redis.ConnectionError("connection refused")
        return 0


def test_the_breaker_retries_redis_every_interval_logs_once_a_minute_and_closes_when_it_answers(caplog):
    pytest.importorskip("redis")
    clock, redis_stub = Clock(), FlakyScript()
    breaker = CircuitBreaker(retry_seconds=10, log_every=60, clock=clock)
    limiter = RedisRateLimiter(redis_stub, 1000, "test", breaker=breaker)

    def outage_lines() -> int:
        return len([r for r in caplog.records if "Redis unavailable" in r.getMessage()])

    with caplog.at_level(logging.WARNING, logger="physcheck.ratelimit"):
        for _ in range(20):
            limiter.retry_after("ada")
        assert (redis_stub.calls, outage_lines()) == (1, 1)
        for step in range(5):  # 50 s: five more tries, one each 10 s, and no more log lines
            clock.now += 10
            for _ in range(20):
                limiter.retry_after("ada")
        assert (redis_stub.calls, outage_lines()) == (6, 1)
        clock.now += 10  # a minute after the first line: the outage is logged again
        limiter.retry_after("ada")
        assert (redis_stub.calls, outage_lines()) == (7, 2)
        redis_stub.down = False
        clock.now += 10
        for _ in range(5):
            limiter.retry_after("ada")
        assert redis_stub.calls == 8 + 4 and breaker.closed
        assert any("answers again" in r.getMessage() for r in caplog.records)


def test_deployments_with_different_prefixes_keep_separate_budgets_in_one_redis(redis_client):
    names = [f"physcheck-test-{uuid.uuid4().hex}" for _ in range(2)]
    first, second = (rate_limiters(REDIS_URL, 1, 1, prefix=name)[0] for name in names)
    try:
        assert first.retry_after("ada") is None
        assert second.retry_after("ada") is None  # not refused: the other deployment's count is apart
        assert first.retry_after("ada") is not None
        for name in names:
            assert redis_client.keys(f"{name}:rate:key:ada") == [f"{name}:rate:key:ada".encode()]
    finally:
        for name in names:
            redis_client.delete(f"{name}:rate:key:ada")


def test_the_prefix_setting_names_the_deployment():
    assert Settings().redis_prefix == "physcheck"
    assert Settings(redis_prefix="course-b").redis_prefix == "course-b"
    with pytest.raises(ValueError):
        Settings(redis_prefix="two words")
