"""The instructor's course pages, scoped to the courses the visitor teaches (a key session or an LMS
instructor's launch alike: `access.require_staff`).

    GET|POST  /instructor/courses                        my courses; make one
    GET       /instructor/courses/{c}                    roster, sign-in links, assignments
    POST      /instructor/courses/{c}/roster             import a roster CSV (pasted or a file)
    POST      /instructor/courses/{c}/links              new personal sign-in links (shown once)
    POST      /instructor/courses/{c}/join-code          a new join code, or none
    GET|POST  /instructor/courses/{c}/assignments/new    the assignment builder
    GET|POST  /instructor/assignments/{a}/edit           the same, for an assignment
    GET       /instructor/courses/{c}/gradebook          students x assignments, a student's parts
    GET       /instructor/assignments/{a}/results        how the course did on each part
    POST      /instructor/assignments/{a}/delete         the assignment goes (its answers stay)
    POST      /instructor/assignments/{a}/release-solutions   its worked solutions open to students now
    POST      /instructor/courses/{c}/extensions         a student's own due date
    POST      /instructor/problems/{id}/as-student       view the student's page in one's own session
"""

from __future__ import annotations

import re
from dataclasses import replace
from datetime import datetime
from typing import Any
from urllib.parse import urlencode
from zoneinfo import ZoneInfo

from fastapi import APIRouter, Request
from fastapi.responses import RedirectResponse, Response
from starlette.concurrency import run_in_threadpool
from starlette.datastructures import UploadFile

from app.courses import access, gradebook, service
from app.courses import sessions as course_sessions
from app.courses.policy import SOLUTIONS_OPEN, granted, late_policy_text, shown
from app.courses.records import (
    AssignmentNotFound,
    AssignmentRecord,
    AssignmentSpec,
    CourseNotFound,
    CourseRecord,
    LateKind,
    LatePolicy,
    SolutionRelease,
    StaffRole,
)
from app.courses.roster_csv import parse_roster
from app.db.errors import ProblemNotFound
from app.deps import RecordId, ServicesDep
from app.instructor import session as auth
from app.instructor.builder_fields import LOCAL, fields_of, fields_typed
from app.instructor.router import PageError, Visitor, _page
from app.services import Services
from app.web.course_pages import course_cookie

router = APIRouter(prefix="/instructor", include_in_schema=False)
MAX_ROSTER_BYTES = 1_000_000
_PROBLEM_ID = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]{0,99}$")


def _course(
    services: Services, who: auth.Visitor, course_id: int, *, only_instructors_may: str = ""
) -> CourseRecord:
    try:
        return access.require_staff(
            services.stores, who.principal, course_id, only_instructors_may=only_instructors_may
        )
    except CourseNotFound:
        raise PageError(404, "No such course", f"There is no course {course_id} of yours.") from None
    except access.InstructorsOnly as refused:
        raise PageError(403, "For the course's instructors", refused.message) from None


def _assignment(
    services: Services, who: auth.Visitor, assignment_id: int, *, only_instructors_may: str = ""
) -> tuple[CourseRecord, AssignmentRecord]:
    """The assignment and its course when the caller teaches it; one of another course is answered
    as one that does not exist, never naming its course (which would tell that it exists)."""
    try:
        record = services.stores.courses.get_assignment(assignment_id)
        course = access.require_staff(
            services.stores, who.principal, record.course_id, only_instructors_may=only_instructors_may
        )
    except (AssignmentNotFound, CourseNotFound):
        raise PageError(
            404, "No such assignment", f"There is no assignment {assignment_id} of yours."
        ) from None
    except access.InstructorsOnly as refused:
        raise PageError(403, "For the course's instructors", refused.message) from None
    return course, record


def _known_zone(name: str) -> bool:
    try:
        ZoneInfo(name)
    except (ValueError, KeyError):
        return False
    return bool(name)


def _parse_local(text: str, timezone: str) -> datetime | None:
    try:
        return datetime.strptime(text.strip(), LOCAL).replace(tzinfo=ZoneInfo(timezone))
    except ValueError:
        return None


# ---- my courses ------------------------------------------------------------------------------------


