"""Class results are counted from the submissions log: students only (instructors' previews apart),
per part, with attempts to the first correct answer and wrong answers grouped by reason and mistake."""

from __future__ import annotations

import pytest

from app.storage import Stores
from physics.verdict import Outcome, ReadAs, Reason, Verdict
from tests.db.helpers import INVALID, PART, PROBLEM, StepClock
from tests.storage.conftest import StoresFor
from tests.storage.helpers import store_problem, submit

OTHER_PART = "block_relative_acceleration"
RIGHT = Verdict(Outcome.CORRECT, 1.0, Reason.EQUIVALENT, "Correct.", ReadAs("m*g", "m g"))
SIGN = Verdict(Outcome.INCORRECT, 0.0, Reason.SIGN_ERROR, "Check the sign.", ReadAs("-m*g", "- m g"))
FREE_FALL = Verdict(Outcome.INCORRECT, 0.0, Reason.KNOWN_MISTAKE, "Not free fall.", ReadAs("g", "g"))
HALF = Verdict(Outcome.INCORRECT, 0.0, Reason.KNOWN_MISTAKE, "Half of it.", ReadAs("g/2", r"\frac{g}{2}"))
DIMENSION = Verdict(Outcome.INCORRECT, 0.0, Reason.WRONG_DIMENSION, "Not an acceleration.", ReadAs("m", "m"))

# (student, part, typed answer, verdict), in the order they were filed.
LOG = [
    ("ada", PART, "-m g", SIGN),
    ("ada", PART, "m g", RIGHT),  # first correct at attempt 2
    ("ada", PART, "m g", RIGHT),  # a later correct answer does not move the first
    ("bob", PART, "g", FREE_FALL),
    ("bob", PART, "m g +", INVALID),  # unreadable: no attempt used
    ("bob", PART, "G", FREE_FALL),  # typed differently, read alike: one wrong answer
    ("bob", PART, "m*g", RIGHT),  # first correct at attempt 3
    ("cy", PART, "g/2", HALF),
    ("cy", PART, "m", DIMENSION),
    ("dee", PART, "m g", RIGHT),  # first correct at attempt 1
    ("eve", PART, "m g +", INVALID),  # tried, nothing graded
    ("ada", OTHER_PART, "g", FREE_FALL),
    ("preview:7", PART, "g", FREE_FALL),  # an instructor's own tries
    ("preview:7", PART, "m g", RIGHT),
    ("preview:lti-session:abc", OTHER_PART, "m g", RIGHT),
]


@pytest.fixture
def stores(stores_for: StoresFor) -> Stores:
    """Stores holding LOG."""
    stores = stores_for(StepClock())
    version = store_problem(stores)
    for student, part, answer, verdict in LOG:
        submit(stores, version, verdict, student=student, part=part, answer=answer)
    return stores


def results(stores: Stores, parts: list[str]) -> dict:
    return {r.part_id: r for r in stores.submissions.class_results(PROBLEM, parts)}


def test_tried_correct_and_attempts_to_first_correct_count_students_only(stores: Stores) -> None:
    part = results(stores, [PART])[PART]
    assert (part.tried, part.correct, part.graded) == (5, 3, 9)
    assert part.percent_correct == 60.0
    assert part.first_correct == {1: 1, 2: 1, 3: 1}
    assert part.median_attempts == 2.0
    assert part.previews == 2


def test_wrong_answers_are_grouped_by_reason_by_known_mistake_and_by_reading(stores: Stores) -> None:
    part = results(stores, [PART])[PART]
    assert [(c.key, c.submissions, c.students) for c in part.wrong_reasons] == [
        ("known_mistake", 3, 2),
        ("sign_error", 1, 1),
        ("wrong_dimension", 1, 1),
    ]
    assert [(c.key, c.submissions, c.students) for c in part.invalid_reasons] == [("parse_error", 2, 2)]
    assert [(c.key, c.submissions, c.students) for c in part.mistakes] == [
        ("Not free fall.", 2, 1),
        ("Half of it.", 1, 1),
    ]
    assert [(a.answer, a.latex, a.reason, a.submissions) for a in part.wrong_answers] == [
        ("g", "g", "known_mistake", 2),
        ("-m*g", "- m g", "sign_error", 1),
        ("g/2", r"\frac{g}{2}", "known_mistake", 1),
        ("m", "m", "wrong_dimension", 1),
    ]


def test_incorrect_feedback_is_kept_per_student_for_kinds_to_read_findings_from(stores: Stores) -> None:
    part = results(stores, [PART])[PART]
    told = sorted((t.student, t.feedback, t.submissions) for t in part.wrong_feedback)
    assert told == [
        ("ada", "Check the sign.", 1),
        ("bob", "Not free fall.", 2),  # typed twice, told alike: one row of two
        ("cy", "Half of it.", 1),
        ("cy", "Not an acceleration.", 1),
    ]  # neither the unreadable answers nor the instructors' tries


def test_parts_come_in_the_order_asked_and_an_untried_part_is_all_zero(stores: Stores) -> None:
    found = stores.submissions.class_results(PROBLEM, [OTHER_PART, "normal_force", PART])
    assert [r.part_id for r in found] == [OTHER_PART, "normal_force", PART]
    other, untried = found[0], found[1]
    assert (other.tried, other.correct, other.previews) == (1, 0, 1)
    assert (untried.tried, untried.correct, untried.percent_correct, untried.median_attempts) == (
        0,
        0,
        None,
        None,
    )
    assert untried.first_correct == {} and not untried.wrong_answers


def test_another_problems_submissions_do_not_count(stores: Stores) -> None:
    found = stores.submissions.class_results("yo-yo", [PART])
    assert (found[0].tried, found[0].graded, found[0].previews) == (0, 0, 0)
