"""`physcheck bank verify`: re-derive and self-test the bank with a progress bar; non-zero on failure."""

from __future__ import annotations

import multiprocessing
import os
import sys
from collections.abc import Iterator, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

from tqdm import tqdm

from app.web.document_text import render_problems
from physics.wording import counted
from problems.errors import ProblemInvalid
from problems.loader import load_bank
from problems.schema import ProblemDocument
from problems.selftest import Report, verify_problem


def verify_command(
    variants: int, only: list[str] | None = None, bank_dir: Path | None = None, jobs: int | None = None
) -> int:
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
    reports: dict[str, Report] = {}
    with tqdm(total=len(documents), unit="problem", file=sys.stderr, disable=None) as bar:
        for problem_id, result in _verified(documents, variants, jobs or os.cpu_count() or 1):
            reports[problem_id] = result
            bar.set_postfix_str(problem_id)
            bar.update(1)
    report = Report([p for doc in documents for p in reports[doc.id].problems])
    print(report.summary())
    unrendered = [(doc.id, path, why) for doc in documents for path, why in render_problems(doc)]
    for problem, path, why in unrendered:
        print(f"  {problem}: {path} does not render cleanly: {why}")
    if unrendered:
        print(f"{counted(len(unrendered), 'text')} failed to render cleanly")
    return 0 if report.ok and not unrendered else 1


def _verified(documents: Sequence[ProblemDocument], variants: int, jobs: int) -> Iterator[tuple[str, Report]]:
    """Each problem's report as it is done; problems are independent, so they are derived side by side."""
    if jobs <= 1 or len(documents) <= 1:
        for doc in documents:
            yield doc.id, verify_problem(doc, variants)
        return
    # forkserver: the parent holds tqdm's monitor thread, which a plain fork would copy mid-state
    context = multiprocessing.get_context("forkserver")
    with ProcessPoolExecutor(max_workers=jobs, mp_context=context) as pool:
        futures = {pool.submit(verify_problem, doc, variants): doc.id for doc in documents}
        for future in as_completed(futures):
            yield futures[future], future.result()
