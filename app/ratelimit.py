"""Per-caller request budgets (a sliding one-minute window), answering how long to wait when spent."""

from __future__ import annotations

import math
import threading
import time
from collections import deque
from collections.abc import Callable


class RateLimiter:
    def __init__(self, per_minute: int, clock: Callable[[], float] = time.monotonic):
        self._per_minute = per_minute
        self._clock = clock
        self._hits: dict[str, deque[float]] = {}
        self._lock = threading.Lock()

    def retry_after(self, caller: str) -> int | None:
        """Record a request; None if allowed, else the whole seconds until one more would be."""
        now = self._clock()
        with self._lock:
            hits = self._hits.setdefault(caller, deque())
            while hits and hits[0] <= now - 60:
                hits.popleft()
            if len(hits) >= self._per_minute:
                return max(1, math.ceil(hits[0] + 60 - now))
            hits.append(now)
            if len(self._hits) > 100_000:  # forget idle callers rather than grow without bound
                self._hits = {k: v for k, v in self._hits.items() if v and v[-1] > now - 60}
            return None
