"""The derived bank travels with the program: a first start loads it and derives nothing; a bank derived
by other code is ignored and the bank derived in workers; a damaged file is refused before any of it is
unpickled."""

from __future__ import annotations

import hashlib
import json
import logging
import shutil
from collections.abc import Callable
from pathlib import Path

import pytest

from app import catalog as catalog_module
from app.bank_verify import verify_command
from app.catalog import Catalog
from app.derivation import DerivationPool, forget_derived
from app.shipped_bank import DamagedBank, build_bank, read_bank, shipped_documents, write_bank
from app.storage import sql_stores
from physics.checking import check_answer
from physics.verdict import Outcome
from problems.fingerprint import source_digest
from problems.loader import bank_digest, load_bank
from tests.derivations import count_derivations

BANK = Path(__file__).resolve().parents[2] / "problems" / "bank"
SECRET = "secret-for-the-test"


@pytest.fixture(scope="module")
def small_bank(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Two bank problems with their hand-typed answers only (no model: quick to derive)."""
    root = tmp_path_factory.mktemp("bank")
    for problem_id in ("atwood", "incline-pulley"):
        (root / problem_id).mkdir()
        shutil.copy(BANK / problem_id / "problem.yaml", root / problem_id / "problem.yaml")
    return root


@pytest.fixture(scope="module")
def shipped(small_bank: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The small bank built as `physcheck bank build` builds it, in derivation workers."""
    path = tmp_path_factory.mktemp("shipped") / "bank.compiled"
    assert build_bank(path, small_bank, jobs=2, echo=False) == []
    forget_derived()  # what the build derived is not remembered for the starts below
    return path


@pytest.fixture
def meanings_checked(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The ids of the documents a start checked the meaning of (each model loaded, every expression
    read): none remembered from an earlier start in this process."""
    monkeypatch.setattr(catalog_module, "_MEANING_CHECKED", set())
    checked: list[str] = []
    real = catalog_module.semantic_errors

    def counting(doc):
        checked.append(doc.id)
        return real(doc)

    monkeypatch.setattr(catalog_module, "semantic_errors", counting)
    return checked


@pytest.fixture
def derivations(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The ids of the documents a start sent to a derivation worker."""
    forget_derived()
    yield count_derivations(monkeypatch)
    forget_derived()


_started: list[Catalog] = []


@pytest.fixture(autouse=True)
def _close_catalogs():
    yield
    while _started:
        _started.pop().close()


def first_start(db, bank: Path, shipped: Path) -> Catalog:
    """What an instance does at its first start on an empty database, with a shipped bank."""
    catalog = Catalog(sql_stores(db), SECRET, bank, deriver=DerivationPool(workers=2), shipped=shipped)
    _started.append(catalog)
    catalog.sync_builtin()
    catalog.warm_up()
    return catalog


def grades_its_reference(catalog: Catalog) -> bool:
    question = catalog.compiled(catalog.get("incline-pulley")).question("acceleration")
    return check_answer("(m2 - m1 sin(theta)) g/(m1 + m2)", question).outcome is Outcome.CORRECT


def test_a_first_start_with_the_shipped_bank_derives_nothing(
    db, small_bank, shipped, derivations, monkeypatch
):
    def parse_the_engine() -> str:
        raise AssertionError("the engine's digest was computed: the shipped bank's file digest names it")

    monkeypatch.setattr(catalog_module, "engine_digest", parse_the_engine)
    catalog = first_start(db, small_bank, shipped)
    assert derivations == []
    assert grades_its_reference(catalog)
    assert catalog.is_stored(catalog.get("atwood"))  # stored sealed: a restart needs no file


def test_a_restart_after_a_first_start_from_the_shipped_bank_needs_no_file(
    db, small_bank, shipped, derivations
):
    first_start(db, small_bank, shipped)
    restarted = first_start(db, small_bank, shipped.with_name("gone.compiled"))
    assert derivations == []
    assert grades_its_reference(restarted)


def test_a_shipped_bank_derived_by_other_code_is_ignored_and_the_bank_derived_in_workers(
    db, small_bank, shipped, derivations, tmp_path, caplog
):
    bank = read_bank(shipped)
    assert bank is not None
    stale = tmp_path / "stale.compiled"
    write_bank(stale, "the engine of another version", "its files", bank.payloads)
    with caplog.at_level(logging.INFO, logger="physcheck.catalog"):
        catalog = first_start(db, small_bank, stale)
    assert sorted(derivations) == ["atwood", "incline-pulley"]
    assert grades_its_reference(catalog)
    logged = [record.getMessage() for record in caplog.records]
    assert "the shipped bank was derived by other code; deriving what is not stored" in logged
    progress = [line for line in logged if line.startswith("derived '")]  # in the order they finished
    assert sorted(line.split()[1] for line in progress) == ["'atwood'", "'incline-pulley'"]
    assert [line.split(" (")[1] for line in progress] == ["1 of 2)", "2 of 2)"]


@pytest.fixture
def bank_parses(monkeypatch: pytest.MonkeyPatch) -> list[Path]:
    """The bank directories a start parsed the files of (none remembered from earlier in this process)."""
    monkeypatch.setattr(catalog_module, "_BANKS_READ", {})
    parsed: list[Path] = []

    def parsing(root, **options):
        parsed.append(root)
        return load_bank(root, **options)

    monkeypatch.setattr(catalog_module, "load_bank", parsing)
    return parsed


def test_a_start_takes_the_bank_documents_from_the_shipped_bank_instead_of_parsing_its_files(
    db, small_bank, shipped, bank_parses
):
    catalog = first_start(db, small_bank, shipped)
    assert bank_parses == []
    assert [catalog.get(doc.id).document for doc in load_bank(small_bank)] == [
        doc.model_dump(mode="json") for doc in load_bank(small_bank)
    ]
    assert grades_its_reference(catalog)


def test_a_bank_file_edited_after_the_build_is_parsed_and_its_edit_served(
    db, small_bank, shipped, bank_parses, tmp_path
):
    edited = tmp_path / "bank"
    shutil.copytree(small_bank, edited)
    problem = edited / "atwood" / "problem.yaml"
    text = problem.read_text()
    title = next(line for line in text.splitlines() if line.startswith("title:"))
    problem.write_text(text.replace(title, "title: The Atwood machine, edited after the build"))
    catalog = first_start(db, edited, shipped)
    assert bank_parses == [edited.resolve()]
    assert catalog.get("atwood").document["title"] == "The Atwood machine, edited after the build"


def test_the_shipped_bank_holds_the_documents_only_for_the_files_and_code_it_was_built_from(
    small_bank, shipped
):
    files, code = bank_digest(small_bank), source_digest()
    assert shipped_documents(shipped, files, code) == load_bank(small_bank)
    assert shipped_documents(shipped, "other files", code) is None
    assert shipped_documents(shipped, files, "other code") is None
    assert shipped_documents(shipped.with_name("gone.compiled"), files, code) is None


def test_a_first_start_does_not_check_again_the_meaning_the_shipped_bank_was_built_with(
    db, small_bank, shipped, meanings_checked
):
    first_start(db, small_bank, shipped)
    assert meanings_checked == []


@pytest.mark.parametrize("file", ["from other code", "damaged", "absent"])
def test_a_first_start_checks_the_meaning_of_what_no_shipped_bank_of_this_code_vouches_for(
    db, small_bank, shipped, meanings_checked, tmp_path, file
):
    other = tmp_path / "other.compiled"
    if file == "from other code":
        bank = read_bank(shipped)
        assert bank is not None
        write_bank(other, bank.engine, "the files of another version", bank.payloads)
    elif file == "damaged":
        other.write_bytes(b"\x80\x04\x95" + shipped.read_bytes())
    first_start(db, small_bank, other)
    assert sorted(meanings_checked) == ["atwood", "incline-pulley"]


def _flip_a_payload_bit(data: bytes) -> bytes:
    return data[:-10] + bytes([data[-10] ^ 1]) + data[-9:]


def _rewritten_digest(data: bytes) -> bytes:
    """A manifest whose first digest is another payload's: each entry must match its own bytes."""
    head, manifest, payloads = data.split(b"\n", 2)
    listed = json.loads(manifest)
    listed["entries"][0]["sha256"] = hashlib.sha256(b"another payload").hexdigest()
    return head + b"\n" + json.dumps(listed).encode() + b"\n" + payloads


DAMAGE: dict[str, Callable[[bytes], bytes]] = {
    "truncated": lambda data: data[: len(data) // 2],
    "a flipped bit in a payload": _flip_a_payload_bit,
    "a digest that is not its payload's": _rewritten_digest,
    "bytes past the last payload": lambda data: data + b"\x80\x04K\x01.",
    "not a shipped bank": lambda data: b"\x80\x04\x95" + data,
    "a manifest cut short": lambda data: data[: data.index(b"\n") + 20],
    "empty": lambda data: b"",
}


@pytest.mark.parametrize("damage", DAMAGE, ids=list(DAMAGE))
def test_a_damaged_shipped_bank_is_refused_before_any_of_it_is_unpickled(
    shipped, tmp_path, damage, monkeypatch
):
    damaged = tmp_path / "damaged.compiled"
    damaged.write_bytes(DAMAGE[damage](shipped.read_bytes()))

    def unpickled(*args, **kwargs):
        raise AssertionError("a payload of a damaged bank was unpickled")

    monkeypatch.setattr("pickle.loads", unpickled)
    with pytest.raises(DamagedBank):
        read_bank(damaged)


def test_a_first_start_with_a_damaged_shipped_bank_logs_it_and_derives_the_bank(
    db, small_bank, shipped, derivations, tmp_path, caplog
):
    damaged = tmp_path / "damaged.compiled"
    damaged.write_bytes(_flip_a_payload_bit(shipped.read_bytes()))
    with caplog.at_level(logging.ERROR, logger="physcheck.catalog"):
        catalog = first_start(db, small_bank, damaged)
    assert sorted(derivations) == ["atwood", "incline-pulley"]
    assert grades_its_reference(catalog)
    [refused] = [record.getMessage() for record in caplog.records]
    assert refused.startswith(f"refusing the shipped bank {damaged}: ")


def test_bank_verify_with_build_writes_the_bank_that_build_writes(
    db, small_bank, shipped, derivations, tmp_path, capsys
):
    """`make test` verifies and builds in one derivation of each problem; a first start loads it."""
    path = tmp_path / "verified.compiled"
    assert verify_command(variants=2, bank_dir=small_bank, jobs=1, build=path) == 0
    built, verified = read_bank(shipped), read_bank(path)
    assert built is not None and verified is not None
    assert verified.payloads.keys() == built.payloads.keys() and verified.source == built.source
    assert shipped_documents(path, bank_digest(small_bank), source_digest()) == load_bank(small_bank)
    assert grades_its_reference(first_start(db, small_bank, path))
    assert derivations == []


def test_bank_verify_of_some_problems_writes_no_bank(small_bank, tmp_path, capsys):
    path = tmp_path / "part.compiled"
    assert verify_command(variants=2, only=["atwood"], bank_dir=small_bank, jobs=1, build=path) == 0
    assert not path.exists()
