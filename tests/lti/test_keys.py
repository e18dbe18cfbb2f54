"""Our signing keys: published with kid, rotation keeps the previous key until the next rotation."""

from __future__ import annotations

import httpx
import pytest
from joserfc import jwt
from joserfc.jwk import KeySet

from app.db.database import Database
from app.storage import sql_tool_keys as keys
from tests.lti.fake_lms import TOOL

pytestmark = pytest.mark.anyio


def published(database: Database) -> list[str]:
    with database.session() as session:
        return [key["kid"] for key in keys.public_jwks(session)["keys"]]


def sign(database: Database) -> str:
    with database.session() as session:
        return keys.sign(session, {"hello": "world"})


@pytest.mark.parametrize("path", ["/lti/jwks", "/.well-known/jwks.json"], ids=["lti", "well-known"])
async def test_jwks_endpoint_publishes_public_rsa_keys_with_kid(browser: httpx.AsyncClient, path: str):
    document = (await browser.get(TOOL + path)).json()
    [key] = document["keys"]
    assert (key["kty"], key["alg"], key["use"]) == ("RSA", "RS256", "sig")
    assert key["kid"]
    assert "d" not in key and "p" not in key


def test_signature_verifies_with_published_key_and_names_its_kid(database: Database):
    token = sign(database)
    with database.session() as session:
        key_set = KeySet.import_key_set(keys.public_jwks(session))  # type: ignore[arg-type]
    verified = jwt.decode(token, key_set, algorithms=["RS256"])
    assert verified.header["kid"] == published(database)[0]


def test_rotation_signs_with_new_key_and_keeps_previous_published(database: Database):
    sign(database)  # creates the first key
    [old] = published(database)
    new = keys.rotate_keys(database)
    assert published(database) == [new, old]
    assert jwt.decode(sign(database), _key_set(database), algorithms=["RS256"]).header["kid"] == new


def test_second_rotation_retires_the_oldest_key(database: Database):
    sign(database)
    [oldest] = published(database)
    middle = keys.rotate_keys(database)
    newest = keys.rotate_keys(database)
    assert published(database) == [newest, middle]
    assert oldest not in published(database)


def _key_set(database: Database) -> KeySet:
    with database.session() as session:
        return KeySet.import_key_set(keys.public_jwks(session))  # type: ignore[arg-type]
