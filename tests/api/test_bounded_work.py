"""Hostile answers get a quick `invalid` and never hold up honest checks; overrunning workers are killed."""

from __future__ import annotations

import asyncio
import itertools
import time
from pathlib import Path

import pytest

from app.grading.pool import GradingPool
from physics.checking import SymbolDecl
from problems.kinds.symbolic import SymbolicJob
from tests.api.slow_task import hanging_grade

SYMBOLS = {
    "x": {"real": True},
    "m": {"dimension": "kg"},
    "g": {"dimension": "m/s^2"},
    "h": {"dimension": "m"},
}


def symbolic(answer: str, expected: str = "m*g*h") -> dict:
    return {"kind": "symbolic", "answer": answer, "expected": expected, "symbols": SYMBOLS}


HOSTILE = [
    pytest.param("9^9^9", id="power-tower"),
    pytest.param("2^2^2^2^2^2", id="tall-tower"),
    pytest.param("factorial(10^9)", id="factorial"),
    pytest.param("10^9!", id="postfix-factorial"),
    pytest.param("1e999999", id="huge-exponent-literal"),
    pytest.param("(x+2)^10000", id="huge-polynomial"),
    pytest.param("(" * 100_000 + "x" + ")" * 100_000, id="deep-nesting"),
    pytest.param("m" * 1_000_000, id="one-megabyte"),
    pytest.param("m*g*h*sec(sinh(10^40)^2)", id="function-of-an-astronomical-constant"),
    pytest.param("m*g*h*" + "(-" * 9 + "x^2-1" + ")^(1/3)" * 9, id="roots-of-negatives-nest"),
    pytest.param(r"m g h \cdot " + r"\sqrt[3]{-" * 9 + "x^2-1" + "}" * 9, id="latex-roots-of-negatives-nest"),
    pytest.param("m*g*h*cosh(cosh(x acos(x)^100)^100)", id="function-of-a-complex-power"),
    pytest.param(
        r"m g h \cosh\left(\cosh^{100}\left(x\arccos^{100}x\right)\right)",
        id="latex-function-of-a-complex-power",
    ),
    pytest.param("m*g*h*asin(sin(10^300))", id="inverse-trig-of-a-huge-angle"),
]


@pytest.mark.parametrize("answer", HOSTILE)
def test_hostile_answer_is_invalid_too_large(client, student_headers, answer):
    response = client.post("/v1/check", json=symbolic(answer), headers=student_headers)
    assert response.status_code == 200
    result = response.json()
    assert (result["verdict"], result["reason"]) == ("invalid", "too_large"), result


# Each is read (no size limit is broken) but has no value sympy's evalf could compute in bounded time:
# the judge must decide it without evalf, long before the time limit kills the worker.
UNBOUNDED_VALUES = [
    pytest.param("exp(exp(exp(exp(exp(exp(m))))))*g*h", "wrong_dimension", id="exp-tower-of-a-mass"),
    pytest.param("m*g*h*exp(exp(exp(exp(exp(exp(x^2))))))", "wrong_value", id="exp-tower"),
    pytest.param("m*g*h*factorial(exp(exp(exp(exp(x^2)))))", "wrong_value", id="factorial-of-exp-tower"),
    pytest.param("m*g*h*factorial(factorial(factorial(x)))", "wrong_value", id="factorial-tower"),
    # No value anywhere, so the bounded proof is tried: trigsimp of a function of a function.
    pytest.param("m*g*h*sinh(sinh(sinh(sinh(sinh(sinh(x^2+2))))))", "wrong_value", id="sinh-nest"),
    # Complex intermediates nested twelve deep: evalf's time grows fourfold per level.
    pytest.param("m*g*h*" + "log10(" * 12 + "x^2+2" + ")" * 12, "wrong_value", id="log10-nest"),
]


@pytest.mark.parametrize(("answer", "reason"), UNBOUNDED_VALUES)
def test_answer_with_unbounded_value_is_graded_not_timed_out(client, student_headers, answer, reason):
    response = client.post("/v1/check", json=symbolic(answer), headers=student_headers)
    assert response.status_code == 200
    result = response.json()
    assert (result["verdict"], result["reason"]) == ("incorrect", reason), result


INJECTIONS = [
    "__import__('os').system('touch {marker}')",
    "().__class__.__base__.__subclasses__()",
    "exec(\"open('{marker}', 'w')\")",
    "eval('1')",
    "lambda: open('{marker}', 'w')",
    "`touch {marker}`",
    'f\'{{open("{marker}", "w")}}\'',
    "m; import os; os.system('touch {marker}')",
    "getattr(m, '__class__')",
]


@pytest.mark.parametrize("template", INJECTIONS)
def test_injection_payload_is_rejected_and_runs_nothing(client, student_headers, tmp_path: Path, template):
    marker = tmp_path / "pwned"
    answer = template.format(marker=marker)
    for body in (symbolic(answer), symbolic("m g h", expected=answer)):
        response = client.post("/v1/check", json=body, headers=student_headers)
        if response.status_code == 200:
            assert response.json()["verdict"] == "invalid", response.json()
        else:
            assert response.status_code == 422  # an injected reference is the author's error
    assert not marker.exists()


