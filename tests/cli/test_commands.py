"""The `physcheck` command line as an administrator uses it (API.md, "Command line")."""

from __future__ import annotations

import csv
import io
import shutil
from pathlib import Path

import pytest
import yaml
from sqlalchemy import select

from app.catalog import Catalog
from app.cli import main
from app.db import keys as key_repository
from app.db.database import Database
from app.db.models import ApiKey
from app.settings import get_settings
from app.storage import sql_stores

BANK = Path(__file__).resolve().parents[2] / "problems" / "bank"


@pytest.fixture
def database_env(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    url = f"sqlite:///{tmp_path / 'cli.db'}"
    monkeypatch.setenv("PHYSCHECK_DATABASE_URL", url)
    get_settings.cache_clear()
    yield url
    get_settings.cache_clear()


@pytest.mark.parametrize("role", ["instructor", "student"])
def test_keys_create_prints_a_working_key_as_the_last_line(database_env, capsys, role):
    assert main(["keys", "create", "--role", role, "--name", "Ada"]) == 0
    key = capsys.readouterr().out.strip().splitlines()[-1]
    database = Database(database_env)
    try:
        with database.session(read_only=True) as session:
            record = key_repository.authenticate(session, key)
            stored = session.scalars(select(ApiKey)).all()
    finally:
        database.dispose()
    assert record is not None and record.role.value == role
    assert all(key not in (row.key_hash, row.prefix) for row in stored)


def test_keys_revoke_makes_the_key_fail(database_env, capsys):
    main(["keys", "create", "--role", "instructor"])
    key = capsys.readouterr().out.strip().splitlines()[-1]
    database = Database(database_env)
    try:
        with database.session(read_only=True) as session:
            key_id = key_repository.authenticate(session, key).id
        assert main(["keys", "revoke", str(key_id)]) == 0
        with database.session(read_only=True) as session:
            assert key_repository.authenticate(session, key) is None
    finally:
        database.dispose()


def _atwood_file(tmp_path: Path, problem_id: str = "cli-atwood", **changes) -> Path:
    doc = yaml.safe_load((BANK / "atwood" / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK / "atwood" / "model.yaml").read_text())
    doc.update(id=problem_id, **changes)
    path = tmp_path / f"{problem_id}.yaml"
    path.write_text(yaml.safe_dump(doc))
    return path


def test_problems_import_then_export_round_trips(database_env, tmp_path, capsys):
    path = _atwood_file(tmp_path)
    assert main(["problems", "import", str(path)]) == 0
    assert "cli-atwood version 1" in capsys.readouterr().out
    assert main(["problems", "import", str(_atwood_file(tmp_path, title="Renamed"))]) == 0
    assert "version 2" in capsys.readouterr().out
    assert main(["problems", "export", "cli-atwood"]) == 0
    exported = yaml.safe_load(capsys.readouterr().out)
    assert (exported["id"], exported["title"]) == ("cli-atwood", "Renamed")


def test_an_imported_problem_is_stored_with_its_compilation(database_env, tmp_path, capsys):
    assert main(["problems", "import", str(_atwood_file(tmp_path))]) == 0
    database = Database(database_env)
    try:
        catalog = Catalog(sql_stores(database), get_settings().secret)
        assert catalog.is_stored(catalog.get("cli-atwood"))  # a server opens it: nothing to derive
    finally:
        database.dispose()


def test_problems_import_lists_every_error_and_fails(database_env, tmp_path, capsys):
    path = _atwood_file(tmp_path, title="", topics="not a list")
    assert main(["problems", "import", str(path)]) == 1
    err = capsys.readouterr().err
    assert "title" in err and "topics" in err


def test_submissions_export_writes_csv_with_every_row(database_env, tmp_path, capsys):
    from app.db import problems as problem_repository
    from app.db import submissions as submission_repository
    from physics.verdict import Judgement, Reason, Verdict

    database = Database(database_env)
    main(["problems", "import", str(_atwood_file(tmp_path))])
    try:
        with database.session() as session:
            record = problem_repository.get_problem(session, "cli-atwood")
            for i in range(3):
                verdict = Verdict.graded(
                    Judgement(i == 2, Reason.EQUIVALENT if i == 2 else Reason.WRONG_VALUE, "f"), None
                )
                submission_repository.record_submission(
                    session,
                    problem_id=record.id,
                    problem_version=1,
                    part_id="acceleration",
                    student="ada",
                    answer=f"answer, {i}",
                    verdict=verdict,
                    max_attempts=None,
                )
    finally:
        database.dispose()
    capsys.readouterr()
    out = tmp_path / "out.csv"
    assert main(["submissions", "export", "--problem", "cli-atwood", "-o", str(out)]) == 0
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    assert [row["answer"] for row in rows] == ["answer, 0", "answer, 1", "answer, 2"]
    assert [row["verdict"] for row in rows] == ["incorrect", "incorrect", "correct"]


def test_submissions_export_names_each_courses_student_as_the_instructors_csv_does(
    database_env, tmp_path, capsys
):
    # the command line's name and email columns had been empty where the web CSV filled them
    from app.courses.records import RosterRow
    from tests.db.helpers import CORRECT

    main(["problems", "import", str(_atwood_file(tmp_path))])
    database = Database(database_env)
    try:
        stores = sql_stores(database)
        course = stores.courses.create_course("Mechanics", owner="key:1")
        stores.courses.import_roster(course.id, [RosterRow("s1", "Ada Lovelace", "ada@uni.example")])
        (ada,) = stores.courses.roster(course.id)
        for student in (ada.student, "keyed-student"):
            stores.submissions.file(
                problem_id="cli-atwood",
                problem_version=1,
                part_id="acceleration",
                student=student,
                answer="g",
                verdict=CORRECT,
                max_attempts=None,
            )
    finally:
        database.dispose()
    out = tmp_path / "out.csv"
    assert main(["submissions", "export", "-o", str(out)]) == 0
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    assert {row["student"]: (row["name"], row["email"]) for row in rows} == {
        ada.student: ("Ada Lovelace", "ada@uni.example"),
        "keyed-student": ("", ""),  # in no course: no roster names them
    }


def test_bank_verify_passes_on_a_good_problem(capsys):
    assert main(["bank", "verify", "--variants", "2", "--problem", "atwood"]) == 0
    out = capsys.readouterr().out
    assert "1 problem, " in out
    assert "0 failures" in out
    assert "(s)" not in out


def test_bank_verify_fails_on_a_broken_bank(tmp_path, monkeypatch, capsys):
    broken = tmp_path / "bank"
    shutil.copytree(BANK / "atwood", broken / "atwood")
    model = (broken / "atwood" / "model.yaml").read_text().replace('position: {y: "-s"}', "position: {y: s}")
    (broken / "atwood" / "model.yaml").write_text(model)
    monkeypatch.setenv("PHYSCHECK_BANK_DIR", str(broken))
    get_settings.cache_clear()
    try:
        assert main(["bank", "verify", "--variants", "2"]) != 0
    finally:
        get_settings.cache_clear()


def test_bank_verify_fails_on_a_statement_that_does_not_render_cleanly(tmp_path, monkeypatch, capsys):
    broken = tmp_path / "bank"
    shutil.copytree(BANK / "atwood", broken / "atwood")
    problem = (broken / "atwood" / "problem.yaml").read_text()
    (broken / "atwood" / "problem.yaml").write_text(
        problem.replace("statement: |\n", "statement: |\n  $\\frac{a}$ `m1\n", 1)
    )
    monkeypatch.setenv("PHYSCHECK_BANK_DIR", str(broken))
    get_settings.cache_clear()
    try:
        assert main(["bank", "verify", "--variants", "1"]) != 0
    finally:
        get_settings.cache_clear()
    out = capsys.readouterr().out
    assert "atwood: statement does not render cleanly" in out
    assert "2 texts failed to render cleanly" in out
    assert "mfrac needs 2 arguments" in out and "stray $ or `" in out


def test_bank_verify_side_by_side_reports_every_problem_in_bank_order(tmp_path, monkeypatch, capsys):
    bank = tmp_path / "bank"
    for problem in ("mass-spring", "atwood"):
        shutil.copytree(BANK / problem, bank / problem)
    problem = (bank / "atwood" / "problem.yaml").read_text()  # a known mistake that is the right answer
    (bank / "atwood" / "problem.yaml").write_text(
        problem.replace("answer: m2*g\n", "answer: 2*m1*m2*g/(m1 + m2)\n")
    )
    monkeypatch.setenv("PHYSCHECK_BANK_DIR", str(bank))
    get_settings.cache_clear()
    try:
        assert main(["bank", "verify", "--variants", "1", "--jobs", "2"]) != 0
    finally:
        get_settings.cache_clear()
    captured = capsys.readouterr()
    lines = captured.out.splitlines()
    assert [line.split(":")[0] for line in lines[:2]] == ["FAIL atwood", "ok   mass-spring"], captured.err
