"""`/` is a page for people, pointing to what they can do; the shared stylesheet is served."""

from __future__ import annotations

from fastapi import FastAPI
from fastapi.testclient import TestClient

from app.web import router as web_routes
from app.web.layout import STATIC_PATH, static_files


def _client() -> TestClient:
    app = FastAPI()
    app.include_router(web_routes.router)
    app.mount(STATIC_PATH, static_files(), name="static")
    return TestClient(app)


def test_home_points_students_instructors_and_developers_to_their_pages() -> None:
    response = _client().get("/")
    assert response.status_code == 200
    assert response.headers["content-type"].startswith("text/html")
    for link in ('href="/problems"', 'href="/instructor"', 'href="/docs"'):
        assert link in response.text
    csp = response.headers["content-security-policy"]
    assert "script-src 'self'" in csp and "unsafe-inline" not in csp


def test_stylesheet_is_served_from_the_app() -> None:
    response = _client().get("/static/physcheck.css")
    assert response.status_code == 200
    assert "max-width" in response.text
