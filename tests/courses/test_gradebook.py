"""Late penalties, statuses and the gradebook, computed from submissions as they were filed."""

from __future__ import annotations

import csv
import io
import uuid
from datetime import UTC, datetime, timedelta

import pytest

from app.courses import gradebook
from app.courses.gradebook import PartSpec
from app.courses.policy import Status, days_late, granted, late_factor, shown, solutions_released
from app.courses.records import (
    AssignmentRecord,
    AssignmentSpec,
    EnrolmentRecord,
    ExtensionRecord,
    LateKind,
    LatePolicy,
    SolutionRelease,
)
from app.db.records import SubmissionRecord
from physics.verdict import Outcome, Reason

DUE = datetime(2026, 3, 2, 23, 59, tzinfo=UTC)
PENALTY = LatePolicy(LateKind.PENALTY, 0.1, 0.3)
PARTS = [PartSpec("yo-yo", "acceleration", None), PartSpec("yo-yo", "tension", 2)]


def _assignment(late: LatePolicy = PENALTY, **changes) -> AssignmentRecord:
    spec = AssignmentSpec(
        **{
            "title": "HW1",
            "problems": ("yo-yo",),
            "opens_at": DUE - timedelta(days=7),
            "due_at": DUE,
            "late": late,
            "solutions": SolutionRelease.AFTER_DUE,
        }
        | changes
    )
    return AssignmentRecord(1, 1, spec, DUE - timedelta(days=8))


def _sub(part: str, outcome: Outcome, at: datetime, student: str = "s1") -> SubmissionRecord:
    return SubmissionRecord(
        id=uuid.uuid4(),
        problem_id="yo-yo",
        problem_version=1,
        part_id=part,
        student=student,
        answer="x",
        verdict=outcome,
        score=1.0 if outcome is Outcome.CORRECT else 0.0,
        reason=Reason.EQUIVALENT if outcome is Outcome.CORRECT else Reason.WRONG_VALUE,
        feedback="",
        read_as=None,
        attempt=None if outcome is Outcome.INVALID else 1,
        created_at=at,
    )


@pytest.mark.parametrize(
    ("after_due", "days", "penalty_factor", "closed_factor"),
    [
        (timedelta(0), 0, 1.0, 1.0),
        (timedelta(seconds=-1), 0, 1.0, 1.0),
        (timedelta(minutes=1), 1, 0.9, None),
        (timedelta(days=1), 1, 0.9, None),
        (timedelta(days=1, seconds=1), 2, 0.8, None),
        (timedelta(days=10), 10, 0.7, None),  # the limit: never more than 30 % off
    ],
)
def test_a_late_day_is_any_part_of_a_day_and_the_penalty_stops_at_its_limit(
    after_due, days, penalty_factor, closed_factor
):
    assert days_late(DUE + after_due, DUE) == days
    assert late_factor(PENALTY, DUE + after_due, DUE) == pytest.approx(penalty_factor)
    assert late_factor(LatePolicy(), DUE + after_due, DUE) == closed_factor


def test_a_late_right_answer_counts_with_its_penalty_and_is_marked():
    subs = [_sub("acceleration", Outcome.CORRECT, DUE + timedelta(hours=30))]
    cell = gradebook.assignment_cell(_assignment(), PARTS, subs, "s1", None, DUE + timedelta(days=3))
    assert cell.score == pytest.approx(0.8) and cell.maximum == 2
    assert cell.late and cell.parts[0].late
    assert cell.status is Status.LATE


def test_an_on_time_right_answer_beats_a_later_penalised_one():
    subs = [
        _sub("acceleration", Outcome.CORRECT, DUE - timedelta(hours=1)),
        _sub("acceleration", Outcome.CORRECT, DUE + timedelta(hours=1)),
    ]
    cell = gradebook.assignment_cell(_assignment(), PARTS, subs, "s1", None, DUE)
    assert cell.score == 1.0 and not cell.late


GRANTED = DUE + timedelta(days=2)  # an extension to EXTENDED, given two days after the due date
EXTENDED = DUE + timedelta(days=5)