@router.get("/courses")
async def courses(request: Request, services: ServicesDep, who: Visitor) -> Response:
    rows = await run_in_threadpool(access.taught_courses, services.stores, who.principal)
    return await _page(request, services, who, "instructor/courses.html", {"title": "Courses", "rows": rows})


@router.post("/courses")
async def create_course(request: Request, services: ServicesDep, who: Visitor) -> Response:
    await auth.require_csrf(request, services, who)
    form = await request.form()
    title = str(form.get("title") or "").strip()[:200]
    timezone = str(form.get("timezone") or "UTC").strip()[:64]
    errors = [] if title else ["Give the course a title."]
    if not _known_zone(timezone):
        # it had become UTC without a word, and every date of the course was then shown in UTC
        errors.append(
            f"“{timezone}” is not a time zone name: write it as Region/City, such as Europe/Paris or "
            "America/New_York (or UTC)."
        )
    if errors:
        rows = await run_in_threadpool(access.taught_courses, services.stores, who.principal)
        values = {
            "title": "Courses",
            "rows": rows,
            "errors": errors,
            "typed": {"title": title, "timezone": timezone},
        }
        return await _page(request, services, who, "instructor/courses.html", values, status=422)
    member = who.principal.member
    if member is None:
        raise PageError(403, "Not an instructor", "This session cannot teach a course.")
    course = await run_in_threadpool(
        lambda: services.stores.courses.create_course(
            title, owner=member, owner_name=who.principal.name, timezone=timezone
        )
    )
    return RedirectResponse(f"/instructor/courses/{course.id}", status_code=303)


# ---- one course: roster, links, assignments --------------------------------------------------------


def _course_context(services: Services, who: auth.Visitor, course: CourseRecord) -> dict[str, Any]:
    assignments = services.stores.courses.assignments(course.id)
    role = access.course_role(services.stores, who.principal, course.id)
    return {
        "course": course,
        # a teaching assistant is refused the roster's import, the join code and the assignments'
        # changes: the page offers them only to the course's instructors
        "instructs": role is StaffRole.INSTRUCTOR,
        "roster": services.stores.courses.roster(course.id),
        "staff": services.stores.courses.staff(course.id),
        "assignments": [
            {
                "record": a,
                "opens": shown(a.spec.opens_at, course.timezone),
                "due": shown(a.spec.due_at, course.timezone),
                "late": late_policy_text(a.spec.late),
                "problems": len(a.problems),
                "attempts": a.spec.max_attempts,
                "solutions": SOLUTIONS_OPEN[a.spec.solutions],
            }
            for a in assignments
        ],
    }


@router.get("/courses/{course_id}")
async def course_page(course_id: RecordId, request: Request, services: ServicesDep, who: Visitor) -> Response:
    def load() -> dict[str, Any]:
        return _course_context(services, who, _course(services, who, course_id))

    values = await run_in_threadpool(load)
    return await _page(
        request, services, who, "instructor/course.html", {"title": values["course"].title, **values}
    )


@router.post("/courses/{course_id}/roster")
async def import_roster(
    course_id: RecordId, request: Request, services: ServicesDep, who: Visitor
) -> Response:
    await auth.require_csrf(request, services, who)
    form = await request.form()
    text = str(form.get("roster") or "")
    upload = form.get("file")
    if isinstance(upload, UploadFile) and upload.filename:
        text = (await upload.read(MAX_ROSTER_BYTES + 1)).decode("utf-8", errors="replace")
    await form.close()  # an empty file field is still a temporary file
    rows, problems = parse_roster(text)

    def save() -> dict[str, Any]:
        course = _course(services, who, course_id, only_instructors_may="import its roster")
        values = _course_context(services, who, course)
        if problems or not rows:
            values["roster_problems"] = problems or []
            values["roster_text"] = text
            values["roster_empty"] = not problems
            return values
        done = services.stores.courses.import_roster(course_id, rows)
        values = _course_context(services, who, course)
        values["imported"] = done
        return values

    values = await run_in_threadpool(save)
    status = 422 if values.get("roster_problems") or values.get("roster_empty") else 200
    return await _page(
        request,
        services,
        who,
        "instructor/course.html",
        {"title": values["course"].title, **values},
        status=status,
    )


