"""Bodies of the problem and submission endpoints (API.md, "Problems and submissions")."""

from __future__ import annotations

import uuid
from datetime import datetime
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from app.schemas.check import InputErrorPublic, ReadAsPublic, VerdictPublic
from problems.fields import RequestText as Text

StudentId = Annotated[Text, Field(min_length=1, max_length=200)]


class PartSummary(BaseModel):
    id: str
    kind: str
    prompt: str


class ProblemSummary(BaseModel):
    id: str
    title: str
    topics: list[str]
    parts: list[PartSummary]
    version: int
    builtin: bool


class GivenValue(BaseModel):
    value: int | float
    unit: str
    text: str


class ChoicePublic(BaseModel):
    label: str  # "A", "B", …: what the student answers with
    text: str


class PartPublic(BaseModel):
    # A kind's own fields pass through as its student view gives them (a Lagrangian part's
    # `coordinates`, an equation's `unknowns` and `asks`, a lab's `data`: README, "The API").
    model_config = ConfigDict(extra="allow")

    id: str
    kind: str
    prompt: str
    units: str | None
    symbols: list[str]
    max_attempts: int | None = None  # graded attempts allowed; None: unlimited
    tolerance: dict[str, float | int] | None = None  # numeric parts: how close counts as right
    choices: list[ChoicePublic] | None = None  # choice parts: what to pick from, answered by label


class ProblemPublic(BaseModel):
    """One student's variant; never a reference answer."""

    id: str
    title: str
    statement: str
    given: dict[str, GivenValue]
    symbols: dict[str, dict[str, Any]]
    parts: list[PartPublic]
    version: int
    student: str


class SubmissionIn(BaseModel):
    # extra="forbid": a client may not send `score`, `correct`, `verdict` or anything else of ours.
    model_config = ConfigDict(extra="forbid")

    answer: Text
    student: StudentId | None = None


class PreviewIn(BaseModel):
    model_config = ConfigDict(extra="forbid")

    answer: Text


class PreviewPublic(BaseModel):
    read_as: ReadAsPublic | None
    error: InputErrorPublic | None
    # The reading typeset as MathML (from read_as.latex, made on the server) for the student page.
    mathml: str | None = None


class SubmissionResult(VerdictPublic):
    submission_id: uuid.UUID
    attempts_used: int
    max_attempts: int | None


class SubmissionPublic(BaseModel):
    submission_id: uuid.UUID
    problem: str
    part: str
    student: str
    answer: str
    verdict: str
    score: float
    reason: str
    feedback: str
    created_at: datetime
    problem_version: int


class SubmissionPage(BaseModel):
    items: list[SubmissionPublic]
    next: str | None


class ProblemCreated(BaseModel):
    id: str
    version: int


class ReferencePublic(BaseModel):
    part: str
    kind: str
    text: str
    latex: str
    units: str | None = None
    # "derived": the engine derived it by two methods and a simulation; "not derived": the author's typed
    # answer, which nothing checked
    source: Literal["derived", "not derived"] = "derived"


class StepPublic(BaseModel):
    title: str
    latex: str


class MethodPublic(BaseModel):
    name: str
    title: str
    steps: list[StepPublic]
    notes: list[str]


class SimulationPublic(BaseModel):
    compared: str
    max_relative_error: float
    points: int


class SolutionPublic(BaseModel):
    """Instructor-only: every part's reference and how the engine derived and verified it."""

    id: str
    version: int
    references: list[ReferencePublic]
    methods: list[MethodPublic]
    agreement: dict[str, list[str]]
    proofs: dict[str, str]
    simulation: dict[str, SimulationPublic]
    methods_agree: bool
    # checks of the model itself beside method agreement (energy bookkeeping, limiting cases, dimensions)
    checks: dict[str, str] = {}


class CountPublic(BaseModel):
    key: str  # a reason (`sign_error`) or a known mistake's feedback
    submissions: int
    students: int


class FindingPublic(BaseModel):
    finding: str  # as the students were told it, e.g. "A normal force (N₁) is missing."
    students: int  # students told it at least once
    submissions: int


class PartResultsPublic(BaseModel):
    part: str
    kind: str
    tried: int  # students with any submission
    correct: int  # students with a correct one
    graded: int  # graded submissions
    previews: int  # instructors' own tries, counted nowhere else
    wrong_reasons: list[CountPublic]
    mistakes: list[CountPublic]
    # for kinds whose feedback names findings (free_body, lagrangian, kinetic_energy, potential_energy),
    # the most students first; null for the others
    findings: list[FindingPublic] | None


class ResultsPublic(BaseModel):
    """Instructor-only: how the class did on each part of a problem (students' work on every version)."""

    id: str
    parts: list[PartResultsPublic]
