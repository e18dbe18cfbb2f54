"""The engine's digest changes with what its code does, not with its docstrings, comments or layout."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from problems.fingerprint import code_meaning, engine_digest, engine_files, source_digest

BEFORE = '''"""A module."""

LIMIT = 10  # how many


def scale(x, factor=2):
    """Scaled."""
    return x * factor
'''

# (edit, changes what the code does)
EDITS = [
    (BEFORE.replace('"""Scaled."""', '"""Scaled by a factor."""'), False),
    (BEFORE.replace('"""A module."""', ""), False),
    (BEFORE.replace("# how many", "# how many at most"), False),
    (BEFORE.replace("\n\n\ndef", "\n\ndef").replace("x * factor", "x*factor"), False),
    (BEFORE.replace("LIMIT = 10", "LIMIT = 11"), True),
    (BEFORE.replace("factor=2", "factor=3"), True),
    (BEFORE.replace("x * factor", "factor * x"), True),
    (BEFORE.replace("return x * factor", "return x * factor\n    return x"), True),
    (BEFORE.replace("def scale(x, factor=2):", "def scale(x: float, factor=2):"), True),
    (BEFORE + 'raise ValueError("a message is code")\n', True),
]


@pytest.mark.parametrize(("edited", "changes"), EDITS)
def test_the_meaning_of_code_changes_only_with_what_it_does(edited: str, changes: bool) -> None:
    assert (code_meaning(edited.encode()) != code_meaning(BEFORE.encode())) is changes


def write_engine(root: Path, module: str) -> None:
    for package in ("physics", "problems"):
        (root / package).mkdir(exist_ok=True)
        (root / package / "__init__.py").write_text("")
    (root / "physics" / "scale.py").write_text(module)


def digests(root: Path) -> tuple[str, str]:
    return source_digest.__wrapped__(root), engine_digest.__wrapped__(root)


def test_a_docstring_edit_changes_the_files_but_not_the_engine(tmp_path: Path) -> None:
    write_engine(tmp_path, BEFORE)
    files, engine = digests(tmp_path)
    write_engine(tmp_path, BEFORE.replace("Scaled.", "Scaled by a factor."))
    assert digests(tmp_path)[0] != files
    assert digests(tmp_path)[1] == engine
    write_engine(tmp_path, BEFORE.replace("factor=2", "factor=3"))
    assert digests(tmp_path)[1] != engine


def test_a_new_module_changes_the_engine(tmp_path: Path) -> None:
    write_engine(tmp_path, BEFORE)
    engine = digests(tmp_path)[1]
    (tmp_path / "problems" / "extra.py").write_text("EXTRA = 1\n")
    assert digests(tmp_path)[1] != engine


def test_no_engine_module_reads_docstrings() -> None:
    """The digest leaves docstrings out: sound only while no engine code reads one at run time."""
    readers = [
        path.name
        for path in engine_files()
        if path.name != "fingerprint.py" and re.search(r"__doc__|getdoc\(", path.read_text(encoding="utf-8"))
    ]
    assert readers == []
