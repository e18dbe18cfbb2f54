"""What the instructor is shown of a numeric part's reference agrees with what grading accepts."""

from __future__ import annotations

from decimal import Decimal

import pytest

from app.instructor.described import SHOWN_FIGURES, describe
from physics.verdict import Outcome
from problems.compiled import CompiledNumericPart, compile_problem
from problems.loader import parse_problem
from problems.variants import fixed_variant
from tests.bank import bank_documents
from tests.problems.documents import spring, stated_value
from tests.problems.test_numeric_mistakes import AT as LIFT_AT
from tests.problems.test_numeric_mistakes import AT_REST, SAID_AGAIN, SWAPPED
from tests.problems.test_numeric_mistakes import compiled as lift_problem


@pytest.mark.parametrize("sigfigs", [None, 2, 3, 5])
def test_a_numeric_reference_is_shown_to_the_figures_its_answers_are_graded_by(sigfigs) -> None:
    doc = spring()
    numeric = next(i for i, part in enumerate(doc["parts"]) if part["kind"] == "numeric")
    if sigfigs is not None:
        doc["parts"][numeric]["tolerance"] = {"sigfigs": sigfigs}
    parsed = parse_problem(doc, check_meaning=False)
    compiled = compile_problem(parsed)
    variant = fixed_variant(parsed, {})
    part_id = doc["parts"][numeric]["id"]
    shown = next(p for p in describe(compiled, variant).parts if p.id == part_id).expected
    assert shown is not None
    number = shown.replace(" × 10^", "e").split()[0]
    assert len(Decimal(number).as_tuple().digits) == (sigfigs or SHOWN_FIGURES)
    part = compiled.parts[part_id]
    assert isinstance(part, CompiledNumericPart)
    if sigfigs is not None:  # what is shown is an answer the part accepts, digit for digit
        verdict = part.spec(variant).grade(shown)
        assert verdict.outcome is Outcome.CORRECT, (shown, verdict)


@pytest.mark.parametrize("with_variant", [False, True], ids=["no-student", "a-student"])
def test_a_stated_value_is_shown_whoever_the_student(with_variant) -> None:
    doc = parse_problem(stated_value("6.02214076e23", "1"))
    compiled = compile_problem(doc, use_model=False)
    info = describe(compiled, fixed_variant(doc, {}) if with_variant else None).parts[0]
    assert (info.expected, info.expected_full) == ("6.022 × 10^23", "6.02214076 × 10^23")
    assert info.latex == r"6.02214076 \times 10^{23}"


def test_mistakes_are_labelled_as_an_instructor_types_them() -> None:
    """The class-results charts label each known mistake with this text: powers as ^, not Python's **."""
    doc = bank_documents()["moving-wedge"]
    texts = [m.text for part in describe(compile_problem(doc)).parts for m in part.mistakes]
    assert any("^" in text for text in texts), texts  # the wedge's slips hold sin(theta)^2
    assert not any("**" in text for text in texts), texts


@pytest.mark.parametrize(
    ("alpha", "listed"),
    [
        pytest.param(None, [(AT_REST, None), (SWAPPED, None), (SAID_AGAIN, None)], id="no-student"),
        pytest.param(
            "30", [(AT_REST, "1.867 s"), (SWAPPED, "1.293 s"), (SAID_AGAIN, "1.867 s")], id="a-student"
        ),
        # 0.9 % from the right value at 44.5°: the 1 % tolerance takes it for it, so no answer shows it
        pytest.param("44.5", [(AT_REST, "1.694 s"), (SAID_AGAIN, "1.694 s")], id="within-tolerance-left-out"),
    ],
)
def test_a_numeric_part_lists_the_known_mistakes_it_recognises(alpha, listed) -> None:
    problem = lift_problem()
    variant = None if alpha is None else fixed_variant(problem.document, {**LIFT_AT, "alpha": alpha})
    parts = {p.id: p for p in describe(problem, variant).parts}
    assert [(m.feedback, m.value) for m in parts["period_numeric"].mistakes] == listed
    # written as the symbolic part shows them, the author's typing
    assert [m.latex for m in parts["period_numeric"].mistakes] == [
        m.latex for m in parts["period"].mistakes if m.feedback in {f for f, _ in listed}
    ]
    assert parts["tension_numeric"].mistakes == ()


def test_a_numeric_part_of_a_model_quantity_lists_the_engines_mistakes() -> None:
    # m1 = 1.0 kg, m2 = 2.0 kg, u = 3.0 m/s: a common velocity of 1.0 m/s, 2.0 m/s with the masses swapped
    doc = bank_documents()["collision-scenarios"]
    variant = fixed_variant(doc, {"m1": "1.0", "m2": "2.0", "u": "3.0"})
    part = next(p for p in describe(compile_problem(doc), variant).parts if p.id == "common_velocity_numeric")
    swapped = [m for m in part.mistakes if "masses are swapped" in m.feedback]
    assert [(m.value, m.by_author) for m in swapped] == [("2.000 m/s", False)]
