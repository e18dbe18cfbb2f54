"""A fault of the grader is never the student's: dead workers are replaced, and nothing is filed meanwhile."""

from __future__ import annotations

import asyncio
import itertools
import os
import signal
import threading
import time
from collections.abc import Iterator

import pytest
from fastapi.testclient import TestClient

from app.authoring import AuthoringPool
from app.db.database import Database
from app.errors import GraderFault, Unavailable
from app.grading.pool import GradingPool
from app.keys import create_key
from app.main import create_app
from app.settings import Settings
from physics.checking import SymbolDecl
from physics.errors import SpecError
from problems.kinds.symbolic import SymbolicJob
from tests.api.slow_task import pid_or_grade, slow_vet, spec_failing_preview

SYMBOLS = (SymbolDecl("m", "kg"),)
RECOVERY_DEADLINE = 60  # only so that a broken pool fails the test instead of hanging it
SUBMIT = "/v1/problems/moving-wedge/parts/wedge_acceleration/submissions"
CORRECT = "-m g sin(θ)cos(θ)/(M + m sin^2 θ)"


def job(answer: str) -> SymbolicJob:
    return SymbolicJob(answer=answer, expected="m", symbols=SYMBOLS)


def make_pool(**overrides: object) -> GradingPool:
    options: dict[str, object] = dict(
        workers=1,
        timeout=5.0,
        memory_mb=1024,
        max_tasks=100,
        queue_size=8,
        task=pid_or_grade,
        preview_task=spec_failing_preview,
    )
    return GradingPool(**(options | overrides))  # type: ignore[arg-type]


@pytest.fixture(scope="module")
def faulty_pool() -> Iterator[GradingPool]:
    pool = make_pool()
    pool.start()
    yield pool
    pool.close()


def worker_pid(pool: GradingPool) -> int:
    pid = asyncio.run(pool.check(job("pid")))
    assert isinstance(pid, int)
    return pid


def graded_after_recovery(pool: GradingPool) -> tuple[str, int]:
    """Check until grading works again; only 'unavailable' (503) is an acceptable answer meanwhile."""
    deadline = time.monotonic() + RECOVERY_DEADLINE
    while True:
        try:
            verdict = asyncio.run(pool.check(job("m")))
            return verdict.outcome.value, worker_pid(pool)
        except Unavailable as refused:
            assert refused.status == 503 and refused.headers["Retry-After"]
            assert time.monotonic() < deadline, "grading did not come back"
            time.sleep(0.1)


@pytest.mark.slow
def test_an_idle_worker_killed_from_outside_is_replaced_and_grading_resumes(faulty_pool):
    victim = worker_pid(faulty_pool)
    os.kill(victim, signal.SIGKILL)  # what the kernel's OOM killer does
    outcome, worker = graded_after_recovery(faulty_pool)
    assert outcome == "correct"
    assert worker != victim
    assert faulty_pool.ready


@pytest.mark.slow
def test_a_worker_that_dies_mid_check_is_a_retryable_503_not_a_verdict(faulty_pool):
    with pytest.raises(Unavailable) as refused:
        asyncio.run(faulty_pool.check(job("die")))
    assert refused.value.status == 503 and refused.value.headers["Retry-After"]
    assert graded_after_recovery(faulty_pool)[0] == "correct"


@pytest.mark.parametrize(
    ("answer", "raised"),
    [
        pytest.param("recurse", GraderFault, id="RecursionError"),
        pytest.param("overflow", GraderFault, id="OverflowError"),
        pytest.param("spec", SpecError, id="SpecError"),  # the caller decides whose reference it was
    ],
)
def test_an_exception_inside_grading_is_a_fault_not_a_verdict(faulty_pool, answer, raised):
    with pytest.raises(raised):
        asyncio.run(faulty_pool.check(job(answer)))


def test_running_out_of_memory_under_the_worker_limit_is_the_answers_too_large(faulty_pool):
    verdict = asyncio.run(faulty_pool.check(job("nomemory")))
    assert (verdict.outcome.value, verdict.reason.value) == ("invalid", "too_large")


class GatedPool(GradingPool):
    """Its first worker starts at once; replacements wait until the test opens the gate (as they wait
    for a fork server that is loading the checker again)."""

    def __init__(self) -> None:
        super().__init__(
            workers=1, timeout=5.0, memory_mb=1024, max_tasks=100, queue_size=8, task=pid_or_grade
        )
        self.gate = threading.Event()

    def _new_pool(self):  # type: ignore[no-untyped-def]
        pool = super()._new_pool()
        spawn, started = pool._spawn, itertools.count()

        def gated_spawn():  # type: ignore[no-untyped-def]
            if next(started):
                self.gate.wait(RECOVERY_DEADLINE)
            return spawn()

        pool._spawn = gated_spawn
        return pool


def _key(settings: Settings, role: str, name: str) -> dict[str, str]:
    database = Database(settings.database_url)
    try:
        return {"Authorization": f"Bearer {create_key(database, role, name)[0]}"}
    finally:
        database.dispose()


