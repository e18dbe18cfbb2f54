"""Request and response bodies of `POST /v1/check` (API.md).

A check is a one-part problem given in the request: each kind's body (`problems.kinds`) uses the
declarations a problem document does (symbols, mistakes, tolerance, choices, numbers read by the one
decimal reader) and is compiled by its kind's own compile, as a part of a problem is.
"""

from __future__ import annotations

from collections import OrderedDict
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


class VerdictJson:
    """A verdict's response body, rendered once per verdict object and kept for the most recent
    `size`: the verdict cache hands back the same object for an identical check, so a repeated check
    is answered with bytes already made (validated and serialized once, by VerdictPublic)."""

    def __init__(self, size: int = 4096):
        self._size = size
        # id -> (verdict, body): holding the verdict keeps its id from being reused by another object
        self._rendered: OrderedDict[int, tuple[Verdict, bytes]] = OrderedDict()

    def __call__(self, verdict: Verdict) -> bytes:
        known = self._rendered.get(id(verdict))
        if known is not None and known[0] is verdict:
            self._rendered.move_to_end(id(verdict))
            return known[1]
        body = VerdictPublic.of(verdict).model_dump_json().encode()
        self._rendered[id(verdict)] = (verdict, body)
        while len(self._rendered) > self._size:
            self._rendered.popitem(last=False)
        return body
