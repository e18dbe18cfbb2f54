"""The launch stores' contract: platforms and their deployments, logins taken once, nonces spent once,
deep-link requests and our sessions; on SQLite, PostgreSQL and the fake."""

from __future__ import annotations

from datetime import timedelta

import pytest

from app.auth import Role
from app.db.types import utc_now
from app.lti.errors import PlatformNotFound
from app.lti.platforms import add_platform, platform_origins
from app.lti.sessions import SessionRecord
from app.storage import Stores
from app.storage.protocols import LoginState, PendingDeepLink
from tests.storage.helpers import in_parallel

ISSUER = "https://lms.example"
URLS = (f"{ISSUER}/auth", f"{ISSUER}/token", f"{ISSUER}/jwks")
NOW = utc_now()


# ---- platforms -------------------------------------------------------------------------------------


def test_registering_again_updates_urls_and_adds_deployments(stores: Stores):
    first = add_platform(stores.platforms, ISSUER, "client", ["d1", "d2"], *URLS)
    again = add_platform(
        stores.platforms, ISSUER, "client", ["d2", "d3"], "https://login.example/a", *URLS[1:]
    )
    assert again.id == first.id
    assert again.auth_url == "https://login.example/a"
    assert stores.platforms.get(first.id) == again
    assert stores.platforms.deployments(first.id) == ["d1", "d2", "d3"]
    assert stores.platforms.is_deployed(first.id, "d3")
    assert not stores.platforms.is_deployed(first.id, "d4")


def test_an_issuer_is_found_without_client_id_only_when_registered_once(stores: Stores):
    one = add_platform(stores.platforms, ISSUER, "a", ["d"], *URLS)
    assert stores.platforms.find(ISSUER, None) == one
    two = add_platform(stores.platforms, ISSUER, "b", ["d"], *URLS)
    assert stores.platforms.find(ISSUER, "b") == two
    with pytest.raises(PlatformNotFound):
        stores.platforms.find(ISSUER, None)
    with pytest.raises(PlatformNotFound):
        stores.platforms.find(ISSUER, "c")
    with pytest.raises(PlatformNotFound):
        stores.platforms.get(two.id + 1)
    assert [p.client_id for p in stores.platforms.list()] == ["a", "b"]


def test_frame_origins_are_each_platforms_issuer_and_login_page(stores: Stores):
    add_platform(stores.platforms, ISSUER, "a", ["d"], "https://login.example/auth?x=1", *URLS[1:])
    add_platform(stores.platforms, ISSUER, "b", ["d"], *URLS)
    assert platform_origins(stores.platforms) == [ISSUER, "https://login.example"]


@pytest.mark.parametrize("url", ["/relative", "ftp://lms.example/auth", "https://"])
def test_registration_needs_absolute_http_urls(stores: Stores, url: str):
    with pytest.raises(ValueError, match="auth_url"):
        add_platform(stores.platforms, ISSUER, "a", ["d"], url, *URLS[1:])
    assert stores.platforms.list() == []


# ---- launch state ----------------------------------------------------------------------------------


@pytest.fixture
def platform_id(stores: Stores) -> int:
    return add_platform(stores.platforms, ISSUER, "client", ["d"], *URLS).id


def test_a_login_is_taken_once_even_by_concurrent_launches(stores: Stores, platform_id: int):
    login = LoginState("nonce", "browser", platform_id, NOW + timedelta(minutes=10))
    stores.launches.save_login("state", login, NOW)
    taken = in_parallel(4, lambda _: stores.launches.take_login("state"))
    assert [t for t in taken if t is not None] == [login]
    assert stores.launches.take_login("unknown") is None


def test_saving_a_login_drops_expired_ones(stores: Stores, platform_id: int):
    stores.launches.save_login("old", LoginState("n1", "b", platform_id, NOW - timedelta(seconds=1)), NOW)
    stores.launches.save_login("new", LoginState("n2", "b", platform_id, NOW + timedelta(minutes=1)), NOW)
    assert stores.launches.take_login("old") is None
    assert stores.launches.take_login("new") is not None


def test_a_nonce_is_spent_once_per_platform(stores: Stores, platform_id: int):
    other = add_platform(stores.platforms, "https://other.example", "client", ["d"], *URLS).id
    later = NOW + timedelta(hours=2)
    spent = in_parallel(4, lambda _: stores.launches.spend_nonce(platform_id, "n", later, NOW))
    assert sorted(spent) == [False, False, False, True]
    assert stores.launches.spend_nonce(other, "n", later, NOW)
    # remembered until it expires, then forgotten
    assert not stores.launches.spend_nonce(platform_id, "n", later, later)
    assert stores.launches.spend_nonce(platform_id, "n", later, later + timedelta(seconds=1))


def test_a_deep_link_request_is_kept_until_dropped(stores: Stores, platform_id: int):
    request = PendingDeepLink("req", "session", platform_id, "d", "https://lms/return", '{"k": 1}', True, NOW)
    stores.launches.save_deep_link(request, NOW)
    assert stores.launches.get_deep_link("req") == request
    stores.launches.drop_deep_link("req")
    assert stores.launches.get_deep_link("req") is None
    stores.launches.drop_deep_link("req")  # again: nothing to do


# ---- our sessions ----------------------------------------------------------------------------------


def _session(platform_id: int, expires_in: timedelta) -> SessionRecord:
    return SessionRecord(
        platform_id, "sub", f"lti:{platform_id}:sub", Role.INSTRUCTOR, "Lee", "csrf", NOW + expires_in
    )


def test_a_session_is_found_by_its_hash_and_expired_ones_are_dropped(stores: Stores, platform_id: int):
    stale = _session(platform_id, timedelta(seconds=-1))
    live = _session(platform_id, timedelta(hours=8))
    stores.lti_sessions.save("stale", stale, NOW - timedelta(hours=9))
    assert stores.lti_sessions.get("stale") == stale  # as saved: the caller judges expiry
    stores.lti_sessions.save("live", live, NOW)
    assert stores.lti_sessions.get("live") == live
    assert stores.lti_sessions.get("stale") is None
