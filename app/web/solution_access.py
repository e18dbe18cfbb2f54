"""THE one place that decides whether a student may see a problem's worked solution.

Every student-facing solution page asks `solution_release` and nothing else. Today it reads the
problem document's `solutions` (after_attempts, the default; always; never) and the student's work;
when courses and assignments carry a release policy (never / after the due date / after the last
attempt, per assignment), this function is the seam to point at it: the pages need not change.
Instructors are not asked: their pages always show the solutions.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.web.student_work import ProblemWork
from problems.schema import ProblemDocument


@dataclass(frozen=True)
class Release:
    released: bool
    why: str  # said to the student either way


def solution_release(doc: ProblemDocument, work: ProblemWork) -> Release:
    """Released when the document says always, or (after_attempts) once every part is done: answered
    correctly, or its attempts used up; never when it says never."""
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
