"""Small builders shared by the storage tests."""

from __future__ import annotations

from datetime import UTC, datetime, timedelta

from sqlalchemy.orm import Session

from app.db.problems import save_builtin
from physics.verdict import InputProblem, Outcome, ReadAs, Reason, Verdict

PROBLEM = "moving-wedge"
PART = "wedge_acceleration"
DOCUMENT = {"id": PROBLEM, "title": "Block on a moving wedge", "parts": [{"id": PART, "kind": "symbolic"}]}

CORRECT = Verdict(Outcome.CORRECT, 1.0, Reason.EQUIVALENT, "Right.", ReadAs("m*g", "m g"))
INCORRECT = Verdict(Outcome.INCORRECT, 0.0, Reason.SIGN_ERROR, "Check the sign.", ReadAs("-m*g", "- m g"))
INVALID = Verdict(
    Outcome.INVALID, 0.0, Reason.PARSE_ERROR, "Unexpected ')'", None, InputProblem("Unexpected ')'", 3)
)


def store_problem(session: Session, problem_id: str = PROBLEM) -> int:
    """A built-in problem to submit against; returns its version."""
    return save_builtin(session, problem_id, {**DOCUMENT, "id": problem_id}).version


class StepClock:
    """A clock that moves one millisecond per reading, from a fixed start."""

    def __init__(self, start: datetime = datetime(2026, 1, 1, tzinfo=UTC)) -> None:
        self.now = start

    def __call__(self) -> datetime:
        self.now += timedelta(milliseconds=1)
        return self.now
