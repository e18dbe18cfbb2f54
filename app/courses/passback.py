"""An assignment's score for the LMS: the gradebook's total of the student's parts (late penalties
applied), out of its number of parts, queued for every line item the assignment was launched from.

Grade targets of assignments are kept in the outbox under the key `assignment:<id>`, beside the
problems' own; the stores queue the new total in the transaction that files each graded submission to
one of its problems (so the queue's order, supersede and exactly-once rules hold as for problems).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from datetime import datetime
from typing import Any

from app.courses.gradebook import PartSpec, assignment_cell
from app.courses.records import AssignmentRecord, ExtensionRecord
from app.db.records import SubmissionRecord

PREFIX = "assignment:"


def target_key(assignment_id: int) -> str:
    return f"{PREFIX}{assignment_id}"


def assignment_of(key: str) -> int | None:
    """The assignment id of a grade target's key, or None for a problem's."""
    if not key.startswith(PREFIX) or not key[len(PREFIX) :].isdigit():
        return None
    return int(key[len(PREFIX) :])


def parts_of(problem_ids: Iterable[str], documents: Mapping[str, Mapping[str, Any]]) -> list[PartSpec]:
    """Every part of the assignment's problems, from their latest documents (one point a part)."""
    parts = []
    for problem_id in problem_ids:
        listed = (documents.get(problem_id) or {}).get("parts")
        for part in listed if isinstance(listed, list) else []:
            if isinstance(part, dict) and part.get("id") is not None:
                parts.append(PartSpec(problem_id, str(part["id"]), None))
    return parts


def assignment_score(
    assignment: AssignmentRecord,
    documents: Mapping[str, Mapping[str, Any]],
    submissions: Sequence[SubmissionRecord],
    student: str,
    extension: ExtensionRecord | None,
    now: datetime,
    solutions_opened: Mapping[str, datetime] | None = None,
) -> tuple[float, float]:
    """(score given, score maximum) as the gradebook counts it."""
    wanted = set(assignment.problems)
    mine = [s for s in submissions if s.student == student and s.problem_id in wanted]
    cell = assignment_cell(
        assignment, parts_of(assignment.problems, documents), mine, student, extension, now, solutions_opened
    )
    return cell.score, float(max(cell.maximum, 1))
