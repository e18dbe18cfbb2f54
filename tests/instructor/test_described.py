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
