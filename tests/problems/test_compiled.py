"""Compiled problems: per-part questions, numeric references per student, and no leaks to students."""

from __future__ import annotations

import json
import pickle
from decimal import Decimal
from functools import cache

import pytest
import sympy

from physics.checking import NumericJob, PartJob, check_answer, run_job
from physics.numeric import round_sigfigs
from physics.verdict import Outcome, Reason
from problems.compiled import CompiledNumericPart, CompiledProblem, CompiledSymbolicPart, compile_problem
from problems.errors import ProblemInvalid
from problems.loader import parse_problem
from problems.schema import ProblemDocument
from problems.selftest import verify_problem
from problems.student import student_view
from problems.variants import draw_variant, fixed_variant
from tests.bank import bank_documents
from tests.problems.documents import spring, stated_value
from tests.sampling import sampled


def bank() -> dict[str, ProblemDocument]:
    return bank_documents()


@cache
def hand(problem_id: str) -> CompiledProblem:
    """Compiled from the hand-typed answers only: fast, and independent of the engine."""
    return compile_problem(bank()[problem_id], use_model=False)


def typed_or_derived(problem_id: str) -> CompiledProblem:
    """The hand-typed answers; the engine's (cached per process) where a part has only a derived one."""
    try:
        return hand(problem_id)
    except ProblemInvalid:
        return compile_problem(bank()[problem_id])


# The seed document's numbers (skier) and textbook values for the others.
REFERENCES = [
    pytest.param(
        "skier-friction", "acceleration_numeric", {"alpha": 35, "mu": "0.13"}, "4.58", id="skier-seed-a"
    ),
    pytest.param(
        "skier-friction", "friction_coefficient_numeric", {"alpha": "3.5"}, "0.0612", id="skier-seed-mu"
    ),
    pytest.param("mass-spring", "period_numeric", {"m": 1, "k": "39.4784176"}, "1.00", id="spring-1s"),
    pytest.param("atwood", "acceleration_numeric", {"m1": 1, "m2": 3}, "4.905", id="atwood-half-g"),
    pytest.param(
        "moving-wedge", "wedge_acceleration_numeric", {"m": 1, "M": 1, "theta": 45}, "-3.27", id="wedge-sign"
    ),
    pytest.param(
        "ballistic-pendulum",
        "bullet_speed_numeric",
        {"m": 10, "M": "0.99", "L": 1, "theta": 60},
        "313.2",
        id="pendulum-grams",
    ),
    pytest.param("yo-yo", "acceleration_numeric", {"r": 1, "k": 1}, "4.905", id="yoyo-cm"),
]


@pytest.mark.parametrize(("problem_id", "part_id", "values", "expected"), REFERENCES)
def test_numeric_reference_at_chosen_values(
    problem_id: str, part_id: str, values: dict[str, object], expected: str
) -> None:
    part = hand(problem_id).part(part_id)
    assert isinstance(part, CompiledNumericPart)
    value = part.reference(fixed_variant(bank()[problem_id], values))  # type: ignore[arg-type]
    digits = len(Decimal(expected).as_tuple().digits)
    assert round_sigfigs(value, digits) == Decimal(expected)


def test_reference_keeps_twelve_significant_figures() -> None:
    part = hand("skier-friction").part("acceleration_numeric")
    assert isinstance(part, CompiledNumericPart)
    value = part.reference(fixed_variant(bank()["skier-friction"], {"alpha": 35, "mu": "0.13"}))
    assert len(value.as_tuple().digits) == 12


def test_a_stated_value_is_every_students_with_all_its_digits() -> None:
    digits = "1.234567890123456789012345678901234567890"
    doc = parse_problem(stated_value(digits, "m"))
    part = compile_problem(doc, use_model=False).part("a_value")
    assert isinstance(part, CompiledNumericPart)
    students = [draw_variant(doc, 1, name, "s3cret") for name in ("alice", "bob")]
    assert {part.reference(student) for student in (None, *students)} == {Decimal(digits)}
    assert (part.expression, part.derived, part.solution().text) == (None, False, digits)
    report = verify_problem(doc, variants=3, use_model=False)
    assert report.ok, report.summary()
    assert {result.check for result in report.problems[0].results} >= {"variant 0", "variant 0 10% off"}


def test_dimensionless_numeric_part_asks_for_a_pure_number() -> None:
    part = hand("skier-friction").part("friction_coefficient_numeric")
    assert isinstance(part, CompiledNumericPart)
    spec = part.spec(fixed_variant(bank()["skier-friction"], {"alpha": "3.5"}))
    assert spec.units is None and check_answer("0.0612", spec).outcome is Outcome.CORRECT


