"""How a class did on one problem, per part, counted in the database from the submissions log.

Students' work only: an instructor's own tries are filed under `preview:<key or session>` identities
and are counted apart (`previews`), so that they never move a class's numbers.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from statistics import median

from sqlalchemy import ColumnElement, case, distinct, func, select
from sqlalchemy.orm import Session

from app.db.models import Submission

PREVIEW_PREFIX = "preview:"
WRONG_ANSWERS_SHOWN = 8


@dataclass(frozen=True)
class Count:
    """One group of submissions: how many, and from how many students."""

    key: str
    submissions: int
    students: int


@dataclass(frozen=True)
class WrongAnswer:
    answer: str  # as the server read it (so `m g` and `m*g` are one answer), else as typed
    latex: str | None  # the reading as TeX, when the answer was read
    reason: str
    submissions: int
    students: int


@dataclass(frozen=True)
class StudentFeedback:
    """What one student was told for their incorrect answers (the same words, however many times)."""

    student: str
    feedback: str
    submissions: int


@dataclass(frozen=True)
class PartResults:
    part_id: str
    tried: int = 0  # students with any submission, readable or not
    correct: int = 0  # students with at least one correct answer
    graded: int = 0  # graded submissions (correct or incorrect; `invalid` uses no attempt)
    # attempts used up to and including the first correct one -> how many students
    first_correct: Mapping[int, int] = field(default_factory=dict)
    wrong_reasons: Sequence[Count] = ()  # incorrect submissions by reason, most common first
    invalid_reasons: Sequence[Count] = ()  # unreadable ones by reason
    mistakes: Sequence[Count] = ()  # known_mistake submissions by the mistake's feedback
    wrong_answers: Sequence[WrongAnswer] = ()  # the most common incorrect answers
    previews: int = 0  # instructors' own submissions, not counted above
    # incorrect submissions by student and feedback, which a kind reads its findings from
    wrong_feedback: Sequence[StudentFeedback] = ()

    @property
    def percent_correct(self) -> float | None:
        return None if self.tried == 0 else 100.0 * self.correct / self.tried

    @property
    def median_attempts(self) -> float | None:
        values = [attempts for attempts, n in self.first_correct.items() for _ in range(n)]
        return None if not values else float(median(values))


def _students_only() -> ColumnElement[bool]:
    return ~Submission.student.startswith(PREVIEW_PREFIX, autoescape=True)


def _counts(rows: Sequence[tuple[str, str, int, int]]) -> dict[str, list[Count]]:
    grouped: dict[str, list[Count]] = defaultdict(list)
    for part_id, key, submissions, students in rows:
        grouped[part_id].append(Count(key, int(submissions), int(students)))
    for items in grouped.values():
        items.sort(key=lambda c: (-c.submissions, c.key))
    return grouped


def class_results(session: Session, problem_id: str, part_ids: Sequence[str]) -> list[PartResults]:
    """Results for each of `part_ids` (in that order; parts of older versions that nobody asked for are
    left out), over every version of the problem."""
    of_problem = Submission.problem_id == problem_id
    students = _students_only()
    per_part = session.execute(
        select(
            Submission.part_id,
            func.count(distinct(Submission.student)),
            func.count(distinct(case((Submission.verdict == "correct", Submission.student)))),
            func.count(Submission.attempt),
        )
        .where(of_problem, students)
        .group_by(Submission.part_id)
    ).all()
    first = session.execute(
        select(Submission.part_id, Submission.student, func.min(Submission.attempt))
        .where(of_problem, students, Submission.verdict == "correct")
        .group_by(Submission.part_id, Submission.student)
    ).all()
    by_reason = session.execute(
        select(
            Submission.part_id,
            Submission.verdict,
            Submission.reason,
            func.count(),
            func.count(distinct(Submission.student)),
        )
        .where(of_problem, students, Submission.verdict != "correct")
        .group_by(Submission.part_id, Submission.verdict, Submission.reason)
    ).all()
    by_mistake = session.execute(
        select(
            Submission.part_id,
            Submission.feedback,
            func.count(),
            func.count(distinct(Submission.student)),
        )
        .where(of_problem, students, Submission.reason == "known_mistake")
        .group_by(Submission.part_id, Submission.feedback)
    ).all()
    shown = func.coalesce(Submission.read_as_text, Submission.answer)
    wrong = session.execute(
        select(
            Submission.part_id,
            shown,
            Submission.reason,
            func.count(),
            func.count(distinct(Submission.student)),
            func.max(Submission.read_as_latex),
        )
        .where(of_problem, students, Submission.verdict == "incorrect")
        .group_by(Submission.part_id, shown, Submission.reason)
    ).all()
    told = session.execute(
        select(Submission.part_id, Submission.student, Submission.feedback, func.count())
        .where(of_problem, students, Submission.verdict == "incorrect")
        .group_by(Submission.part_id, Submission.student, Submission.feedback)
    ).all()
    previews = session.execute(
        select(Submission.part_id, func.count()).where(of_problem, ~students).group_by(Submission.part_id)
    ).all()

    totals = {row[0]: row[1:] for row in per_part}
    firsts: dict[str, Counter[int]] = defaultdict(Counter)
    for part_id, _, attempt in first:
        if attempt is not None:  # a correct verdict always used an attempt
            firsts[part_id][int(attempt)] += 1
    wrong_reasons = _counts([(p, r, n, s) for p, v, r, n, s in by_reason if v == "incorrect"])
    invalid_reasons = _counts([(p, r, n, s) for p, v, r, n, s in by_reason if v == "invalid"])
    mistakes = _counts([(p, f, n, s) for p, f, n, s in by_mistake])
    answers: dict[str, list[WrongAnswer]] = defaultdict(list)
    for part_id, answer, reason, n, s, latex in wrong:
        answers[part_id].append(WrongAnswer(answer, latex or None, reason, int(n), int(s)))
    preview_counts = {part_id: int(n) for part_id, n in previews}
    feedback: dict[str, list[StudentFeedback]] = defaultdict(list)
    for part_id, student, said, n in told:
        feedback[part_id].append(StudentFeedback(student, said, int(n)))

    results = []
    for part_id in part_ids:
        tried, correct, graded = totals.get(part_id, (0, 0, 0))
        common = sorted(answers.get(part_id, []), key=lambda a: (-a.submissions, a.answer))
        results.append(
            PartResults(
                part_id=part_id,
                tried=int(tried),
                correct=int(correct),
                graded=int(graded),
                first_correct=dict(sorted(firsts.get(part_id, Counter()).items())),
                wrong_reasons=wrong_reasons.get(part_id, []),
                invalid_reasons=invalid_reasons.get(part_id, []),
                mistakes=mistakes.get(part_id, []),
                wrong_answers=common[:WRONG_ANSWERS_SHOWN],
                previews=preview_counts.get(part_id, 0),
                wrong_feedback=feedback.get(part_id, []),
            )
        )
    return results