@router.post("/courses/{course_id}/links")
async def sign_in_links(
    course_id: RecordId, request: Request, services: ServicesDep, who: Visitor
) -> Response:
    """New personal links for everyone on the roster, or for one student: shown once, on this page."""
    await auth.require_csrf(request, services, who)
    form = await request.form()
    only = str(form.get("student") or "")
    now = request.app.state.lti.clock()
    base = str(request.base_url).rstrip("/")

    def issue() -> dict[str, Any]:
        course = _course(services, who, course_id)
        roster = services.stores.courses.roster(course_id)
        chosen = [e for e in roster if not only or e.student == only]
        links = [
            {
                "enrolment": e,
                "url": base
                + course_sessions.SIGN_IN_PATH
                + course_sessions.issue_link(services.stores.courses, course_id, e.student, now),
            }
            for e in chosen
        ]
        return {
            "course": course,
            "links": links,
            "expires": shown(now + course_sessions.LINK_LIFETIME, course.timezone),
        }

    values = await run_in_threadpool(issue)
    return await _page(request, services, who, "instructor/links.html", {"title": "Sign-in links", **values})


# ---- the assignment builder ---------------------------------------------------------------------


def _builder_context(
    services: Services,
    who: auth.Visitor,
    course: CourseRecord,
    record: AssignmentRecord | None,
    query: str,
    now: datetime,
    chosen: list[str] | None = None,
    typed: dict[str, str] | None = None,
) -> dict[str, Any]:
    colleagues = access.colleagues(services.stores, who.principal)
    shared = services.stores.courses.shared_problems()
    picked = list(record.problems) if chosen is None and record is not None else list(chosen or [])
    bank = []
    needle = query.casefold().strip()
    for problem in services.catalog.list():
        if not access.may_use_problem(problem, who.principal, colleagues, shared):
            continue
        doc = services.catalog.document(problem)
        haystack = " ".join([doc.title, problem.id, *doc.topics]).casefold()
        if needle and needle not in haystack and problem.id not in picked:
            continue
        bank.append({"id": problem.id, "title": doc.title, "topics": doc.topics, "parts": len(doc.parts)})
    bank.sort(
        key=lambda row: (
            picked.index(row["id"]) if row["id"] in picked else len(picked),
            str(row["title"]).casefold(),
        )
    )
    spec = record.spec if record is not None else None
    return {
        "course": course,
        "record": record,
        "query": query,
        "bank": bank,
        "picked": picked,
        "fields": typed or fields_of(spec, course.timezone, now),
        "solutions_open": SOLUTIONS_OPEN,
    }


@router.get("/courses/{course_id}/assignments/new")
async def new_assignment(
    course_id: RecordId, request: Request, services: ServicesDep, who: Visitor, q: str = "", pick: str = ""
) -> Response:
    """The builder; `pick` ticks a problem already (a problem's page links here to assign it)."""

    def load() -> dict[str, Any]:
        course = _course(services, who, course_id, only_instructors_may="add assignments")
        chosen = [pick] if _PROBLEM_ID.match(pick) else []
        now = request.app.state.lti.clock()
        return _builder_context(services, who, course, None, q[:100], now, chosen)

    values = await run_in_threadpool(load)
    return await _page(
        request, services, who, "instructor/assignment.html", {"title": "New assignment", **values}
    )


@router.get("/assignments/{assignment_id}/edit")
async def edit_assignment(
    assignment_id: RecordId, request: Request, services: ServicesDep, who: Visitor, q: str = ""
) -> Response:
    def load() -> dict[str, Any]:
        course, record = _assignment(
            services, who, assignment_id, only_instructors_may="change its assignments"
        )
        return _builder_context(services, who, course, record, q[:100], request.app.state.lti.clock())

    values = await run_in_threadpool(load)
    return await _page(
        request,
        services,
        who,
        "instructor/assignment.html",
        {"title": f"Edit {values['record'].title}", **values},
    )


