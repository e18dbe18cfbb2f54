"""The in-memory course store: the same contract as `sql_courses` (tests/storage runs both), one
lock standing in for a transaction."""

from __future__ import annotations

import threading
from collections.abc import Callable, Sequence
from dataclasses import replace
from datetime import UTC, datetime

from app.courses import passback
from app.courses.records import (
    AssignmentNotFound,
    AssignmentRecord,
    AssignmentSpec,
    CourseNotFound,
    CourseRecord,
    CourseSession,
    EnrolmentRecord,
    ExtensionRecord,
    JoinCodeTaken,
    RosterImport,
    RosterRow,
    StaffRecord,
    StaffRole,
    roster_identity,
)
from app.db.errors import NotFound
from app.db.records import SubmissionRecord
from app.db.types import utc_now
from app.storage.memory import MemoryProblemStore, MemoryScoreOutbox
from physics.verdict import Outcome as Verdicts

Clock = Callable[[], datetime]


def _utc(spec: AssignmentSpec) -> AssignmentSpec:
    """As the database gives dates back: in UTC, whatever zone they came in."""
    return replace(spec, opens_at=spec.opens_at.astimezone(UTC), due_at=spec.due_at.astimezone(UTC))


class MemoryCourseStore:
    def __init__(self, clock: Clock = utc_now) -> None:
        self._clock = clock
        self._lock = threading.Lock()
        self._courses: dict[int, CourseRecord] = {}
        self._staff: dict[tuple[int, str], StaffRecord] = {}
        self._enrolments: dict[tuple[int, str], EnrolmentRecord] = {}
        self._tokens: dict[str, tuple[int, str, datetime, datetime | None, bool]] = {}  # + reusable
        self._sessions: dict[str, CourseSession] = {}
        self._assignments: dict[int, AssignmentRecord] = {}
        self._extensions: dict[tuple[int, str], ExtensionRecord] = {}
        self._shared: set[str] = set()
        self._solution_views: dict[tuple[str, str], datetime] = {}  # (student, problem)
        self._next_assignment = 1

    def create_course(
        self,
        title: str,
        *,
        owner: str,
        owner_name: str = "",
        timezone: str = "UTC",
        lti_context: tuple[int, str] | None = None,
    ) -> CourseRecord:
        with self._lock:
            if lti_context is not None:
                for course in self._courses.values():
                    if (course.lti_platform_id, course.lti_context_id) == lti_context:
                        return course
            course = CourseRecord(
                id=len(self._courses) + 1,
                title=title,
                timezone=timezone,
                join_code=None,
                lti_platform_id=None if lti_context is None else lti_context[0],
                lti_context_id=None if lti_context is None else lti_context[1],
                created_at=self._clock(),
            )
            self._courses[course.id] = course
            self._staff[(course.id, owner)] = StaffRecord(course.id, owner, StaffRole.INSTRUCTOR, owner_name)
            return course

    def get_course(self, course_id: int) -> CourseRecord:
        with self._lock:
            return self._course(course_id)

    def _course(self, course_id: int) -> CourseRecord:
        if course_id not in self._courses:
            raise CourseNotFound(course_id)
        return self._courses[course_id]

    def course_for_context(self, platform_id: int, context_id: str) -> CourseRecord | None:
        with self._lock:
            for course in self._courses.values():
                if (course.lti_platform_id, course.lti_context_id) == (platform_id, context_id):
                    return course
        return None

    def course_by_join_code(self, code: str) -> CourseRecord | None:
        with self._lock:
            return next((c for c in self._courses.values() if c.join_code == code), None)

    def set_join_code(self, course_id: int, code: str | None) -> CourseRecord:
        with self._lock:
            course = self._course(course_id)
            if code is not None and any(
                c.join_code == code and c.id != course_id for c in self._courses.values()
            ):
                raise JoinCodeTaken(code)
            course = replace(course, join_code=code)
            self._courses[course_id] = course
            return course

    def courses_taught(self, member: str) -> list[tuple[CourseRecord, StaffRole]]:
        with self._lock:
            found = [(self._courses[c], s.role) for (c, m), s in self._staff.items() if m == member]
        return sorted(found, key=lambda pair: pair[0].id)

    def courses_enrolled(self, student: str) -> list[CourseRecord]:
        with self._lock:
            found = [self._courses[c] for (c, s) in self._enrolments if s == student]
        return sorted(found, key=lambda course: course.id)

    def add_staff(self, course_id: int, member: str, role: StaffRole, name: str = "") -> StaffRecord:
        with self._lock:
            self._course(course_id)
            record = StaffRecord(course_id, member, StaffRole(role), name)
            self._staff[(course_id, member)] = record
            return record

    def remove_staff(self, course_id: int, member: str) -> None:
        with self._lock:
            self._staff.pop((course_id, member), None)

    def staff(self, course_id: int) -> list[StaffRecord]:
        with self._lock:
            found = [s for (c, _), s in self._staff.items() if c == course_id]
        return sorted(found, key=lambda s: s.member)

    def import_roster(self, course_id: int, rows: Sequence[RosterRow]) -> RosterImport:
        added = updated = unchanged = 0
        with self._lock:
            self._course(course_id)
            for row in rows:
                student = roster_identity(course_id, row.roster_id)
                known = self._enrolments.get((course_id, student))
                if known is None:
                    added += 1
                    self._enrolments[(course_id, student)] = EnrolmentRecord(
                        course_id, student, row.roster_id, row.name, row.email, self._clock()
                    )
                elif (known.name, known.email) == (row.name, row.email):
                    unchanged += 1
                else:
                    updated += 1
                    self._enrolments[(course_id, student)] = replace(known, name=row.name, email=row.email)
        return RosterImport(added, updated, unchanged)

    def enrol(self, course_id: int, student: str, name: str = "", email: str = "") -> EnrolmentRecord:
        with self._lock:
            self._course(course_id)
            known = self._enrolments.get((course_id, student))
            if known is None:
                known = EnrolmentRecord(course_id, student, None, name, email, self._clock())
                self._enrolments[(course_id, student)] = known
            return known

    def roster(self, course_id: int) -> list[EnrolmentRecord]:
        with self._lock:
            found = [e for (c, _), e in self._enrolments.items() if c == course_id]
        return sorted(found, key=lambda e: (e.name, e.student))

    def enrolment(self, course_id: int, student: str) -> EnrolmentRecord | None:
        with self._lock:
            return self._enrolments.get((course_id, student))

    def issue_sign_in(
        self, course_id: int, student: str, token_hash: str, expires_at: datetime, *, reusable: bool = False
    ) -> None:
        with self._lock:
            if (course_id, student) not in self._enrolments:
                raise NotFound(f"{student!r} is not enrolled in course {course_id}")
            for key, (c, s, _, used, _) in list(self._tokens.items()):
                if (c, s) == (course_id, student) and used is None:
                    del self._tokens[key]
            self._tokens[token_hash] = (course_id, student, expires_at, None, reusable)

    def redeem_sign_in(self, token_hash: str, now: datetime) -> tuple[int, str] | None:
        with self._lock:
            found = self._tokens.get(token_hash)
            if found is None:
                return None
            course_id, student, expires_at, used, reusable = found
            if used is not None or expires_at <= now:
                return None
            if not reusable:
                self._tokens[token_hash] = (course_id, student, expires_at, now, reusable)
            return course_id, student

    def save_session(self, id_hash: str, session: CourseSession, now: datetime) -> None:
        with self._lock:
            for key in [k for k, s in self._sessions.items() if s.expires_at < now]:
                del self._sessions[key]
            self._sessions[id_hash] = session

    def get_session(self, id_hash: str) -> CourseSession | None:
        with self._lock:
            return self._sessions.get(id_hash)

    def end_session(self, id_hash: str) -> None:
        with self._lock:
            self._sessions.pop(id_hash, None)

    def create_assignment(self, course_id: int, spec: AssignmentSpec) -> AssignmentRecord:
        with self._lock:
            self._course(course_id)
            record = AssignmentRecord(self._next_assignment, course_id, _utc(spec), self._clock())
            self._next_assignment += 1
            self._assignments[record.id] = record
            return record

    def update_assignment(self, assignment_id: int, spec: AssignmentSpec) -> AssignmentRecord:
        with self._lock:
            record = replace(self._assignment(assignment_id), spec=_utc(spec))
            self._assignments[assignment_id] = record
            return record

    def delete_assignment(self, assignment_id: int) -> None:
        with self._lock:
            self._assignment(assignment_id)
            del self._assignments[assignment_id]
            for key in [k for k in self._extensions if k[0] == assignment_id]:
                del self._extensions[key]

    def _assignment(self, assignment_id: int) -> AssignmentRecord:
        if assignment_id not in self._assignments:
            raise AssignmentNotFound(assignment_id)
        return self._assignments[assignment_id]

    def get_assignment(self, assignment_id: int) -> AssignmentRecord:
        with self._lock:
            return self._assignment(assignment_id)

    def assignments(self, course_id: int) -> list[AssignmentRecord]:
        with self._lock:
            found = [a for a in self._assignments.values() if a.course_id == course_id]
        return sorted(found, key=lambda a: (a.spec.due_at, a.id))

    def set_extension(self, assignment_id: int, student: str, extension: ExtensionRecord | None) -> None:
        with self._lock:
            self._assignment(assignment_id)
            if extension is None:
                self._extensions.pop((assignment_id, student), None)
            else:
                self._extensions[(assignment_id, student)] = _utc_extension(extension)

    def extensions(self, assignment_id: int) -> dict[str, ExtensionRecord]:
        with self._lock:
            return {s: due for (a, s), due in self._extensions.items() if a == assignment_id}

    def open_solution(self, student: str, problem_id: str, now: datetime) -> datetime:
        with self._lock:
            return self._solution_views.setdefault((student, problem_id), now.astimezone(UTC))

    def solutions_opened(self, student: str) -> dict[str, datetime]:
        with self._lock:
            return {problem: at for (who, problem), at in self._solution_views.items() if who == student}

    def share_problem(self, problem_id: str, shared: bool) -> None:
        with self._lock:
            if shared:
                self._shared.add(problem_id)
            else:
                self._shared.discard(problem_id)

    def shared_problems(self) -> set[str]:
        with self._lock:
            return set(self._shared)


