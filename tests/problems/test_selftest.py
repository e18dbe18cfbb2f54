"""The bank self-test: references accepted in many forms, mistakes rejected, numbers in many units."""

from __future__ import annotations

import pytest

from problems.loader import load_bank, parse_problem
from problems.selftest import Report, rewritings, unit_alternatives, verify_problem
from tests.problems.documents import spring


def test_small_problem_passes_its_self_test() -> None:
    calls: list[tuple[str, int, int]] = []
    report = verify_problem(
        parse_problem(spring()), variants=3, progress=lambda *a: calls.append(a), use_model=False
    )
    assert report.ok, report.summary()
    checks = {r.check for r in report.failures} | {r.check for r in report.problems[0].results}
    assert {
        "rewrite as derived",
        "mistake 1",
        "variant 0",
        "variant 0 10% off",
        "variant 0 mistake 1",
        "variant 2 in rad/ms",
    } <= checks
    assert calls[-1] == ("tiny-spring:angular_frequency_numeric", 2, 2)


def test_bank_problem_with_its_model_passes_its_self_test() -> None:
    from problems.loader import BANK_DIR, load_problem_dir

    report = verify_problem(load_problem_dir(BANK_DIR / "atwood"), variants=3)
    assert report.ok, report.summary()
    checks = [r.check for r in report.problems[0].results]
    assert checks.count("methods agree") == 2  # acceleration and tension
    assert "variant 1 in cm/s^2" in checks


def test_a_mistake_equal_to_the_answer_fails_the_self_test() -> None:
    data = spring()
    data["parts"][0]["mistakes"][0]["answer"] = "sqrt(k)/sqrt(m)"
    report = verify_problem(parse_problem(data), variants=1, use_model=False)
    assert not report.ok
    assert [(r.part, r.check) for r in report.failures] == [("angular_frequency", "mistake 1")]
    assert "FAIL tiny-spring" in report.summary()


def test_given_values_outside_the_constraints_fail_the_self_test() -> None:
    data = spring()
    data["constraints"] = ["k < 50*m"]  # k is drawn up to 100 N/m with m down to 0.5 kg
    report = verify_problem(parse_problem(data), variants=10, use_model=False)
    failures = [r for r in report.failures if r.check.endswith("in domain")]
    assert failures and "k < 50*m fails at" in failures[0].detail


def test_compile_failure_is_a_failed_check_not_an_exception() -> None:
    data = spring()
    del data["given"]["k"]
    data["statement"] = "No values."
    report = verify_problem(parse_problem(data), variants=1, use_model=False)
    assert [r.check for r in report.failures] == ["compile parts[1].of"]


@pytest.mark.parametrize(
    ("expression_text", "form"),
    [
        pytest.param(
            "(m + M)*g/(M + m*sin(theta)**2)",
            "M*g/(M + m*sin(theta)**2) + g*m/(M + m*sin(theta)**2)",
            id="expanded",
        ),
        pytest.param("2*sin(theta)*cos(theta)", "sin(2*theta)", id="double-angle"),
    ],
)
def test_rewritings_include_distinct_equivalent_forms(expression_text: str, form: str) -> None:
    import sympy

    from physics.mathinput import parse_math

    names = {n: sympy.Symbol(n, positive=True) for n in ("m", "M", "g", "theta")}
    texts = rewritings(parse_math(expression_text, names).expr)
    assert form in texts.values()
    assert len(set(texts.values())) == len(texts)


def test_unit_alternatives_cover_prefixes_and_km_per_hour() -> None:
    assert "km/h" in unit_alternatives("m/s")
    assert unit_alternatives("furlong") == []


def test_report_summary_counts_failures() -> None:
    assert Report().summary().endswith("0 problems, 0 checks, 0 failures")


def _bank_ids() -> list[str]:
    return sorted(doc.id for doc in load_bank(check_meaning=False))


@pytest.mark.slow
@pytest.mark.bank_selftest
@pytest.mark.parametrize("problem_id", _bank_ids())
def test_every_bank_problem_passes_its_self_test(problem_id: str) -> None:
    # one test per problem, so each stays within the per-test timeout as the bank grows; `make test`
    # deselects these because `physcheck bank verify` runs the same self-test there with 20 variants
    [doc] = [d for d in load_bank(check_meaning=False) if d.id == problem_id]
    report = verify_problem(doc, variants=5)
    assert report.ok, report.summary()


def test_rewritings_are_typed_as_a_student_would_and_untypeable_forms_left_out() -> None:
    import sympy

    m1, m2, g = sympy.symbols("m1 m2 g", positive=True)
    texts = rewritings(sympy.Abs(m1 - m2) * g / (m1 + m2))
    assert texts["as derived"] == "g*abs(m1 - m2)/(m1 + m2)"
    assert not any("Abs" in text for text in texts.values())
    assert rewritings(sympy.Min(m1, m2) * g) == {}
