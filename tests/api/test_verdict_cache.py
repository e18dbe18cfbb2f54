"""Identical checks are graded once; every submission is still filed and counts as an attempt."""

from __future__ import annotations

import asyncio
import functools
from collections.abc import Iterator
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from app.grading.pool import GradingPool
from app.main import create_app
from app.settings import Settings
from physics.checking import SymbolDecl
from problems.kinds.symbolic import SymbolicJob
from tests.api.conftest import _headers
from tests.api.slow_task import counted_grade

SUBMIT = "/v1/problems/atwood/parts/acceleration/submissions"


@pytest.fixture
def tally(tmp_path: Path) -> Path:
    path = tmp_path / "graded.txt"
    path.touch()
    return path


@pytest.fixture
def counting_pool(tally: Path) -> Iterator[GradingPool]:
    pool = GradingPool(
        workers=1,
        timeout=10.0,
        memory_mb=1024,
        max_tasks=100,
        queue_size=8,
        task=functools.partial(counted_grade, str(tally)),
    )
    pool.start()
    yield pool
    pool.close()


def graded(tally: Path, answer: str) -> int:
    return tally.read_text().splitlines().count(answer)


def test_identical_check_jobs_are_graded_once(counting_pool, tally):
    symbols = (SymbolDecl("m", "kg"), SymbolDecl("g", "m/s^2"))

    def check(answer: str, expected: str = "m*g") -> str:
        job = SymbolicJob(answer=answer, expected=expected, symbols=symbols)
        return asyncio.run(counting_pool.check(job)).outcome.value

    assert [check("g m"), check("g m"), check("g m")] == ["correct"] * 3
    assert graded(tally, "g m") == 1
    assert check("g m", expected="2*m*g") == "incorrect"  # another reference: another job
    assert graded(tally, "g m") == 2


def test_identical_submissions_share_a_verdict_but_each_is_filed_and_counted(db, counting_pool, tally):
    settings = Settings(database_url=db.url, secret="test-secret-0123456789", warm_up=False)
    with TestClient(create_app(settings, pool=counting_pool)) as client:
        headers = _headers(settings, "student", "ada")
        answer = "(m2 - m1) g/(m1 + m2)"
        results = [client.post(SUBMIT, json={"answer": answer}, headers=headers).json() for _ in range(3)]
    assert [r["verdict"] for r in results] == ["correct"] * 3
    assert [r["attempts_used"] for r in results] == [1, 2, 3]
    assert len({r["submission_id"] for r in results}) == 3
    assert graded(tally, answer) == 1
