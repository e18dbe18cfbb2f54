"""API keys: shown once, found by the key itself, refused once revoked (every store)."""

from __future__ import annotations

import pytest

from app.db.errors import KeyNotFound
from app.db.keys import KEY_PREFIX
from app.db.records import Role
from app.storage import Stores


def test_new_key_has_the_prefix_and_at_least_128_random_bits(stores: Stores) -> None:
    created = stores.keys.create(Role.INSTRUCTOR, name="Ada")
    assert created.plaintext.startswith(KEY_PREFIX)
    assert (len(created.plaintext) - len(KEY_PREFIX)) * 6 >= 128  # token_urlsafe: 6 bits a character
    assert created.plaintext not in repr(created)


def test_the_right_key_authenticates_as_its_record(stores: Stores) -> None:
    created = stores.keys.create(Role.STUDENT, name="Cy", student="cy@example.edu")
    assert stores.keys.authenticate(created.plaintext) == created.record
    assert stores.keys.get(created.record.id) == created.record
    assert created.record.student == "cy@example.edu"


@pytest.mark.parametrize(
    "mangle",
    [
        lambda key: key[:-1] + ("A" if key[-1] != "A" else "B"),
        lambda key: key[:-4],
        lambda key: key + "x",
        lambda key: "xyz_" + key[4:],
        lambda key: "",
        lambda key: key + "a" * 500,
    ],
    ids=["last-char-changed", "truncated", "extended", "wrong-prefix", "empty", "very-long"],
)
def test_a_wrong_key_is_refused(stores: Stores, mangle) -> None:
    created = stores.keys.create(Role.INSTRUCTOR)
    assert stores.keys.authenticate(mangle(created.plaintext)) is None


def test_a_revoked_key_is_refused_and_revoking_again_keeps_the_first_time(stores: Stores) -> None:
    created = stores.keys.create(Role.INSTRUCTOR)
    other = stores.keys.create(Role.INSTRUCTOR)
    revoked = stores.keys.revoke(created.record.id)
    assert revoked.revoked
    assert stores.keys.authenticate(created.plaintext) is None
    assert stores.keys.authenticate(other.plaintext) == other.record
    assert stores.keys.revoke(created.record.id).revoked_at == revoked.revoked_at


@pytest.mark.parametrize("operation", ["revoke", "get"])
def test_an_unknown_key_id_is_not_found(stores: Stores, operation: str) -> None:
    with pytest.raises(KeyNotFound) as raised:
        getattr(stores.keys, operation)(12345)
    assert raised.value.key_id == 12345


def test_a_student_key_gets_its_own_identity_when_none_is_given(stores: Stores) -> None:
    first = stores.keys.create(Role.STUDENT).record
    second = stores.keys.create(Role.STUDENT).record
    assert first.student and second.student and first.student != second.student


def test_an_instructor_key_cannot_name_a_student(stores: Stores) -> None:
    with pytest.raises(ValueError, match="only student keys"):
        stores.keys.create(Role.INSTRUCTOR, student="s1")


def test_list_shows_every_key_oldest_first_and_can_hide_revoked_ones(stores: Stores) -> None:
    names = ["a", "b", "c"]
    ids = [stores.keys.create(Role.INSTRUCTOR, name=name).record.id for name in names]
    stores.keys.revoke(ids[1])
    assert [key.name for key in stores.keys.list()] == names
    assert [key.name for key in stores.keys.list(include_revoked=False)] == ["a", "c"]
