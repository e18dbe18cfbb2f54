"""Upload vetting is shared fairly: a bounded queue, and one upload in flight per instructor key."""

from __future__ import annotations

import asyncio

import pytest

from app.authoring import AuthoringPool
from app.errors import Busy
from tests.api.slow_task import slow_vet


class SlowAuthoringPool(AuthoringPool):
    _task = staticmethod(slow_vet)  # type: ignore[assignment]


@pytest.fixture
def vetting():
    pool = SlowAuthoringPool(timeout=5.0, memory_mb=1024, queue_size=1)
    yield pool
    pool.close()


@pytest.mark.slow
def test_one_instructor_has_one_upload_in_flight_and_the_queue_is_bounded(vetting):
    async def scenario():
        first = asyncio.ensure_future(vetting.vet(b"sleep", "json", "1"))
        await asyncio.sleep(0.05)
        with pytest.raises(Busy, match="previous upload") as same_instructor:
            await vetting.vet(b"quick", "json", "1")
        queued = asyncio.ensure_future(vetting.vet(b"quick", "json", "2"))  # worker busy: one may wait
        await asyncio.sleep(0.05)
        with pytest.raises(Busy, match="queued to the limit") as full:
            await vetting.vet(b"quick", "json", "3")
        outcomes = await asyncio.gather(first, queued)
        again = await vetting.vet(b"quick", "json", "1")  # the instructor's turn is given back
        return same_instructor.value, full.value, outcomes, again

    same_instructor, full, (first, queued), again = asyncio.run(scenario())
    for refused in (same_instructor, full):
        assert refused.status == 503 and int(refused.headers["Retry-After"]) > 0
    assert "longer than" in first.errors[0][1]  # killed at the time limit
    assert queued.errors == again.errors == [("", "vetted")]
