"""Every forged, stale, misaddressed or replayed launch is refused with a plain page and no session."""

from __future__ import annotations

import base64
from collections.abc import Callable
from typing import Any

import httpx
import pytest

from tests.lti.conftest import Fakes, start_login
from tests.lti.fake_lms import (
    CLIENT_ID,
    TOOL,
    FakeLms,
    other_private_key_pem,
    public_pem,
)
from tests.lti.forge import DROP, LTI, FromNow, hs256, launch_claims, rs256, unsigned

pytestmark = pytest.mark.anyio

Forger = Callable[[FakeLms, str], str]


def signed(**overrides: Any) -> Forger:
    return lambda lms, nonce: rs256(launch_claims(nonce, **overrides), lms.private_pem, lms.kid)


REFUSED: list[Any] = [
    pytest.param(
        lambda lms, nonce: rs256(launch_claims(nonce), other_private_key_pem(), lms.kid),
        401,
        "bad_signature",
        id="signed-by-another-key",
    ),
    pytest.param(
        lambda lms, nonce: unsigned(launch_claims(nonce), lms.kid),
        401,
        "algorithm_not_allowed",
        id="alg-none",
    ),
    pytest.param(
        lambda lms, nonce: hs256(launch_claims(nonce), public_pem(lms.private_pem).encode(), lms.kid),
        401,
        "algorithm_not_allowed",
        id="hs256-keyed-with-public-key",
    ),
    pytest.param(
        lambda lms, nonce: rs256(launch_claims(nonce), lms.private_pem, None), 401, "missing_kid", id="no-kid"
    ),
    pytest.param(
        lambda lms, nonce: rs256(launch_claims(nonce), lms.private_pem, "not-published"),
        401,
        "unknown_kid",
        id="unknown-kid",
    ),
    pytest.param(signed(iss="https://evil.test"), 401, "wrong_issuer", id="wrong-issuer"),
    pytest.param(signed(aud="someone-else"), 401, "wrong_audience", id="wrong-audience"),
    pytest.param(signed(aud=[CLIENT_ID, "other"]), 401, "missing_azp", id="several-audiences-without-azp"),
    pytest.param(
        signed(aud=[CLIENT_ID, "other"], azp="other"), 401, "wrong_azp", id="azp-names-another-client"
    ),
    pytest.param(
        signed(**{LTI + "deployment_id": "unknown"}), 403, "unknown_deployment", id="unknown-deployment"
    ),
    pytest.param(signed(exp=FromNow(-61 - 5)), 401, "expired", id="expired-beyond-leeway"),
    pytest.param(signed(iat=FromNow(120)), 401, "issued_in_future", id="future-iat-beyond-leeway"),
    pytest.param(signed(iat=DROP), 401, "missing_iat", id="no-iat"),
    pytest.param(signed(nonce="another-nonce"), 401, "nonce_mismatch", id="wrong-nonce"),
    pytest.param(signed(**{LTI + "version": "1.1"}), 401, "unsupported_version", id="wrong-version"),
    pytest.param(signed(**{LTI + "message_type": "Other"}), 401, "unsupported_message_type", id="wrong-type"),
    pytest.param(signed(sub=DROP), 401, "missing_sub", id="anonymous"),
    pytest.param(signed(**{LTI + "roles": DROP}), 401, "missing_roles", id="no-roles"),
]


def assert_refusal_page(response: httpx.Response, status: int, code: str) -> None:
    assert response.status_code == status, response.text
    assert response.headers["content-type"].startswith("text/html")
    assert "This launch was refused" in response.text
    assert f"<code>{code}</code>" in response.text
    assert "Traceback" not in response.text
    assert "physcheck_session" not in response.headers.get("set-cookie", "")


@pytest.mark.parametrize(("forge", "status", "code"), REFUSED)
async def test_forged_or_invalid_launch_is_refused(
    browser: httpx.AsyncClient,
    lms: FakeLms,
    fakes: Fakes,
    forge: Forger,
    status: int,
    code: str,
):
    login = await start_login(browser)
    response = await browser.post(
        f"{TOOL}/lti/launch", data={"id_token": forge(lms, login.nonce), "state": login.state}
    )
    assert_refusal_page(response, status, code)
    assert fakes.sessions.records() == []


ACCEPTED: list[Any] = [
    pytest.param(signed(exp=FromNow(-30)), id="expired-within-leeway"),
    pytest.param(signed(iat=FromNow(30)), id="future-iat-within-leeway"),
    pytest.param(signed(aud=[CLIENT_ID, "other"], azp=CLIENT_ID), id="several-audiences-with-our-azp"),
    pytest.param(signed(aud=[CLIENT_ID]), id="audience-as-list"),
    # Real platforms send large tokens (Canvas: many claims, several KB).
    pytest.param(signed(**{"https://example.test/ext": "x" * 12_000}), id="large-token"),
]


@pytest.mark.parametrize("forge", ACCEPTED)
async def test_launch_within_rules_is_accepted(browser: httpx.AsyncClient, lms: FakeLms, forge: Forger):
    login = await start_login(browser)
    response = await browser.post(
        f"{TOOL}/lti/launch", data={"id_token": forge(lms, login.nonce), "state": login.state}
    )
    assert response.status_code == 303, response.text