def test_symbolic_question_accepts_the_reference_and_names_a_known_mistake() -> None:
    question = hand("incline-pulley").question("acceleration")
    assert check_answer("(m2 - m1 sin(theta)) g/(m1 + m2)", question).outcome is Outcome.CORRECT
    wrong = check_answer("(m2 - m1) g/(m1 + m2)", question)
    assert wrong.reason is Reason.KNOWN_MISTAKE and "sin" in wrong.feedback


def test_jobs_carry_the_compiled_question_that_grades_like_the_question() -> None:
    compiled = hand("incline-pulley")
    job = compiled.job("acceleration", "(m2 - m1 sin(theta)) g/(m1 + m2)")
    assert isinstance(job, PartJob)
    # As a worker receives it: pickled, so nothing it needs is left behind in this process.
    crossed = pickle.loads(pickle.dumps(job))
    assert run_job(crossed).outcome is Outcome.CORRECT
    wrong = run_job(PartJob("(m2 - m1) g/(m1 + m2)", crossed.key, crossed.payload))
    assert wrong.reason is Reason.KNOWN_MISTAKE
    variant = draw_variant(bank()["incline-pulley"], 1, "alice", "s3cret")
    numeric = compiled.job("acceleration_numeric", "1 m/s^2", variant)
    assert isinstance(numeric, NumericJob) and numeric.spec.units == "m/s^2"


def test_numeric_part_needs_the_students_variant() -> None:
    with pytest.raises(ValueError, match="variant"):
        hand("atwood").question("acceleration_numeric")


def test_compilation_is_cached_per_version() -> None:
    doc = bank()["atwood"]
    assert compile_problem(doc, 7, use_model=False) is compile_problem(doc, 7, use_model=False)
    assert compile_problem(doc, 8, use_model=False) is not compile_problem(doc, 7, use_model=False)


def test_numeric_part_over_a_symbol_without_a_given_is_refused() -> None:
    data = spring()
    del data["given"]["k"]
    data["statement"] = "No values."
    with pytest.raises(ProblemInvalid) as caught:
        compile_problem(parse_problem(data), use_model=False)
    assert caught.value.errors == [("parts[1].of", "needs given values for k")]


def test_numeric_units_of_the_wrong_dimension_are_refused() -> None:
    data = spring()
    data["parts"][1]["units"] = "m/s"
    with pytest.raises(ProblemInvalid) as caught:
        compile_problem(parse_problem(data), use_model=False)
    assert [p for p, _ in caught.value.errors] == ["parts[1].units"]


# Compiling derives every problem it draws: a daily sample keeps the suite in its time (tests/sampling.py).
@pytest.mark.parametrize("problem_id", sampled(sorted(bank()), 8, "student-view-reference"))
def test_student_view_never_contains_a_reference(problem_id: str) -> None:
    doc, compiled = bank()[problem_id], typed_or_derived(problem_id)
    variant = draw_variant(doc, 1, "alice", "s3cret")
    shown = json.dumps(student_view(doc, variant), ensure_ascii=False)
    for part_id, part in compiled.parts.items():
        if isinstance(part, CompiledSymbolicPart):
            if not part.expected.is_Symbol:  # a lone symbol's name is in the view by design
                assert sympy.sstr(part.expected) not in shown, part_id
            answer = doc.part(part_id).answer  # type: ignore[union-attr]
            assert answer is None or len(answer) < 4 or answer not in shown, part_id
        elif isinstance(part, CompiledNumericPart):
            value = part.reference(variant)
            for figures in (3, 4, 12):
                assert str(round_sigfigs(abs(value), figures)) not in shown, (part_id, figures)
        else:  # a Lagrangian, an energy, an equation: its reference as the solution writes it
            assert part.solution().text not in shown, part_id


# ---- with the engine's model (atwood: the quickest to derive) ------------------------------------


def atwood_data() -> dict[str, object]:
    import yaml

    from problems.loader import BANK_DIR

    data = yaml.safe_load((BANK_DIR / "atwood" / "problem.yaml").read_text())
    data["model"] = yaml.safe_load((BANK_DIR / "atwood" / "model.yaml").read_text())
    return data


def test_model_derivation_is_the_reference_and_agrees_with_the_hand_answer() -> None:
    compiled = compile_problem(parse_problem(atwood_data()), 1)
    assert compiled.derived is not None
    part = compiled.part("acceleration")
    assert isinstance(part, CompiledSymbolicPart)
    assert sympy.simplify(part.expected - compiled.derived.quantities["acceleration"]) == 0


def test_engine_mistakes_the_author_already_wrote_are_not_repeated() -> None:
    compiled = compile_problem(parse_problem(atwood_data()), 1)
    for part in compiled.parts.values():
        if isinstance(part, CompiledSymbolicPart):
            exprs = [m.expr for m in part.context.mistakes]
            assert all(sympy.simplify(a - b) != 0 for i, a in enumerate(exprs) for b in exprs[:i]), part.id


