"""Problems: versions kept forever, built-ins saved idempotently, retired problems hidden."""

from __future__ import annotations

import threading

import pytest

from app.db.database import Database
from app.db.errors import ProblemExists, ProblemNotFound, ProblemVersionNotFound
from app.db.keys import create_key
from app.db.problems import (
    add_version,
    create_problem,
    document_hash,
    get_problem,
    list_problems,
    retire_problem,
    save_builtin,
)
from app.db.records import Role

V1 = {"id": "yo-yo", "title": "Yo-yo", "parts": [{"id": "acceleration"}]}
V2 = {"id": "yo-yo", "title": "Yo-yo (revised)", "parts": [{"id": "acceleration"}, {"id": "tension"}]}


def _instructor(db: Database) -> int:
    with db.session() as session:
        return create_key(session, Role.INSTRUCTOR).record.id


def test_document_hash_ignores_key_order() -> None:
    assert document_hash({"a": 1, "b": [1, 2]}) == document_hash({"b": [1, 2], "a": 1})
    assert document_hash({"a": 1}) != document_hash({"a": 2})


def test_saving_an_unchanged_builtin_keeps_its_version(db: Database) -> None:
    with db.session() as session:
        first = save_builtin(session, "yo-yo", V1)
    with db.session() as session:
        again = save_builtin(session, "yo-yo", dict(reversed(V1.items())))
    assert (first.version, again.version, again.latest_version) == (1, 1, 1)
    assert again.builtin


def test_saving_a_changed_builtin_adds_a_version_and_keeps_the_old_one(db: Database) -> None:
    with db.session() as session:
        save_builtin(session, "yo-yo", V1)
    with db.session() as session:
        second = save_builtin(session, "yo-yo", V2)
    assert second.version == 2
    with db.session(read_only=True) as session:
        assert get_problem(session, "yo-yo").document == V2
        assert get_problem(session, "yo-yo", 1).document == V1
        assert get_problem(session, "yo-yo", 1).latest_version == 2


def test_put_makes_a_new_version_and_resending_it_changes_nothing(db: Database) -> None:
    owner = _instructor(db)
    with db.session() as session:
        created = create_problem(session, "mine", V1, owner_key_id=owner)
    with db.session() as session:
        updated = add_version(session, "mine", V2)
    with db.session() as session:
        resent = add_version(session, "mine", V2)
    assert (created.version, updated.version, resent.version) == (1, 2, 2)
    assert updated.owner_key_id == owner and not updated.builtin


def test_creating_an_existing_id_is_refused(db: Database) -> None:
    owner = _instructor(db)
    with db.session() as session:
        save_builtin(session, "yo-yo", V1)
    with pytest.raises(ProblemExists) as raised, db.session() as session:
        create_problem(session, "yo-yo", V2, owner_key_id=owner)
    assert raised.value.problem_id == "yo-yo"


def test_a_failed_create_leaves_the_transaction_usable(db: Database) -> None:
    owner = _instructor(db)
    with db.session() as session:
        save_builtin(session, "yo-yo", V1)
    with db.session() as session:
        with pytest.raises(ProblemExists):
            create_problem(session, "yo-yo", V2, owner_key_id=owner)
        create_problem(session, "other", V2, owner_key_id=owner)
    with db.session(read_only=True) as session:
        assert [problem.id for problem in list_problems(session)] == ["other", "yo-yo"]


def test_a_builtin_cannot_take_over_an_instructors_problem(db: Database) -> None:
    owner = _instructor(db)
    with db.session() as session:
        create_problem(session, "yo-yo", V1, owner_key_id=owner)
    with pytest.raises(ProblemExists), db.session() as session:
        save_builtin(session, "yo-yo", V2)


def test_a_retired_problem_is_hidden_but_its_versions_are_kept(db: Database) -> None:
    with db.session() as session:
        save_builtin(session, "yo-yo", V1)
        save_builtin(session, "moving-wedge", V2)
    with db.session() as session:
        retired = retire_problem(session, "yo-yo")
    assert retired.retired
    with db.session(read_only=True) as session:
        assert [problem.id for problem in list_problems(session)] == ["moving-wedge"]
        assert {p.id for p in list_problems(session, include_retired=True)} == {"moving-wedge", "yo-yo"}
        with pytest.raises(ProblemNotFound):
            get_problem(session, "yo-yo")
        assert get_problem(session, "yo-yo", 1, include_retired=True).document == V1


@pytest.mark.parametrize(
    "operation",
    [
        lambda session: add_version(session, "yo-yo", V2),
        lambda session: retire_problem(session, "yo-yo"),
        lambda session: create_problem(session, "yo-yo", V2, owner_key_id=1),
    ],
    ids=["new-version", "retire-again", "reuse-the-id"],
)
def test_a_retired_problem_takes_no_changes(db: Database, operation) -> None:
    _instructor(db)
    with db.session() as session:
        save_builtin(session, "yo-yo", V1)
        retire_problem(session, "yo-yo")
    with pytest.raises((ProblemNotFound, ProblemExists)), db.session() as session:
        operation(session)


def test_saving_a_retired_builtin_leaves_it_retired(db: Database) -> None:
    with db.session() as session:
        save_builtin(session, "yo-yo", V1)
        retire_problem(session, "yo-yo")
    with db.session() as session:
        assert save_builtin(session, "yo-yo", V1).retired


@pytest.mark.parametrize(
    ("problem_id", "version", "error"),
    [("nope", None, ProblemNotFound), ("yo-yo", 7, ProblemVersionNotFound)],
    ids=["unknown-problem", "unknown-version"],
)
def test_getting_what_does_not_exist_is_not_found(db: Database, problem_id, version, error) -> None:
    with db.session() as session:
        save_builtin(session, "yo-yo", V1)
    with pytest.raises(error), db.session(read_only=True) as session:
        get_problem(session, problem_id, version)


def test_list_can_be_limited_to_one_owner(db: Database) -> None:
    owner = _instructor(db)
    with db.session() as session:
        save_builtin(session, "yo-yo", V1)
        create_problem(session, "mine", V2, owner_key_id=owner)
    with db.session(read_only=True) as session:
        assert [problem.id for problem in list_problems(session, owner_key_id=owner)] == ["mine"]


def _in_parallel(count: int, work) -> list[object]:
    """Run work(i) in `count` threads started together; return results or the exceptions raised."""
    barrier = threading.Barrier(count)
    results: list[object] = [None] * count

    def run(index: int) -> None:
        barrier.wait()
        try:
            results[index] = work(index)
        except Exception as error:
            results[index] = error

    threads = [threading.Thread(target=run, args=(index,)) for index in range(count)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return results


def test_processes_saving_the_same_builtin_at_once_agree_on_one_version(db: Database) -> None:
    def save(_: int) -> int:
        with db.session() as session:
            return save_builtin(session, "yo-yo", V1).version

    assert _in_parallel(4, save) == [1, 1, 1, 1]


def test_parallel_new_versions_each_get_their_own_number(db: Database) -> None:
    owner = _instructor(db)
    with db.session() as session:
        create_problem(session, "mine", V1, owner_key_id=owner)

    def put(index: int) -> int:
        with db.session() as session:
            return add_version(session, "mine", {**V2, "revision": index}).version

    assert sorted(_in_parallel(5, put)) == [2, 3, 4, 5, 6]
