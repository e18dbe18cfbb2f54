"""Our signing keys as platforms fetch them (signing and rotation: tests/storage/test_tool_keys.py)."""

from __future__ import annotations

import httpx
import pytest

from tests.lti.fake_lms import TOOL

pytestmark = pytest.mark.anyio


@pytest.mark.parametrize("path", ["/lti/jwks", "/.well-known/jwks.json"], ids=["lti", "well-known"])
async def test_jwks_endpoint_publishes_public_rsa_keys_with_kid(browser: httpx.AsyncClient, path: str):
    document = (await browser.get(TOOL + path)).json()
    [key] = document["keys"]
    assert (key["kty"], key["alg"], key["use"]) == ("RSA", "RS256", "sig")
    assert key["kid"]
    assert "d" not in key and "p" not in key
