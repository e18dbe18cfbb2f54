"""Courses: staff, rosters and sign-in links, assignments, extensions and the gradebook.

Every call is scoped to the caller's courses: a course the caller does not teach answers 404, as if
it did not exist. TAs read everything, issue sign-in links and grant extensions; instructors also
change the course, its staff, roster and assignments. An enrolled student lists their courses and
their own standing on each assignment.
"""

from __future__ import annotations

from collections.abc import Sequence
from datetime import datetime
from typing import Annotated

from fastapi import APIRouter, Body, Path, Request
from fastapi.responses import Response
from starlette.concurrency import run_in_threadpool

from app.auth import Principal
from app.courses import access, gradebook, service
from app.courses import sessions as course_sessions
from app.courses.gradebook import AssignmentCell, Gradebook
from app.courses.policy import due_for, granted
from app.courses.records import (
    AssignmentNotFound,
    AssignmentRecord,
    AssignmentSpec,
    CourseNotFound,
    CourseRecord,
    EnrolmentRecord,
    LateKind,
    LatePolicy,
    SolutionRelease,
    StaffRole,
)
from app.courses.roster_csv import parse_roster
from app.db.errors import ProblemNotFound
from app.deps import RECORD_ID_MAX, CurrentPrincipal, Instructor, ServicesDep
from app.errors import AppError, Conflict, NotFound
from app.openapi import AUTHENTICATED, errors
from app.schemas import examples
from app.schemas.courses import (
    AssignmentIn,
    AssignmentOut,
    CourseIn,
    CourseOut,
    ExtensionIn,
    ExtensionOut,
    GradebookOut,
    GradebookRowOut,
    GradeCellOut,
    JoinCodeOut,
    LatePolicyIn,
    PartScoreOut,
    RosterImportOut,
    ShareIn,
    SignInLinkOut,
    StaffIn,
    StaffOut,
    StudentOut,
    StudentStanding,
)
from app.services import Services

router = APIRouter(tags=["courses"], responses=AUTHENTICATED)
CourseIdPath = Annotated[int, Path(ge=1, le=RECORD_ID_MAX, openapi_examples=examples.COURSE_ID)]
AssignmentIdPath = Annotated[int, Path(ge=1, le=RECORD_ID_MAX, openapi_examples=examples.ASSIGNMENT_ID)]
StudentPath = Annotated[str, Path(openapi_examples=examples.ROSTERED_STUDENT)]
SharedProblemPath = Annotated[str, Path(openapi_examples=examples.UPLOADED_PROBLEM_ID)]
CSV_MEDIA = "text/csv"


class MalformedRoster(AppError):
    status, code = 422, "malformed_request"


class UnusableProblem(AppError):
    status, code = 422, "malformed_request"


def now_of(request: Request) -> datetime:
    clock: datetime = request.app.state.lti.clock()
    return clock


def course_out(course: CourseRecord, role: str) -> CourseOut:
    staff = role != "student"
    return CourseOut(
        id=course.id,
        title=course.title,
        timezone=course.timezone,
        role=role,
        join_code=course.join_code if staff else None,
        lti=course.lti_context_id is not None,
    )


def assignment_out(record: AssignmentRecord, points: int) -> AssignmentOut:
    spec = record.spec
    return AssignmentOut(
        id=record.id,
        course_id=record.course_id,
        title=spec.title,
        problems=list(spec.problems),
        opens_at=spec.opens_at,
        due_at=spec.due_at,
        late=LatePolicyIn(kind=spec.late.kind.value, per_day=spec.late.per_day, limit=spec.late.limit),
        max_attempts=spec.max_attempts,
        solutions=spec.solutions.value,
        points=points,
    )


def student_out(enrolment: EnrolmentRecord) -> StudentOut:
    return StudentOut(
        student=enrolment.student, roster_id=enrolment.roster_id, name=enrolment.name, email=enrolment.email
    )


def _staff(
    services: Services, principal: Principal, course_id: CourseIdPath, *, only_instructors_may: str = ""
) -> CourseRecord:
    return access.require_staff(
        services.stores, principal, course_id, only_instructors_may=only_instructors_may
    )


# ---- courses and staff -------------------------------------------------------------------------------


