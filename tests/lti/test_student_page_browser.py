"""Headless Chromium drives the student page in key mode: type an answer, see the preview and the
verdict; a screenshot is saved to `artifacts/` (or PHYSCHECK_ARTIFACTS_DIR). Skipped without Chromium."""

from __future__ import annotations

import os
import shutil
import socket
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from fastapi import FastAPI, Request
from fastapi.responses import JSONResponse

from app.lti.context import LtiContext
from app.lti.router import router
from tests.lti.conftest import STUDENT_KEY

pytestmark = [pytest.mark.browser, pytest.mark.slow]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


def fake_api(app: FastAPI) -> None:
    """Stand-ins for the lead's /v1 routes the page calls, with the student key as bearer token."""

    def authorized(request: Request) -> bool:
        return request.headers.get("authorization") == f"Bearer {STUDENT_KEY}"

    @app.post("/v1/problems/{problem_id}/parts/{part_id}/preview")
    async def preview(problem_id: str, part_id: str, request: Request) -> Any:
        if not authorized(request):
            return JSONResponse({"error": {"code": "unauthenticated", "message": "no key"}}, status_code=401)
        answer = (await request.json())["answer"]
        return {"read_as": {"text": "*".join(answer.split()), "latex": ""}, "error": None}

    @app.post("/v1/problems/{problem_id}/parts/{part_id}/submissions", status_code=201)
    async def submit(problem_id: str, part_id: str, request: Request) -> Any:
        if not authorized(request):
            return JSONResponse({"error": {"code": "unauthenticated", "message": "no key"}}, status_code=401)
        answer = (await request.json())["answer"]
        correct = "*".join(answer.split()) == "m*g"
        return {"verdict": "correct" if correct else "incorrect", "feedback": "", "attempts_used": 1}


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


@pytest.fixture
def served(context: LtiContext) -> Iterator[str]:
    import uvicorn

    app = FastAPI()
    app.include_router(router)
    fake_api(app)
    app.state.lti = context
    port = free_port()
    server = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning"))
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + 20
    while not server.started and time.monotonic() < deadline:
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}"
    server.should_exit = True
    thread.join(timeout=10)


@pytest.mark.skipif(CHROMIUM is None, reason="Debian's chromium package is not installed")
def test_student_types_answer_sees_preview_and_verdict(served: str):
    from playwright.sync_api import expect, sync_playwright

    artifacts = Path(os.environ.get("PHYSCHECK_ARTIFACTS_DIR", "artifacts"))
    artifacts.mkdir(parents=True, exist_ok=True)
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, headless=True)
        try:
            page = browser.new_page()
            page.goto(f"{served}/p/moving-wedge")
            page.get_by_label("Your student key").fill(STUDENT_KEY)
            page.get_by_role("button", name="Open").click()
            answer = page.get_by_label("Your answer").first
            answer.fill("m g")
            expect(page.locator("#preview-0")).to_contain_text("Read as: m*g")
            page.get_by_role("button", name="Check answer").first.click()
            expect(page.locator(".verdict").first).to_contain_text("Correct.")
            page.screenshot(path=str(artifacts / "student-page.png"), full_page=True)
        finally:
            browser.close()
