"""A new problem started from a built-in one: its files as their author wrote them (comments kept, no
defaults filled in), the model under `model:`, under a new id. A blank box and a file name
(problems/FORMAT.md) the instructor cannot open was all the upload page had offered to start from."""

from __future__ import annotations

import re
from pathlib import Path

from problems.loader import BANK_DIR

_ID_LINE = re.compile(r"^id:.*$", re.MULTILINE)


def starter_source(problem_id: str, bank_dir: Path | None) -> str | None:
    """The upload text of a built-in problem under the id `<id>-copy`, or None when the bank has no
    such directory (an uploaded problem: its author edits it as a new version)."""
    root = (bank_dir or BANK_DIR).resolve()
    folder = (root / problem_id).resolve()
    if folder.parent != root or not (folder / "problem.yaml").is_file():
        return None
    problem = (folder / "problem.yaml").read_text(encoding="utf-8").rstrip("\n")
    problem = _ID_LINE.sub(f"id: {problem_id}-copy", problem, count=1)
    model_file = folder / "model.yaml"
    if not model_file.is_file():
        return problem + "\n"
    model = model_file.read_text(encoding="utf-8").rstrip("\n").splitlines()
    indented = "\n".join(f"  {line}" if line.strip() else "" for line in model)
    return f"{problem}\nmodel:\n{indented}\n"
