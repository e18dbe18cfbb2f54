"""A `POST /v1/check` body is a one-part problem: the kind's own compile makes its question, as a bank
part's with the same reference (a numeric body's part states its value, exact, as a bank part may)."""

from __future__ import annotations

import pytest
from pydantic import TypeAdapter

from physics.checking import run_job
from physics.errors import SpecError
from problems.compiled import compile_problem
from problems.errors import ProblemInvalid
from problems.kinds import CheckIn
from problems.loader import parse_problem
from tests.problems.documents import FRICTION_CHOICE, spring, spring_with_choice, stated_value

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


# ---- numeric: a body is a one-part problem whose part states its value ----------------------------


def stated_problem(value: str, units: str, *, check_meaning: bool = True, **part: object):
    return parse_problem(stated_value(value, units, **part), check_meaning=check_meaning)


def numeric_body(answer: str, expected: str, units: str | None, **extra: object):
    sent = {"kind": "numeric", "answer": answer, "expected": expected, **extra}
    return TypeAdapter(CheckIn).validate_python(sent if units is None else {**sent, "units": units})


NUMERIC_CASES = [
    # (expected, units, the part's and the body's other fields, answers)
    ("4.5807", "m/s^2", {}, ["4.58 m/s^2", "16.49 km/h/s", "4.58", "-4.58 m/s^2", "5.2 m/s^2", "4,58 m/s^2"]),
    ("4.5807", "m/s^2", {"tolerance": {"sigfigs": 3}}, ["4.58 m/s^2", "4.6 m/s^2", "4.59 m/s^2"]),
    ("4.5807", "m/s^2", {"arithmetic": False}, ["229/50 m/s^2", "4.58 m/s^2"]),
    ("4.5807", "m/s^2", {"units_system": "SI"}, ["15.03 ft/s^2", "4.58 m/s^2"]),
    ("4.5807", "m/s^2", {"units_required": False}, ["4.58", "4.58 m/s"]),
    ("0.45", None, {}, ["0.45", "45 %", "0.45 m", "0.5"]),
    ("-40", "°C", {"tolerance": {"abs": "0.001"}}, ["-40 °F", "233.15 K", "-40"]),
    ("6.02214076e23", None, {}, ["6.022e23", "6.1e23"]),
    (
        "1.234567890123456789012345678901234567890",
        "m",
        {"tolerance": {"rel": "1e-35"}},
        ["1.234567890123456789012345678901234567890 m", "1.23456789012 m", "1.234567890123 m"],
    ),
]


@pytest.mark.parametrize(("expected", "units", "fields", "answers"), NUMERIC_CASES)
def test_a_numeric_body_grades_as_a_bank_part_stating_its_value(expected, units, fields, answers):
    part = compile_problem(stated_problem(expected, units or "1", **fields), use_model=False).part("a_value")
    for answer in answers:
        body = numeric_body(answer, expected, units, **fields)
        assert body.job().question() == part.question()
        assert run_job(body.job()) == run_job(part.job(answer)), answer


@pytest.mark.parametrize(
    ("units", "extra", "message"),
    [
        pytest.param(
            "blorps", {}, "cannot read 'blorps' at character 0: Unknown unit 'blorps'", id="unknown"
        ),
        pytest.param("m/s^", {}, "cannot read 'm/s^' at character 4: A power of a unit", id="unreadable"),
        pytest.param("", {}, "cannot read '' at character 0: No units were given", id="empty"),
        pytest.param(
            "ft", {"units_system": "SI"}, "units 'ft' are not SI, but units_system is SI", id="not-si"
        ),
    ],
)
def test_a_numeric_body_with_units_it_cannot_use_is_refused_at_units(units, extra, message):
    with pytest.raises(SpecError) as raised:
        numeric_body("1 m", "1", units, **extra).job()
    assert raised.value.path == ("units",)
    assert raised.value.message.startswith(message)


def test_compiling_a_part_stating_its_value_refuses_units_it_cannot_use_at_its_units():
    doc = stated_problem("1", "ft", check_meaning=False, units_system="SI")  # compile alone, as a body is
    with pytest.raises(ProblemInvalid) as raised:
        compile_problem(doc, use_model=False)
    assert raised.value.errors == [("parts[0].units", "units 'ft' are not SI, but units_system is SI")]


# ---- choice ---------------------------------------------------------------------------------------


def test_a_choice_body_compiles_to_the_question_of_a_bank_part_with_its_choices():
    part = compile_problem(parse_problem(spring_with_choice()), use_model=False).part("friction_direction")
    sent = {"kind": "choice", "answer": "B", "choices": FRICTION_CHOICE["choices"]}
    assert TypeAdapter(CheckIn).validate_python(sent).job().question() == part.question()