@router.post("/v1/courses", status_code=201, response_model=CourseOut, responses=errors(403, 422))
async def create_course(
    body: Annotated[CourseIn, Body(openapi_examples=examples.COURSE)],
    services: ServicesDep,
    principal: Instructor,
) -> CourseOut:
    """A new course, taught by the caller."""
    member = principal.member
    assert member is not None  # every instructor has one
    course = await run_in_threadpool(
        services.stores.courses.create_course,
        body.title,
        owner=member,
        owner_name=principal.name,
        timezone=body.timezone,
    )
    return course_out(course, "instructor")


@router.get("/v1/courses", response_model=list[CourseOut])
async def list_courses(services: ServicesDep, principal: CurrentPrincipal) -> list[CourseOut]:
    """The courses the caller teaches, or (a student) is enrolled in."""

    def load() -> list[CourseOut]:
        if principal.student is not None:
            return [
                course_out(c, "student") for c in services.stores.courses.courses_enrolled(principal.student)
            ]
        return [course_out(c, role.value) for c, role in access.taught_courses(services.stores, principal)]

    return await run_in_threadpool(load)


@router.get("/v1/courses/{course_id}", response_model=CourseOut, responses=errors(404, 422))
async def get_course(
    course_id: CourseIdPath, services: ServicesDep, principal: CurrentPrincipal
) -> CourseOut:
    def load() -> CourseOut:
        if principal.student is not None:
            if services.stores.courses.enrolment(course_id, principal.student) is None:
                raise NotFound(f"There is no course {course_id} of yours.")
            return course_out(services.stores.courses.get_course(course_id), "student")
        role = access.course_role(services.stores, principal, course_id)
        if role is None:
            raise NotFound(f"There is no course {course_id} of yours.")
        return course_out(services.stores.courses.get_course(course_id), role.value)

    return await run_in_threadpool(load)


@router.get("/v1/courses/{course_id}/staff", response_model=list[StaffOut], responses=errors(403, 404, 422))
async def list_staff(course_id: CourseIdPath, services: ServicesDep, principal: Instructor) -> list[StaffOut]:
    def load() -> list[StaffOut]:
        _staff(services, principal, course_id)
        return [
            StaffOut(member=s.member, role=s.role.value, name=s.name)
            for s in services.stores.courses.staff(course_id)
        ]

    return await run_in_threadpool(load)


@router.put("/v1/courses/{course_id}/staff", response_model=StaffOut, responses=errors(403, 404, 422))
async def add_staff(
    course_id: CourseIdPath,
    body: Annotated[StaffIn, Body(openapi_examples=examples.STAFF)],
    services: ServicesDep,
    principal: Instructor,
) -> StaffOut:
    """Add a co-instructor or TA (or change their role) by their key id or LMS identity."""

    def save() -> StaffOut:
        _staff(services, principal, course_id, only_instructors_may="change its staff")
        made = services.stores.courses.add_staff(course_id, body.member, StaffRole(body.role), body.name)
        return StaffOut(member=made.member, role=made.role.value, name=made.name)

    return await run_in_threadpool(save)


@router.delete(
    "/v1/courses/{course_id}/staff/{member}", status_code=204, responses=errors(403, 404, 409, 422)
)
async def remove_staff(
    course_id: CourseIdPath, member: str, services: ServicesDep, principal: Instructor
) -> Response:
    def remove() -> None:
        _staff(services, principal, course_id, only_instructors_may="change its staff")
        staff = services.stores.courses.staff(course_id)
        instructors = [s.member for s in staff if s.role is StaffRole.INSTRUCTOR]
        if instructors == [member]:
            raise Conflict("A course keeps at least one instructor.")
        services.stores.courses.remove_staff(course_id, member)

    await run_in_threadpool(remove)
    return Response(status_code=204)


# ---- roster, sign-in links and join codes --------------------------------------------------------


@router.get(
    "/v1/courses/{course_id}/roster", response_model=list[StudentOut], responses=errors(403, 404, 422)
)
async def roster(course_id: CourseIdPath, services: ServicesDep, principal: Instructor) -> list[StudentOut]:
    def load() -> list[StudentOut]:
        _staff(services, principal, course_id)
        return [student_out(e) for e in services.stores.courses.roster(course_id)]

    return await run_in_threadpool(load)


