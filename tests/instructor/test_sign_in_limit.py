"""Instructor sign-in attempts are limited per address and per key prefix (429 with Retry-After, the
form shown again); an address or a prefix over its budget does not lock out the others."""

from __future__ import annotations

from fastapi.testclient import TestClient

from app.db.keys import KEY_PREFIX, LOOKUP_CHARS
from tests.instructor.conftest import sign_in

LIMIT = 10  # the default PHYSCHECK_SIGN_IN_ATTEMPTS_PER_MINUTE


def _from(client: TestClient, address: str) -> TestClient:
    """Another browser, at `address`, on the same running app."""
    return TestClient(client.app, client=(address, 40000), follow_redirects=False)


def _guess(prefix_char: str, n: int) -> str:
    return KEY_PREFIX + prefix_char * LOOKUP_CHARS + f"guess{n:04d}"


def test_one_address_is_refused_after_its_attempts_and_others_are_not(
    client: TestClient, instructor_key: str
):
    for n in range(LIMIT):
        assert sign_in(client, _guess("abcdefghijklmnop"[n], n)).status_code == 401
    refused = sign_in(client, instructor_key)
    assert refused.status_code == 429
    assert int(refused.headers["retry-after"]) > 0
    assert "Too many sign-in attempts" in refused.text
    assert "physcheck_instructor=" not in refused.headers.get("set-cookie", "")
    assert sign_in(_from(client, "203.0.113.9"), instructor_key).status_code == 303


def test_one_key_prefix_is_refused_after_its_attempts_from_many_addresses(
    client: TestClient, instructor_key: str
):
    for n in range(LIMIT):
        assert sign_in(_from(client, f"198.51.100.{n}"), _guess("z", n)).status_code == 401
    assert sign_in(_from(client, "198.51.100.200"), _guess("z", 99)).status_code == 429
    assert sign_in(_from(client, "198.51.100.201"), instructor_key).status_code == 303
