"""Roster CSVs as registrars and LMSs export them: with or without a header, columns in any order."""

from __future__ import annotations

import pytest

from app.courses.records import RosterRow
from app.courses.roster_csv import parse_roster


@pytest.mark.parametrize(
    "text",
    [
        "s1,Ada Lovelace,ada@x.org\ns2,Alan Turing,\n",
        "id,name,email\ns1,Ada Lovelace,ada@x.org\ns2,Alan Turing,\n",
        "\ufeffEmail,Student ID,Name\r\nada@x.org,s1,Ada Lovelace\r\n,s2,Alan Turing\r\n\r\n",
        'Student ID,Name\ns1,"Ada Lovelace"\ns2,Alan Turing\n',
        "id,name,email\rs1,Ada Lovelace,ada@x.org\rs2,Alan Turing,\r",  # Excel for Mac ends lines with \r
    ],
)
def test_rosters_are_read_with_or_without_header(text):
    rows, problems = parse_roster(text)
    assert problems == []
    assert [r.roster_id for r in rows] == ["s1", "s2"]
    assert rows[1] == RosterRow("s2", "Alan Turing", "")


def test_every_bad_line_is_reported_at_once():
    rows, problems = parse_roster("s1,Ada,ada@x\ns 2,Bob,\ns3,,\ns4,Dee,not-an-email\ns1,Eve,\n")
    assert [r.roster_id for r in rows] == ["s1"]
    assert [p.line for p in problems] == [2, 3, 4, 5]
    assert "line 1" in problems[-1].message


def test_a_field_past_the_csv_size_limit_is_a_problem_on_its_line():
    rows, problems = parse_roster("s1,Ada\ns2," + "B" * 200_000 + "\n")
    assert rows == []
    assert [p.line for p in problems] == [2]
    assert "cannot be read as CSV" in problems[0].message
