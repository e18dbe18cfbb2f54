"""Who may see what, in one place.

- A course is seen only by its staff (instructors and TAs); to anyone else it does not exist (404).
  Its TAs see it but may not change it: what only its instructors may do is refused them (403).
- A student enrolled in any course sees only the problems of their courses' open assignments; a
  student in no course (an API key, or an LMS link to one problem) keeps the per-problem access they
  had before courses.
- An instructor never reaches a student enrolled only in courses they do not teach.
- An upload belongs to its author's courses: its author and their co-staff use it, every instructor
  once it is shared to the bank; built-in problems are everyone's.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from datetime import datetime
from typing import Any

from app.auth import Principal
from app.courses.policy import accepting, due_for
from app.courses.records import (
    AssignmentRecord,
    CourseNotFound,
    CourseRecord,
    EnrolmentRecord,
    ExtensionRecord,
    StaffRole,
)
from app.db.records import ProblemRecord
from app.errors import Forbidden
from app.storage import Stores
from app.storage.protocols import CourseStore


class InstructorsOnly(Forbidden):
    """A teaching assistant asking for what only the course's instructors may do: they see the course,
    so it is not hidden from them as one they do not teach."""

    def __init__(self, course_id: int, action: str) -> None:
        super().__init__(f"Only the course's instructors may {action}; you are its teaching assistant.")
        self.course_id = course_id
        self.action = action


def course_role(stores: Stores, principal: Principal, course_id: int) -> StaffRole | None:
    member = principal.member
    if member is None or not principal.is_instructor:
        return None
    return next(
        (role for course, role in stores.courses.courses_taught(member) if course.id == course_id), None
    )


def require_staff(
    stores: Stores, principal: Principal, course_id: int, *, only_instructors_may: str = ""
) -> CourseRecord:
    """The course when the caller teaches it, else CourseNotFound; with `only_instructors_may` (what
    the caller asks to do, "import its roster"), InstructorsOnly for its teaching assistants."""
    role = course_role(stores, principal, course_id)
    if role is None:
        raise CourseNotFound(course_id)
    if only_instructors_may and role is not StaffRole.INSTRUCTOR:
        raise InstructorsOnly(course_id, only_instructors_may)
    return stores.courses.get_course(course_id)


def taught_courses(stores: Stores, principal: Principal) -> list[tuple[CourseRecord, StaffRole]]:
    member = principal.member
    return [] if member is None or not principal.is_instructor else stores.courses.courses_taught(member)


def student_assignments(stores: Stores, student: str) -> list[tuple[CourseRecord, AssignmentRecord]]:
    return [
        (c, a) for c in stores.courses.courses_enrolled(student) for a in stores.courses.assignments(c.id)
    ]


def assigned_problems(stores: Stores, student: str, now: datetime) -> set[str] | None:
    """The problems a student may open: those of their courses' open assignments; None (no limit)
    for a student in no course."""
    courses = stores.courses.courses_enrolled(student)
    if not courses:
        return None
    # (A problem launched by its own LMS link is opened too, `opening` says; lists show assignments'.)
    return {
        problem
        for course in courses
        for assignment in stores.courses.assignments(course.id)
        if assignment.spec.opens_at <= now
        for problem in assignment.problems
    }


def may_open_problem(stores: Stores, principal: Principal, problem_id: str, now: datetime) -> bool:
    """A student's own view of a problem (instructors decide through `may_use_problem`)."""
    if principal.student is None:
        return True
    allowed = assigned_problems(stores, principal.student, now)
    return allowed is None or problem_id in allowed


def may_reach_student(stores: Stores, principal: Principal, student: str) -> bool:
    """An instructor's key naming a student: fine for a student in no course, else only for one
    enrolled in a course the caller teaches."""
    courses = stores.courses.courses_enrolled(student)
    if not courses:
        return True
    taught = {course.id for course, _ in taught_courses(stores, principal)}
    return any(course.id in taught for course in courses)