@pytest.mark.parametrize(
    ("answered", "granted_at", "solution_opened", "score"),
    [
        # graded two days late before the extension: it keeps its grade, as in an LMS
        (DUE + timedelta(hours=30), GRANTED, None, 0.8),
        # given within the extended window: counts in full
        (DUE + timedelta(days=3), GRANTED, None, 1.0),
        # after the student's own due date: late from it, a day
        (EXTENDED + timedelta(hours=1), GRANTED, None, 0.9),
        # the teacher asked the extension to cover the answers already given
        (DUE + timedelta(hours=30), None, None, 1.0),
        # an extension granted ahead of the due date covers everything after it
        (DUE + timedelta(hours=30), DUE - timedelta(days=1), None, 1.0),
        # within the extension but after opening the worked solution: frozen, earns nothing
        (DUE + timedelta(days=3), GRANTED, DUE + timedelta(hours=50), 0.0),
    ],
)
def test_an_extension_counts_for_answers_given_after_it_was_granted(
    answered, granted_at, solution_opened, score
):
    subs = [_sub("acceleration", Outcome.CORRECT, answered)]
    cell = gradebook.assignment_cell(
        _assignment(),
        PARTS,
        subs,
        "s1",
        ExtensionRecord(EXTENDED, granted_at),
        answered,
        {"yo-yo": solution_opened} if solution_opened else None,
    )
    assert cell.score == pytest.approx(score)
    assert cell.late is (0 < score < 1) and cell.extended and cell.due == EXTENDED


def test_an_extension_lifts_the_penalty_for_that_student_only():
    late = DUE + timedelta(hours=30)
    students = [EnrolmentRecord(1, s, s, s, "", DUE) for s in ("s1", "s2")]
    book = gradebook.build(
        students,
        [_assignment()],
        {1: PARTS},
        {s: [_sub("acceleration", Outcome.CORRECT, late, s)] for s in ("s1", "s2")},
        {1: {"s1": ExtensionRecord(EXTENDED, DUE)}},
        late,
    )
    assert book.cell("s1", 1).score == 1.0 and book.cell("s1", 1).status is Status.IN_PROGRESS
    assert book.cell("s2", 1).score == pytest.approx(0.8) and not book.cell("s2", 1).extended


@pytest.mark.parametrize(
    ("current", "regrade_earlier", "expected"),
    [
        (None, False, ExtensionRecord(EXTENDED, GRANTED)),
        (None, True, ExtensionRecord(EXTENDED, None)),
        # moved: granted anew, the answers before keeping the due date they were given under
        (
            ExtensionRecord(DUE + timedelta(days=1), DUE),
            False,
            ExtensionRecord(EXTENDED, GRANTED, (ExtensionRecord(DUE + timedelta(days=1), DUE),)),
        ),
        (
            ExtensionRecord(DUE + timedelta(days=1), None),
            False,
            ExtensionRecord(EXTENDED, GRANTED, (ExtensionRecord(DUE + timedelta(days=1), None),)),
        ),
        (
            ExtensionRecord(DUE + timedelta(days=1), DUE, (ExtensionRecord(DUE, None),)),
            False,
            ExtensionRecord(
                EXTENDED,
                GRANTED,
                (ExtensionRecord(DUE, None), ExtensionRecord(DUE + timedelta(days=1), DUE)),
            ),
        ),
        # set again to the same date: nothing changes
        (ExtensionRecord(EXTENDED, DUE), False, ExtensionRecord(EXTENDED, DUE)),
        # moved with the tick: it covers every answer, and nothing earlier matters
        (ExtensionRecord(DUE + timedelta(days=1), DUE), True, ExtensionRecord(EXTENDED, None)),
    ],
)
def test_an_extension_is_granted_from_now_unless_the_teacher_regrades_earlier_answers(
    current, regrade_earlier, expected
):
    assert granted(current, EXTENDED, GRANTED, regrade_earlier=regrade_earlier) == expected


