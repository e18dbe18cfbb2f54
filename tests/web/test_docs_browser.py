"""/docs in Chromium with every other host unreachable: Swagger UI renders the API from our own files,
and "Authorize" then "Try it out" sends the key as a bearer token."""

from __future__ import annotations

from typing import Any

import pytest

from tests.browser import LiveServer

pytestmark = [pytest.mark.browser, pytest.mark.slow]


def test_docs_work_offline_and_try_it_out_sends_the_key(live_server: LiveServer, chromium: Any) -> None:
    from playwright.sync_api import expect

    context = chromium.new_context(viewport={"width": 1280, "height": 900})
    elsewhere: list[str] = []

    def only_our_origin(route: Any) -> None:
        if route.request.url.startswith(live_server.url):
            route.continue_()
        else:
            elsewhere.append(route.request.url)
            route.abort()

    context.route("**/*", only_our_origin)
    sent: list[dict[str, str]] = []
    try:
        page = context.new_page()
        page.on(
            "request", lambda request: sent.append(request.headers) if "/v1/problems" in request.url else None
        )
        page.goto(live_server.url + "/docs")
        expect(page.locator(".swagger-ui .info .title")).to_contain_text("physcheck", timeout=30_000)

        key = live_server.key("student", "docs", student="docs-student")
        page.locator(".swagger-ui .auth-wrapper .authorize").click()
        page.locator(".auth-container input").fill(key)
        page.locator(".auth-btn-wrapper .authorize").click()
        page.locator(".auth-btn-wrapper .btn-done").click()

        operation = page.locator("[id^='operations-problems-list_problems']")
        operation.locator(".opblock-summary").click()
        operation.get_by_role("button", name="Try it out").click()
        operation.get_by_role("button", name="Execute").click()
        expect(operation.locator(".live-responses-table tbody .response-col_status").first).to_have_text(
            "200", timeout=30_000
        )
    finally:
        context.close()
    assert elsewhere == []
    assert sent and sent[-1].get("authorization") == f"Bearer {key}"
