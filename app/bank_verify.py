"""`physcheck bank verify`: re-derive and self-test the bank with a progress bar; non-zero on failure."""

from __future__ import annotations

import multiprocessing
import os
import sys
from collections.abc import Iterator, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

from tqdm import tqdm

from app.db.problems import document_hash
from app.derivation import pack
from app.shipped_bank import BankRead, write_bank
from app.web.document_text import render_problems
from physics.wording import counted
from problems.compiled import compile_problem
from problems.errors import ProblemInvalid
from problems.fingerprint import engine_digest, source_digest
from problems.loader import bank_digest, load_bank
from problems.schema import ProblemDocument
from problems.selftest import Report, verify_problem


def verify_command(
    variants: int,
    only: list[str] | None = None,
    bank_dir: Path | None = None,
    jobs: int | None = None,
    build: Path | None = None,
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
    payloads: dict[str, bytes] = {}
    with tqdm(total=len(documents), unit="problem", file=sys.stderr, disable=None) as bar:
        for doc, result, payload in _verified(
            documents, variants, jobs or os.cpu_count() or 1, build is not None
        ):
            reports[doc.id] = result
            if payload is not None:
                payloads[document_hash(doc.model_dump(mode="json"))] = payload
            bar.set_postfix_str(doc.id)
            bar.update(1)
    report = Report([p for doc in documents for p in reports[doc.id].problems])
    print(report.summary())
    unrendered = [(doc.id, path, why) for doc in documents for path, why in render_problems(doc)]
    for problem, path, why in unrendered:
        print(f"  {problem}: {path} does not render cleanly: {why}")
    if unrendered:
        print(f"{counted(len(unrendered), 'text')} failed to render cleanly")
    ok = report.ok and not unrendered
    if build is not None and ok and not only:
        write_bank(build, engine_digest(), source_digest(), payloads, BankRead(bank_digest(bank_dir), bank))
        print(f"wrote {build}")
    return 0 if ok else 1


def _verified(
    documents: Sequence[ProblemDocument], variants: int, jobs: int, pack_them: bool
) -> Iterator[tuple[ProblemDocument, Report, bytes | None]]:
    """Each problem's report (and packed derivation, for --build) as it is done; problems are
    independent, so they are derived side by side."""
    if jobs <= 1 or len(documents) <= 1:
        for doc in documents:
            yield doc, *_checked(doc, variants, pack_them)
        return
    # forkserver: the parent holds tqdm's monitor thread, which a plain fork would copy mid-state
    context = multiprocessing.get_context("forkserver")
    with ProcessPoolExecutor(max_workers=jobs, mp_context=context) as pool:
        futures = {pool.submit(_checked, doc, variants, pack_them): doc for doc in documents}
        for future in as_completed(futures):
            yield futures[future], *future.result()


def _checked(doc: ProblemDocument, variants: int, pack_it: bool) -> tuple[Report, bytes | None]:
    """The self-test, and with `pack_it` the derivation it made packed as a first start loads it (the
    compile is cached in this process: `bank verify --build` derives the bank once, not twice)."""
    report = verify_problem(doc, variants)
    if not pack_it or not report.ok:
        return report, None
    return report, pack(compile_problem(doc).prepare())
