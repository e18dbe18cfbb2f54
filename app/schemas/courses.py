"""Bodies of the course, roster, assignment and gradebook endpoints (API.md, "Courses")."""

from __future__ import annotations

from datetime import datetime
from typing import Annotated, Literal

from pydantic import AwareDatetime, BaseModel, Field, field_validator, model_validator

from problems.fields import RequestText as Text

Title = Annotated[Text, Field(min_length=1, max_length=200)]
ProblemId = Annotated[str, Field(pattern=r"^[A-Za-z0-9][A-Za-z0-9._-]{0,99}$")]


class CourseIn(BaseModel):
    title: Title
    timezone: Annotated[str, Field(max_length=64, description="IANA zone dates are shown in")] = "UTC"

    @field_validator("timezone")
    @classmethod
    def _known_zone(cls, value: str) -> str:
        from zoneinfo import ZoneInfo, ZoneInfoNotFoundError

        try:
            ZoneInfo(value)
        except (ZoneInfoNotFoundError, ValueError):
            raise ValueError(
                f"unknown time zone {value!r}; use an IANA name such as 'Europe/Paris'"
            ) from None
        return value


class CourseOut(BaseModel):
    id: int
    title: str
    timezone: str
    role: Literal["instructor", "ta", "student"]
    join_code: str | None = None  # staff only
    lti: bool = False  # made from an LMS context


class StaffIn(BaseModel):
    member: Annotated[
        str,
        Field(
            min_length=1,
            max_length=200,
            description="'key:<API key id>' for an instructor key, or an LMS user's 'lti:<platform>:<sub>'",
        ),
    ]
    role: Literal["instructor", "ta"]
    name: Annotated[Text, Field(max_length=200)] = ""


class StaffOut(BaseModel):
    member: str
    role: str
    name: str


class StudentOut(BaseModel):
    student: str = Field(description="The identity the student's submissions are filed under.")
    roster_id: str | None
    name: str
    email: str


class RosterImportOut(BaseModel):
    added: int
    updated: int
    unchanged: int


class SignInLinkOut(BaseModel):
    student: str
    name: str
    email: str
    url: str = Field(description="Personal and single-use; a new link makes the older one stop working.")
    expires_at: datetime


class JoinCodeOut(BaseModel):
    join_code: str | None
    url: str | None


class LatePolicyIn(BaseModel):
    kind: Literal["closed", "penalty"] = "closed"
    per_day: Annotated[float, Field(ge=0, le=1, description="fraction of the score lost per late day")] = 0.0
    limit: Annotated[float, Field(ge=0, le=1, description="the most lost, as a fraction")] = 1.0


class AssignmentIn(BaseModel):
    title: Title
    problems: Annotated[list[ProblemId], Field(min_length=1, max_length=100)]
    opens_at: AwareDatetime
    due_at: AwareDatetime
    late: LatePolicyIn = LatePolicyIn()
    max_attempts: Annotated[
        int | None, Field(ge=1, le=1000, description="per part; null: each problem's own")
    ] = None
    solutions: Literal["never", "after_due", "after_last_attempt", "released"] = "after_due"

    @model_validator(mode="after")
    def _consistent(self) -> AssignmentIn:
        if self.due_at < self.opens_at:
            raise ValueError("due_at is before opens_at")
        if len(set(self.problems)) != len(self.problems):
            raise ValueError("a problem appears more than once")
        return self


class AssignmentOut(AssignmentIn):
    id: int
    course_id: int
    points: int = Field(description="The number of parts: each counts one point.")


class StudentStanding(BaseModel):
    """A student's own view of an assignment (the instructor's fields are not shown)."""

    id: int
    course_id: int
    title: str
    problems: list[str]
    opens_at: datetime
    due_at: datetime = Field(description="This student's due date: their extension when they have one.")
    late: LatePolicyIn
    status: Literal["not open", "not started", "in progress", "done", "late", "closed"]
    score: float
    points: int
    late_penalty_applied: bool


class ExtensionIn(BaseModel):
    due_at: AwareDatetime
    # An extension counts for the answers given from when it is granted: earlier late answers keep
    # their penalty unless the teacher asks to regrade them too.
    regrade_earlier: bool = False


class ExtensionOut(BaseModel):
    student: str
    due_at: datetime
    granted_at: datetime | None = None  # null: it covers answers given before it was granted too


class PartScoreOut(BaseModel):
    problem: str
    part: str
    score: float
    late: bool
    attempts: int
    solution_opened_at: datetime | None = None


class GradeCellOut(BaseModel):
    assignment: int
    score: float
    points: int
    late: bool = Field(description="A late penalty was applied to the score.")
    status: str
    due_at: datetime
    extended: bool
    attempted: bool = Field(description="Some part was answered and graded: a score of 0 was earned.")
    solution_opened: bool = Field(
        description="The student opened a worked solution: no credit on its parts after."
    )
    parts: list[PartScoreOut]


class GradebookRowOut(BaseModel):
    student: StudentOut
    total: float
    points: int
    assignments: list[GradeCellOut]


class GradebookOut(BaseModel):
    course: int
    assignments: list[AssignmentOut]
    students: list[GradebookRowOut]


class ShareIn(BaseModel):
    shared: bool
