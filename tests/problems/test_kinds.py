"""Answer kinds: every kind the schema admits is registered, and the third kind (multiple choice) is
one module that the document, compiler, self-test and student view all reach through the registry."""

from __future__ import annotations

import json
import typing

import pytest

from physics.choice import Choice, ChoiceQuestion
from physics.verdict import Outcome, Reason
from problems.compiled import compile_problem
from problems.errors import ProblemInvalid
from problems.kinds import KINDS, AnyCompiledPart, CheckIn, Part
from problems.loader import parse_problem
from problems.selftest import verify_problem
from problems.student import student_view
from problems.variants import draw_variant
from tests.problems.documents import spring_with_choice


def _kinds_of(annotated: object) -> set[str]:
    union = typing.get_args(annotated)[0]
    return {typing.get_args(model.model_fields["kind"].annotation)[0] for model in typing.get_args(union)}


def test_every_kind_the_schema_admits_is_registered_and_compiles_to_its_own_part() -> None:
    assert (
        _kinds_of(Part)
        == set(KINDS)
        == {
            "symbolic",
            "numeric",
            "choice",
            "lagrangian",
            "kinetic_energy",
            "potential_energy",
            "equation",
            "data",
            "free_body",
        }
    )
    # one compiled part per kind module (the three energy kinds share theirs)
    assert len(typing.get_args(AnyCompiledPart)) == len({type(kind) for kind in KINDS.values()})


def test_every_registered_kind_can_be_checked_ad_hoc() -> None:
    assert _kinds_of(CheckIn) == set(KINDS)


def test_a_choice_part_compiles_to_a_question_graded_by_letter_or_text() -> None:
    part = compile_problem(parse_problem(spring_with_choice()), use_model=False).part("friction_direction")
    question = part.question()
    assert isinstance(question, ChoiceQuestion)
    verdicts = {answer: question.grade(answer) for answer in ("A", "b)", "(c)", "up the  SLOPE", "D", "up")}
    assert verdicts["A"].outcome is Outcome.CORRECT and verdicts["A"].read_as.text == "A"
    assert verdicts["up the  SLOPE"].outcome is Outcome.CORRECT
    assert (verdicts["b)"].reason, verdicts["b)"].feedback) == (
        Reason.KNOWN_MISTAKE,
        "Friction opposes the sliding, which is down the slope.",
    )
    assert (verdicts["(c)"].outcome, verdicts["(c)"].reason) == (Outcome.INCORRECT, Reason.WRONG_VALUE)
    for unreadable in ("D", "up"):
        assert (verdicts[unreadable].outcome, verdicts[unreadable].reason) == (
            Outcome.INVALID,
            Reason.PARSE_ERROR,
        )
        assert "A to C" in verdicts[unreadable].feedback


SLOPE_CHOICES = ChoiceQuestion(
    (Choice("Up the slope"), Choice("Down the slope"), Choice("Perpendicular to the slope")), correct=0
)
CHOICES_AS_STUDENTS_NAME_THEM = [
    # (answer, the letter it names, or None: refused)
    ("option a", "A"),
    ("Choice B", "B"),
    ("Up the slope.", "A"),  # the text, with a full stop
    ("a) Up the slope", "A"),  # the letter with its text, as the list prints it
    ("B - Down the slope", "B"),
    ("c: perpendicular to the slope", "C"),
    ("ｂ", "B"),  # fullwidth, from an East Asian input method
    ("A\u200b", "A"),  # a zero-width space copied with it
    ("b) Up the slope", None),  # the letter of one and the text of another: which?
    ("a) up", None),
    ("option d", None),
]


@pytest.mark.parametrize(
    ("answer", "named"), CHOICES_AS_STUDENTS_NAME_THEM, ids=[c[0] for c in CHOICES_AS_STUDENTS_NAME_THEM]
)
def test_a_choice_is_named_as_students_name_it(answer: str, named: str | None) -> None:
    verdict = SLOPE_CHOICES.grade(answer)
    if named is None:
        assert (verdict.outcome, verdict.reason) == (Outcome.INVALID, Reason.PARSE_ERROR)
        assert "A to C" in verdict.feedback
        return
    assert verdict.read_as is not None and verdict.read_as.text == named


def test_a_choice_preview_names_the_choice_without_grading_it() -> None:
    question = compile_problem(parse_problem(spring_with_choice()), use_model=False).question(
        "friction_direction"
    )
    read = question.read("b", None)  # type: ignore[arg-type]
    assert read.read_as is not None and read.read_as.text == "B" and read.error is None
    assert question.read("Z", None).error is not None  # type: ignore[arg-type]


BROKEN_CHOICES = [
    pytest.param(
        lambda part: part["choices"][2].update(correct=True),
        ("parts[2].choices", "mark exactly one choice correct: true (2 are)"),
        id="two-right",
    ),
    pytest.param(
        lambda part: part["choices"][0].update(correct=False),
        ("parts[2].choices", "mark exactly one choice correct: true (0 are)"),
        id="none-right",
    ),
    pytest.param(
        lambda part: part["choices"][2].update(text="down the  slope"),
        ("parts[2].choices[2].text", "the same text as choices[1]: students could not tell them apart"),
        id="same-text",
    ),
    pytest.param(
        lambda part: part["choices"][0].update(feedback="Well done."),
        ("parts[2].choices[0].feedback", "feedback is for wrong choices; the right one is told 'Correct.'"),
        id="feedback-on-the-right-one",
    ),
]


@pytest.mark.parametrize(("change", "error"), BROKEN_CHOICES)
def test_a_broken_choice_part_is_refused_with_its_path(change, error) -> None:
    data = spring_with_choice()
    change(data["parts"][2])
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(data)
    assert caught.value.errors == [error]


def test_one_choice_is_too_few() -> None:
    data = spring_with_choice()
    data["parts"][2]["choices"] = data["parts"][2]["choices"][:1]
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(data)
    assert caught.value.errors == [("parts[2].choices", "must have at least 2 items")]


def test_the_student_sees_the_choices_and_never_which_is_right() -> None:
    doc = parse_problem(spring_with_choice())
    view = student_view(doc, draw_variant(doc, 1, "alice", "s3cret"))
    part = view["parts"][2]
    assert part["kind"] == "choice" and part["max_attempts"] == 1
    assert part["choices"] == [
        {"label": "A", "text": "Up the slope"},
        {"label": "B", "text": "Down the slope"},
        {"label": "C", "text": "Perpendicular to the slope"},
    ]
    shown = json.dumps(view)
    assert "correct" not in shown and "opposes" not in shown


def test_the_self_test_grades_every_choice() -> None:
    report = verify_problem(parse_problem(spring_with_choice()), variants=2, use_model=False)
    checks = {r.check: r.ok for r in report.problems[0].results if r.part == "friction_direction"}
    assert checks == {
        "choice A": True,
        "choice B": True,
        "choice C": True,
        "right choice by its text": True,
        "no such choice": True,
    }
    assert report.ok, report.summary()