@router.post(
    "/v1/courses/{course_id}/roster",
    response_model=RosterImportOut,
    responses=errors(403, 404, 413, 422),
    openapi_extra={
        "requestBody": {
            "required": True,
            "content": {
                CSV_MEDIA: {
                    "schema": {"type": "string"},
                    "examples": {"roster": {"summary": "Two students", "value": examples.ROSTER_CSV}},
                }
            },
        }
    },
)
async def import_roster(
    course_id: CourseIdPath, request: Request, services: ServicesDep, principal: Instructor
) -> RosterImportOut:
    """A roster CSV (`id,name,email`, header optional): new students are added, known ids updated,
    never duplicated; nothing is imported if any line is wrong (422 lists every one)."""
    raw = await request.body()
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        raise MalformedRoster("The roster must be UTF-8 text.") from None
    rows, problems = parse_roster(text)
    if problems:
        raise MalformedRoster(
            f"{len(problems)} line(s) of the roster could not be read; nothing was imported.",
            [{"path": f"line {p.line}", "message": p.message} for p in problems],
        )

    def save() -> RosterImportOut:
        _staff(services, principal, course_id, only_instructors_may="import its roster")
        done = services.stores.courses.import_roster(course_id, rows)
        return RosterImportOut(added=done.added, updated=done.updated, unchanged=done.unchanged)

    return await run_in_threadpool(save)


@router.post(
    "/v1/courses/{course_id}/sign-in-links",
    response_model=list[SignInLinkOut],
    responses=errors(403, 404, 422),
    openapi_extra=examples.json_body(examples.SIGN_IN_LINKS),
)
async def sign_in_links(
    course_id: CourseIdPath,
    request: Request,
    services: ServicesDep,
    principal: Instructor,
    students: Annotated[list[str] | None, Body(embed=True, max_length=5000)] = None,
) -> list[SignInLinkOut]:
    """New personal sign-in links for the named students (all enrolled ones when none are named);
    each replaces the student's older unused link. Shown once: send them to the students."""
    now = now_of(request)

    def issue() -> list[SignInLinkOut]:
        _staff(services, principal, course_id)
        enrolled = {e.student: e for e in services.stores.courses.roster(course_id)}
        wanted = list(enrolled) if students is None else students
        unknown = [s for s in wanted if s not in enrolled]
        if unknown:
            raise NotFound(f"Not enrolled in course {course_id}: {', '.join(unknown[:5])}.")
        links = []
        for student in wanted:
            token = course_sessions.issue_link(services.stores.courses, course_id, student, now)
            links.append(
                SignInLinkOut(
                    student=student,
                    name=enrolled[student].name,
                    email=enrolled[student].email,
                    url=str(request.base_url).rstrip("/") + course_sessions.SIGN_IN_PATH + token,
                    expires_at=now + course_sessions.LINK_LIFETIME,
                )
            )
        return links

    return await run_in_threadpool(issue)


@router.post(
    "/v1/courses/{course_id}/join-code",
    response_model=JoinCodeOut,
    responses=errors(403, 404, 422),
    openapi_extra=examples.json_body(examples.JOIN_CODE),
)
async def new_join_code(
    course_id: CourseIdPath,
    request: Request,
    services: ServicesDep,
    principal: Instructor,
    enabled: Annotated[bool, Body(embed=True)] = True,
) -> JoinCodeOut:
    """A fresh join code (students enrol themselves at its URL), or none (`{"enabled": false}`)."""

    def save() -> JoinCodeOut:
        _staff(services, principal, course_id, only_instructors_may="change its join code")
        code = course_sessions.new_join_code() if enabled else None
        course = services.stores.courses.set_join_code(course_id, code)
        url = None if code is None else str(request.base_url).rstrip("/") + course_sessions.JOIN_PATH + code
        return JoinCodeOut(join_code=course.join_code, url=url)

    return await run_in_threadpool(save)


# ---- assignments and extensions ------------------------------------------------------------------


def _spec(body: AssignmentIn) -> AssignmentSpec:
    return AssignmentSpec(
        title=body.title,
        problems=tuple(body.problems),
        opens_at=body.opens_at,
        due_at=body.due_at,
        late=LatePolicy(LateKind(body.late.kind), body.late.per_day, body.late.limit),
        max_attempts=body.max_attempts,
        solutions=SolutionRelease(body.solutions),
    )


