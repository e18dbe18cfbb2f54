"""The course store's contract: courses and staff, rosters re-imported without duplicates, single-use
sign-in links, sessions, assignments and extensions; on SQLite, PostgreSQL and the fake."""

from __future__ import annotations

from datetime import datetime, timedelta
from zoneinfo import ZoneInfo

import pytest

from app.courses.records import (
    AssignmentNotFound,
    AssignmentSpec,
    CourseNotFound,
    CourseSession,
    ExtensionRecord,
    JoinCodeTaken,
    LateKind,
    LatePolicy,
    RosterRow,
    SolutionRelease,
    StaffRole,
    roster_identity,
)
from app.db.errors import NotFound
from app.db.types import utc_now
from app.lti.platforms import add_platform
from app.storage import Stores
from tests.storage.helpers import in_parallel, store_problem

NOW = utc_now()
ROSTER = [
    RosterRow("s001", "Ada Lovelace", "ada@uni.example"),
    RosterRow("s002", "Alan Turing", "alan@uni.example"),
]


def _spec(
    title: str = "Homework 1", problems: tuple[str, ...] = ("yo-yo", "moving-wedge"), **changes
) -> AssignmentSpec:
    fields = {
        "title": title,
        "problems": problems,
        "opens_at": NOW - timedelta(days=1),
        "due_at": NOW + timedelta(days=6),
        "late": LatePolicy(LateKind.PENALTY, 0.1, 0.5),
        "max_attempts": 3,
        "solutions": SolutionRelease.AFTER_DUE,
    } | changes
    return AssignmentSpec(**fields)


# ---- courses and staff -----------------------------------------------------------------------------


def test_a_new_course_is_taught_by_its_owner_and_nobody_else(stores: Stores):
    course = stores.courses.create_course(
        "Mechanics", owner="key:1", owner_name="Prof", timezone="Europe/Paris"
    )
    other = stores.courses.create_course("Optics", owner="key:2")
    assert stores.courses.get_course(course.id) == course
    assert course.timezone == "Europe/Paris"
    assert stores.courses.courses_taught("key:1") == [(course, StaffRole.INSTRUCTOR)]
    assert stores.courses.courses_taught("key:2") == [(other, StaffRole.INSTRUCTOR)]
    assert stores.courses.courses_taught("key:3") == []
    with pytest.raises(CourseNotFound):
        stores.courses.get_course(other.id + 100)


def test_staff_are_added_with_roles_changed_and_removed(stores: Stores):
    course = stores.courses.create_course("Mechanics", owner="key:1")
    stores.courses.add_staff(course.id, "key:2", StaffRole.TA, "Tess")
    stores.courses.add_staff(course.id, "key:3", StaffRole.INSTRUCTOR)
    stores.courses.add_staff(course.id, "key:3", StaffRole.TA)
    assert [(s.member, s.role) for s in stores.courses.staff(course.id)] == [
        ("key:1", StaffRole.INSTRUCTOR),
        ("key:2", StaffRole.TA),
        ("key:3", StaffRole.TA),
    ]
    stores.courses.remove_staff(course.id, "key:2")
    assert [s.member for s in stores.courses.staff(course.id)] == ["key:1", "key:3"]
    assert stores.courses.courses_taught("key:2") == []


def test_an_lms_context_has_one_course_however_often_it_launches(stores: Stores):
    platform = add_platform(
        stores.platforms, "https://lms.example", "c", ["d"], *(["https://lms.example/x"] * 3)
    )
    first = stores.courses.create_course("Physics 1", owner="lti:1:t", lti_context=(platform.id, "ctx-1"))
    again = stores.courses.create_course(
        "Physics 1 renamed", owner="lti:1:u", lti_context=(platform.id, "ctx-1")
    )
    assert again == first
    assert stores.courses.course_for_context(platform.id, "ctx-1") == first
    assert stores.courses.course_for_context(platform.id, "ctx-2") is None


def test_concurrent_first_launches_make_one_course(stores: Stores):
    platform = add_platform(
        stores.platforms, "https://lms.example", "c", ["d"], *(["https://lms.example/x"] * 3)
    )
    made = in_parallel(
        4, lambda _: stores.courses.create_course("P", owner="lti:1:t", lti_context=(platform.id, "ctx")).id
    )
    assert all(isinstance(m, int) for m in made) and len(set(made)) == 1


