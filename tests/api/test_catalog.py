"""The catalog compiles each problem version once, however many requests arrive first, and keeps it
across restarts: only a changed version (or code that does something else) is compiled again."""

from __future__ import annotations

import logging
import shutil
import threading
from pathlib import Path

import pytest
import yaml
from sqlalchemy import select

from app import catalog as catalog_module
from app.catalog import Catalog
from app.db.models import CompiledProblemRow
from app.derivation import DerivationPool, forget_derived
from app.storage import sql_stores
from physics.checking import check_answer
from physics.verdict import Outcome
from tests.derivations import count_derivations

BANK = Path(__file__).resolve().parents[2] / "problems" / "bank"
SECRET = "secret-for-the-test"


@pytest.fixture
def compilations(monkeypatch) -> list[str]:
    """The ids of the problems the catalog has derived (rather than loaded), in order; none is
    remembered from earlier tests."""
    forget_derived()
    yield count_derivations(monkeypatch)
    forget_derived()


_started: list[Catalog] = []


@pytest.fixture(autouse=True)
def _close_catalogs():
    """Every catalog a test starts is closed after it: its derivation workers killed."""
    yield
    while _started:
        _started.pop().close()


def test_concurrent_first_requests_derive_a_problem_once(db, compilations):
    catalog = Catalog(sql_stores(db), "secret-for-the-test")
    _started.append(catalog)
    catalog.sync_builtin()
    record = catalog.get("atwood")
    results = []
    threads = [threading.Thread(target=lambda: results.append(catalog.compiled(record))) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert compilations == ["atwood"]
    assert len(results) == 4 and len({id(r) for r in results}) == 1


@pytest.fixture
def small_bank(tmp_path: Path) -> Path:
    """Two bank problems with their hand-typed answers only (no model: quick to compile)."""
    for problem_id in ("atwood", "incline-pulley"):
        (tmp_path / problem_id).mkdir()
        shutil.copy(BANK / problem_id / "problem.yaml", tmp_path / problem_id / "problem.yaml")
    return tmp_path


def start(db, bank: Path, secret: str = SECRET) -> Catalog:
    """What an instance does at start: store the bank, then compile or load every problem."""
    catalog = Catalog(sql_stores(db), secret, bank)
    _started.append(catalog)
    catalog.sync_builtin()
    catalog.warm_up()
    return catalog


def grades_its_reference(catalog: Catalog) -> bool:
    question = catalog.compiled(catalog.get("incline-pulley")).question("acceleration")
    return check_answer("(m2 - m1 sin(theta)) g/(m1 + m2)", question).outcome is Outcome.CORRECT


def test_a_restart_loads_the_compiled_bank_instead_of_compiling_it(db, small_bank, compilations):
    start(db, small_bank)
    assert sorted(compilations) == ["atwood", "incline-pulley"]
    restarted = start(db, small_bank)
    assert sorted(compilations) == ["atwood", "incline-pulley"]  # nothing compiled again
    assert grades_its_reference(restarted)


def test_a_restart_is_warm_before_it_opens_any_stored_compilation(db, small_bank, monkeypatch):
    start(db, small_bank)
    restarted = Catalog(sql_stores(db), SECRET, small_bank)
    _started.append(restarted)
    restarted.sync_builtin()
    warm_when_opened: list[bool] = []
    real_open = catalog_module.CompiledStore.open

    def observed_open(record, payload):
        warm_when_opened.append(restarted.warm.is_set())
        return real_open(record, payload)

    monkeypatch.setattr(catalog_module.CompiledStore, "open", staticmethod(observed_open))
    restarted.warm_up()
    assert warm_when_opened == [True, True]  # both opened, and only after the instance said ready
    assert grades_its_reference(restarted)


def test_only_a_changed_version_is_compiled_again(db, small_bank, compilations):
    start(db, small_bank)
    problem = small_bank / "atwood" / "problem.yaml"
    problem.write_text(problem.read_text().replace("title: Atwood machine", "title: The Atwood machine"))
    start(db, small_bank)
    assert compilations[2:] == ["atwood"]


def test_a_tampered_or_foreign_entry_is_ignored_and_compiled_again(db, small_bank, compilations):
    start(db, small_bank)
    with db.session() as session:
        for row in session.scalars(select(CompiledProblemRow)):
            middle = len(row.payload) // 2
            row.payload = row.payload[:middle] + bytes([row.payload[middle] ^ 1]) + row.payload[middle + 1 :]
    tampered = start(db, small_bank)
    assert sorted(compilations[2:]) == ["atwood", "incline-pulley"]
    assert grades_its_reference(tampered)
    start(db, small_bank, secret="another-secret-entirely")  # written under another secret: not ours
    assert sorted(compilations[4:]) == ["atwood", "incline-pulley"]


def test_changed_engine_code_compiles_again(db, small_bank, compilations, monkeypatch):
    start(db, small_bank)
    monkeypatch.setattr(catalog_module, "source_digest", lambda: "the files have changed")
    monkeypatch.setattr(catalog_module, "engine_digest", lambda: "and what they do with them")
    start(db, small_bank)
    assert sorted(compilations[2:]) == ["atwood", "incline-pulley"]


def test_an_edit_that_changes_no_code_keeps_the_compiled_bank(db, small_bank, compilations, monkeypatch):
    start(db, small_bank)
    monkeypatch.setattr(catalog_module, "source_digest", lambda: "a docstring was edited")
    restarted = start(db, small_bank)
    assert sorted(compilations) == ["atwood", "incline-pulley"]  # nothing compiled again
    assert grades_its_reference(restarted)


def test_a_restart_of_unchanged_files_does_not_parse_the_engine_again(db, small_bank, monkeypatch):
    start(db, small_bank)

    def parse_again() -> str:
        raise AssertionError("the engine's digest was computed again")

    monkeypatch.setattr(catalog_module, "engine_digest", parse_again)  # as in a new process
    assert grades_its_reference(start(db, small_bank))


def test_an_edited_bank_document_has_its_meaning_checked_again(db, small_bank):
    from problems.errors import ProblemInvalid

    start(db, small_bank)
    problem = small_bank / "atwood" / "problem.yaml"
    problem.write_text(
        problem.read_text().replace("answer: 2*m1*m2*g/(m1 + m2)", "answer: 2*m1*q*g/(m1 + m2)")
    )
    with pytest.raises(ProblemInvalid, match="q"):
        Catalog(sql_stores(db), SECRET, small_bank).sync_builtin()


def test_a_first_start_derives_side_by_side_in_worker_processes_and_a_restart_loads_it(
    db, small_bank, compilations, monkeypatch
):
    def in_this_process(*args):
        raise AssertionError("derived in the server process")

    monkeypatch.setattr("problems.compiled.build_problem", in_this_process)
    first = Catalog(sql_stores(db), SECRET, small_bank, deriver=DerivationPool(workers=2))
    _started.append(first)
    first.sync_builtin()
    first.warm_up()
    assert sorted(compilations) == ["atwood", "incline-pulley"]  # in workers (this process cannot)
    assert grades_its_reference(first)
    with db.session() as session:
        assert len(session.scalars(select(CompiledProblemRow)).all()) >= 2
    restarted = start(db, small_bank)
    assert sorted(compilations) == ["atwood", "incline-pulley"]  # stored by the first start
    assert grades_its_reference(restarted)


def test_a_problem_that_fails_to_derive_side_by_side_is_logged_and_the_others_are_ready(
    db, small_bank, caplog
):
    stores = sql_stores(db)
    broken = yaml.safe_load((small_bank / "atwood" / "problem.yaml").read_text())
    broken["id"] = "broken-atwood"
    broken["parts"][0]["answer"] = "(m2 - m1)*g/(m1 + m2) + zeta"  # zeta: declared nowhere
    stores.problems.save_builtin("broken-atwood", broken)
    catalog = Catalog(stores, SECRET, small_bank, deriver=DerivationPool(workers=2))
    _started.append(catalog)
    catalog.sync_builtin()
    with caplog.at_level(logging.ERROR, logger="physcheck.catalog"):
        catalog.warm_up()
    assert catalog.warm.is_set()
    [logged] = [r.getMessage() for r in caplog.records]
    assert logged.startswith("problem 'broken-atwood' version 1 is refused by this code") and "zeta" in logged
    assert grades_its_reference(catalog)


def test_a_first_start_tells_how_many_problems_it_has_derived_until_it_is_warm(db, small_bank):
    catalog = Catalog(sql_stores(db), SECRET, small_bank)
    _started.append(catalog)
    catalog.sync_builtin()
    assert catalog.deriving is None  # nothing derived yet
    assert catalog._derive_all(catalog.list()) == set()  # the warm-up's derivations, warm not set yet
    assert catalog.deriving == (2, 2)
    catalog.warm.set()
    assert catalog.deriving is None
