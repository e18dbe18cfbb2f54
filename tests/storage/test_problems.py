"""Problems: versions kept forever, built-ins saved idempotently, retired problems hidden (every store)."""

from __future__ import annotations

import pytest

from app.db.errors import ProblemExists, ProblemNotFound, ProblemVersionNotFound
from app.db.records import Role
from app.storage import CompiledEntry, Stores
from tests.storage.helpers import in_parallel

V1 = {"id": "yo-yo", "title": "Yo-yo", "parts": [{"id": "acceleration"}]}
V2 = {"id": "yo-yo", "title": "Yo-yo (revised)", "parts": [{"id": "acceleration"}, {"id": "tension"}]}


def _instructor(stores: Stores) -> int:
    return stores.keys.create(Role.INSTRUCTOR).record.id


def test_saving_an_unchanged_builtin_keeps_its_version(stores: Stores) -> None:
    first = stores.problems.save_builtin("yo-yo", V1)
    again = stores.problems.save_builtin("yo-yo", dict(reversed(V1.items())))
    assert (first.version, again.version, again.latest_version) == (1, 1, 1)
    assert again.builtin and again.document_hash == first.document_hash


def test_saving_a_changed_builtin_adds_a_version_and_keeps_the_old_one(stores: Stores) -> None:
    stores.problems.save_builtin("yo-yo", V1)
    assert stores.problems.save_builtin("yo-yo", V2).version == 2
    assert stores.problems.get("yo-yo").document == V2
    assert stores.problems.get("yo-yo", 1).document == V1
    assert stores.problems.get("yo-yo", 1).latest_version == 2


def test_a_stored_document_is_a_copy_of_what_was_given(stores: Stores) -> None:
    document = {**V1, "parts": [{"id": "acceleration"}]}
    stores.problems.save_builtin("yo-yo", document)
    document["parts"].append({"id": "later"})
    assert stores.problems.get("yo-yo").document == V1


def test_put_makes_a_new_version_and_resending_it_changes_nothing(stores: Stores) -> None:
    owner = _instructor(stores)
    created = stores.problems.create("mine", V1, owner_key_id=owner)
    updated = stores.problems.add_version("mine", V2)
    resent = stores.problems.add_version("mine", V2)
    assert (created.version, updated.version, resent.version) == (1, 2, 2)
    assert updated.owner_key_id == owner and not updated.builtin


def test_creating_an_existing_id_is_refused(stores: Stores) -> None:
    owner = _instructor(stores)
    stores.problems.save_builtin("yo-yo", V1)
    with pytest.raises(ProblemExists) as raised:
        stores.problems.create("yo-yo", V2, owner_key_id=owner)
    assert raised.value.problem_id == "yo-yo"
    assert stores.problems.get("yo-yo").document == V1


def test_a_builtin_cannot_take_over_an_instructors_problem(stores: Stores) -> None:
    stores.problems.create("yo-yo", V1, owner_key_id=_instructor(stores))
    with pytest.raises(ProblemExists):
        stores.problems.save_builtin("yo-yo", V2)


def test_a_retired_problem_is_hidden_but_its_versions_are_kept(stores: Stores) -> None:
    stores.problems.save_builtin("yo-yo", V1)
    stores.problems.save_builtin("moving-wedge", V2)
    assert stores.problems.retire("yo-yo").retired
    assert [problem.id for problem in stores.problems.list()] == ["moving-wedge"]
    assert [p.id for p in stores.problems.list(include_retired=True)] == ["moving-wedge", "yo-yo"]
    with pytest.raises(ProblemNotFound):
        stores.problems.get("yo-yo")
    assert stores.problems.get("yo-yo", 1, include_retired=True).document == V1


@pytest.mark.parametrize(
    ("operation", "error"),
    [
        (lambda stores: stores.problems.add_version("yo-yo", V2), ProblemNotFound),
        (lambda stores: stores.problems.retire("yo-yo"), ProblemNotFound),
        (lambda stores: stores.problems.create("yo-yo", V2, owner_key_id=1), ProblemExists),
    ],
    ids=["new-version", "retire-again", "reuse-the-id"],
)
def test_a_retired_problem_takes_no_changes(stores: Stores, operation, error) -> None:
    _instructor(stores)
    stores.problems.save_builtin("yo-yo", V1)
    stores.problems.retire("yo-yo")
    with pytest.raises(error):
        operation(stores)
    assert stores.problems.save_builtin("yo-yo", V1).retired  # saving the bank leaves it retired


@pytest.mark.parametrize(
    ("problem_id", "version", "error"),
    [
        ("nope", None, ProblemNotFound),
        ("yo-yo", 7, ProblemVersionNotFound),
        ("yo-yo", 0, ProblemVersionNotFound),
    ],
    ids=["unknown-problem", "unknown-version", "version-zero"],
)
def test_getting_what_does_not_exist_is_not_found(stores: Stores, problem_id, version, error) -> None:
    stores.problems.save_builtin("yo-yo", V1)
    with pytest.raises(error):
        stores.problems.get(problem_id, version)


def test_list_is_by_id_and_can_be_limited_to_one_owner(stores: Stores) -> None:
    owner = _instructor(stores)
    stores.problems.save_builtin("yo-yo", V1)
    stores.problems.create("mine", V2, owner_key_id=owner)
    assert [problem.id for problem in stores.problems.list()] == ["mine", "yo-yo"]
    assert [problem.id for problem in stores.problems.list(owner_key_id=owner)] == ["mine"]


def test_saving_the_same_builtin_at_once_agrees_on_one_version(stores: Stores) -> None:
    assert in_parallel(4, lambda _: stores.problems.save_builtin("yo-yo", V1).version) == [1, 1, 1, 1]


def test_parallel_new_versions_each_get_their_own_number(stores: Stores) -> None:
    stores.problems.create("mine", V1, owner_key_id=_instructor(stores))
    numbers = in_parallel(5, lambda i: stores.problems.add_version("mine", {**V2, "revision": i}).version)
    assert sorted(numbers) == [2, 3, 4, 5, 6]


def test_a_version_is_stored_with_its_compilation_and_a_refused_one_stores_neither(stores: Stores) -> None:
    owner = _instructor(stores)
    first = CompiledEntry("k1" * 32, b"compiled v1", "m1" * 32)
    stores.problems.create("mine", V1, owner_key_id=owner, compiled=first)
    assert stores.compiled.get(first.key) == (b"compiled v1", "m1" * 32)
    second = CompiledEntry("k2" * 32, b"compiled v2", "m2" * 32)
    assert stores.problems.add_version("mine", V2, compiled=second).version == 2
    assert stores.compiled.get(second.key) == (b"compiled v2", "m2" * 32)

    builtin = CompiledEntry("k4" * 32, b"compiled bank", "m4" * 32)
    stores.problems.save_builtin("yo-yo", V1, compiled=builtin)
    assert stores.compiled.get(builtin.key) == (b"compiled bank", "m4" * 32)

    taken = CompiledEntry("k3" * 32, b"never stored", "m3" * 32)
    with pytest.raises(ProblemExists):
        stores.problems.create("mine", V1, owner_key_id=owner, compiled=taken)
    with pytest.raises(ProblemExists):
        stores.problems.save_builtin("mine", V1, compiled=taken)
    stores.problems.retire("mine")
    with pytest.raises(ProblemNotFound):
        stores.problems.add_version("mine", V1, compiled=taken)
    assert stores.compiled.get(taken.key) is None
