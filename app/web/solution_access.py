"""THE one place that decides whether a student may see a problem's worked solution.

Every student-facing solution page asks `solution_release` and nothing else. A problem opened within
an assignment (a course's student) follows the assignment's release policy: never, after the due date
(the student's own, with an extension), or after the last attempt. Otherwise it reads the problem
document's `solutions` (after_attempts, the default; always; never) and the student's work.
Instructors are not asked: their pages always show the solutions.
"""

from __future__ import annotations

from dataclasses import dataclass
from datetime import datetime

from app.courses.policy import solutions_released
from app.courses.records import AssignmentRecord
from app.web.student_work import ProblemWork
from problems.schema import ProblemDocument


@dataclass(frozen=True)
class Release:
    released: bool
    why: str  # said to the student either way


@dataclass(frozen=True)
class Within:
    """The assignment a problem is opened in, the student's due date for it, and the time now."""

    assignment: AssignmentRecord
    due: datetime
    now: datetime


def solution_release(doc: ProblemDocument, work: ProblemWork, within: Within | None = None) -> Release:
    """Within an assignment, its policy decides. Else released when the document says always, or
    (after_attempts) once every part is done: answered correctly, or its attempts used up; never when
    it says never."""
    if within is not None:
        finished = all(
            (w := work.parts.get(part.id)) is not None and (w.solved or w.locked) for part in doc.parts
        )
        released, why = solutions_released(within.assignment, within.due, within.now, all_parts_done=finished)
        return Release(released, why)
    if doc.solutions == "always":
        return Release(True, "Your instructor has released this solution.")
    if doc.solutions == "never":
        return Release(False, "Your instructor has not released the worked solution of this problem.")
    open_parts = [
        index + 1
        for index, part in enumerate(doc.parts)
        if (done := work.parts.get(part.id)) is None or not (done.solved or done.locked)
    ]
    if not open_parts:
        return Release(True, "Every part is done: answered correctly or out of attempts.")
    said = ", ".join(str(n) for n in open_parts)
    return Release(
        False,
        f"The worked solution opens once every part is done, answered correctly or out of attempts; "
        f"part{'s' if len(open_parts) > 1 else ''} {said} still open.",
    )