def _read_builder(form: Any, course: CourseRecord) -> tuple[AssignmentSpec | None, list[str], list[str]]:
    """(the spec or None, the problems picked in order, what is wrong) from the builder's form."""
    errors = []
    orders = []
    for index, problem_id in enumerate(form.getlist("problem")):
        raw = str(form.get(f"order-{problem_id}") or "")
        orders.append((int(raw) if raw.isdigit() else 1000 + index, index, str(problem_id)))
    picked = [problem_id for _, _, problem_id in sorted(orders)]
    title = str(form.get("title") or "").strip()[:200]
    opens = _parse_local(str(form.get("opens_at") or ""), course.timezone)
    due = _parse_local(str(form.get("due_at") or ""), course.timezone)
    if not title:
        errors.append("Give the assignment a title.")
    if not picked:
        errors.append("Pick at least one problem.")
    if opens is None or due is None:
        errors.append("Set both the opening and the due date.")
    elif due < opens:
        # moving a due date into the past meets the opening date left as it was: say which to move
        errors.append(
            f"The due date, {shown(due, course.timezone)}, is before the opening date,"
            f" {shown(opens, course.timezone)}: set Opens earlier too, or the due date later."
        )
    kind = (
        LateKind(str(form.get("late") or "closed"))
        if form.get("late") in ("closed", "penalty")
        else LateKind.CLOSED
    )
    try:
        per_day = float(str(form.get("per_day") or "0")) / 100
        limit = float(str(form.get("limit") or "100")) / 100
        late = LatePolicy(kind, per_day, limit)
    except ValueError:
        errors.append("The late penalty is a percentage from 0 to 100.")
        late = LatePolicy()
    attempts_text = str(form.get("max_attempts") or "").strip()
    max_attempts = int(attempts_text) if attempts_text.isdigit() and int(attempts_text) > 0 else None
    if attempts_text and max_attempts is None:
        errors.append("Attempts per part is a whole number of at least 1, or empty for each problem's own.")
    release = str(form.get("solutions") or "after_due")
    solutions = (
        SolutionRelease(release)
        if release in {r.value for r in SolutionRelease}
        else SolutionRelease.AFTER_DUE
    )
    if errors or opens is None or due is None:
        return None, picked, errors
    return AssignmentSpec(title, tuple(picked), opens, due, late, max_attempts, solutions), picked, errors


async def _save_builder(
    request: Request, services: Services, who: auth.Visitor, course_id: int | None, assignment_id: int | None
) -> Response:
    await auth.require_csrf(request, services, who)
    form = await request.form()

    def save() -> dict[str, Any] | int:
        if assignment_id is not None:
            course, record = _assignment(
                services, who, assignment_id, only_instructors_may="change its assignments"
            )
        else:
            assert course_id is not None
            course, record = _course(services, who, course_id, only_instructors_may="add assignments"), None
        spec, picked, errors = _read_builder(form, course)
        colleagues = access.colleagues(services.stores, who.principal)
        shared = services.stores.courses.shared_problems()
        assigned = record.problems if record is not None else ()
        for problem_id in picked:
            try:
                found = services.catalog.get(problem_id)
            except ProblemNotFound:
                errors.append(f"There is no problem {problem_id!r} of yours.")
                continue
            if not access.may_use_problem(found, who.principal, colleagues, shared):
                errors.append(f"There is no problem {problem_id!r} of yours.")
            elif problem_id not in assigned and services.catalog.refusal(found) is not None:
                errors.append(
                    f"{problem_id!r} no longer verifies under this version of physcheck, so students could "
                    "not answer it: edit it first (its page says why)."
                )
        if spec is None or errors:
            now = request.app.state.lti.clock()
            values = _builder_context(services, who, course, record, "", now, picked, fields_typed(form))
            return {**values, "errors": errors}
        if record is None:
            return services.stores.courses.create_assignment(course.id, spec).course_id
        return services.stores.courses.update_assignment(record.id, spec).course_id

    outcome = await run_in_threadpool(save)
    if isinstance(outcome, int):
        return RedirectResponse(f"/instructor/courses/{outcome}?saved=assignment", status_code=303)
    return await _page(
        request, services, who, "instructor/assignment.html", {"title": "Assignment", **outcome}, status=422
    )


@router.post("/courses/{course_id}/assignments/new")
async def create_assignment(
    course_id: RecordId, request: Request, services: ServicesDep, who: Visitor
) -> Response:
    return await _save_builder(request, services, who, course_id, None)


@router.post("/assignments/{assignment_id}/edit")
async def update_assignment(
    assignment_id: RecordId, request: Request, services: ServicesDep, who: Visitor
) -> Response:
    return await _save_builder(request, services, who, None, assignment_id)