def test_join_codes_are_unique_across_courses(stores: Stores):
    one = stores.courses.create_course("A", owner="key:1")
    two = stores.courses.create_course("B", owner="key:1")
    stores.courses.set_join_code(one.id, "PHYS-1234")
    assert stores.courses.course_by_join_code("PHYS-1234") == stores.courses.get_course(one.id)
    with pytest.raises(JoinCodeTaken):
        stores.courses.set_join_code(two.id, "PHYS-1234")
    stores.courses.set_join_code(one.id, None)
    assert stores.courses.course_by_join_code("PHYS-1234") is None


# ---- rosters -----------------------------------------------------------------------------------------


def test_reimporting_a_roster_updates_and_never_duplicates(stores: Stores):
    course = stores.courses.create_course("Mechanics", owner="key:1")
    first = stores.courses.import_roster(course.id, ROSTER)
    assert (first.added, first.updated, first.unchanged) == (2, 0, 0)
    again = stores.courses.import_roster(
        course.id,
        [RosterRow("s001", "Ada King", "ada@uni.example"), ROSTER[1], RosterRow("s003", "Emmy Noether", "")],
    )
    assert (again.added, again.updated, again.unchanged) == (1, 1, 1)
    roster = stores.courses.roster(course.id)
    assert [(e.roster_id, e.name) for e in roster] == [
        ("s001", "Ada King"),
        ("s002", "Alan Turing"),
        ("s003", "Emmy Noether"),
    ]
    assert roster[0].student == roster_identity(course.id, "s001")
    assert stores.courses.courses_enrolled(roster[0].student) == [course]


def test_the_same_roster_id_in_two_courses_is_two_students(stores: Stores):
    one = stores.courses.create_course("A", owner="key:1")
    two = stores.courses.create_course("B", owner="key:2")
    stores.courses.import_roster(one.id, ROSTER)
    stores.courses.import_roster(two.id, ROSTER[:1])
    assert {e.student for e in stores.courses.roster(one.id)}.isdisjoint(
        e.student for e in stores.courses.roster(two.id)
    )


def test_enrolling_again_keeps_the_first_enrolment(stores: Stores):
    course = stores.courses.create_course("A", owner="key:1")
    first = stores.courses.enrol(course.id, "lti:1:abc", "Bea")
    assert stores.courses.enrol(course.id, "lti:1:abc", "Other") == first
    assert stores.courses.enrolment(course.id, "lti:1:abc") == first
    assert stores.courses.enrolment(course.id, "lti:1:zzz") is None


# ---- sign-in links and sessions -------------------------------------------------------------------


def test_a_sign_in_link_works_once(stores: Stores):
    course = stores.courses.create_course("A", owner="key:1")
    stores.courses.import_roster(course.id, ROSTER)
    student = roster_identity(course.id, "s001")
    stores.courses.issue_sign_in(course.id, student, "h1", NOW + timedelta(days=7))
    assert stores.courses.redeem_sign_in("h1", NOW) == (course.id, student)
    assert stores.courses.redeem_sign_in("h1", NOW) is None
    assert stores.courses.redeem_sign_in("unknown", NOW) is None


def test_a_new_link_replaces_the_unused_one_and_an_expired_link_fails(stores: Stores):
    course = stores.courses.create_course("A", owner="key:1")
    stores.courses.import_roster(course.id, ROSTER)
    student = roster_identity(course.id, "s001")
    stores.courses.issue_sign_in(course.id, student, "old", NOW + timedelta(days=7))
    stores.courses.issue_sign_in(course.id, student, "new", NOW + timedelta(days=7))
    assert stores.courses.redeem_sign_in("old", NOW) is None
    assert stores.courses.redeem_sign_in("new", NOW + timedelta(days=8)) is None
    assert stores.courses.redeem_sign_in("new", NOW) == (course.id, student)


def test_a_link_to_come_back_signs_in_each_time_until_a_new_link_replaces_it(stores: Stores):
    course = stores.courses.create_course("A", owner="key:1")
    stores.courses.import_roster(course.id, ROSTER)
    student = roster_identity(course.id, "s001")
    stores.courses.issue_sign_in(course.id, student, "back", NOW + timedelta(days=7), reusable=True)
    for _ in range(3):
        assert stores.courses.redeem_sign_in("back", NOW) == (course.id, student)
    assert stores.courses.redeem_sign_in("back", NOW + timedelta(days=8)) is None
    stores.courses.issue_sign_in(course.id, student, "mailed", NOW + timedelta(days=7))
    assert stores.courses.redeem_sign_in("back", NOW) is None


