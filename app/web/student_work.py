"""A student's standing on one problem, read from the database: per part the attempts used of the
limit, the best score (what the LMS holds: a later wrong attempt never lowers it), and the history of
submissions, newest first; for the problem, the sum of the parts' best scores."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from datetime import datetime
from typing import Any

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


@dataclass
class PartWork:
    used: int = 0
    limit: int | None = None
    best: float | None = None  # None: no graded attempt yet
    history: list[Attempt] = field(default_factory=list)  # newest first
    frozen_at: datetime | None = None  # the worked solution was opened then: later answers earn nothing

    @property
    def locked(self) -> bool:
        return self.limit is not None and self.used >= self.limit

    @property
    def solved(self) -> bool:
        return self.best is not None and self.best >= 1.0

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


def shown_feedback(verdict: Outcome, feedback: str) -> str:
    """The feedback as the page shows it after its own word for the verdict: without the "Correct."
    that word already says, whether it ends the feedback (after a settled reading's note: "Read as …: the only
    reading … Correct.") or starts it (before a unit's note: "Correct. Hz is the unit …")."""
    if verdict is Outcome.CORRECT:  # leading ("Correct. Hz is the unit …") or trailing
        return feedback.strip().removeprefix("Correct.").strip().removesuffix("Correct.").strip()
    return feedback


def _attempt(record: SubmissionRecord) -> Attempt:
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
    frozen_at: datetime | None = None,
) -> ProblemWork:
    """The student's work on the parts of `parts` (the student view's parts, with `max_attempts`);
    answers from `frozen_at` on (the worked solution opened) are shown but do not count."""
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
        part.history.insert(0, _attempt(record))
        if record.verdict != Outcome.INVALID and (frozen_at is None or record.created_at < frozen_at):
            part.best = max(part.best or 0.0, record.score)
    for part_id, part in work.items():
        part.used = store.attempts_used(problem_id, part_id, student)
    return ProblemWork(work)
