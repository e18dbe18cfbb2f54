"""Request and response bodies of `POST /v1/check` (API.md).

A check is a one-part problem given in the request: each kind's body (`problems.kinds`) uses the
declarations a problem document does (symbols, mistakes, tolerance, choices, numbers read by the one
decimal reader) and builds the job its parts compile to.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict

from physics.verdict import Verdict
from problems import kinds

# Each kind's body is defined by its module (problems/kinds/), registered there; one union, by `kind`.
CheckIn = kinds.CheckIn


class ReadAsPublic(BaseModel):
    model_config = ConfigDict(from_attributes=True)  # built straight from physics.verdict.ReadAs

    text: str
    latex: str
    # Set when the expected dimension chose between readings (`mv/qB` as m·v/(q·B)); shown to students.
    note: str | None = None


class InputErrorPublic(BaseModel):
    model_config = ConfigDict(from_attributes=True)  # built straight from physics.verdict.InputProblem

    message: str
    position: int | None


class VerdictPublic(BaseModel):
    verdict: Literal["correct", "incorrect", "invalid"]
    score: float
    reason: str
    feedback: str
    read_as: ReadAsPublic | None
    error: InputErrorPublic | None

    @classmethod
    def of(cls, verdict: Verdict) -> VerdictPublic:
        return cls(
            verdict=verdict.outcome.value,
            score=verdict.score,
            reason=verdict.reason.value,
            feedback=verdict.feedback,
            read_as=verdict.read_as,
            error=verdict.error,
        )