def test_an_ended_session_is_gone(stores: Stores):
    course = stores.courses.create_course("A", owner="key:1")
    live = CourseSession(course.id, "course:1:s001", "Ada", "csrf1", NOW + timedelta(hours=8))
    stores.courses.save_session("mine", live, NOW)
    stores.courses.save_session("theirs", live, NOW)
    stores.courses.end_session("mine")
    stores.courses.end_session("unknown")  # twice, or never opened: nothing to do
    assert stores.courses.get_session("mine") is None and stores.courses.get_session("theirs") == live


def test_links_are_issued_only_to_enrolled_students(stores: Stores):
    course = stores.courses.create_course("A", owner="key:1")
    with pytest.raises(NotFound):
        stores.courses.issue_sign_in(course.id, "course:1:nobody", "h", NOW + timedelta(days=1))


def test_of_concurrent_redeemers_exactly_one_signs_in(stores: Stores):
    course = stores.courses.create_course("A", owner="key:1")
    stores.courses.import_roster(course.id, ROSTER)
    stores.courses.issue_sign_in(course.id, roster_identity(course.id, "s001"), "h", NOW + timedelta(days=1))
    results = in_parallel(4, lambda _: stores.courses.redeem_sign_in("h", NOW))
    assert sum(r is not None for r in results) == 1


def test_sessions_are_kept_and_expired_ones_dropped_on_save(stores: Stores):
    course = stores.courses.create_course("A", owner="key:1")
    old = CourseSession(course.id, "course:1:s001", "Ada", "csrf1", NOW - timedelta(hours=1))
    live = CourseSession(course.id, "course:1:s002", "Alan", "csrf2", NOW + timedelta(hours=8))
    stores.courses.save_session("old", old, NOW - timedelta(hours=2))
    assert stores.courses.get_session("old") == old
    stores.courses.save_session("live", live, NOW)
    assert stores.courses.get_session("live") == live
    assert stores.courses.get_session("old") is None


# ---- assignments and extensions -------------------------------------------------------------------


def test_assignments_keep_their_problem_order_policies_and_zones(stores: Stores):
    course = stores.courses.create_course("A", owner="key:1")
    later = stores.courses.create_assignment(
        course.id, _spec("HW2", ("b", "a", "c"), due_at=NOW + timedelta(days=9))
    )
    sooner = stores.courses.create_assignment(course.id, _spec("HW1"))
    assert stores.courses.assignments(course.id) == [sooner, later]
    got = stores.courses.get_assignment(later.id)
    assert got.problems == ("b", "a", "c")
    assert got.spec.late == LatePolicy(LateKind.PENALTY, 0.1, 0.5)
    assert got.spec.due_at == NOW + timedelta(days=9)
    assert got.spec.due_at.utcoffset() == timedelta(0)


def test_dates_come_back_in_utc_whatever_zone_they_were_given_in(stores: Stores):
    paris = ZoneInfo("Europe/Paris")
    course = stores.courses.create_course("A", owner="key:1")
    due = datetime(2026, 3, 8, 23, 59, tzinfo=paris)
    made = stores.courses.create_assignment(course.id, _spec(opens_at=due - timedelta(days=7), due_at=due))
    stores.courses.set_extension(made.id, "s1", ExtensionRecord(due + timedelta(days=1), due))
    got = stores.courses.get_assignment(made.id).spec.due_at
    assert got == due and got.tzinfo is not None and got.utcoffset() == timedelta(0)
    extension = stores.courses.extensions(made.id)["s1"]
    assert extension.due_at.utcoffset() == timedelta(0)
    assert extension.granted_at is not None and extension.granted_at.utcoffset() == timedelta(0)


def test_an_assignment_is_updated_and_deleted_with_its_extensions(stores: Stores):
    course = stores.courses.create_course("A", owner="key:1")
    made = stores.courses.create_assignment(course.id, _spec())
    changed = stores.courses.update_assignment(
        made.id,
        _spec(
            "HW1 (fixed)", ("yo-yo",), late=LatePolicy(), solutions=SolutionRelease.NEVER, max_attempts=None
        ),
    )
    assert stores.courses.get_assignment(made.id) == changed
    assert changed.spec.late.kind is LateKind.CLOSED and changed.spec.max_attempts is None
    stores.courses.set_extension(made.id, "course:1:s001", ExtensionRecord(NOW + timedelta(days=10), NOW))
    stores.courses.delete_assignment(made.id)
    with pytest.raises(AssignmentNotFound):
        stores.courses.get_assignment(made.id)
    with pytest.raises(AssignmentNotFound):
        stores.courses.delete_assignment(made.id)
    assert stores.courses.assignments(course.id) == []


