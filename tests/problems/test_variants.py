"""Per-student values: deterministic, different between students, inside ranges, rounded as asked."""

from __future__ import annotations

import json
from decimal import Decimal

import pytest

from problems.loader import parse_problem
from problems.schema import GivenDecl, ProblemDocument
from problems.student import student_view
from problems.variants import (
    Variant,
    draw_value,
    draw_variant,
    fill_statement,
    fixed_variant,
    format_quantity,
    shown_quantity,
)
from tests.problems.documents import spring

SECRET = "test-secret"
STUDENTS = [f"student-{i}" for i in range(200)]


def doc() -> ProblemDocument:
    return parse_problem(spring(), check_meaning=False)


def test_same_student_same_problem_gets_the_same_values() -> None:
    assert draw_variant(doc(), 1, "alice", SECRET) == draw_variant(doc(), 1, "alice", SECRET)


@pytest.mark.parametrize(
    ("other_student", "other_version", "other_secret"),
    [
        pytest.param("bob", 1, SECRET, id="another-student"),
        pytest.param("alice", 2, SECRET, id="another-version"),
        pytest.param("alice", 1, "another-secret", id="another-secret"),
    ],
)
def test_values_change_with_student_version_and_secret(
    other_student: str, other_version: int, other_secret: str
) -> None:
    mine = draw_variant(doc(), 1, "alice", SECRET)
    theirs = draw_variant(doc(), other_version, other_student, other_secret)
    assert mine.values != theirs.values


def test_students_get_many_different_values() -> None:
    masses = {draw_variant(doc(), 1, s, SECRET).values["m"] for s in STUDENTS}
    assert len(masses) > 10


@pytest.mark.parametrize("name", ["m", "k", "theta"])
def test_every_drawn_value_lies_inside_its_range(name: str) -> None:
    given = doc().given[name]
    for student in STUDENTS:
        value = draw_variant(doc(), 1, student, SECRET).values[name]
        assert given.min <= value <= given.max


def test_values_are_rounded_to_their_significant_figures() -> None:
    for student in STUDENTS:
        value = draw_variant(doc(), 1, student, SECRET).values["m"]  # sigfigs 2 in [0.5, 2.0]
        assert len(value.as_tuple().digits) == 2


def test_values_lie_on_their_step_grid() -> None:
    for student in STUDENTS:
        value = draw_variant(doc(), 1, student, SECRET).values["k"]  # step 5 from 10
        assert (value - 10) % 5 == 0


def test_step_grid_reaches_both_ends() -> None:
    seen = {draw_variant(doc(), 1, s, SECRET).values["k"] for s in STUDENTS}
    assert Decimal(10) in seen and Decimal(100) in seen


def test_fixed_given_always_takes_its_value_as_written() -> None:
    given = GivenDecl(min=Decimal("9.81"), max=Decimal("9.81"), unit="m/s^2")
    assert {draw_value(given, Decimal(u) / 10) for u in range(10)} == {Decimal("9.81")}


def test_rounding_never_leaves_the_range() -> None:
    given = GivenDecl(min=Decimal("1.04"), max=Decimal("1.16"), unit="kg", sigfigs=2)
    for u in range(100):
        value = draw_value(given, Decimal(u) / 100)
        assert given.min <= value <= given.max


@pytest.mark.parametrize(
    ("value", "unit", "text"),
    [
        pytest.param("35", "deg", "35°", id="degrees"),
        pytest.param("2.50", "kg", "2.50 kg", id="keeps-figures"),
        pytest.param("9.81", "m/s^2", "9.81 m/s²", id="superscript"),
        pytest.param("0.031", "1", "0.031", id="dimensionless"),
        pytest.param("1.65E-21", "J", "1.65 × 10^-21 J", id="tiny"),
    ],
)
def test_given_values_are_shown_with_their_units(value: str, unit: str, text: str) -> None:
    assert format_quantity(Decimal(value), unit) == text


def test_statement_placeholders_are_filled_but_latex_braces_are_not() -> None:
    variant = fixed_variant(doc(), {"m": "1.5", "k": 40})
    text = fill_statement(doc().statement, doc(), variant)
    assert "$m$ = 1.5 kg" in text and "$k$ = 40 N/m" in text
    assert "\\frac{m}{k}" in text


def test_student_view_has_the_contract_fields() -> None:
    view = student_view(doc(), draw_variant(doc(), 1, "alice", SECRET))
    assert set(view) >= {"id", "title", "statement", "given", "parts"}
    assert set(view["given"]["m"]) >= {"value", "unit"}
    for part in view["parts"]:
        assert set(part) >= {"id", "kind", "prompt", "units", "symbols"}
    json.dumps(view)  # plain JSON


def test_student_view_names_the_symbols_each_part_may_use() -> None:
    view = student_view(doc(), draw_variant(doc(), 1, "alice", SECRET))
    assert view["parts"][0]["symbols"] == ["m", "k"]
    assert view["parts"][1]["units"] == "rad/s"


def test_variant_for_another_problem_fills_nothing() -> None:
    stray = Variant("other", 1, "alice", {"q": Decimal(1)})
    assert fill_statement("see {m}", doc(), stray) == "see {m}"


# (value, unit, as a page shows it, as an API's value and a CSV's cell read it back)
SHOWN = [
    (Decimal("-3.044"), "m/s^2", "\u22123.044 m/s²", "-3.044 m/s²"),
    (Decimal("-1.5E-5"), "m", "\u22121.5 × 10^\u22125 m", "-1.5 × 10^-5 m"),
    (Decimal("-35"), "deg", "\u221235°", "-35°"),
    (Decimal("2.5"), "kg", "2.5 kg", "2.5 kg"),
]


@pytest.mark.parametrize(("value", "unit", "shown", "read_back"), SHOWN)
def test_a_page_shows_a_negative_value_with_a_true_minus_and_read_back_text_keeps_the_hyphen(
    value: Decimal, unit: str, shown: str, read_back: str
) -> None:
    # a hand-out read "Part 4: -3.044 m/s²", a hyphen where a typeset page has a minus
    assert shown_quantity(value, unit) == shown
    assert format_quantity(value, unit) == read_back
