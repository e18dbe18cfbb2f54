"""Students' answers stay out of the log unless an operator turns them on (PHYSCHECK_LOG_ANSWERS): a
submission's log line names the problem, part, student and verdict, not what was typed."""

from __future__ import annotations

import io
import json
import logging

from fastapi.testclient import TestClient

from app.grading.pool import GradingPool
from app.logs import JsonLogFormatter
from app.settings import Settings
from tests.api.conftest import key_headers, make_app

SUBMIT = "/v1/problems/atwood/parts/acceleration/submissions"
ANSWER = "g (m2 - m1)/(m1 + m2) + 0*zebra"


def _submit_and_log(settings: Settings, backend: str, pool: GradingPool, answer: str = ANSWER) -> str:
    """Every line the service logs while a student submits, as the server writes them."""
    text = io.StringIO()
    with TestClient(make_app(settings, backend, pool=pool)) as client:
        handler = logging.StreamHandler(text)
        handler.setFormatter(JsonLogFormatter())
        logging.getLogger("physcheck").addHandler(handler)
        try:
            headers = key_headers(client, "student", "ada", student="ada-1815")
            response = client.post(SUBMIT, json={"answer": answer}, headers=headers)
            assert response.status_code == 201, response.text
        finally:
            logging.getLogger("physcheck").removeHandler(handler)
    return text.getvalue()


def test_answers_are_not_logged_by_default(settings: Settings, backend: str, grading_pool: GradingPool):
    logged = _submit_and_log(settings, backend, grading_pool)
    assert '"message": "graded"' in logged and "ada-1815" in logged
    assert "zebra" not in logged
    assert '"answer"' not in logged


def test_an_operator_may_log_answers(settings: Settings, backend: str, grading_pool: GradingPool):
    settings = settings.model_copy(update={"log_answers": True})
    logged = _submit_and_log(settings, backend, grading_pool)
    assert "zebra" in logged


def test_logged_answers_are_truncated_and_escaped(
    settings: Settings, backend: str, grading_pool: GradingPool
):
    settings = settings.model_copy(update={"log_answers": True})
    forged = 'x\n{"level": "CRITICAL", "message": "forged"}' + "y" * 500
    lines = _submit_and_log(settings, backend, grading_pool, forged).splitlines()
    graded = [json.loads(line) for line in lines if '"graded"' in line]
    assert len(graded) == 1
    assert graded[0]["answer"].startswith('x\n{"level"') and len(graded[0]["answer"]) <= 121
    assert not any("forged" in line and '"level": "CRITICAL"' in line.split('"answer"')[0] for line in lines)