def test_extensions_are_set_moved_and_removed_per_student(stores: Stores):
    course = stores.courses.create_course("A", owner="key:1")
    made = stores.courses.create_assignment(course.id, _spec())
    stores.courses.set_extension(made.id, "s1", ExtensionRecord(NOW + timedelta(days=8), NOW))
    stores.courses.set_extension(made.id, "s1", ExtensionRecord(NOW + timedelta(days=9), None))
    stores.courses.set_extension(made.id, "s2", ExtensionRecord(NOW + timedelta(days=8), NOW))
    paris = ZoneInfo("Europe/Paris")
    replaced = (
        ExtensionRecord(NOW + timedelta(days=8), None),
        ExtensionRecord(NOW.astimezone(paris) + timedelta(days=9), NOW.astimezone(paris) + timedelta(days=1)),
    )
    stores.courses.set_extension(made.id, "s3", ExtensionRecord(NOW + timedelta(days=10), NOW, replaced))
    got = stores.courses.extensions(made.id)
    assert got == {
        "s1": ExtensionRecord(NOW + timedelta(days=9), None),
        "s2": ExtensionRecord(NOW + timedelta(days=8), NOW),
        "s3": ExtensionRecord(NOW + timedelta(days=10), NOW, replaced),
    }
    assert all(x.due_at.utcoffset() == timedelta(0) for x in got["s3"].earlier)
    stores.courses.set_extension(made.id, "s3", ExtensionRecord(NOW + timedelta(days=11), NOW))
    assert stores.courses.extensions(made.id)["s3"].earlier == ()
    stores.courses.set_extension(made.id, "s2", None)
    assert set(stores.courses.extensions(made.id)) == {"s1", "s3"}
    with pytest.raises(AssignmentNotFound):
        stores.courses.set_extension(made.id + 99, "s1", ExtensionRecord(NOW, NOW))


@pytest.mark.parametrize(
    "changes",
    [
        {"due_at": NOW - timedelta(days=3)},
        {"problems": ("a", "a")},
        {"max_attempts": 0},
        {"opens_at": NOW.replace(tzinfo=None)},
    ],
)
def test_an_impossible_assignment_is_refused_before_storage(changes):
    with pytest.raises(ValueError):
        _spec(**changes)


def test_uploads_are_shared_to_the_bank_and_taken_back(stores: Stores):
    store_problem(stores, "upload-1")
    stores.courses.share_problem("upload-1", True)
    stores.courses.share_problem("upload-1", True)
    assert stores.courses.shared_problems() == {"upload-1"}
    stores.courses.share_problem("upload-1", False)
    assert stores.courses.shared_problems() == set()


def test_the_first_opening_of_a_worked_solution_is_the_one_kept(stores: Stores):
    first = stores.courses.open_solution("course:1:s001", "yo-yo", NOW)
    again = stores.courses.open_solution("course:1:s001", "yo-yo", NOW + timedelta(hours=1))
    stores.courses.open_solution("course:1:s002", "moving-wedge", NOW + timedelta(hours=2))
    assert first == again == NOW
    assert stores.courses.solutions_opened("course:1:s001") == {"yo-yo": NOW}
    assert stores.courses.solutions_opened("nobody") == {}


def test_concurrent_openings_of_a_worked_solution_keep_one_time(stores: Stores):
    moments = [NOW + timedelta(seconds=n) for n in range(4)]
    kept = in_parallel(4, lambda n: stores.courses.open_solution("s", "yo-yo", moments[n]))
    assert len(set(kept)) == 1 and stores.courses.solutions_opened("s") == {"yo-yo": kept[0]}


@pytest.mark.parametrize("release", list(SolutionRelease))
def test_every_solution_release_is_stored_and_read_back(stores: Stores, release: SolutionRelease):
    course = stores.courses.create_course("A", owner="key:1")
    made = stores.courses.create_assignment(course.id, _spec(solutions=release))
    assert stores.courses.get_assignment(made.id).spec.solutions is release