@pytest.mark.slow
def test_while_grading_is_down_ready_and_checks_answer_503_with_retry_after(db: Database):
    settings = Settings(database_url=db.url, secret="test-secret-0123456789", warm_up=False)
    pool = GatedPool()
    pool.start()
    try:
        with TestClient(create_app(settings, pool=pool)) as client:
            headers = _key(settings, "instructor", "prof")
            body = {"kind": "symbolic", "answer": "m", "expected": "m", "symbols": {"m": {"dimension": "kg"}}}
            assert client.get("/ready").status_code == 200
            os.kill(worker_pid(pool), signal.SIGKILL)
            deadline = time.monotonic() + RECOVERY_DEADLINE
            while pool.ready:
                assert time.monotonic() < deadline, "the broken pool was never noticed"
                time.sleep(0.05)
            for response in (client.get("/ready"), client.post("/v1/check", json=body, headers=headers)):
                assert response.status_code == 503
                assert response.headers["Retry-After"]
                assert set(response.json()["error"]) == {"code", "message", "details"}
            pool.gate.set()
            while (response := client.post("/v1/check", json=body, headers=headers)).status_code == 503:
                assert time.monotonic() < deadline, "grading did not come back"
                time.sleep(0.1)
            assert response.status_code == 200 and response.json()["verdict"] == "correct"
            assert client.get("/ready").status_code == 200
    finally:
        pool.gate.set()
        pool.close()


@pytest.fixture
def submitting(db: Database, faulty_pool: GradingPool) -> Iterator[tuple[TestClient, dict[str, str]]]:
    settings = Settings(database_url=db.url, secret="test-secret-0123456789", warm_up=False)
    with TestClient(create_app(settings, pool=faulty_pool)) as client:
        yield client, _key(settings, "student", "ada")


@pytest.mark.slow
@pytest.mark.parametrize(
    ("answer", "status", "code"),
    [
        pytest.param("die", 503, "unavailable", id="worker-died"),
        pytest.param("recurse", 500, "grader_fault", id="RecursionError"),
        pytest.param("overflow", 500, "grader_fault", id="OverflowError"),
        pytest.param("spec", 500, "grader_fault", id="stored-reference-fails"),
    ],
)
@pytest.mark.sample(10)
def test_a_grader_fault_on_a_submission_files_nothing_and_uses_no_attempt(submitting, answer, status, code):
    client, student = submitting
    response = client.post(SUBMIT, json={"answer": answer}, headers=student)
    assert response.status_code == status, response.text
    assert response.json()["error"]["code"] == code
    assert client.get("/v1/submissions", headers=student).json()["items"] == []
    deadline = time.monotonic() + RECOVERY_DEADLINE
    while (graded := client.post(SUBMIT, json={"answer": CORRECT}, headers=student)).status_code == 503:
        assert time.monotonic() < deadline, "grading did not come back"
        time.sleep(0.1)
    assert graded.status_code == 201, graded.text
    assert (graded.json()["verdict"], graded.json()["attempts_used"]) == ("correct", 1)


class SlowAuthoringPool(AuthoringPool):
    _task = staticmethod(slow_vet)  # type: ignore[assignment]


@pytest.fixture
def vetting() -> Iterator[AuthoringPool]:
    pool = SlowAuthoringPool(timeout=30.0, memory_mb=1024)
    yield pool
    pool.close()


async def vetting_pid(pool: AuthoringPool) -> int:
    """The vetting worker's process id, once the pool has one to vet with (503s meanwhile)."""
    deadline = time.monotonic() + RECOVERY_DEADLINE
    while True:
        try:
            vetted = await pool.vet(b"pid", "json")
        except Unavailable:
            assert time.monotonic() < deadline, "upload vetting did not come back"
            await asyncio.sleep(0.1)
            continue
        [(path, pid)] = vetted.errors
        assert path == "pid", vetted.errors  # vetted by the task, not failed by the pool
        return int(pid)


@pytest.mark.slow
def test_a_vetting_worker_killed_while_idle_is_replaced_for_the_next_upload(vetting):
    async def scenario():
        victim = await vetting_pid(vetting)
        os.kill(victim, signal.SIGKILL)
        return victim, await vetting_pid(vetting)

    victim, successor = asyncio.run(scenario())
    assert successor != victim


@pytest.mark.slow
def test_an_upload_whose_vetting_worker_is_killed_gets_503_not_a_vetting_error(vetting):
    async def scenario():
        victim = await vetting_pid(vetting)
        upload = asyncio.ensure_future(vetting.vet(b"sleep", "json"))
        await asyncio.sleep(0)  # the upload runs up to its await: sent to the worker by then
        os.kill(victim, signal.SIGKILL)
        with pytest.raises(Unavailable) as refused:
            await upload
        return refused.value, victim, await vetting_pid(vetting)

    refused, victim, successor = asyncio.run(scenario())
    assert refused.status == 503 and int(refused.headers["Retry-After"]) > 0
    assert successor != victim


@pytest.mark.slow
def test_a_stored_problem_whose_reference_fails_in_a_preview_is_a_grader_fault(submitting):
    client, student = submitting
    url = SUBMIT.replace("submissions", "preview")
    response = client.post(url, json={"answer": "spec"}, headers=student)
    assert response.status_code == 500 and response.json()["error"]["code"] == "grader_fault"
    assert client.post(url, json={"answer": "m g"}, headers=student).status_code == 200
