"""The course store on SQLAlchemy (SQLite or PostgreSQL): each call one transaction."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from datetime import UTC, datetime
from typing import Any

from sqlalchemy import delete, select, update
from sqlalchemy.exc import IntegrityError

from app.courses.models import (
    Assignment,
    BankShare,
    Course,
    CourseSessionRow,
    CourseStaff,
    Enrolment,
    Extension,
    SignInToken,
    SolutionView,
)
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
    LateKind,
    LatePolicy,
    RosterImport,
    RosterRow,
    SolutionRelease,
    StaffRecord,
    StaffRole,
    roster_identity,
)
from app.db.database import Database
from app.db.errors import NotFound
from app.db.types import utc_now

Clock = Callable[[], datetime]


def _course(row: Course) -> CourseRecord:
    return CourseRecord(
        id=row.id,
        title=row.title,
        timezone=row.timezone,
        join_code=row.join_code,
        lti_platform_id=row.lti_platform_id,
        lti_context_id=row.lti_context_id,
        created_at=row.created_at,
    )


def _enrolment(row: Enrolment) -> EnrolmentRecord:
    return EnrolmentRecord(row.course_id, row.student, row.roster_id, row.name, row.email, row.created_at)


def assignment_record(row: Assignment) -> AssignmentRecord:
    spec = AssignmentSpec(
        title=row.title,
        problems=tuple(str(p) for p in row.problems),
        opens_at=row.opens_at,
        due_at=row.due_at,
        late=LatePolicy(LateKind(row.late_policy), row.penalty_per_day, row.penalty_limit),
        max_attempts=row.max_attempts,
        solutions=SolutionRelease(row.solutions),
    )
    return AssignmentRecord(row.id, row.course_id, spec, row.created_at)


def extension_record(row: Extension) -> ExtensionRecord:
    earlier = tuple(
        ExtensionRecord(_utc(due), None if granted is None else _utc(granted))
        for granted, due in row.earlier or ()
    )
    return ExtensionRecord(row.due_at, row.granted_at, earlier)


def _earlier_json(extension: ExtensionRecord) -> list[Any] | None:
    return [
        [
            None if x.granted_at is None else x.granted_at.astimezone(UTC).isoformat(),
            x.due_at.astimezone(UTC).isoformat(),
        ]
        for x in extension.earlier
    ] or None


def _utc(text: str) -> datetime:
    return datetime.fromisoformat(text).astimezone(UTC)


def _write_spec(row: Assignment, spec: AssignmentSpec) -> None:
    row.title = spec.title
    row.problems = list(spec.problems)
    row.opens_at = spec.opens_at
    row.due_at = spec.due_at
    row.late_policy = spec.late.kind.value
    row.penalty_per_day = spec.late.per_day
    row.penalty_limit = spec.late.limit
    row.max_attempts = spec.max_attempts
    row.solutions = spec.solutions.value


class SqlCourseStore:
    def __init__(self, database: Database, clock: Clock = utc_now) -> None:
        self._database, self._clock = database, clock

    def create_course(
        self,
        title: str,
        *,
        owner: str,
        owner_name: str = "",
        timezone: str = "UTC",
        lti_context: tuple[int, str] | None = None,
    ) -> CourseRecord:
        if lti_context is not None and (known := self.course_for_context(*lti_context)) is not None:
            return known
        try:
            with self._database.session() as session:
                row = Course(
                    title=title,
                    timezone=timezone,
                    lti_platform_id=None if lti_context is None else lti_context[0],
                    lti_context_id=None if lti_context is None else lti_context[1],
                    created_at=self._clock(),
                )
                session.add(row)
                session.flush()
                session.add(
                    CourseStaff(
                        course_id=row.id, member=owner, role=StaffRole.INSTRUCTOR.value, name=owner_name
                    )
                )
                return _course(row)
        except IntegrityError:
            # Two first launches from one LMS context at once: the other made it.
            if lti_context is not None and (known := self.course_for_context(*lti_context)) is not None:
                return known
            raise

    def get_course(self, course_id: int) -> CourseRecord:
        with self._database.session(read_only=True) as session:
            row = session.get(Course, course_id)
            if row is None:
                raise CourseNotFound(course_id)
            return _course(row)

    def course_for_context(self, platform_id: int, context_id: str) -> CourseRecord | None:
        query = select(Course).where(
            Course.lti_platform_id == platform_id, Course.lti_context_id == context_id
        )
        with self._database.session(read_only=True) as session:
            row = session.scalars(query).first()
            return None if row is None else _course(row)

    def course_by_join_code(self, code: str) -> CourseRecord | None:
        with self._database.session(read_only=True) as session:
            row = session.scalars(select(Course).where(Course.join_code == code)).first()
            return None if row is None else _course(row)

    def set_join_code(self, course_id: int, code: str | None) -> CourseRecord:
        try:
            with self._database.session() as session:
                row = session.get(Course, course_id)
                if row is None:
                    raise CourseNotFound(course_id)
                row.join_code = code
                session.flush()
                return _course(row)
        except IntegrityError:
            raise JoinCodeTaken(code or "") from None

    def courses_taught(self, member: str) -> list[tuple[CourseRecord, StaffRole]]:
        query = (
            select(Course, CourseStaff.role)
            .join(CourseStaff, CourseStaff.course_id == Course.id)
            .where(CourseStaff.member == member)
            .order_by(Course.id)
        )
        with self._database.session(read_only=True) as session:
            return [(_course(row), StaffRole(role)) for row, role in session.execute(query)]

    def courses_enrolled(self, student: str) -> list[CourseRecord]:
        query = (
            select(Course)
            .join(Enrolment, Enrolment.course_id == Course.id)
            .where(Enrolment.student == student)
            .order_by(Course.id)
        )
        with self._database.session(read_only=True) as session:
            return [_course(row) for row in session.scalars(query)]

    def add_staff(self, course_id: int, member: str, role: StaffRole, name: str = "") -> StaffRecord:
        with self._database.session() as session:
            if session.get(Course, course_id) is None:
                raise CourseNotFound(course_id)
            row = session.get(CourseStaff, (course_id, member))
            if row is None:
                session.add(
                    CourseStaff(course_id=course_id, member=member, role=StaffRole(role).value, name=name)
                )
            else:
                row.role, row.name = StaffRole(role).value, name or row.name
                name = row.name
        return StaffRecord(course_id, member, StaffRole(role), name)

    def remove_staff(self, course_id: int, member: str) -> None:
        with self._database.session() as session:
            session.execute(
                delete(CourseStaff).where(CourseStaff.course_id == course_id, CourseStaff.member == member)
            )

    def staff(self, course_id: int) -> list[StaffRecord]:
        query = select(CourseStaff).where(CourseStaff.course_id == course_id).order_by(CourseStaff.member)
        with self._database.session(read_only=True) as session:
            return [
                StaffRecord(row.course_id, row.member, StaffRole(row.role), row.name)
                for row in session.scalars(query)
            ]

    def import_roster(self, course_id: int, rows: Sequence[RosterRow]) -> RosterImport:
        added = updated = unchanged = 0
        with self._database.session() as session:
            if session.get(Course, course_id) is None:
                raise CourseNotFound(course_id)
            for line in rows:
                student = roster_identity(course_id, line.roster_id)
                known = session.get(Enrolment, (course_id, student))
                if known is None:
                    added += 1
                    session.add(
                        Enrolment(
                            course_id=course_id,
                            student=student,
                            roster_id=line.roster_id,
                            name=line.name,
                            email=line.email,
                            created_at=self._clock(),
                        )
                    )
                    session.flush()
                elif (known.name, known.email) == (line.name, line.email):
                    unchanged += 1
                else:
                    updated += 1
                    known.name, known.email = line.name, line.email
        return RosterImport(added, updated, unchanged)

    def enrol(self, course_id: int, student: str, name: str = "", email: str = "") -> EnrolmentRecord:
        try:
            with self._database.session() as session:
                if session.get(Course, course_id) is None:
                    raise CourseNotFound(course_id)
                known = session.get(Enrolment, (course_id, student))
                if known is None:
                    known = Enrolment(
                        course_id=course_id, student=student, name=name, email=email, created_at=self._clock()
                    )
                    session.add(known)
                    session.flush()
                return _enrolment(known)
        except IntegrityError:  # enrolled by a concurrent call
            found = self.enrolment(course_id, student)
            if found is None:
                raise
            return found

    def roster(self, course_id: int) -> list[EnrolmentRecord]:
        query = (
            select(Enrolment)
            .where(Enrolment.course_id == course_id)
            .order_by(Enrolment.name, Enrolment.student)
        )
        with self._database.session(read_only=True) as session:
            return [_enrolment(row) for row in session.scalars(query)]

    def enrolment(self, course_id: int, student: str) -> EnrolmentRecord | None:
        with self._database.session(read_only=True) as session:
            row = session.get(Enrolment, (course_id, student))
            return None if row is None else _enrolment(row)

    def issue_sign_in(
        self, course_id: int, student: str, token_hash: str, expires_at: datetime, *, reusable: bool = False
    ) -> None:
        with self._database.session() as session:
            if session.get(Enrolment, (course_id, student)) is None:
                raise NotFound(f"{student!r} is not enrolled in course {course_id}")
            session.execute(
                delete(SignInToken).where(
                    SignInToken.course_id == course_id,
                    SignInToken.student == student,
                    SignInToken.used_at.is_(None),
                )
            )
            session.add(
                SignInToken(
                    token_hash=token_hash,
                    course_id=course_id,
                    student=student,
                    expires_at=expires_at,
                    reusable=reusable,
                )
            )

    def redeem_sign_in(self, token_hash: str, now: datetime) -> tuple[int, str] | None:
        # One conditional UPDATE: of concurrent redeemers exactly one sees a row changed.
        with self._database.session() as session:
            spent = session.execute(
                update(SignInToken)
                .where(
                    SignInToken.token_hash == token_hash,
                    SignInToken.used_at.is_(None),
                    SignInToken.expires_at > now,
                    SignInToken.reusable.is_(False),
                )
                .values(used_at=now)
            )
            row = session.get(SignInToken, token_hash)
            if getattr(spent, "rowcount", 0) == 1 or (
                row is not None and row.reusable and row.used_at is None and row.expires_at > now
            ):
                assert row is not None
                return row.course_id, row.student
            return None

    def save_session(self, id_hash: str, session_record: CourseSession, now: datetime) -> None:
        with self._database.session() as session:
            session.execute(delete(CourseSessionRow).where(CourseSessionRow.expires_at < now))
            session.add(
                CourseSessionRow(
                    id_hash=id_hash,
                    course_id=session_record.course_id,
                    student=session_record.student,
                    name=session_record.name,
                    csrf_token=session_record.csrf_token,
                    expires_at=session_record.expires_at,
                    problem_id=session_record.problem_id,
                )
            )

    def get_session(self, id_hash: str) -> CourseSession | None:
        with self._database.session(read_only=True) as session:
            row = session.get(CourseSessionRow, id_hash)
            if row is None:
                return None
            return CourseSession(
                row.course_id, row.student, row.name, row.csrf_token, row.expires_at, row.problem_id
            )

    def end_session(self, id_hash: str) -> None:
        with self._database.session() as session:
            session.execute(delete(CourseSessionRow).where(CourseSessionRow.id_hash == id_hash))

    def create_assignment(self, course_id: int, spec: AssignmentSpec) -> AssignmentRecord:
        with self._database.session() as session:
            if session.get(Course, course_id) is None:
                raise CourseNotFound(course_id)
            row = Assignment(course_id=course_id, created_at=self._clock())
            _write_spec(row, spec)
            session.add(row)
            session.flush()
            return assignment_record(row)

    def update_assignment(self, assignment_id: int, spec: AssignmentSpec) -> AssignmentRecord:
        with self._database.session() as session:
            row = session.get(Assignment, assignment_id)
            if row is None:
                raise AssignmentNotFound(assignment_id)
            _write_spec(row, spec)
            session.flush()
            return assignment_record(row)

    def delete_assignment(self, assignment_id: int) -> None:
        with self._database.session() as session:
            row = session.get(Assignment, assignment_id)
            if row is None:
                raise AssignmentNotFound(assignment_id)
            session.execute(delete(Extension).where(Extension.assignment_id == assignment_id))
            session.delete(row)

    def get_assignment(self, assignment_id: int) -> AssignmentRecord:
        with self._database.session(read_only=True) as session:
            row = session.get(Assignment, assignment_id)
            if row is None:
                raise AssignmentNotFound(assignment_id)
            return assignment_record(row)

    def assignments(self, course_id: int) -> list[AssignmentRecord]:
        query = (
            select(Assignment)
            .where(Assignment.course_id == course_id)
            .order_by(Assignment.due_at, Assignment.id)
        )
        with self._database.session(read_only=True) as session:
            return [assignment_record(row) for row in session.scalars(query)]

    def set_extension(self, assignment_id: int, student: str, extension: ExtensionRecord | None) -> None:
        with self._database.session() as session:
            if session.get(Assignment, assignment_id) is None:
                raise AssignmentNotFound(assignment_id)
            row = session.get(Extension, (assignment_id, student))
            if extension is None:
                if row is not None:
                    session.delete(row)
            elif row is None:
                session.add(
                    Extension(
                        assignment_id=assignment_id,
                        student=student,
                        due_at=extension.due_at,
                        granted_at=extension.granted_at,
                        earlier=_earlier_json(extension),
                    )
                )
            else:
                row.due_at, row.granted_at = extension.due_at, extension.granted_at
                row.earlier = _earlier_json(extension)

    def extensions(self, assignment_id: int) -> dict[str, ExtensionRecord]:
        query = select(Extension).where(Extension.assignment_id == assignment_id)
        with self._database.session(read_only=True) as session:
            return {row.student: extension_record(row) for row in session.scalars(query)}

    def open_solution(self, student: str, problem_id: str, now: datetime) -> datetime:
        try:
            with self._database.session() as session:
                row = session.get(SolutionView, (student, problem_id))
                if row is None:
                    row = SolutionView(student=student, problem_id=problem_id, opened_at=now)
                    session.add(row)
                    session.flush()
                return row.opened_at
        except IntegrityError:  # another tab opened it at the same moment: the first stands
            found = self.solutions_opened(student).get(problem_id)
            if found is None:
                raise
            return found

    def solutions_opened(self, student: str) -> dict[str, datetime]:
        query = select(SolutionView).where(SolutionView.student == student)
        with self._database.session(read_only=True) as session:
            return {row.problem_id: row.opened_at for row in session.scalars(query)}

    def share_problem(self, problem_id: str, shared: bool) -> None:
        with self._database.session() as session:
            row = session.get(BankShare, problem_id)
            if shared and row is None:
                session.add(BankShare(problem_id=problem_id, shared_at=self._clock()))
            elif not shared and row is not None:
                session.delete(row)

    def shared_problems(self) -> set[str]:
        with self._database.session(read_only=True) as session:
            return set(session.scalars(select(BankShare.problem_id)))