@router.post("/assignments/{assignment_id}/delete")
async def delete_assignment(
    assignment_id: RecordId, request: Request, services: ServicesDep, who: Visitor
) -> Response:
    """As the API's DELETE: the assignment goes, its students' answers stay in the log."""
    await auth.require_csrf(request, services, who)

    def remove() -> int:
        course, record = _assignment(
            services, who, assignment_id, only_instructors_may="delete its assignments"
        )
        services.stores.courses.delete_assignment(record.id)
        return course.id

    course_id = await run_in_threadpool(remove)
    return RedirectResponse(f"/instructor/courses/{course_id}?saved=deleted", status_code=303)


@router.post("/assignments/{assignment_id}/release-solutions")
async def release_solutions(
    assignment_id: RecordId, request: Request, services: ServicesDep, who: Visitor
) -> Response:
    """Worked solutions open to every student now; one who opens one while their answers still count
    earns nothing on its parts after (app/web/solution_page.py)."""
    await auth.require_csrf(request, services, who)

    def release() -> int:
        course, record = _assignment(
            services, who, assignment_id, only_instructors_may="release its worked solutions"
        )
        spec = replace(record.spec, solutions=SolutionRelease.RELEASED)
        services.stores.courses.update_assignment(record.id, spec)
        return course.id

    course_id = await run_in_threadpool(release)
    return RedirectResponse(f"/instructor/courses/{course_id}?saved=released", status_code=303)


# ---- the gradebook ---------------------------------------------------------------------------------


@router.get("/courses/{course_id}/gradebook")
async def gradebook_page(
    course_id: RecordId, request: Request, services: ServicesDep, who: Visitor, student: str = ""
) -> Response:
    now = request.app.state.lti.clock()

    def load() -> dict[str, Any]:
        course = _course(services, who, course_id)
        book = service.course_gradebook(services.stores, services.catalog, course, now)
        return {
            "course": course,
            "book": book,
            "student": student,
            "shown": shown,
            "extension_note": lambda cell: gradebook.extension_note(
                cell, lambda d: shown(d, course.timezone)
            ),
            "titles": _titles(services, {p for a in book.assignments for p in a.problems}),
        }

    values = await run_in_threadpool(load)
    return await _page(
        request,
        services,
        who,
        "instructor/gradebook.html",
        {"title": f"Gradebook: {values['course'].title}", **values},
    )


def _titles(services: Services, problem_ids: set[str]) -> dict[str, str]:
    """Each problem's title, by id (a retired or unknown problem keeps its id)."""
    titles = {}
    for problem_id in problem_ids:
        try:
            titles[problem_id] = services.catalog.document(services.catalog.get(problem_id)).title
        except ProblemNotFound:
            titles[problem_id] = problem_id
    return titles


@router.get("/courses/{course_id}/gradebook.csv")
async def gradebook_csv(
    course_id: RecordId, request: Request, services: ServicesDep, who: Visitor
) -> Response:
    now = request.app.state.lti.clock()

    def load() -> str:
        course = _course(services, who, course_id)
        return gradebook.to_csv(service.course_gradebook(services.stores, services.catalog, course, now))

    text = await run_in_threadpool(load)
    return Response(
        text,
        media_type="text/csv; charset=utf-8",
        headers={"Content-Disposition": f'attachment; filename="gradebook-course-{course_id}.csv"'},
    )


@router.post("/courses/{course_id}/extensions")
async def extension(course_id: RecordId, request: Request, services: ServicesDep, who: Visitor) -> Response:
    await auth.require_csrf(request, services, who)
    form = await request.form()
    student = str(form.get("student") or "")
    assignment_text = str(form.get("assignment") or "")

    def save() -> None:
        course = _course(services, who, course_id)
        if services.stores.courses.enrolment(course_id, student) is None or not assignment_text.isdigit():
            raise PageError(
                422, "No such student or assignment", "Pick a student and an assignment of this course."
            )
        try:
            record = services.stores.courses.get_assignment(int(assignment_text))
        except AssignmentNotFound:
            record = None
        if record is None or record.course_id != course_id:
            raise PageError(422, "No such assignment", "Pick an assignment of this course.")
        due = _parse_local(str(form.get("due_at") or ""), course.timezone)
        now = request.app.state.lti.clock()
        current = services.stores.courses.extensions(record.id).get(student)
        extension = (
            None
            if due is None
            else granted(current, due, now, regrade_earlier=form.get("regrade_earlier") == "on")
        )
        services.stores.courses.set_extension(record.id, student, extension)
        service.resend_total(services.stores, services.catalog, record, student, now)

    await run_in_threadpool(save)
    # back to the student's own parts, with what now stands: the form alone had reset to the first student
    shown_again = urlencode({"student": student, "extended": assignment_text})
    return RedirectResponse(f"/instructor/courses/{course_id}/gradebook?{shown_again}", status_code=303)