@pytest.mark.parametrize(
    ("answered", "score"),
    [
        # before the first grant: late by the assignment's due date, two days
        (DUE + timedelta(hours=25), 0.8),
        # under the first extension (to DUE + 36 h), 4 h past it: late by it, as graded then
        (DUE + timedelta(hours=40), 0.9),
        # after the move: the new due date
        (DUE + timedelta(days=3), 1.0),
    ],
)
def test_a_moved_extension_leaves_each_earlier_answer_the_due_date_it_was_given_under(answered, score):
    first = granted(None, DUE + timedelta(hours=36), DUE + timedelta(hours=26), regrade_earlier=False)
    moved = granted(first, EXTENDED, GRANTED, regrade_earlier=False)
    subs = [_sub("acceleration", Outcome.CORRECT, answered)]
    cell = gradebook.assignment_cell(_assignment(), PARTS, subs, "s1", moved, EXTENDED)
    assert cell.score == pytest.approx(score) and cell.due == EXTENDED


def test_under_a_closed_policy_late_work_does_not_count():
    subs = [_sub("acceleration", Outcome.CORRECT, DUE + timedelta(minutes=5))]
    cell = gradebook.assignment_cell(
        _assignment(LatePolicy()), PARTS, subs, "s1", None, DUE + timedelta(days=1)
    )
    assert cell.score == 0.0 and cell.status is Status.CLOSED


@pytest.mark.parametrize(
    ("subs", "now", "expected"),
    [
        ([], DUE - timedelta(days=8), Status.NOT_OPEN),
        ([], DUE - timedelta(days=1), Status.NOT_STARTED),
        ([("acceleration", Outcome.INVALID)], DUE - timedelta(days=1), Status.IN_PROGRESS),
        ([("acceleration", Outcome.CORRECT)], DUE - timedelta(days=1), Status.IN_PROGRESS),
        (
            [
                ("acceleration", Outcome.CORRECT),
                ("tension", Outcome.INCORRECT),
                ("tension", Outcome.INCORRECT),
            ],
            DUE - timedelta(days=1),
            Status.DONE,  # tension is out of its 2 attempts
        ),
        ([], DUE + timedelta(days=1), Status.LATE),
    ],
)
def test_status_of_a_student_on_an_assignment(subs, now, expected):
    filed = [_sub(part, outcome, DUE - timedelta(days=2)) for part, outcome in subs]
    assert gradebook.assignment_cell(_assignment(), PARTS, filed, "s1", None, now).status is expected


def test_the_csv_has_a_row_per_student_numbers_for_scores_and_inert_text():
    students = [
        EnrolmentRecord(1, "course:1:s1", "s1", "Ada", "ada@x", DUE),
        EnrolmentRecord(1, "course:1:s2", "s2", "=HYPERLINK(1)", "", DUE),
    ]
    subs = {"course:1:s1": [_sub("acceleration", Outcome.CORRECT, DUE + timedelta(hours=2), "course:1:s1")]}
    book = gradebook.build(students, [_assignment()], {1: PARTS}, subs, {}, DUE + timedelta(days=1))
    rows = list(csv.reader(io.StringIO(gradebook.to_csv(book))))
    assert rows[0] == ["Student ID", "Name", "Email", "HW1 (out of 2)", "Total (out of 2)", "Notes"]
    assert rows[1] == ["s1", "Ada", "ada@x", "0.9", "0.9", "HW1: late penalty applied"]
    assert rows[2][1] == "'=HYPERLINK(1)" and rows[2][3] == ""  # nothing answered: no grade, not a 0


@pytest.mark.parametrize(
    ("granted_at", "note"),
    [
        (GRANTED, "HW1: extended to 2026-03-07 23:59 UTC, granted 2026-03-04 23:59 UTC"),
        (None, "HW1: extended to 2026-03-07 23:59 UTC, covering the answers given before it too"),
    ],
)
def test_the_csv_says_when_each_extension_was_granted(granted_at, note):
    students = [EnrolmentRecord(1, "course:1:s1", "s1", "Ada", "ada@x", DUE)]
    extensions = {1: {"course:1:s1": ExtensionRecord(EXTENDED, granted_at)}}
    book = gradebook.build(students, [_assignment()], {1: PARTS}, {}, extensions, GRANTED)
    rows = list(csv.reader(io.StringIO(gradebook.to_csv(book))))
    assert rows[0] == ["Student ID", "Name", "Email", "HW1 (out of 2)", "Total (out of 2)", "Notes"]
    assert rows[1][-1] == note


