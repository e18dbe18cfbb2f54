"""The submissions CSV never hands a spreadsheet a formula (OWASP CSV injection): a text cell that a
spreadsheet would run is prefixed with a single quote, everything else is kept as it was typed."""

from __future__ import annotations

import csv
import io

import pytest

from app.spreadsheet import SafeWriter, safe_cell
from app.transfer import export_submissions
from tests.cli.test_commands import _atwood_file, database_env  # noqa: F401 (fixture)

CELLS = [
    ('=HYPERLINK("http://evil.test","x")', '\'=HYPERLINK("http://evil.test","x")'),
    ("+1+cmd|' /C calc'!A0", "'+1+cmd|' /C calc'!A0"),
    ("-2+3+cmd|' /C calc'!A0", "'-2+3+cmd|' /C calc'!A0"),
    ("@SUM(1+1)*cmd|' /C calc'!A0", "'@SUM(1+1)*cmd|' /C calc'!A0"),
    ("\t=1+1", "'\t=1+1"),
    ("\r=1+1", "'\r=1+1"),
    ("-3.2", "'-3.2"),  # a student's negative number is text too: see app/spreadsheet.py
    ("-m*g*sin(theta)", "'-m*g*sin(theta)"),
    # Spreadsheets skip what one cannot see before the sign: blanks, line breaks, invisible characters.
    (" =1+1", "' =1+1"),
    ("   @SUM(A1:A2)", "'   @SUM(A1:A2)"),
    ("\n=1+1", "'\n=1+1"),
    ("\r\n+1+1", "'\r\n+1+1"),
    (" \t-2+3", "' \t-2+3"),
    ("\u200b=1+1", "'\u200b=1+1"),  # zero-width space
    ('\ufeff=HYPERLINK("http://evil.test")', '\'\ufeff=HYPERLINK("http://evil.test")'),  # BOM
    ("\u00a0=1+1", "'\u00a0=1+1"),  # no-break space
    ("\u2060\u200d@SUM(1)", "'\u2060\u200d@SUM(1)"),  # word joiner, zero-width joiner
    ("\u202e=1+1", "'\u202e=1+1"),  # right-to-left override
    ("\u3000=1+1", "'\u3000=1+1"),  # ideographic space
    ("\u00ad-1", "'\u00ad-1"),  # soft hyphen
    ("＝1+1", "'＝1+1"),  # full-width equals sign
    (" 4.58 m/s^2", " 4.58 m/s^2"),
    ("\u200b", "\u200b"),
    ("4.58 m/s^2", "4.58 m/s^2"),
    ("m g sin(θ) = a", "m g sin(θ) = a"),
    ("", ""),
    ("'quoted", "'quoted"),
]


@pytest.mark.parametrize(("typed", "exported"), CELLS, ids=[repr(c[0])[:24] for c in CELLS])
def test_text_cell_that_starts_a_formula_gets_a_quote(typed: str, exported: str):
    assert safe_cell(typed) == exported


@pytest.mark.parametrize("number", [-3.2, 0, -1, 2.5], ids=str)
def test_numbers_we_computed_stay_numbers(number: float):
    assert safe_cell(number) == number


def test_written_row_reads_back_with_separators_and_quotes_as_data():
    out = io.StringIO()
    SafeWriter(out).writerow(["=1,2", 'say "hi"', 0.5, "-3.2"])
    assert next(csv.reader(io.StringIO(out.getvalue()))) == ["'=1,2", 'say "hi"', "0.5", "'-3.2"]


def test_exported_submissions_carry_no_formula(database_env, tmp_path):  # noqa: F811 (the fixture)
    from app.cli import main
    from app.db.database import Database
    from app.storage import sql_stores
    from physics.verdict import Judgement, Reason, Verdict

    main(["problems", "import", str(_atwood_file(tmp_path))])
    database = Database(database_env)
    try:
        stores = sql_stores(database)
        record = stores.problems.get("cli-atwood")
        for typed, _ in CELLS:
            stores.submissions.file(
                problem_id=record.id,
                problem_version=1,
                part_id="acceleration",
                student="=cmd|' /C calc'!A0",
                answer=typed,
                verdict=Verdict.graded(Judgement(False, Reason.WRONG_VALUE, "f"), None),
                max_attempts=None,
            )
        out = io.StringIO()
        assert export_submissions(stores.submissions, "cli-atwood", out) == len(CELLS)
    finally:
        database.dispose()
    rows = list(csv.DictReader(io.StringIO(out.getvalue())))
    assert [row["answer"] for row in rows] == [exported for _, exported in CELLS]
    assert {row["student"] for row in rows} == {"'=cmd|' /C calc'!A0"}
    # Every exported cell is already inert: none would be given a quote again.
    assert all(safe_cell(cell) == cell for row in rows for cell in row.values())
