"""API keys: shown once, stored only hashed, refused once revoked."""

from __future__ import annotations

import pytest
from sqlalchemy import text

from app.db.database import Database
from app.db.errors import KeyNotFound
from app.db.keys import KEY_PREFIX, authenticate, create_key, get_key, list_keys, revoke_key
from app.db.records import Role


def test_new_key_has_the_prefix_and_at_least_128_random_bits(db: Database) -> None:
    with db.session() as session:
        created = create_key(session, Role.INSTRUCTOR, name="Ada")
    assert created.plaintext.startswith(KEY_PREFIX)
    # token_urlsafe: 6 bits per character.
    assert (len(created.plaintext) - len(KEY_PREFIX)) * 6 >= 128
    assert created.plaintext not in repr(created)


def test_the_plaintext_key_is_stored_nowhere(db: Database) -> None:
    with db.session() as session:
        created = create_key(session, Role.STUDENT, name="Bea")
    secret_part = created.plaintext[len(created.record.prefix) :]
    with db.session(read_only=True) as session:
        rows = session.execute(text("SELECT * FROM api_keys")).all()
    stored = " ".join(str(value) for row in rows for value in row)
    assert created.plaintext not in stored
    assert secret_part not in stored


def test_the_right_key_authenticates_as_its_record(db: Database) -> None:
    with db.session() as session:
        created = create_key(session, Role.STUDENT, name="Cy", student="cy@example.edu")
    with db.session(read_only=True) as session:
        assert authenticate(session, created.plaintext) == created.record
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
def test_a_wrong_key_is_refused(db: Database, mangle) -> None:
    with db.session() as session:
        created = create_key(session, Role.INSTRUCTOR)
    with db.session(read_only=True) as session:
        assert authenticate(session, mangle(created.plaintext)) is None


def test_a_revoked_key_is_refused(db: Database) -> None:
    with db.session() as session:
        created = create_key(session, Role.INSTRUCTOR)
        other = create_key(session, Role.INSTRUCTOR)
    with db.session() as session:
        revoked = revoke_key(session, created.record.id)
    assert revoked.revoked
    with db.session(read_only=True) as session:
        assert authenticate(session, created.plaintext) is None
        assert authenticate(session, other.plaintext) == other.record


def test_revoking_twice_keeps_the_first_revocation_time(db: Database) -> None:
    with db.session() as session:
        key_id = create_key(session, Role.INSTRUCTOR).record.id
    with db.session() as session:
        first = revoke_key(session, key_id)
    with db.session() as session:
        second = revoke_key(session, key_id)
    assert second.revoked_at == first.revoked_at


@pytest.mark.parametrize("operation", [revoke_key, get_key], ids=["revoke", "get"])
def test_an_unknown_key_id_is_not_found(db: Database, operation) -> None:
    with pytest.raises(KeyNotFound) as raised, db.session() as session:
        operation(session, 12345)
    assert raised.value.key_id == 12345


def test_a_student_key_gets_its_own_identity_when_none_is_given(db: Database) -> None:
    with db.session() as session:
        first = create_key(session, Role.STUDENT).record
        second = create_key(session, Role.STUDENT).record
    assert first.student and second.student and first.student != second.student


def test_an_instructor_key_cannot_name_a_student(db: Database) -> None:
    with pytest.raises(ValueError, match="only student keys"), db.session() as session:
        create_key(session, Role.INSTRUCTOR, student="s1")


def test_list_shows_every_key_oldest_first_and_can_hide_revoked_ones(db: Database) -> None:
    with db.session() as session:
        names = ["a", "b", "c"]
        ids = [create_key(session, Role.INSTRUCTOR, name=name).record.id for name in names]
        revoke_key(session, ids[1])
    with db.session(read_only=True) as session:
        assert [key.name for key in list_keys(session)] == names
        assert [key.name for key in list_keys(session, include_revoked=False)] == ["a", "c"]
