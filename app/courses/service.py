"""Course work read together from the stores and the catalog: an assignment's parts, a student's
submissions, a course's gradebook. Blocking (database, documents): call it off the event loop."""

from __future__ import annotations

from datetime import datetime

from app.catalog import Catalog
from app.courses import gradebook, passback
from app.courses.gradebook import AssignmentCell, Gradebook, PartSpec
from app.courses.records import AssignmentRecord, CourseRecord
from app.db.errors import ProblemNotFound
from app.db.records import SubmissionRecord
from app.storage import Stores
from app.storage.protocols import MAX_PAGE_LIMIT


def assignment_parts(catalog: Catalog, assignment: AssignmentRecord) -> list[PartSpec]:
    """Every part of its problems, in order (a retired or unknown problem has none)."""
    parts = []
    for problem_id in assignment.problems:
        try:
            record = catalog.get(problem_id)
        except ProblemNotFound:
            continue
        for part in catalog.document(record).parts:
            parts.append(PartSpec(problem_id, part.id, catalog.max_attempts(record, part.id)))
    return parts


def submissions_of(stores: Stores, student: str) -> list[SubmissionRecord]:
    items: list[SubmissionRecord] = []
    cursor = None
    while True:
        page = stores.submissions.page(student=student, limit=MAX_PAGE_LIMIT, cursor=cursor)
        items.extend(page.items)
        if page.next is None:
            return items
        cursor = page.next


def course_gradebook(stores: Stores, catalog: Catalog, course: CourseRecord, now: datetime) -> Gradebook:
    students = stores.courses.roster(course.id)
    assignments = stores.courses.assignments(course.id)
    return gradebook.build(
        students,
        assignments,
        {a.id: assignment_parts(catalog, a) for a in assignments},
        {e.student: submissions_of(stores, e.student) for e in students},
        {a.id: stores.courses.extensions(a.id) for a in assignments},
        now,
        {e.student: stores.courses.solutions_opened(e.student) for e in students},
    )


def student_cell(
    stores: Stores, catalog: Catalog, assignment: AssignmentRecord, student: str, now: datetime
) -> AssignmentCell:
    wanted = set(assignment.problems)
    mine = [s for s in submissions_of(stores, student) if s.problem_id in wanted]
    extension = stores.courses.extensions(assignment.id).get(student)
    return gradebook.assignment_cell(
        assignment,
        assignment_parts(catalog, assignment),
        mine,
        student,
        extension,
        now,
        stores.courses.solutions_opened(student),
    )


def resend_total(
    stores: Stores, catalog: Catalog, assignment: AssignmentRecord, student: str, now: datetime
) -> int:
    """Queue the student's assignment total again for its LMS line items (after an extension changed
    the penalty); how many were queued (none when it was not launched from an LMS)."""
    cell = student_cell(stores, catalog, assignment, student, now)
    return stores.outbox.enqueue(
        passback.target_key(assignment.id), student, cell.score, float(max(cell.maximum, 1)), now
    )