def students_taught(stores: Stores, principal: Principal) -> dict[str, EnrolmentRecord]:
    """The students of the courses the caller teaches, by the identity their work is filed under
    (`course:3:join-…` means nothing to the instructor reading it: their name and email do)."""
    return {
        enrolment.student: enrolment
        for course, _ in taught_courses(stores, principal)
        for enrolment in stores.courses.roster(course.id)
    }


def enrolled_anywhere(courses: CourseStore) -> Callable[[str], EnrolmentRecord | None]:
    """Who an identity is, from the roster of the first course enrolling it: the command line's
    export, whose operator reads every course, names students as an instructor's pages name theirs.
    Looked up once per identity."""
    found: dict[str, EnrolmentRecord | None] = {}

    def person(student: str) -> EnrolmentRecord | None:
        if student not in found:
            enrolments = (courses.enrolment(c.id, student) for c in courses.courses_enrolled(student))
            found[student] = next((e for e in enrolments if e is not None), None)
        return found[student]

    return person


def colleagues(stores: Stores, principal: Principal) -> set[int]:
    """Key ids of the caller and of every API-key colleague on the staff of a course they teach."""
    ids = {int(principal.key_id)} if principal.api_key and principal.key_id.isdigit() else set()
    for course, _ in taught_courses(stores, principal):
        for member in stores.courses.staff(course.id):
            if member.member.startswith("key:") and member.member[4:].isdigit():
                ids.add(int(member.member[4:]))
    return ids


def may_use_problem(
    record: ProblemRecord, principal: Principal, colleague_ids: set[int], shared: set[str]
) -> bool:
    """Whether an instructor may list, assign, or read the solution of this problem."""
    return record.builtin or record.id in shared or record.owner_key_id in colleague_ids


@dataclass(frozen=True)
class Opening:
    """Whether a student's answer to a problem counts now, and under which assignment."""

    assignment: AssignmentRecord | None  # None: the student is in no course (no assignment rules)
    course: CourseRecord | None
    accepting: bool
    due: datetime | None
    why: str = ""
    extension: ExtensionRecord | None = None  # the student's, which counts from when it was granted

    def attempts_in(self, view: Mapping[str, Any]) -> Mapping[str, Any]:
        """A student's view of the problem with each part's attempts as this assignment allows them
        (its `max_attempts` is over each problem's own), so that the page and the API tell the
        student the limit their submissions are held to."""
        limit = None if self.assignment is None else self.assignment.spec.max_attempts
        if limit is None:
            return view
        return {**view, "parts": [{**part, "max_attempts": limit} for part in view.get("parts", [])]}


def opening(
    stores: Stores, student: str, problem_id: str, now: datetime, course_id: int | None = None
) -> Opening | None:
    """None when the problem is not in any of the student's open assignments (it does not exist for
    them); else the assignment that takes the answer: the first accepting one by due date, or the
    latest due when none accepts. With `course_id`, only that course's assignments: the course the
    student is working in (a problem in two courses had its answers filed under the first)."""
    courses = stores.courses.courses_enrolled(student)
    if not courses:
        return None if course_id is not None else Opening(None, None, True, None)
    if course_id is not None:
        courses = [course for course in courses if course.id == course_id]
    found: list[tuple[CourseRecord, AssignmentRecord, ExtensionRecord | None]] = []
    for course in courses:
        for assignment in stores.courses.assignments(course.id):
            if problem_id in assignment.problems and assignment.spec.opens_at <= now:
                found.append((course, assignment, stores.courses.extensions(assignment.id).get(student)))
    if not found:
        # A problem the student was launched into by its own LMS link (graded there) stays theirs.
        launched = course_id is None and stores.outbox.launched(student, problem_id)
        return Opening(None, None, True, None) if launched else None
    for course, assignment, extension in found:
        due = due_for(assignment, extension)
        if accepting(assignment, due, now):
            return Opening(assignment, course, True, due, extension=extension)
    course, assignment, extension = found[-1]
    return Opening(
        assignment,
        course,
        False,
        due_for(assignment, extension),
        f"{assignment.title!r} closed at its due date; answers are no longer accepted.",
        extension,
    )