@pytest.mark.parametrize(
    ("release", "now", "done", "released"),
    [
        (SolutionRelease.NEVER, DUE + timedelta(days=30), True, False),
        (SolutionRelease.AFTER_DUE, DUE - timedelta(minutes=1), True, False),
        (SolutionRelease.AFTER_DUE, DUE + timedelta(minutes=1), False, True),
        (SolutionRelease.AFTER_LAST_ATTEMPT, DUE - timedelta(days=1), False, False),
        (SolutionRelease.AFTER_LAST_ATTEMPT, DUE - timedelta(days=1), True, True),
    ],
)
def test_solutions_open_by_the_assignments_release_policy(release, now, done, released):
    assignment = _assignment(solutions=release)
    assert solutions_released(assignment, DUE, now, all_parts_done=done)[0] is released


def test_dates_are_shown_in_the_courses_zone():
    assert shown(DUE, "America/New_York") == "Mon 02 Mar 2026, 18:59 EST"
    assert shown(DUE, "Not/AZone").endswith("UTC")


@pytest.mark.parametrize(
    ("answered_after_opening", "score"),
    [
        (timedelta(minutes=-1), 0.9),  # answered late, then read the solution: the answer counts
        (timedelta(0), 0.0),
        (timedelta(minutes=1), 0.0),  # read the solution, then answered: checked, earns nothing
    ],
)
def test_answers_after_opening_the_worked_solution_earn_no_credit(answered_after_opening, score):
    opened = DUE + timedelta(hours=1)
    subs = [_sub("acceleration", Outcome.CORRECT, opened + answered_after_opening)]
    cell = gradebook.assignment_cell(
        _assignment(), PARTS, subs, "s1", None, DUE + timedelta(days=1), {"yo-yo": opened}
    )
    assert cell.score == score
    assert cell.parts[0].attempts == 1 and cell.parts[0].frozen_at == opened and cell.frozen


def test_the_csv_notes_a_grade_frozen_by_opening_the_worked_solution():
    students = [EnrolmentRecord(1, "course:1:s1", "s1", "Ada", "ada@x", DUE)]
    opened = DUE + timedelta(hours=1)
    subs = {"course:1:s1": [_sub("acceleration", Outcome.CORRECT, opened, "course:1:s1")]}
    book = gradebook.build(
        students,
        [_assignment()],
        {1: PARTS},
        subs,
        {},
        DUE + timedelta(days=1),
        {"course:1:s1": {"yo-yo": opened}},
    )
    row = list(csv.reader(io.StringIO(gradebook.to_csv(book))))[1]
    assert row[-1] == "HW1: grade frozen, worked solution opened (yo-yo at 2026-03-03 00:59 UTC)"


@pytest.mark.parametrize(
    ("subs", "shown"),
    [
        ([], ""),  # not started
        ([("acceleration", Outcome.INVALID)], ""),  # nothing could be read: still nothing answered
        ([("acceleration", Outcome.INCORRECT)], "0.0"),  # answered wrong: a 0 earned
        ([("acceleration", Outcome.CORRECT)], "1.0"),
    ],
)
def test_the_csv_leaves_an_assignment_not_started_empty_apart_from_a_0_earned(subs, shown):
    students = [EnrolmentRecord(1, "course:1:s1", "s1", "Ada", "ada@x", DUE)]
    filed = {
        "course:1:s1": [
            _sub(part, outcome, DUE - timedelta(hours=1), "course:1:s1") for part, outcome in subs
        ]
    }
    book = gradebook.build(students, [_assignment()], {1: PARTS}, filed, {}, DUE)
    assert list(csv.reader(io.StringIO(gradebook.to_csv(book))))[1][3] == shown