def assignment_grade_queue(
    outbox_store: MemoryScoreOutbox,
    problems: MemoryProblemStore,
    courses: MemoryCourseStore,
    submissions: Callable[[], list[SubmissionRecord]],
) -> Callable[[SubmissionRecord], object]:
    """`sql_assignment_grades.queue_assignment_grades` for the fakes: a launched assignment's new
    total, queued with the submission (the hook runs before it is visible, so it is counted here)."""

    def queue(stored: SubmissionRecord) -> None:
        if stored.verdict is Verdicts.INVALID:
            return
        keys = {problem for student, problem, _, _ in outbox_store.targets() if student == stored.student}
        for key in sorted(keys):
            assignment_id = passback.assignment_of(key)
            if assignment_id is None:
                continue
            try:
                assignment = courses.get_assignment(assignment_id)
            except AssignmentNotFound:
                continue
            if stored.problem_id not in assignment.problems:
                continue
            documents = {}
            for problem_id in assignment.problems:
                try:
                    documents[problem_id] = problems.get(problem_id, include_retired=True).document
                except NotFound:
                    continue
            given, maximum = passback.assignment_score(
                assignment,
                documents,
                [*submissions(), stored],
                stored.student,
                courses.extensions(assignment_id).get(stored.student),
                stored.created_at,
                courses.solutions_opened(stored.student),
            )
            outbox_store.enqueue(key, stored.student, given, maximum, stored.created_at)

    return queue


def _utc_extension(extension: ExtensionRecord) -> ExtensionRecord:
    """As the SQL store hands it back: its times in UTC."""
    granted = None if extension.granted_at is None else extension.granted_at.astimezone(UTC)
    earlier = tuple(_utc_extension(x) for x in extension.earlier)
    return ExtensionRecord(extension.due_at.astimezone(UTC), granted, earlier)
