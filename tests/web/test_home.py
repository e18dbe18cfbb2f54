"""`/` is a page for people, pointing to what they can do; the shared stylesheet is served."""

from __future__ import annotations

import threading
from types import SimpleNamespace

import pytest
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


class _Catalog:
    """The catalog as the pages read it: ready (`warm`) or still deriving, with its progress."""

    def __init__(self, ready: bool, deriving: tuple[int, int] | None) -> None:
        self.warm = threading.Event()
        if ready:
            self.warm.set()
        self.deriving = deriving


@pytest.mark.parametrize(
    ("ready", "deriving", "said"),
    [
        (False, None, "still preparing its problems."),  # before the first is derived: no count yet
        (False, (12, 40), "still preparing its problems (12 of 40 ready)."),
        (True, None, None),
    ],
)
def test_home_says_while_the_bank_is_still_being_derived_at_a_first_start(
    ready: bool, deriving: tuple[int, int] | None, said: str | None
) -> None:
    # it had said nothing while /ready said "Still compiling the problems (N of M derived)"
    client = _client()
    client.app.state.services = SimpleNamespace(catalog=_Catalog(ready, deriving))  # type: ignore[attr-defined]
    text = client.get("/").text
    if said is None:
        assert "preparing its problems" not in text
    else:
        assert said in text and "its page waits for it" in text
