"""CSV cells that a spreadsheet will not run (OWASP, "CSV Injection").

A text cell starting with `=`, `+`, `-`, `@`, tab or carriage return is read by Excel, LibreOffice and
Google Sheets as a formula, which can fetch URLs or start programs on the instructor's machine. So is
one where that sign follows spaces, a line break or a character one cannot see (a zero-width space, a
byte-order mark, a no-break space): spreadsheets skip them on import, and an instructor reading the
file sees nothing before the sign either. Full-width signs (`＝`, `＋`, `－`, `＠`) count too: Excel
with an East Asian input method takes `＝` as `=`. Such a cell gets a leading single quote, which the
spreadsheet shows as plain text; the writer quotes every text cell so separators and quotes inside it
stay data.

A student's `-3.2` is prefixed too, as OWASP advises for untrusted text: every text cell we export is
what someone typed, and keeping it text keeps it verbatim (`-3.20` would otherwise lose the
significant figure that a `sigfigs` verdict is about, and `-3.2+cmd|…` begins like a number). Numbers
we computed (score, attempt, version) are written as numbers and never prefixed.
"""

from __future__ import annotations

import csv
import unicodedata
from collections.abc import Iterable
from typing import TextIO

FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r", "＝", "＋", "－", "＠")
# Separators (spaces, line and paragraph breaks), controls (tab, newline, CR, NUL) and format
# characters (zero-width space and joiners, BOM, bidi marks, soft hyphen): nothing a reader sees.
_UNSEEN_CATEGORIES = frozenset({"Zs", "Zl", "Zp", "Cc", "Cf"})


def _first_seen(value: str) -> str:
    """`value` from its first character that is neither blank nor invisible."""
    for index, char in enumerate(value):
        if unicodedata.category(char) not in _UNSEEN_CATEGORIES:
            return value[index:]
    return ""


def safe_cell(value: object) -> object:
    """A text value made inert for spreadsheets; any other value unchanged."""
    if isinstance(value, str) and (
        value.startswith(FORMULA_STARTS) or _first_seen(value).startswith(FORMULA_STARTS)
    ):
        return "'" + value
    return value


class SafeWriter:
    """`csv.writer` whose rows go through `safe_cell`, with every text cell quoted."""

    def __init__(self, out: TextIO) -> None:
        self._writer = csv.writer(out, quoting=csv.QUOTE_NONNUMERIC)

    def writerow(self, row: Iterable[object]) -> None:
        self._writer.writerow([safe_cell(value) for value in row])
