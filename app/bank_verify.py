"""`physcheck bank verify`: re-derive and self-test the bank with a progress bar; non-zero on failure."""

from __future__ import annotations

import sys
from pathlib import Path

from tqdm import tqdm

from app.web.document_text import render_problems
from problems.errors import ProblemInvalid
from problems.loader import load_bank
from problems.selftest import verify_bank


def verify_command(variants: int, only: list[str] | None = None, bank_dir: Path | None = None) -> int:
    try:
        bank = load_bank(bank_dir)
    except ProblemInvalid as error:
        print(error.message, file=sys.stderr)
        return 1
    documents = [doc for doc in bank if not only or doc.id in only]
    missing = sorted(set(only or ()) - {doc.id for doc in documents})
    if missing:
        print(f"not in the bank: {', '.join(missing)}", file=sys.stderr)
        return 2
    with tqdm(total=len(documents), unit="problem", file=sys.stderr, disable=None) as bar:

        def progress(label: str, done: int, total: int) -> None:
            bar.set_postfix_str(label)
            bar.update(1)

        report = verify_bank(documents, variants, progress)
    print(report.summary())
    unrendered = [(doc.id, path, why) for doc in documents for path, why in render_problems(doc)]
    for problem, path, why in unrendered:
        print(f"  {problem}: {path} does not render cleanly: {why}")
    if unrendered:
        print(f"{len(unrendered)} text(s) do not render cleanly")
    return 0 if report.ok and not unrendered else 1
