"""Derivation workers: a document derived in a worker process, under its time limit; one that fails is
refused again at once; closing kills the workers mid-derivation."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
import yaml

from app.derivation import DerivationFailed, DerivationPool, DerivationTimedOut, forget_derived, unpack
from app.grading.processes import PoolUnavailable

BANK = Path(__file__).resolve().parents[2] / "problems" / "bank"


def atwood(**changes) -> dict:
    doc = yaml.safe_load((BANK / "atwood" / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK / "atwood" / "model.yaml").read_text())
    return {**doc, **changes}


@pytest.fixture
def scheduled(monkeypatch) -> list[str]:
    """The ids of the documents sent to a worker; nothing remembered from other tests."""
    forget_derived()
    sent: list[str] = []
    real = DerivationPool._schedule

    def counting(self, document):
        sent.append(document["id"])
        return real(self, document)

    monkeypatch.setattr(DerivationPool, "_schedule", counting)
    yield sent
    forget_derived()


def test_a_document_is_derived_once_in_a_worker_and_then_remembered(scheduled):
    pool = DerivationPool(workers=1, timeout=120)
    try:
        payload = pool.submit(atwood(id="atwood-here")).result()
        again = pool.submit(atwood(id="atwood-here")).result()
    finally:
        pool.close()
    compiled = unpack(payload, 3)
    assert compiled is not None and compiled.version == 3 and compiled.derived is not None
    assert again == payload and scheduled == ["atwood-here"]


def test_a_document_that_fails_is_refused_again_without_a_worker(scheduled):
    broken = atwood(id="broken")
    broken["parts"][0]["answer"] = "(m2 - m1)*g/(m1 + m2) + zeta"  # zeta: declared nowhere
    pool = DerivationPool(workers=1, timeout=120)
    try:
        with pytest.raises(DerivationFailed, match="zeta"):
            pool.submit(broken).result()
        with pytest.raises(DerivationFailed, match="zeta"):
            pool.submit(broken).result()
    finally:
        pool.close()
    assert scheduled == ["broken"]


def test_a_derivation_someone_waits_for_goes_before_those_queued_for_no_one(scheduled):
    pool = DerivationPool(workers=1, timeout=120)
    finished: list[str] = []
    try:
        futures = {name: pool.submit(atwood(id=name)) for name in ("first", "second", "third", "last")}
        for name, future in futures.items():
            future.add_done_callback(lambda _, name=name: finished.append(name))
        assert pool.submit(atwood(id="last"), urgent=True) is futures["last"]  # the same derivation
        for future in futures.values():
            future.result()
    finally:
        pool.close()
    # "first" was running already; "last" was waiting behind the other two, and now goes before them.
    assert finished == ["first", "last", "second", "third"]


def test_a_new_derivation_someone_waits_for_goes_before_those_queued_for_no_one(scheduled):
    # a problem stored after a first start (an upload, an edit) had waited behind the whole bank
    pool = DerivationPool(workers=1, timeout=120)
    finished: list[str] = []
    try:
        futures = {name: pool.submit(atwood(id=name)) for name in ("first", "second", "third")}
        futures["asked"] = pool.submit(atwood(id="asked"), urgent=True)
        for name, future in futures.items():
            future.add_done_callback(lambda _, name=name: finished.append(name))
        for future in futures.values():
            future.result()
    finally:
        pool.close()
    assert finished == ["first", "asked", "second", "third"]


def test_a_derivation_past_its_time_limit_is_killed_and_tried_again_when_asked(scheduled):
    pool = DerivationPool(workers=1, timeout=0.001)  # far below any derivation
    try:
        for _ in range(2):
            with pytest.raises(DerivationTimedOut, match="longer than"):
                pool.submit(atwood(id="slow")).result()
    finally:
        pool.close()
    assert scheduled == ["slow", "slow"]


def test_closing_kills_a_derivation_in_progress():
    forget_derived()
    pool = DerivationPool(workers=1, timeout=120)
    future = pool.submit(atwood(id="closed-early"))
    assert pool._pool is not None
    pids = [worker.process.pid for worker in pool._pool._live]  # the processes to watch
    assert pids
    pool.close()
    with pytest.raises(PoolUnavailable):
        future.result()
    for pid in pids:  # killed and reaped by the fork server
        with pytest.raises(ProcessLookupError):
            os.kill(pid, 0)
