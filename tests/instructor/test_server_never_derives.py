"""The server process never derives a model: an upload is stored with what its vetting worker derived,
and a problem that is not stored compiled yet is derived in a worker process. Every derivation entry
point is made to fail in this (the server's) process, then an upload is previewed, saved, graded and
shown on every page; the workers, forked from the fork server, are untouched by the patch."""

from __future__ import annotations

import subprocess
import sys

import pytest
from fastapi.testclient import TestClient

from tests.derivations import count_derivations
from tests.instructor.conftest import csrf_of, new_key, stores_of
from tests.instructor.test_pages import upload_text


@pytest.fixture
def derivations_here(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """Calls of a derivation entry point in this process (each also raises)."""
    calls: list[str] = []

    def refuse(name: str):
        def called(*args, **kwargs):
            calls.append(name)
            raise AssertionError(f"{name} was called in the server process")

        return called

    for target in (
        "physics.engine.derive",
        "physics.engine.derivation.derive",
        "problems.modelinfo.derive",
        "problems.modelinfo.derive_doc",
        "problems.compiled.derive_doc",
        "problems.compiled.build_problem",
        "problems.vetting.derive",
        "problems.vetting.derive_doc",
        "problems.vetting.vet_document",
        "app.authoring.vet_document",
    ):
        monkeypatch.setattr(target, refuse(target))
    return calls


@pytest.fixture
def sent_to_workers(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The ids of the documents the catalog asked a derivation worker for."""
    return count_derivations(monkeypatch)


def test_an_upload_is_previewed_stored_graded_and_shown_without_deriving_in_the_server(
    derivations_here: list[str], sent_to_workers: list[str], signed_in: TestClient, instructor_key: str
):
    """The patch is in place before the app starts: storing the bank derives nothing either."""
    token = csrf_of(signed_in.get("/instructor/problems/new").text)
    preview = signed_in.post(
        "/instructor/problems/new", data={"csrf": token, "source": upload_text(), "action": "preview"}
    )
    assert preview.status_code == 200, preview.text
    assert 'alttext="\\frac{g r^{2}}{k^{2} + r^{2}}"' in preview.text  # the derived answer, from the worker
    saved = signed_in.post(
        "/instructor/problems/new", data={"csrf": token, "source": upload_text(), "action": "save"}
    )
    assert saved.status_code == 303, saved.text

    services = signed_in.app.state.services  # type: ignore[attr-defined]
    record = services.catalog.get("my-yoyo")
    assert services.catalog.is_stored(record)  # at upload

    for page in ("/instructor/problems/my-yoyo", "/instructor/problems/my-yoyo/solution"):
        response = signed_in.get(page, params={"student": "ada"})
        assert response.status_code == 200, (page, response.text)
    student = {"Authorization": f"Bearer {new_key(stores_of(signed_in), 'student', 'Ada', 'ada')}"}
    graded = signed_in.post(
        "/v1/problems/my-yoyo/parts/acceleration/submissions",
        json={"answer": "g r^2/(k^2 + r^2)"},
        headers=student,
    )
    assert graded.status_code == 201, graded.text
    assert graded.json()["verdict"] == "correct"
    assert signed_in.get("/p/my-yoyo", headers=student).status_code == 200
    author = {"Authorization": f"Bearer {instructor_key}"}  # an upload is its author's courses' only
    assert signed_in.get("/v1/problems/my-yoyo/solution", headers=author).status_code == 200
    assert sent_to_workers == []  # the upload's own compilation: nothing derived again

    # The bank's yo-yo, not stored compiled yet (no warm-up here): derived by a worker, then graded.
    bank = signed_in.post(
        "/v1/problems/yo-yo/parts/acceleration/submissions",
        json={"answer": "g r^2/(k^2 + r^2)"},
        headers=student,
    )
    assert bank.status_code == 201, bank.text
    assert sent_to_workers == ["yo-yo"]
    assert derivations_here == []


def instructor(client: TestClient) -> dict[str, str]:
    return {"Authorization": f"Bearer {new_key(stores_of(client), 'instructor', 'Prof Bo')}"}


def test_the_api_stores_each_version_with_its_compilation(
    derivations_here: list[str], sent_to_workers: list[str], client: TestClient
):
    headers = {**instructor(client), "content-type": "application/yaml"}
    assert client.post("/v1/problems", content=upload_text(), headers=headers).status_code == 201
    revised = upload_text(title="My yo-yo, revised")
    assert client.put("/v1/problems/my-yoyo", content=revised, headers=headers).status_code == 200
    services = client.app.state.services  # type: ignore[attr-defined]
    for version in (1, 2):
        record = services.catalog.get("my-yoyo", version)
        assert services.catalog.is_stored(record)
        assert services.catalog.compiled(record).version == version
    assert sent_to_workers == [] and derivations_here == []


def test_the_vetting_worker_imports_no_page_code():
    """What the pages show of an upload is built where pages are: the worker's module needs none of it."""
    code = (
        "import sys, app.authoring; "
        "print(sorted(m for m in sys.modules if m.startswith(('app.instructor', 'app.web'))))"
    )
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=True
    )
    assert done.stdout.strip() == "[]"