def _check_problems(
    services: Services, principal: Principal, problems: list[str], assigned: Sequence[str] = ()
) -> None:
    """Every problem exists and is the caller's to assign (built-in, shared, or their courses'), and
    none but those `assigned` already is one this code refuses (stored under older code): its students
    could not answer it."""
    colleagues = access.colleagues(services.stores, principal)
    shared = services.stores.courses.shared_problems()
    bad = []
    for index, problem_id in enumerate(problems):
        try:
            record = services.catalog.get(problem_id)
        except ProblemNotFound:
            record = None
        if record is None or not access.may_use_problem(record, principal, colleagues, shared):
            bad.append(
                {"path": f"problems.{index}", "message": f"there is no problem {problem_id!r} of yours"}
            )
        elif problem_id not in assigned and services.catalog.refusal(record) is not None:
            bad.append(
                {
                    "path": f"problems.{index}",
                    "message": f"{problem_id!r} no longer verifies under this version of physcheck, so its "
                    "students could not answer it: edit it first (its page says why)",
                }
            )
    if bad:
        raise UnusableProblem("Some problems cannot be assigned.", bad)


def _points(services: Services, record: AssignmentRecord) -> int:
    return len(service.assignment_parts(services.catalog, record))


@router.post(
    "/v1/courses/{course_id}/assignments",
    status_code=201,
    response_model=AssignmentOut,
    responses=errors(403, 404, 422),
)
async def create_assignment(
    course_id: CourseIdPath,
    body: Annotated[AssignmentIn, Body(openapi_examples=examples.ASSIGNMENT)],
    services: ServicesDep,
    principal: Instructor,
) -> AssignmentOut:
    def save() -> AssignmentOut:
        _staff(services, principal, course_id, only_instructors_may="add assignments")
        _check_problems(services, principal, body.problems)
        made = services.stores.courses.create_assignment(course_id, _spec(body))
        return assignment_out(made, _points(services, made))

    return await run_in_threadpool(save)


@router.get(
    "/v1/courses/{course_id}/assignments",
    response_model=list[AssignmentOut] | list[StudentStanding],
    responses=errors(404, 422),
)
async def list_assignments(
    course_id: CourseIdPath, request: Request, services: ServicesDep, principal: CurrentPrincipal
) -> list[AssignmentOut] | list[StudentStanding]:
    """Staff get every assignment; an enrolled student their standing on each (status, score, their
    own due date)."""
    now = now_of(request)

    def load() -> list[AssignmentOut] | list[StudentStanding]:
        if principal.student is None:
            _staff(services, principal, course_id)
            return [
                assignment_out(a, _points(services, a))
                for a in services.stores.courses.assignments(course_id)
            ]
        if services.stores.courses.enrolment(course_id, principal.student) is None:
            raise NotFound(f"There is no course {course_id} of yours.")
        return [
            standing(a, service.student_cell(services.stores, services.catalog, a, principal.student, now))
            for a in services.stores.courses.assignments(course_id)
        ]

    return await run_in_threadpool(load)


def standing(record: AssignmentRecord, cell: AssignmentCell) -> StudentStanding:
    spec = record.spec
    return StudentStanding(
        id=record.id,
        course_id=record.course_id,
        title=spec.title,
        problems=list(spec.problems) if cell.status.value != "not open" else [],
        opens_at=spec.opens_at,
        due_at=cell.due,
        late=LatePolicyIn(kind=spec.late.kind.value, per_day=spec.late.per_day, limit=spec.late.limit),
        status=cell.status.value,
        score=cell.score,
        points=cell.maximum,
        late_penalty_applied=cell.late,
    )


def _assignment_as_staff(
    services: Services,
    principal: Principal,
    assignment_id: AssignmentIdPath,
    *,
    only_instructors_may: str = "",
) -> AssignmentRecord:
    """The assignment when the caller teaches its course; else the 404 of one that does not exist,
    never naming its course (which would tell that it exists, and whose it is)."""
    record = services.stores.courses.get_assignment(assignment_id)
    try:
        _staff(services, principal, record.course_id, only_instructors_may=only_instructors_may)
    except CourseNotFound:
        raise AssignmentNotFound(assignment_id) from None
    return record


