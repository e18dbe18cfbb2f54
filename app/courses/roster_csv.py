"""A roster CSV: `id,name,email` (a header line optional; columns found by name when there is one)."""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass

from app.courses.records import RosterRow

MAX_ROWS = 5000
_ID = {"id", "student id", "student_id", "studentid", "sis id", "username", "login"}
_NAME = {"name", "full name", "student name", "student"}
_EMAIL = {"email", "e-mail", "email address", "mail"}


@dataclass(frozen=True)
class RosterProblem:
    line: int
    message: str


def parse_roster(text: str) -> tuple[list[RosterRow], list[RosterProblem]]:
    """Every row, or every problem found (all at once, with its line number)."""
    # newline="": csv ends a line at \r\n, \n or a lone \r itself (Excel for Mac's "CSV" ends lines with \r).
    reader = csv.reader(io.StringIO(text.lstrip("\ufeff"), newline=""))
    try:
        lines = list(reader)
    except csv.Error as error:  # a field past csv's size limit
        return [], [RosterProblem(reader.line_num, f"the line cannot be read as CSV ({error})")]
    rows: list[RosterRow] = []
    problems: list[RosterProblem] = []
    columns = (0, 1, 2)
    start = 0
    if lines:
        header = [cell.strip().lower() for cell in lines[0]]
        if any(cell in _ID for cell in header):
            found = [_find(header, names) for names in (_ID, _NAME, _EMAIL)]
            if found[0] is None or found[1] is None:
                return [], [RosterProblem(1, "the header needs an id column and a name column")]
            columns = (found[0], found[1], found[2] if found[2] is not None else -1)
            start = 1
    seen: dict[str, int] = {}
    for number, cells in enumerate(lines[start:], start=start + 1):
        if not any(cell.strip() for cell in cells):
            continue
        if len(rows) + len(problems) >= MAX_ROWS:
            problems.append(RosterProblem(number, f"a roster has at most {MAX_ROWS} students"))
            break
        id_, name, email = (cells[c].strip() if 0 <= c < len(cells) else "" for c in columns)
        if not id_ or len(id_) > 100 or any(ch.isspace() for ch in id_):
            problems.append(
                RosterProblem(number, "the id is missing, longer than 100 characters or has spaces")
            )
        elif not name or len(name) > 200:
            problems.append(RosterProblem(number, "the name is missing or longer than 200 characters"))
        elif email and ("@" not in email or len(email) > 254):
            problems.append(RosterProblem(number, f"{email!r} is not an email address"))
        elif id_ in seen:
            problems.append(RosterProblem(number, f"id {id_!r} is also on line {seen[id_]}"))
        else:
            seen[id_] = number
            rows.append(RosterRow(id_, name, email))
    return rows, problems


def _find(header: list[str], names: set[str]) -> int | None:
    return next((index for index, cell in enumerate(header) if cell in names), None)
