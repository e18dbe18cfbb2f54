"""The gradebook: each student's best score on each part of each assignment, late penalties applied.

A part's best is the highest score of its graded submissions, each multiplied by its late factor
against the due date in force when it was made (an extension counts from when it was granted), and a
submission after the due date under a closed policy does not count, nor one made after the student
opened the problem's worked solution: the part's grade is frozen then. An assignment's score is the
sum of its parts' bests, out of its number of parts. Submissions are the append-only log: the
gradebook is always recomputed from it, never stored.
"""

from __future__ import annotations

import io
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from datetime import datetime

from app.courses.policy import Counting, Status, due_for, status
from app.courses.records import AssignmentRecord, EnrolmentRecord, ExtensionRecord
from app.db.records import SubmissionRecord
from app.spreadsheet import SafeWriter
from physics.verdict import Outcome


@dataclass(frozen=True)
class PartSpec:
    problem_id: str
    part_id: str
    max_attempts: int | None


@dataclass(frozen=True)
class PartCell:
    problem_id: str
    part_id: str
    score: float  # best, penalty applied
    late: bool  # the best came from a late submission that lost points
    attempts: int
    solved: bool
    locked: bool  # out of attempts
    frozen_at: datetime | None = None  # when the student opened the worked solution: no credit after


@dataclass(frozen=True)
class AssignmentCell:
    assignment_id: int
    student: str
    score: float
    maximum: int
    late: bool
    status: Status
    due: datetime
    extended: bool
    parts: tuple[PartCell, ...]
    extension: ExtensionRecord | None = None

    @property
    def attempted(self) -> bool:
        """Some part was answered and graded: a 0 is then a score, not "not started"."""
        return any(part.attempts for part in self.parts)

    @property
    def frozen(self) -> bool:
        """Some part's grade was frozen by the student opening its worked solution."""
        return any(part.frozen_at is not None for part in self.parts)


def part_cell(part: PartSpec, submissions: Iterable[SubmissionRecord], counting: Counting) -> PartCell:
    best, best_late, attempts, solved = 0.0, False, 0, False
    for item in submissions:
        if item.verdict is Outcome.INVALID:
            continue
        attempts += 1
        factor = counting.factor(item.created_at)
        if factor is None:
            continue
        solved = solved or item.verdict is Outcome.CORRECT
        counted = item.score * factor
        if counted > best:
            best, best_late = counted, factor < 1.0
    limit = counting.assignment.spec.max_attempts or part.max_attempts
    locked = limit is not None and attempts >= limit
    return PartCell(
        part.problem_id,
        part.part_id,
        round(best, 6),
        best_late,
        attempts,
        solved,
        locked,
        counting.solution_opened,
    )


def assignment_cell(
    assignment: AssignmentRecord,
    parts: Sequence[PartSpec],
    submissions: Sequence[SubmissionRecord],
    student: str,
    extension: ExtensionRecord | None,
    now: datetime,
    solutions_opened: Mapping[str, datetime] | None = None,
) -> AssignmentCell:
    """`solutions_opened`: when the student first opened each problem's worked solution."""
    due = due_for(assignment, extension)
    opened = solutions_opened or {}
    by_part: dict[tuple[str, str], list[SubmissionRecord]] = {}
    for item in submissions:
        by_part.setdefault((item.problem_id, item.part_id), []).append(item)
    cells = tuple(
        part_cell(
            p,
            by_part.get((p.problem_id, p.part_id), ()),
            Counting(assignment, extension, opened.get(p.problem_id)),
        )
        for p in parts
    )
    started = any(by_part.get((p.problem_id, p.part_id)) for p in parts)
    done = bool(cells) and all(c.solved or c.locked for c in cells)
    return AssignmentCell(
        assignment_id=assignment.id,
        student=student,
        score=round(sum(c.score for c in cells), 6),
        maximum=len(cells),
        late=any(c.late for c in cells),
        status=status(assignment, due, now, started=started, done=done),
        due=due,
        extended=due > assignment.spec.due_at,
        parts=cells,
        extension=extension,
    )


