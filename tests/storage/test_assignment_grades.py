"""A graded submission to a problem of an assignment launched from an LMS queues the assignment's
total (late penalties applied) in the submission's own transaction, for its line item alone; on
SQLite, PostgreSQL and the fake."""

from __future__ import annotations

from datetime import timedelta

from app.courses.passback import target_key
from app.courses.records import AssignmentSpec, LateKind, LatePolicy
from app.db.types import utc_now
from app.lti.platforms import add_platform
from app.storage import Stores
from tests.db.helpers import CORRECT, INCORRECT, INVALID
from tests.storage.helpers import store_problem, submit

NOW = utc_now()
URLS = ("https://lms.example/auth", "https://lms.example/token", "https://lms.example/jwks")


def _launched_assignment(stores: Stores, *, due_in: timedelta, problems=("p1", "p2")) -> int:
    for problem in problems:
        store_problem(stores, problem)
    platform = add_platform(stores.platforms, "https://lms.example", "client", ["d"], *URLS)
    course = stores.courses.create_course("Physics", owner="lti:1:teacher", lti_context=(platform.id, "ctx"))
    made = stores.courses.create_assignment(
        course.id,
        AssignmentSpec(
            "HW",
            tuple(problems),
            NOW - timedelta(days=7),
            NOW + due_in,
            LatePolicy(LateKind.PENALTY, 0.25, 0.5),
        ),
    )
    stores.courses.enrol(course.id, "s1")
    stores.outbox.add_target(
        platform,
        student="s1",
        problem_id=target_key(made.id),
        lineitem_url="https://lms.example/li/hw",
        sub="u1",
    )
    return made.id


def test_each_graded_answer_queues_the_assignment_total_in_order(stores: Stores):
    assignment = _launched_assignment(stores, due_in=timedelta(days=1))
    submit(stores, problem="p1", verdict=INCORRECT)
    submit(stores, problem="p1", verdict=INVALID)  # no attempt, no score
    submit(stores, problem="p1", verdict=CORRECT)
    submit(stores, problem="p2", verdict=CORRECT)
    queued = [(q.problem_id, q.score_given, q.score_maximum) for q in stores.outbox.scores()]
    key = target_key(assignment)
    # Each new one supersedes the unsent one before it: only the latest total waits to be sent.
    assert queued[-1] == (key, 2.0, 2.0)
    assert {q.problem_id for q in stores.outbox.scores()} == {key}
    pending = [q for q in stores.outbox.scores() if q.status == "pending"]
    assert [(q.score_given, q.score_maximum) for q in pending] == [(2.0, 2.0)]
    timestamps = [q.timestamp for q in stores.outbox.scores()]
    assert timestamps == sorted(timestamps)


def test_a_late_answer_is_sent_with_its_penalty(stores: Stores):
    _launched_assignment(stores, due_in=-timedelta(hours=1))  # due an hour ago: one day late
    submit(stores, problem="p1", verdict=CORRECT)
    [queued] = [q for q in stores.outbox.scores() if q.status == "pending"]
    assert (queued.score_given, queued.score_maximum) == (0.75, 2.0)


def test_a_problem_outside_the_assignment_queues_nothing_for_it(stores: Stores):
    _launched_assignment(stores, due_in=timedelta(days=1), problems=("p1",))
    store_problem(stores, "other")
    submit(stores, problem="other", verdict=CORRECT)
    submit(stores, problem="p1", verdict=CORRECT, student="someone-else")
    assert stores.outbox.scores() == []


def test_a_problem_launched_by_its_own_link_stays_open_to_an_enrolled_student(stores: Stores):
    from app.courses.access import opening

    _launched_assignment(stores, due_in=timedelta(days=1), problems=("p1",))
    store_problem(stores, "linked")
    assert not stores.outbox.launched("s1", "linked")
    assert opening(stores, "s1", "linked", NOW) is None  # enrolled: outside the assignment, not theirs
    platform = stores.platforms.list()[0]
    stores.outbox.add_target(
        platform, student="s1", problem_id="linked", lineitem_url="https://lms.example/li/9", sub="u1"
    )
    assert stores.outbox.launched("s1", "linked")
    found = opening(stores, "s1", "linked", NOW)
    assert found is not None and found.accepting and found.assignment is None