@router.get(
    "/v1/assignments/{assignment_id}",
    response_model=AssignmentOut | StudentStanding,
    responses=errors(404, 422),
)
async def get_assignment(
    assignment_id: AssignmentIdPath, request: Request, services: ServicesDep, principal: CurrentPrincipal
) -> AssignmentOut | StudentStanding:
    """Staff get the assignment; an enrolled student their standing on it, as in the course's list (a
    browser signed in to several courses acts in the assignment's own: its id names it)."""
    now = now_of(request)

    def load() -> AssignmentOut | StudentStanding:
        if principal.student is None:
            record = _assignment_as_staff(services, principal, assignment_id)
            return assignment_out(record, _points(services, record))
        record = services.stores.courses.get_assignment(assignment_id)
        if services.stores.courses.enrolment(record.course_id, principal.student) is None:
            raise AssignmentNotFound(assignment_id)  # as for one that does not exist
        return standing(
            record, service.student_cell(services.stores, services.catalog, record, principal.student, now)
        )

    return await run_in_threadpool(load)


@router.put("/v1/assignments/{assignment_id}", response_model=AssignmentOut, responses=errors(403, 404, 422))
async def update_assignment(
    assignment_id: AssignmentIdPath,
    body: Annotated[AssignmentIn, Body(openapi_examples=examples.ASSIGNMENT)],
    services: ServicesDep,
    principal: Instructor,
) -> AssignmentOut:
    def save() -> AssignmentOut:
        current = _assignment_as_staff(
            services, principal, assignment_id, only_instructors_may="change its assignments"
        )
        _check_problems(services, principal, body.problems, current.problems)
        made = services.stores.courses.update_assignment(assignment_id, _spec(body))
        return assignment_out(made, _points(services, made))

    return await run_in_threadpool(save)


@router.delete("/v1/assignments/{assignment_id}", status_code=204, responses=errors(403, 404, 422))
async def delete_assignment(
    assignment_id: AssignmentIdPath, services: ServicesDep, principal: Instructor
) -> Response:
    """The assignment goes; its students' submissions stay (the log is append-only)."""

    def remove() -> None:
        _assignment_as_staff(
            services, principal, assignment_id, only_instructors_may="delete its assignments"
        )
        services.stores.courses.delete_assignment(assignment_id)

    await run_in_threadpool(remove)
    return Response(status_code=204)


@router.get(
    "/v1/assignments/{assignment_id}/extensions",
    response_model=list[ExtensionOut],
    responses=errors(403, 404, 422),
)
async def list_extensions(
    assignment_id: AssignmentIdPath, services: ServicesDep, principal: Instructor
) -> list[ExtensionOut]:
    def load() -> list[ExtensionOut]:
        _assignment_as_staff(services, principal, assignment_id)
        found = services.stores.courses.extensions(assignment_id)
        return [
            ExtensionOut(student=s, due_at=x.due_at, granted_at=x.granted_at)
            for s, x in sorted(found.items())
        ]

    return await run_in_threadpool(load)


@router.put(
    "/v1/assignments/{assignment_id}/extensions/{student}",
    response_model=ExtensionOut,
    responses=errors(403, 404, 422),
)
async def set_extension(
    assignment_id: AssignmentIdPath,
    student: StudentPath,
    body: Annotated[ExtensionIn, Body(openapi_examples=examples.EXTENSION)],
    request: Request,
    services: ServicesDep,
    principal: Instructor,
) -> ExtensionOut:
    """The student's own due date for this assignment, for the answers they give from now on: answers
    already graded keep their late penalty unless `regrade_earlier` (an LMS gets the total again)."""
    now = now_of(request)

    def save() -> ExtensionOut:
        record = _assignment_as_staff(services, principal, assignment_id)
        if services.stores.courses.enrolment(record.course_id, student) is None:
            raise NotFound(f"{student!r} is not enrolled in this course.")
        current = services.stores.courses.extensions(assignment_id).get(student)
        extension = granted(current, body.due_at, now, regrade_earlier=body.regrade_earlier)
        services.stores.courses.set_extension(assignment_id, student, extension)
        service.resend_total(services.stores, services.catalog, record, student, now)
        return ExtensionOut(
            student=student, due_at=due_for(record, extension), granted_at=extension.granted_at
        )

    return await run_in_threadpool(save)