# ---- view as a student -----------------------------------------------------------------------------


@router.post("/problems/{problem_id}/as-student")
async def view_as_student(problem_id: str, request: Request, services: ServicesDep, who: Visitor) -> Response:
    """The student's page of a problem in the instructor's own session: a key's visitor gets a
    student session under their preview identity (their tries filed apart, as always); an LMS
    instructor's launch session already previews."""
    await auth.require_csrf(request, services, who)
    if not _PROBLEM_ID.match(problem_id):
        raise PageError(404, "No such problem", f"There is no problem {problem_id!r}.")
    response = RedirectResponse(f"/p/{problem_id}", status_code=303)
    if who.principal.api_key:
        context = request.app.state.lti
        cookie, session = await run_in_threadpool(
            course_sessions.open_preview,
            services.stores.courses,
            who.principal.key_id,
            who.principal.name,
            problem_id,
            context.clock(),
        )
        # beside the browser's course sessions, not in place of them (the preview is the latest)
        await course_cookie(response, request, context, cookie, session)
    return response


@router.post("/courses/{course_id}/join-code")
async def join_code(course_id: RecordId, request: Request, services: ServicesDep, who: Visitor) -> Response:
    """A fresh join code for the course, or none (`enabled=0`)."""
    await auth.require_csrf(request, services, who)
    form = await request.form()
    enabled = str(form.get("enabled") or "1") != "0"

    def save() -> None:
        _course(services, who, course_id, only_instructors_may="change its join code")
        services.stores.courses.set_join_code(course_id, course_sessions.new_join_code() if enabled else None)

    await run_in_threadpool(save)
    return RedirectResponse(f"/instructor/courses/{course_id}#join", status_code=303)


@router.get("/assignments/{assignment_id}/results")
async def assignment_results(
    assignment_id: RecordId, request: Request, services: ServicesDep, who: Visitor
) -> Response:
    """How the course's students did on each part of an assignment (from the gradebook: only this
    course's students, late penalties applied to the scores)."""
    now = request.app.state.lti.clock()

    def load() -> dict[str, Any]:
        course, record = _assignment(services, who, assignment_id)
        book = service.course_gradebook(services.stores, services.catalog, course, now)
        cells = [book.cell(e.student, record.id) for e in book.students]
        rows = []
        titles: dict[str, str] = {}
        for index, part in enumerate(service.assignment_parts(services.catalog, record)):
            done = [c.parts[index] for c in cells if index < len(c.parts)]
            tried = [p for p in done if p.attempts]
            if part.problem_id not in titles:
                titles[part.problem_id] = services.catalog.document(
                    services.catalog.get(part.problem_id)
                ).title
            rows.append(
                {
                    "problem": part.problem_id,
                    "title": titles[part.problem_id],
                    "part": part.part_id,
                    "tried": len(tried),
                    "correct": sum(p.solved for p in tried),
                    "late": sum(p.late for p in tried),
                    "mean": sum(p.score for p in done) / len(done) if done else 0.0,
                    "attempts": sum(p.attempts for p in tried) / len(tried) if tried else 0.0,
                }
            )
        statuses: dict[str, int] = {}
        for cell in cells:
            statuses[cell.status.value] = statuses.get(cell.status.value, 0) + 1
        return {
            "course": course,
            "record": record,
            "rows": rows,
            "students": len(cells),
            "statuses": statuses,
        }

    values = await run_in_threadpool(load)
    return await _page(
        request,
        services,
        who,
        "instructor/assignment_results.html",
        {"title": f"Results: {values['record'].title}", **values},
    )
