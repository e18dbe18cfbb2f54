"""The result of checking one answer: graded (correct/incorrect) or invalid, never both."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

from physics.errors import AnswerError


class Outcome(StrEnum):
    CORRECT = "correct"
    INCORRECT = "incorrect"
    INVALID = "invalid"


class Reason(StrEnum):
    EQUIVALENT = "equivalent"
    WRONG_VALUE = "wrong_value"
    SIGN_ERROR = "sign_error"
    CONSTANT_FACTOR = "constant_factor"
    WRONG_DIMENSION = "wrong_dimension"
    KNOWN_MISTAKE = "known_mistake"
    PARSE_ERROR = "parse_error"
    AMBIGUOUS = "ambiguous"
    UNKNOWN_SYMBOL = "unknown_symbol"
    UNKNOWN_FUNCTION = "unknown_function"
    TOO_LARGE = "too_large"
    TIMEOUT = "timeout"
    MISSING_UNITS = "missing_units"
    UNEXPECTED_UNITS = "unexpected_units"
    UNKNOWN_UNIT = "unknown_unit"
    SIGFIGS = "sigfigs"


@dataclass(frozen=True)
class ReadAs:
    """How the answer was understood, rendered from the parsed tree."""

    text: str
    latex: str
    note: str | None = None  # how one of several readings was chosen (by the expected dimension)

    def __reduce__(self) -> tuple[object, tuple[object, ...]]:
        return ReadAs, (self.text, self.latex, self.note)  # pickled with each verdict: plain values


@dataclass(frozen=True)
class InputProblem:
    message: str
    position: int | None = None


@dataclass(frozen=True)
class Preview:
    """How an answer reads, before it is submitted: never a verdict, never a hint of correctness."""

    read_as: ReadAs | None
    error: InputProblem | None


@dataclass(frozen=True)
class Judgement:
    """A graded decision before it is wrapped into a verdict: which reason and what to tell the student."""

    correct: bool
    reason: Reason
    feedback: str


@dataclass(frozen=True)
class Verdict:
    outcome: Outcome
    score: float
    reason: Reason
    feedback: str
    read_as: ReadAs | None = None
    error: InputProblem | None = None

    @classmethod
    def graded(cls, judgement: Judgement, read_as: ReadAs | None) -> Verdict:
        if judgement.correct:
            return cls(Outcome.CORRECT, 1.0, judgement.reason, judgement.feedback, read_as)
        return cls(Outcome.INCORRECT, 0.0, judgement.reason, judgement.feedback, read_as)

    @classmethod
    def invalid(cls, error: AnswerError, read_as: ReadAs | None = None) -> Verdict:
        return cls(
            Outcome.INVALID,
            0.0,
            Reason(error.reason),
            error.message,
            read_as,
            InputProblem(error.message, error.position),
        )

    def __reduce__(self) -> tuple[object, tuple[object, ...]]:
        # Every verdict crosses from a worker to the server in a pickle: as plain values (the enums by
        # their value, read back from a table) it is made and read in a third of the default's time.
        return _verdict, (
            self.outcome.value,
            self.score,
            self.reason.value,
            self.feedback,
            self.read_as,
            self.error,
        )


_OUTCOMES = {outcome.value: outcome for outcome in Outcome}
_REASONS = {reason.value: reason for reason in Reason}


def _verdict(
    outcome: str, score: float, reason: str, feedback: str, read_as: ReadAs | None, error: InputProblem | None
) -> Verdict:
    """A pickled verdict read back (Verdict.__reduce__)."""
    return Verdict(_OUTCOMES[outcome], score, _REASONS[reason], feedback, read_as, error)
