"""The tool (our router on the in-memory stores) and a fake LMS, both on loopback ASGI. A test looks
into the stores through `fakes` where a test on SQL would count rows; the storage contract itself is
held on SQLite and PostgreSQL by tests/storage."""

from __future__ import annotations

import base64
import json
import shutil
from collections.abc import AsyncIterator, Iterator
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any
from urllib.parse import parse_qs, urlsplit

import httpx
import pytest
from fastapi import FastAPI
from joserfc.jwk import RSAKey

from app.auth import Principal, Role
from app.grading.pool import GradingPool
from app.lti import keys
from app.lti.context import LtiContext
from app.lti.router import router
from app.settings import Settings
from app.storage import Stores, memory_stores
from app.storage.memory import MemoryScoreOutbox, MemoryToolKeys
from app.storage.memory_lti import MemoryLaunchStore, MemoryLtiSessionStore
from problems.loader import BANK_DIR
from tests.lti.fake_lms import CLIENT_ID, DEPLOYMENT_ID, ISSUER, TOOL, FakeLms, register_fake_lms

PROBLEMS = {
    "moving-wedge": {"title": "Block on a moving wedge", "parts": [{"id": "a"}, {"id": "b"}]},
    "yo-yo": {"title": "Yo-yo", "parts": [{"id": "acceleration"}]},
}


@pytest.fixture
def anyio_backend() -> str:
    return "asyncio"


@pytest.fixture(scope="session")
def lti_grading_pool() -> Iterator[GradingPool]:
    """One grading worker for the whole run, for the tests that run the real app (starting one per
    test would dominate their time)."""
    pool = GradingPool(workers=1, timeout=5.0, memory_mb=1024, max_tasks=1000, queue_size=16)
    pool.start()
    yield pool
    pool.close()


@pytest.fixture(scope="session")
def yo_yo_bank(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A bank of the built-in yo-yo alone, for the tests that run the real app: its lifespan compiles
    every bank problem in a thread that outlives the app, and one problem is all these tests need."""
    bank = tmp_path_factory.mktemp("bank")
    shutil.copytree(BANK_DIR / "yo-yo", bank / "yo-yo")
    return bank


@pytest.fixture
def lms() -> FakeLms:
    return FakeLms()


@pytest.fixture
def settings() -> Settings:
    # The tool's stores come with the context; no warm-up: deriving the whole bank in this process
    # would slow every test (problems compile on use).
    return Settings(database_url="sqlite://", base_url=TOOL, secret="test-secret-123", warm_up=False)


@pytest.fixture(scope="session")
def tool_key() -> RSAKey:
    return keys.generate()


@pytest.fixture
def stores(tool_key: RSAKey) -> Stores:
    """The tool's stores: in-memory fakes with two problems, the fake LMS registered and our signing
    key (made once per run: RSA is slow)."""
    stores = replace(memory_stores(), tool_keys=MemoryToolKeys([tool_key]))
    for problem_id, document in PROBLEMS.items():
        stores.problems.save_builtin(problem_id, document)
    register_fake_lms(stores)
    return stores


@dataclass(frozen=True)
class Fakes:
    """The in-memory stores a test looks into: logins in progress, our sessions, grade targets."""

    launches: MemoryLaunchStore
    sessions: MemoryLtiSessionStore
    outbox: MemoryScoreOutbox


@pytest.fixture
def fakes(stores: Stores) -> Fakes:
    assert isinstance(stores.launches, MemoryLaunchStore), "a test that looks into the fakes runs on them"
    assert isinstance(stores.lti_sessions, MemoryLtiSessionStore)
    assert isinstance(stores.outbox, MemoryScoreOutbox)
    return Fakes(stores.launches, stores.lti_sessions, stores.outbox)


STUDENT_KEY = "student-key-for-tests"


def fake_student_view(problem_id: str, student: str) -> dict[str, Any]:
    """Shaped like the API's student view; the statement carries math and markup to escape."""
    if problem_id not in PROBLEMS:
        raise LookupError(problem_id)
    document = PROBLEMS[problem_id]
    return {
        "id": problem_id,
        "title": f"{document['title']} <i>for</i> {student}",
        "statement": "A block of mass $m$ on a wedge of angle $\\theta$ <script>alert(1)</script>.\n\nUse $g$.",
        "parts": [
            {"id": part["id"], "kind": "symbolic", "prompt": f"Find ${part['id']}$.", "units": None,
             "symbols": ["m", "M", "theta", "g"]}
            for part in document["parts"]
        ],
    }  # fmt: skip


def fake_authenticate_key(key: str) -> Principal | None:
    return Principal("7", Role.STUDENT, "Student", "key-student") if key == STUDENT_KEY else None


@pytest.fixture
def context(stores: Stores, settings: Settings, lms: FakeLms) -> LtiContext:
    return LtiContext(
        stores=stores,
        settings=settings,
        transport=httpx.ASGITransport(app=lms.app),
        student_view=fake_student_view,
        authenticate_key=fake_authenticate_key,
    )


@pytest.fixture
def tool_app(context: LtiContext) -> FastAPI:
    app = FastAPI()
    app.include_router(router)
    app.state.lti = context
    return app


@pytest.fixture
async def browser(tool_app: FastAPI, lms: FakeLms) -> AsyncIterator[httpx.AsyncClient]:
    """A browser that reaches both sites (and keeps their cookies); the LMS already trusts our keys."""
    mounts = {
        "all://tool.test": httpx.ASGITransport(app=tool_app),
        "all://lms.test": httpx.ASGITransport(app=lms.app),
    }
    async with httpx.AsyncClient(mounts=mounts) as client:
        lms.trust_tool_keys((await client.get(f"{TOOL}/lti/jwks")).json())
        yield client


@dataclass
class Login:
    auth_url: str
    state: str
    nonce: str


async def start_login(browser: httpx.AsyncClient, **overrides: str) -> Login:
    params = {
        "iss": ISSUER,
        "login_hint": "student-1",
        "target_link_uri": f"{TOOL}/lti/launch",
        "client_id": CLIENT_ID,
        "lti_deployment_id": DEPLOYMENT_ID,
        "lti_message_hint": "link-1",
        **overrides,
    }
    response = await browser.get(f"{TOOL}/lti/login", params=params)
    assert response.status_code == 302, response.text
    location = response.headers["location"]
    query = {k: v[0] for k, v in parse_qs(urlsplit(location).query).items()}
    return Login(location, query["state"], query["nonce"])


async def platform_launch(browser: httpx.AsyncClient) -> httpx.Response:
    """The whole flow with the real platform: login, authorization, form post to the tool."""
    login = await start_login(browser)
    answer = (await browser.get(login.auth_url)).json()
    return await browser.post(
        answer["launch_url"], data={"id_token": answer["id_token"], "state": answer["state"]}
    )


def unverified_claims(token: str) -> dict[str, Any]:
    payload = token.split(".")[1]
    return json.loads(base64.urlsafe_b64decode(payload + "=" * (-len(payload) % 4)))