async def test_replayed_launch_is_refused(browser: httpx.AsyncClient, lms: FakeLms):
    login = await start_login(browser)
    form = {"id_token": signed()(lms, login.nonce), "state": login.state}
    assert (await browser.post(f"{TOOL}/lti/launch", data=form)).status_code == 303
    assert_refusal_page(await browser.post(f"{TOOL}/lti/launch", data=form), 400, "unknown_state")


async def test_replayed_id_token_with_fresh_state_is_refused(browser: httpx.AsyncClient, lms: FakeLms):
    first = await start_login(browser)
    token = signed()(lms, first.nonce)
    assert (
        await browser.post(f"{TOOL}/lti/launch", data={"id_token": token, "state": first.state})
    ).status_code == 303
    second = await start_login(browser)
    response = await browser.post(f"{TOOL}/lti/launch", data={"id_token": token, "state": second.state})
    assert_refusal_page(response, 401, "nonce_mismatch")


async def test_state_from_another_browser_is_refused_and_spent(
    browser: httpx.AsyncClient, lms: FakeLms, tool_app: Any
):
    login = await start_login(browser)
    form = {"id_token": signed()(lms, login.nonce), "state": login.state}
    async with httpx.AsyncClient(transport=httpx.ASGITransport(app=tool_app)) as attacker:
        assert_refusal_page(await attacker.post(f"{TOOL}/lti/launch", data=form), 400, "state_mismatch")
    # Deleted on use: not even the right browser can use it now.
    assert_refusal_page(await browser.post(f"{TOOL}/lti/launch", data=form), 400, "unknown_state")


async def test_unknown_state_is_refused(browser: httpx.AsyncClient, lms: FakeLms):
    login = await start_login(browser)
    form = {"id_token": signed()(lms, login.nonce), "state": "made-up"}
    assert_refusal_page(await browser.post(f"{TOOL}/lti/launch", data=form), 400, "unknown_state")


async def test_launch_without_id_token_is_refused(browser: httpx.AsyncClient):
    assert_refusal_page(
        await browser.post(f"{TOOL}/lti/launch", data={"state": "x"}), 400, "missing_id_token"
    )


LOGIN_REFUSED: list[Any] = [
    pytest.param({"iss": "https://unknown.test"}, 400, "unknown_platform", id="unknown-issuer"),
    pytest.param({"client_id": "other"}, 400, "unknown_platform", id="unknown-client-id"),
    pytest.param({"lti_deployment_id": "other"}, 403, "unknown_deployment", id="unknown-deployment"),
    pytest.param({"target_link_uri": "https://evil.test/x"}, 400, "foreign_target", id="foreign-target"),
    pytest.param({"login_hint": ""}, 400, "missing_login_hint", id="no-login-hint"),
]


@pytest.mark.parametrize(("overrides", "status", "code"), LOGIN_REFUSED)
async def test_bad_login_initiation_is_refused(
    browser: httpx.AsyncClient, overrides: dict[str, str], status: int, code: str
):
    params = {
        "iss": "https://lms.test",
        "login_hint": "student-1",
        "target_link_uri": f"{TOOL}/lti/launch",
        "client_id": CLIENT_ID,
        "lti_deployment_id": "deployment-1",
        **overrides,
    }
    assert_refusal_page(await browser.post(f"{TOOL}/lti/login", data=params), status, code)


async def test_platform_key_rotation_is_picked_up_by_one_refetch(browser: httpx.AsyncClient, lms: FakeLms):
    first = await start_login(browser)
    token = signed()(lms, first.nonce)
    assert (
        await browser.post(f"{TOOL}/lti/launch", data={"id_token": token, "state": first.state})
    ).status_code == 303
    lms.private_pem = other_private_key_pem()
    lms.registration.set_platform_private_key(lms.private_pem).set_platform_public_key(
        public_pem(lms.private_pem)
    )
    second = await start_login(browser)
    token = signed()(lms, second.nonce)
    assert (
        await browser.post(f"{TOOL}/lti/launch", data={"id_token": token, "state": second.state})
    ).status_code == 303


async def test_unreachable_platform_keys_give_a_clear_page_not_a_stack_trace(
    browser: httpx.AsyncClient, lms: FakeLms, fakes: Fakes
):
    lms.jwks_down = True
    login = await start_login(browser)
    response = await browser.post(
        f"{TOOL}/lti/launch", data={"id_token": signed()(lms, login.nonce), "state": login.state}
    )
    assert response.status_code == 502
    assert "could not be reached" in response.text and "Traceback" not in response.text
    assert fakes.sessions.records() == []


@pytest.mark.parametrize(
    "header",
    [b"[" * 40000, b'{"alg": "RS256", "kid": "' + b"k" * 3000 + b'"}'],
    ids=["deeply-nested", "oversized"],
)
def test_a_monstrous_token_header_is_refused_not_a_crash(header: bytes):
    from app.lti.errors import UntrustedToken
    from app.lti.id_token import read_header

    encoded = base64.urlsafe_b64encode(header).decode().rstrip("=")
    with pytest.raises(UntrustedToken):
        read_header(f"{encoded}.e30.sig")
