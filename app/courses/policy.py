"""Due dates, late penalties, a student's status on an assignment and when its solutions open.

Pure functions of the records and the clock: the gradebook, the pages and the submission gate all
ask here, so a late submission is judged the same way everywhere.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from datetime import datetime, timedelta
from enum import StrEnum
from zoneinfo import ZoneInfo, ZoneInfoNotFoundError

from app.courses.records import AssignmentRecord, ExtensionRecord, LateKind, LatePolicy, SolutionRelease

DAY = timedelta(days=1)


class Status(StrEnum):
    NOT_OPEN = "not open"
    NOT_STARTED = "not started"
    IN_PROGRESS = "in progress"
    DONE = "done"
    LATE = "late"
    CLOSED = "closed"


def due_for(assignment: AssignmentRecord, extension: ExtensionRecord | None) -> datetime:
    """The student's due date: their extension when they have one (it may only move it later)."""
    due = assignment.spec.due_at
    return due if extension is None or extension.due_at < due else extension.due_at


def granted(
    current: ExtensionRecord | None, due_at: datetime, now: datetime, *, regrade_earlier: bool
) -> ExtensionRecord:
    """An extension to `due_at` granted now. It counts for answers given from now on, as an LMS's
    does (earlier late answers keep their penalty), or for every answer when the teacher asks. Moving
    one is granting it anew: the answers given before keep the due date they were given under (the
    one it replaces, or the assignment's), so a move regrades nothing a new extension would not."""
    if regrade_earlier:
        return ExtensionRecord(due_at, None)
    if current is None:
        return ExtensionRecord(due_at, now)
    if current.due_at == due_at:
        return current
    return ExtensionRecord(due_at, now, (*current.earlier, replace(current, earlier=())))


def days_late(submitted_at: datetime, due: datetime) -> int:
    """Whole days started after the due date: a minute late is one day."""
    if submitted_at <= due:
        return 0
    return math.ceil((submitted_at - due) / DAY)


def late_factor(policy: LatePolicy, submitted_at: datetime, due: datetime) -> float | None:
    """What a submission's score is multiplied by; None when it is not accepted (closed and late)."""
    late = days_late(submitted_at, due)
    if late == 0:
        return 1.0
    if policy.kind is LateKind.CLOSED:
        return None
    return 1.0 - min(policy.limit, policy.per_day * late)


@dataclass(frozen=True)
class Counting:
    """How an assignment counts one student's answers to one problem: its late policy and due date,
    the student's extension, and when they opened the problem's worked solution. The gradebook and
    the problem page both count with it, so the page shows what the gradebook holds."""

    assignment: AssignmentRecord
    extension: ExtensionRecord | None = None
    solution_opened: datetime | None = None

    def factor(self, submitted_at: datetime) -> float | None:
        """What a graded answer's score counts for: its late factor against the due date in force when
        it was given; None when it earns nothing (late under a closed policy, or given after the
        worked solution was opened: copied, not solved)."""
        if self.solution_opened is not None and submitted_at >= self.solution_opened:
            return None
        in_force = None if self.extension is None else self.extension.in_force(submitted_at)
        due = due_for(self.assignment, in_force)
        return late_factor(self.assignment.spec.late, submitted_at, due)


def accepting(assignment: AssignmentRecord, due: datetime, now: datetime) -> bool:
    """Whether a submission now counts: open, and before the due date or with a late penalty."""
    if now < assignment.spec.opens_at:
        return False
    return now <= due or assignment.spec.late.kind is LateKind.PENALTY


def status(
    assignment: AssignmentRecord, due: datetime, now: datetime, *, started: bool, done: bool
) -> Status:
    if now < assignment.spec.opens_at:
        return Status.NOT_OPEN
    if done:
        return Status.DONE
    if now > due:
        return Status.LATE if assignment.spec.late.kind is LateKind.PENALTY else Status.CLOSED
    return Status.IN_PROGRESS if started else Status.NOT_STARTED


# When an assignment's worked solutions open, as the builder offers it and the course page lists it.
SOLUTIONS_OPEN = {
    SolutionRelease.AFTER_DUE: "After the due date",
    SolutionRelease.AFTER_LAST_ATTEMPT: "Once every part is done",
    SolutionRelease.NEVER: "Never",
    SolutionRelease.RELEASED: "Now: released",
}


def late_policy_text(policy: LatePolicy) -> str:
    """Said to students beside the due date."""
    if policy.kind is LateKind.CLOSED:
        return "No submissions are accepted after the due date."
    per_day = f"{policy.per_day * 100:g} %"
    limit = f"{policy.limit * 100:g} %"
    return f"Late work loses {per_day} of its score for each day (or part of a day) late, at most {limit}."


def solutions_released(
    assignment: AssignmentRecord, due: datetime, now: datetime, *, all_parts_done: bool
) -> tuple[bool, str]:
    """Whether a student may see the worked solutions of this assignment's problems, and why."""
    release = assignment.spec.solutions
    if release is SolutionRelease.NEVER:
        return False, "Your instructor does not release worked solutions for this assignment."
    if release is SolutionRelease.RELEASED:
        return True, "Your instructor has released the worked solutions of this assignment."
    if release is SolutionRelease.AFTER_DUE:
        if now > due:
            return True, "The assignment is past its due date, so its worked solutions are open."
        return False, f"The worked solution opens after the due date ({due:%Y-%m-%d %H:%M} UTC)."
    if all_parts_done:
        return True, "Every part is done: answered correctly or out of attempts."
    return False, "The worked solution opens once every part is done, answered correctly or out of attempts."


def shown(moment: datetime, timezone: str) -> str:
    """A date as the course reads it: in the course's zone, with the zone's abbreviation."""
    try:
        zone = ZoneInfo(timezone)
    except (ZoneInfoNotFoundError, ValueError):
        zone = ZoneInfo("UTC")
    local = moment.astimezone(zone)
    return f"{local:%a %d %b %Y, %H:%M} {local.tzname()}"
