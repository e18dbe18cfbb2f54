"""A student's standing on one problem, read from the database: per part the attempts used of the
limit, the best score (what the LMS and the gradebook hold: a later wrong attempt never lowers it, a
late one counts with its penalty), and the history of submissions, newest first; for the problem, the
sum of the parts' best scores."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from datetime import datetime
from typing import Any

from app.courses.policy import Counting
from app.db.records import SubmissionRecord
from app.storage import SubmissionStore
from physics.verdict import Outcome

MAX_PAGES = 5  # 5 000 submissions by one student to one problem: more than anyone needs shown
PAGE = 1000


@dataclass(frozen=True)
class Attempt:
    answer: str
    verdict: str
    score: float
    feedback: str
    error: str
    number: int | None  # the graded attempt's number; None for an unreadable answer (no attempt used)
    created_at: datetime
    latex: str | None  # how the answer was read, to typeset it
    late_factor: float = 1.0  # what a late answer's score counted for (0.9: a 10 % penalty)


@dataclass
class PartWork:
    used: int = 0
    limit: int | None = None
    best: float | None = None  # None: no graded attempt yet; else its score as counted (penalty applied)
    history: list[Attempt] = field(default_factory=list)  # newest first
    frozen_at: datetime | None = None  # the worked solution was opened then: later answers earn nothing
    late_factor: float = 1.0  # the best attempt was late: its score counted for this much
    correct: bool = False  # a counted answer was right (late, its best is under 1)

    @property
    def locked(self) -> bool:
        return self.limit is not None and self.used >= self.limit

    @property
    def solved(self) -> bool:
        return self.correct or (self.best is not None and self.best >= 1.0)

    @property
    def earned_in_full(self) -> bool:
        """Its whole point is counted. A part solved late (a penalty taken) is not: reading the worked
        solution is asked about for it as for an open part, since answers still count there."""
        return self.best is not None and self.best >= 1.0

    @property
    def late_penalty(self) -> float:
        """The share of the best attempt's score its lateness cost (0.1 for 10 %)."""
        return round(1.0 - self.late_factor, 6)

    @property
    def last_answer(self) -> str:
        return self.history[0].answer if self.history else ""


@dataclass
class ProblemWork:
    parts: dict[str, PartWork]

    @property
    def score(self) -> float:
        return sum(work.best or 0.0 for work in self.parts.values())

    @property
    def maximum(self) -> int:
        return len(self.parts)

    @property
    def attempted(self) -> bool:
        return any(work.history for work in self.parts.values())

    @property
    def late(self) -> bool:
        """A part's best attempt lost points for being late."""
        return any(work.late_penalty > 0 for work in self.parts.values())


def shown_feedback(verdict: Outcome, feedback: str) -> str:
    """The feedback as the page shows it after its own word for the verdict: without the "Correct."
    that word already says, whether it ends the feedback (after a settled reading's note: "Read as …: the only
    reading … Correct.") or starts it (before a unit's note: "Correct. Hz is the unit …")."""
    if verdict is Outcome.CORRECT:  # leading ("Correct. Hz is the unit …") or trailing
        return feedback.strip().removeprefix("Correct.").strip().removesuffix("Correct.").strip()
    return feedback


def _attempt(record: SubmissionRecord, factor: float | None) -> Attempt:
    invalid = record.verdict == Outcome.INVALID
    return Attempt(
        answer=record.answer,
        verdict=record.verdict.value,
        score=record.score,
        feedback="" if invalid else shown_feedback(record.verdict, record.feedback),
        error=record.feedback if invalid else "",
        number=record.attempt,
        created_at=record.created_at,
        latex=record.read_as.latex if record.read_as else None,
        late_factor=1.0 if invalid or factor is None else factor,
    )


def _submissions(store: SubmissionStore, problem_id: str, student: str) -> list[SubmissionRecord]:
    items: list[SubmissionRecord] = []
    cursor = None
    for _ in range(MAX_PAGES):
        page = store.page(problem_id=problem_id, student=student, limit=PAGE, cursor=cursor)
        items.extend(page.items)
        cursor = page.next
        if cursor is None:
            break
    return items


def load_work(
    store: SubmissionStore,
    problem_id: str,
    student: str,
    parts: Sequence[Mapping[str, Any]],
    counting: Counting | None = None,
) -> ProblemWork:
    """The student's work on the parts of `parts` (the student view's parts, with `max_attempts`),
    counted as the assignment `counting` counts it (late penalties; answers after the worked solution
    was opened are shown but earn nothing); without one every graded answer counts in full."""
    frozen_at = None if counting is None else counting.solution_opened
    work = {
        str(part["id"]): PartWork(
            limit=part.get("max_attempts") if part.get("max_attempts") else None, frozen_at=frozen_at
        )
        for part in parts
    }
    for record in _submissions(store, problem_id, student):
        part = work.get(record.part_id)
        if part is None:  # a part a later version dropped
            continue
        factor = 1.0 if counting is None else counting.factor(record.created_at)
        part.history.insert(0, _attempt(record, factor))
        if record.verdict == Outcome.INVALID or factor is None:
            continue
        counted = round(record.score * factor, 6)  # as the gradebook rounds it
        if part.best is None or counted > part.best:
            part.best, part.late_factor = counted, factor
        part.correct = part.correct or record.verdict == Outcome.CORRECT
    for part_id, part in work.items():
        part.used = store.attempts_used(problem_id, part_id, student)
    return ProblemWork(work)
