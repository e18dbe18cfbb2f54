"""Command-line import and export: problems as YAML/JSON files, submissions as CSV."""

from __future__ import annotations

import json
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any, TextIO

import yaml
from tqdm import tqdm

from app.authoring import vet
from app.courses.records import EnrolmentRecord
from app.db.records import ProblemRecord
from app.spreadsheet import SafeWriter
from app.storage import CompiledEntry, ProblemStore, SubmissionStore
from problems.errors import ProblemInvalid

SUBMISSION_COLUMNS = (
    "submission_id",
    "created_at",
    "problem",
    "problem_version",
    "part",
    "student",
    "answer",
    "verdict",
    "score",
    "reason",
    "attempt",
    "feedback",
    # Last, so that scripts reading the earlier columns by position still do: a course's student's,
    # from its roster (`student` alone read `course:1:join-3f2a…`).
    "name",
    "email",
)
EXPORT_PAGE = 1000


def import_problem(
    problems: ProblemStore, path: Path, seal: Callable[[dict[str, Any], bytes], CompiledEntry] | None = None
) -> ProblemRecord:
    """Vet and store a problem file: a new problem, or a new version of one the CLI or bank owns; with
    `seal` (the server's `Catalog.entry`), stored with the compiled problem the vetting derived, so
    that no server derives it again.

    Raises ProblemInvalid with every fault found.
    """
    vetted = vet(path.read_bytes(), "json" if path.suffix.lower() == ".json" else "yaml")
    if vetted.document is None:
        raise ProblemInvalid(vetted.errors)
    compiled = None if seal is None or vetted.compiled is None else seal(vetted.document, vetted.compiled)
    # Stored like the built-in bank (no owner key): unchanged files keep their version.
    return problems.save_builtin(vetted.document["id"], vetted.document, compiled=compiled)


def export_problem(problems: ProblemStore, problem_id: str, fmt: str, out: TextIO) -> None:
    record = problems.get(problem_id, include_retired=True)
    document = dict(record.document)
    if fmt == "json":
        json.dump(document, out, indent=2, ensure_ascii=False)
        out.write("\n")
    else:
        yaml.safe_dump(document, out, sort_keys=False, allow_unicode=True)


def _name_and_email(person: Callable[[str], EnrolmentRecord | None] | None, student: str) -> tuple[str, str]:
    found = None if person is None else person(student)
    return ("", "") if found is None else (found.name, found.email)


def export_submissions(
    submissions: SubmissionStore,
    problem_id: str | None,
    out: TextIO,
    *,
    student: str | None = None,
    progress: bool = True,
    include: Callable[[str], bool] | None = None,
    person: Callable[[str], EnrolmentRecord | None] | None = None,
) -> int:
    """Every submission (of one problem, of one student) as CSV, oldest first; returns how many rows
    were written. Text cells are neutralised for spreadsheets (`app.spreadsheet`). `progress=False`
    (the web pages) draws no progress bar on stderr; `include(student)` false leaves a student's rows out
    (an instructor's page exports only the students of their courses); `person(student)` gives the
    roster's name and email of a course's student, by the identity their work is filed under."""
    writer = SafeWriter(out)
    writer.writerow(SUBMISSION_COLUMNS)
    rows, cursor = 0, None
    with tqdm(unit=" submissions", file=sys.stderr, disable=None if progress else True) as bar:
        while True:
            page = submissions.page(problem_id=problem_id, student=student, limit=EXPORT_PAGE, cursor=cursor)
            items = [i for i in page.items if include is None or include(i.student)]
            for item in items:
                writer.writerow(
                    (
                        item.id,
                        item.created_at.isoformat(),
                        item.problem_id,
                        item.problem_version,
                        item.part_id,
                        item.student,
                        item.answer,
                        item.verdict.value,
                        item.score,
                        item.reason.value,
                        "" if item.attempt is None else item.attempt,
                        item.feedback,
                        *_name_and_email(person, item.student),
                    )
                )
            rows += len(items)
            bar.update(len(page.items))
            if page.next is None:
                return rows
            cursor = page.next