@dataclass(frozen=True)
class Gradebook:
    students: tuple[EnrolmentRecord, ...]
    assignments: tuple[AssignmentRecord, ...]
    cells: Mapping[tuple[str, int], AssignmentCell]  # (student, assignment id)
    maximum: Mapping[int, int]  # points of each assignment: its number of parts

    def cell(self, student: str, assignment_id: int) -> AssignmentCell:
        return self.cells[(student, assignment_id)]

    def total(self, student: str) -> tuple[float, int]:
        found = [self.cells[(student, a.id)] for a in self.assignments]
        return round(sum(c.score for c in found), 6), sum(c.maximum for c in found)


def build(
    students: Sequence[EnrolmentRecord],
    assignments: Sequence[AssignmentRecord],
    parts: Mapping[int, Sequence[PartSpec]],
    submissions: Mapping[str, Sequence[SubmissionRecord]],
    extensions: Mapping[int, Mapping[str, ExtensionRecord]],
    now: datetime,
    solutions_opened: Mapping[str, Mapping[str, datetime]] | None = None,
) -> Gradebook:
    """`parts` per assignment id, `submissions` per student, `extensions` per assignment id,
    `solutions_opened` per student (then per problem)."""
    cells = {}
    for enrolment in students:
        mine = submissions.get(enrolment.student, ())
        for assignment in assignments:
            wanted = set(assignment.problems)
            cells[(enrolment.student, assignment.id)] = assignment_cell(
                assignment,
                parts.get(assignment.id, ()),
                [s for s in mine if s.problem_id in wanted],
                enrolment.student,
                extensions.get(assignment.id, {}).get(enrolment.student),
                now,
                (solutions_opened or {}).get(enrolment.student),
            )
    maximum = {a.id: len(parts.get(a.id, ())) for a in assignments}
    return Gradebook(tuple(students), tuple(assignments), cells, maximum)


def to_csv(book: Gradebook) -> str:
    """One row per student: id, name, email, each assignment's points (its maximum in the header; empty
    when nothing was answered, as LMS imports read "no grade", apart from a 0 earned), the total, and
    notes (late penalties, extensions with when each was granted). Scores are written as numbers and
    text cells quoted and made inert (`app.spreadsheet`), so spreadsheets and LMS gradebook imports read them."""
    out = io.StringIO()
    writer = SafeWriter(out)
    writer.writerow(
        ["Student ID", "Name", "Email"]
        + [f"{a.title} (out of {book.maximum[a.id]})" for a in book.assignments]
        + [f"Total (out of {sum(book.maximum.values())})", "Notes"]
    )
    for enrolment in book.students:
        cells = [book.cell(enrolment.student, a.id) for a in book.assignments]
        notes = []
        for assignment, cell in zip(book.assignments, cells, strict=True):
            if cell.late:
                notes.append(f"{assignment.title}: late penalty applied")
            if cell.frozen:
                notes.append(f"{assignment.title}: grade frozen, worked solution opened ({_frozen(cell)})")
            if cell.extended:
                notes.append(f"{assignment.title}: {extension_note(cell, _utc)}")
        total, _ = book.total(enrolment.student)
        writer.writerow(
            [enrolment.shown_id, enrolment.name, enrolment.email]
            + [c.score if c.attempted else "" for c in cells]
            + [total, "; ".join(notes)]
        )
    return out.getvalue()


def extension_note(cell: AssignmentCell, when: Callable[[datetime], str]) -> str:
    """An extension, its dates written by `when`: to when, and since when it counts, which says which
    late penalties it lifted (the CSV's note and the gradebook page say it alike)."""
    granted_at = None if cell.extension is None else cell.extension.granted_at
    since = (
        ", covering the answers given before it too"
        if granted_at is None
        else f", granted {when(granted_at)}"
    )
    return f"extended to {when(cell.due)}{since}"


def _utc(moment: datetime) -> str:
    return f"{moment:%Y-%m-%d %H:%M} UTC"


def _frozen(cell: AssignmentCell) -> str:
    """ "yo-yo at 2026-03-03 10:00 UTC" for each problem whose worked solution froze its parts' grades."""
    opened = {p.problem_id: p.frozen_at for p in cell.parts if p.frozen_at is not None}
    return ", ".join(f"{problem} at {at:%Y-%m-%d %H:%M} UTC" for problem, at in opened.items())
