"""A `POST /v1/check` body is a one-part problem: the kind's own compile makes its question, as a bank
part's with the same reference."""

from __future__ import annotations

import pytest
from pydantic import TypeAdapter

from physics.checking import run_job
from physics.errors import SpecError
from problems.compiled import compile_problem
from problems.kinds import CheckIn
from problems.loader import parse_problem
from tests.problems.documents import spring

MISTAKE = {"answer": "sqrt(k/m)/(2*pi)", "feedback": "That is the frequency f, not omega."}


def bank_part():  # the spring's symbolic part, every declared symbol allowed and no limits: as a body has
    data = spring()
    part = data["parts"][0]
    del part["symbols"], part["limits"]
    doc = parse_problem(data)
    return doc, compile_problem(doc, use_model=False).part(part["id"])


def body(answer: str, expected: str = "sqrt(k/m)", mistakes: list | None = None):
    doc, _ = bank_part()
    symbols = {name: decl.model_dump(exclude_none=True) for name, decl in doc.symbols.items()}
    sent = {"kind": "symbolic", "answer": answer, "expected": expected, "symbols": symbols}
    return TypeAdapter(CheckIn).validate_python(
        {**sent, "mistakes": [MISTAKE] if mistakes is None else mistakes}
    )


def test_a_check_body_compiles_to_the_question_of_a_bank_part_with_its_reference():
    _, part = bank_part()
    assert body("x").job().question() == part.compiled


@pytest.mark.parametrize(
    "answer", ["sqrt(k/m)", "(k/m)^(1/2)", "sqrt(k/m)/(2pi)", "sqrt(m/k)", "k/m", "sqrt(k/", "q"]
)
def test_a_check_body_grades_as_the_bank_part_with_its_reference(answer):
    _, part = bank_part()
    assert run_job(body(answer).job()) == run_job(part.job(answer))


@pytest.mark.parametrize(
    ("expected", "mistakes", "path"),
    [
        pytest.param("sqrt(k/", None, ("expected",), id="reference"),
        pytest.param(
            "sqrt(k/m)", [MISTAKE, {"answer": "k/", "feedback": "no"}], ("mistakes", 1), id="mistake"
        ),
    ],
)
def test_an_unreadable_reference_is_reported_at_the_field_the_body_sent(expected, mistakes, path):
    with pytest.raises(SpecError) as raised:
        run_job(body("k", expected, mistakes).job())
    assert raised.value.path == path