@router.delete(
    "/v1/assignments/{assignment_id}/extensions/{student}", status_code=204, responses=errors(403, 404, 422)
)
async def remove_extension(
    assignment_id: AssignmentIdPath,
    student: str,
    request: Request,
    services: ServicesDep,
    principal: Instructor,
) -> Response:
    now = now_of(request)

    def remove() -> None:
        record = _assignment_as_staff(services, principal, assignment_id)
        services.stores.courses.set_extension(assignment_id, student, None)
        service.resend_total(services.stores, services.catalog, record, student, now)

    await run_in_threadpool(remove)
    return Response(status_code=204)


# ---- the gradebook ---------------------------------------------------------------------------------


def gradebook_out(course: CourseRecord, book: Gradebook) -> GradebookOut:
    rows = []
    for enrolment in book.students:
        total, points = book.total(enrolment.student)
        cells = []
        for assignment in book.assignments:
            cell = book.cell(enrolment.student, assignment.id)
            cells.append(
                GradeCellOut(
                    assignment=assignment.id,
                    score=cell.score,
                    points=cell.maximum,
                    late=cell.late,
                    status=cell.status.value,
                    due_at=cell.due,
                    extended=cell.extended,
                    attempted=cell.attempted,
                    solution_opened=cell.frozen,
                    parts=[
                        PartScoreOut(
                            problem=p.problem_id,
                            part=p.part_id,
                            score=p.score,
                            late=p.late,
                            attempts=p.attempts,
                            solution_opened_at=p.frozen_at,
                        )
                        for p in cell.parts
                    ],
                )
            )
        rows.append(
            GradebookRowOut(student=student_out(enrolment), total=total, points=points, assignments=cells)
        )
    return GradebookOut(
        course=course.id,
        assignments=[assignment_out(a, book.maximum[a.id]) for a in book.assignments],
        students=rows,
    )


@router.get("/v1/courses/{course_id}/gradebook", response_model=GradebookOut, responses=errors(403, 404, 422))
async def get_gradebook(
    course_id: CourseIdPath, request: Request, services: ServicesDep, principal: Instructor
) -> GradebookOut:
    """Students x assignments: best scores with late penalties applied (and marked), per part on
    each cell, extensions shown."""
    now = now_of(request)

    def load() -> GradebookOut:
        course = _staff(services, principal, course_id)
        return gradebook_out(course, service.course_gradebook(services.stores, services.catalog, course, now))

    return await run_in_threadpool(load)


@router.get(
    "/v1/courses/{course_id}/gradebook.csv",
    response_class=Response,
    responses={
        200: {"content": {CSV_MEDIA: {}}, "description": "One row per student"},
        **errors(403, 404, 422),
    },
)
async def gradebook_csv(
    course_id: CourseIdPath, request: Request, services: ServicesDep, principal: Instructor
) -> Response:
    """The gradebook as CSV: Student ID, Name, Email, one column per assignment (points), Total, Notes."""
    now = now_of(request)

    def load() -> tuple[CourseRecord, str]:
        course = _staff(services, principal, course_id)
        return course, gradebook.to_csv(
            service.course_gradebook(services.stores, services.catalog, course, now)
        )

    course, text = await run_in_threadpool(load)
    return Response(
        text,
        media_type="text/csv; charset=utf-8",
        headers={"Content-Disposition": f'attachment; filename="gradebook-course-{course.id}.csv"'},
    )


# ---- uploads shared to the bank -----------------------------------------------------------------


@router.put("/v1/problems/{problem_id}/shared", response_model=ShareIn, responses=errors(403, 404, 422))
async def share_problem(
    problem_id: SharedProblemPath,
    body: Annotated[ShareIn, Body(openapi_examples=examples.SHARE)],
    services: ServicesDep,
    principal: Instructor,
) -> ShareIn:
    """Share one's upload to the bank (every instructor may then assign it), or take it back."""

    def save() -> ShareIn:
        try:
            record = services.catalog.get(problem_id)
        except ProblemNotFound:
            record = None
        owner = principal.api_key and record is not None and str(record.owner_key_id) == principal.key_id
        if not owner:
            raise NotFound(f"There is no upload {problem_id!r} of yours.")
        assert record is not None
        services.stores.courses.share_problem(record.id, body.shared)
        return body

    return await run_in_threadpool(save)