def test_hand_answer_that_disagrees_with_the_model_is_refused() -> None:
    data = atwood_data()
    data["parts"][0]["answer"] = "(m1 - m2)*g/(m1 + m2)"  # type: ignore[index]
    with pytest.raises(ProblemInvalid) as caught:
        compile_problem(parse_problem(data), 1)
    assert [p for p, _ in caught.value.errors] == ["parts[0].answer"]
    assert "disagrees with the model" in caught.value.errors[0][1]


def test_part_without_answer_takes_its_quantity_from_the_model() -> None:
    data = atwood_data()
    del data["parts"][1]["answer"]  # type: ignore[union-attr]
    compiled = compile_problem(parse_problem(data), 1)
    m1, m2, g = (compiled.table[n] for n in ("m1", "m2", "g"))
    assert sympy.simplify(compiled.reference_expressions()["tension"] - 2 * m1 * m2 * g / (m1 + m2)) == 0


def test_part_quantity_missing_from_the_model_is_reported_at_parse() -> None:
    data = atwood_data()
    del data["parts"][1]["answer"]  # type: ignore[union-attr]
    data["parts"][1]["quantity"] = "pulley_force"  # type: ignore[index]
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(data)
    assert caught.value.errors == [
        (
            "parts[1].quantity",
            "the model has no quantity 'pulley_force'; its quantities are acceleration, tension",
        )
    ]


def test_a_misspelled_quantity_beside_a_typed_answer_is_an_error_not_a_fall_back() -> None:
    data = atwood_data()
    data["parts"][1]["quantity"] = "tensoin"  # type: ignore[index]
    data["parts"][1]["answer"] = "m1*g"  # type: ignore[index]  # wrong, and nothing would check it
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(data)
    ((path, message),) = caught.value.errors
    assert path == "parts[1].quantity"
    assert "'tensoin'" in message and "tension" in message


def test_a_part_with_only_a_typed_answer_is_labelled_not_derived() -> None:
    data = atwood_data()
    data["parts"][1]["id"] = "string_tension"  # type: ignore[index]  # no model quantity of that name
    for part in data["parts"]:  # type: ignore[union-attr]
        if part.get("of") == "tension":
            part["of"] = "string_tension"
    data["model"]["unused"] = ["tension"]  # type: ignore[index]  # derived, no part asks for it: on purpose
    compiled = compile_problem(parse_problem(data), 1)
    assert "string_tension" in compiled.not_derived
    assert "acceleration" not in compiled.not_derived
    m1, m2, g = (compiled.table[n] for n in ("m1", "m2", "g"))
    assert (
        sympy.simplify(compiled.reference_expressions()["string_tension"] - 2 * m1 * m2 * g / (m1 + m2)) == 0
    )


def test_model_faults_are_reported_under_model() -> None:
    data = atwood_data()
    data["model"]["quantities"]["acceleration"] = {"acceleration": "nowhere"}  # type: ignore[index]
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(data)
    assert caught.value.errors and all(p.startswith("model.") for p, _ in caught.value.errors), (
        caught.value.errors
    )


def test_numeric_part_passes_arithmetic_and_units_system_to_its_check() -> None:
    data = spring()
    data["parts"][1].update({"arithmetic": False, "units_system": "SI"})
    part = compile_problem(parse_problem(data), use_model=False).part("angular_frequency_numeric")
    assert isinstance(part, CompiledNumericPart)
    spec = part.spec(draw_variant(parse_problem(data), 1, "alice", "s3cret"))
    assert (spec.arithmetic, spec.units_system) == (False, "SI")
    assert check_answer("sqrt(2) rad/s", spec).reason is Reason.PARSE_ERROR
    assert check_answer("1 rev/s", spec).reason is Reason.UNKNOWN_UNIT


def test_numeric_part_takes_arithmetic_and_any_units_by_default() -> None:
    part = compile_problem(parse_problem(spring()), use_model=False).part("angular_frequency_numeric")
    assert isinstance(part, CompiledNumericPart)
    spec = part.spec(draw_variant(parse_problem(spring()), 1, "alice", "s3cret"))
    assert (spec.arithmetic, spec.units_system) == (True, None)


def test_numeric_part_passes_angular_units_to_its_check_and_dumps_as_before_without_it() -> None:
    data = spring()
    assert "angular_units" not in parse_problem(data).model_dump()["parts"][1]
    data["parts"][1]["angular_units"] = "strict"
    doc = parse_problem(data)
    assert doc.model_dump()["parts"][1]["angular_units"] == "strict"
    part = compile_problem(doc, use_model=False).part("angular_frequency_numeric")
    assert isinstance(part, CompiledNumericPart)
    assert part.spec(draw_variant(doc, 1, "alice", "s3cret")).angular_units == "strict"
