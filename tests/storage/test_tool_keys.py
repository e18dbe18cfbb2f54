"""Our LTI signing keys, on every store: published with their kid, and a rotation keeps the previous
key published until the next one."""

from __future__ import annotations

from joserfc import jwt
from joserfc.jwk import KeySet

from app.storage import Stores


def published(stores: Stores) -> list[str]:
    return [key["kid"] for key in stores.tool_keys.public_jwks()["keys"]]


def key_set(stores: Stores) -> KeySet:
    return KeySet.import_key_set(stores.tool_keys.public_jwks())  # type: ignore[arg-type]


def sign(stores: Stores) -> str:
    return stores.tool_keys.sign({"hello": "world"})


def test_signature_verifies_with_published_key_and_names_its_kid(stores: Stores) -> None:
    token = sign(stores)
    verified = jwt.decode(token, key_set(stores), algorithms=["RS256"])
    assert verified.header["kid"] == published(stores)[0]


def test_rotation_signs_with_new_key_and_keeps_previous_published(stores: Stores) -> None:
    sign(stores)  # creates the first key
    [old] = published(stores)
    new = stores.tool_keys.rotate()
    assert published(stores) == [new, old]
    assert jwt.decode(sign(stores), key_set(stores), algorithms=["RS256"]).header["kid"] == new


def test_second_rotation_retires_the_oldest_key(stores: Stores) -> None:
    sign(stores)
    [oldest] = published(stores)
    middle = stores.tool_keys.rotate()
    newest = stores.tool_keys.rotate()
    assert published(stores) == [newest, middle]
    assert oldest not in published(stores)