async def _check_all(pool: GradingPool, answers: list[str]) -> list[tuple[str, float]]:
    symbols = (
        SymbolDecl("x", real=True),
        SymbolDecl("m", "kg"),
        SymbolDecl("g", "m/s^2"),
        SymbolDecl("h", "m"),
    )

    async def one(answer: str) -> tuple[str, float]:
        started = time.perf_counter()
        verdict = await pool.check(SymbolicJob(answer=answer, expected="m*g*h", symbols=symbols))
        return verdict.outcome.value + "/" + verdict.reason.value, time.perf_counter() - started

    return await asyncio.gather(*(one(a) for a in answers))


def test_honest_check_completes_while_hostile_ones_are_refused(grading_pool):
    hostile = [p.values[0] for p in HOSTILE if p.id != "one-megabyte"]
    results = asyncio.run(_check_all(grading_pool, [*hostile, "m g h", "mgh", "m h g"]))
    outcomes = [outcome for outcome, _ in results]
    assert outcomes[-3:] == ["correct/equivalent"] * 3
    assert all(outcome == "invalid/too_large" for outcome in outcomes[:-3]), outcomes


_SPELLINGS = itertools.count(2)


def unseen_m() -> str:
    """An answer equal to m that the pool has not graded yet: a remembered verdict skips the queue."""
    n = next(_SPELLINGS)
    return f"{n}*m/{n}"


@pytest.fixture(scope="module")
def hanging_pool():
    pool = GradingPool(
        workers=1, timeout=0.5, memory_mb=1024, max_tasks=100, queue_size=4, task=hanging_grade
    )
    pool.start()
    yield pool
    pool.close()


def test_overrunning_check_is_killed_and_answered_timeout(hanging_pool):
    symbols = (SymbolDecl("m", "kg"),)

    async def scenario():
        hung = await hanging_pool.check(SymbolicJob(answer="hang", expected="m", symbols=symbols))
        after = await hanging_pool.check(SymbolicJob(answer="m", expected="m", symbols=symbols))
        return hung, after

    hung, after = asyncio.run(scenario())
    assert (hung.outcome.value, hung.reason.value) == ("invalid", "timeout")
    assert "simplify" in hung.feedback
    # The killed worker was replaced: the next check is graded normally.
    assert after.outcome.value == "correct"


def test_full_queue_answers_busy_with_retry_after(hanging_pool):
    from app.errors import Busy

    symbols = (SymbolDecl("m", "kg"),)

    async def scenario():
        jobs = [
            hanging_pool.check(SymbolicJob(answer="hang", expected="m", symbols=symbols)) for _ in range(5)
        ]
        tasks = [asyncio.ensure_future(job) for job in jobs]
        await asyncio.sleep(0.05)
        with pytest.raises(Busy) as refused:
            await hanging_pool.check(SymbolicJob(answer=unseen_m(), expected="m", symbols=symbols))
        await asyncio.gather(*tasks)
        return refused.value

    refused = asyncio.run(scenario())
    assert refused.headers["Retry-After"] == "1"


def test_previews_count_against_the_queue_too(hanging_pool):
    from app.errors import Busy

    symbols = (SymbolDecl("m", "kg"),)

    async def scenario():
        tasks = [
            asyncio.ensure_future(
                hanging_pool.check(SymbolicJob(answer="hang", expected="m", symbols=symbols))
            )
            for _ in range(5)
        ]
        await asyncio.sleep(0.05)
        with pytest.raises(Busy):
            await hanging_pool.preview(SymbolicJob(answer="m", expected="m", symbols=symbols))
        await asyncio.gather(*tasks)

    asyncio.run(scenario())


def test_one_student_cannot_hold_more_than_its_share_of_the_workers(hanging_pool):
    from app.errors import Busy

    symbols = (SymbolDecl("m", "kg"),)

    def job(answer: str) -> SymbolicJob:
        return SymbolicJob(answer=answer, expected="m", symbols=symbols)

    async def scenario():
        held = [asyncio.ensure_future(hanging_pool.check(job("hang"), "ada")) for _ in range(2)]
        await asyncio.sleep(0.05)
        with pytest.raises(Busy, match="still being checked"):
            await hanging_pool.check(job(unseen_m()), "ada")
        queued = asyncio.ensure_future(hanging_pool.check(job(unseen_m()), "bob"))  # another student gets in
        unlimited = asyncio.ensure_future(hanging_pool.check(job(unseen_m()), None))  # an instructor key too
        results = await asyncio.gather(*held, queued, unlimited)
        after = await hanging_pool.check(job(unseen_m()), "ada")  # the share is given back
        return results, after

    results, after = asyncio.run(scenario())
    assert [r.reason.value for r in results] == ["timeout", "timeout", "equivalent", "equivalent"]
    assert after.outcome.value == "correct"
