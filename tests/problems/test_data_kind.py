"""Lab-data parts: each student's measurements are reproducible from their seed and differ from another
student's; the fit is the least-squares one (checked against the closed form on a known dataset), and
the grading tolerance follows its standard error; fitting the wrong variable or missing a factor is
said; the student sees their own table, plot and CSV."""

from __future__ import annotations

import math
from functools import cache

import numpy as np
import pytest
import sympy

from app.web.layout import templates
from app.web.student_page import _parts
from physics.fitting import fit_parameter, measurements
from physics.verdict import Outcome, Reason
from problems.compiled import compile_problem
from problems.kinds.data import measured_text
from problems.student import student_view
from problems.variants import draw_variant
from tests.bank import bank_documents

g, theta, L = sympy.symbols("g theta L", positive=True)
ANGLES = [math.radians(a) for a in (5, 10, 15, 20, 25, 30, 35)]
KNOWN = [0.885, 1.73, 2.36, 3.39, 4.0, 4.91, 5.55]  # a (m/s²) at those angles


def test_the_fit_of_a_known_dataset_is_the_least_squares_line_through_the_origin() -> None:
    fit = fit_parameter(g * sympy.sin(theta), theta, g, ANGLES, KNOWN, {}, start=9.81)
    s, a = np.sin(ANGLES), np.array(KNOWN)
    slope = float(s @ a / (s @ s))  # the textbook formula, independently
    residual = a - slope * s
    error = math.sqrt(float(residual @ residual) / (len(a) - 1) / float(s @ s))
    assert fit.value == pytest.approx(slope, rel=1e-12)
    assert fit.standard_error == pytest.approx(error, rel=1e-9)


def test_a_nonlinear_fit_is_where_the_squared_residuals_are_least() -> None:
    periods = [
        2 * math.pi * math.sqrt(length / 9.7) * (1 + e)
        for length, e in ((0.2, 0.01), (0.4, -0.02), (0.6, 0.0), (0.8, 0.015))
    ]
    lengths = [0.2, 0.4, 0.6, 0.8]
    fit = fit_parameter(2 * sympy.pi * sympy.sqrt(L / g), L, g, lengths, periods, {}, start=9.81)

    def squares(value: float) -> float:
        return sum(
            (t - 2 * math.pi * math.sqrt(x / value)) ** 2 for x, t in zip(lengths, periods, strict=True)
        )

    assert squares(fit.value) < squares(fit.value * (1 + 1e-4)) and squares(fit.value) < squares(
        fit.value * (1 - 1e-4)
    )


def test_measurements_are_reproducible_from_the_seed_and_noisy_as_asked() -> None:
    xs = [0.1 + 0.001 * i for i in range(2000)]
    first = measurements(g * sympy.sin(theta), theta, xs, {g: 9.81}, 0.03, "alice", figures=12)
    assert first == measurements(g * sympy.sin(theta), theta, xs, {g: 9.81}, 0.03, "alice", figures=12)
    assert first != measurements(g * sympy.sin(theta), theta, xs, {g: 9.81}, 0.03, "bob", figures=12)
    relative = np.array(first) / (9.81 * np.sin(xs)) - 1
    assert 0.027 < float(np.std(relative)) < 0.033


@cache
def _lab():
    doc = bank_documents()["incline-lab"]
    return doc, compile_problem(doc)


def _student(name: str):
    doc, compiled = _lab()
    variant = draw_variant(doc, 1, name, "secret")
    part = compiled.part("g_fit")
    return part, variant


def test_each_students_data_are_their_own_and_the_same_each_time() -> None:
    part, alice = _student("alice")
    _, bob = _student("bob")
    assert part.lab(alice) == part.lab(alice)
    assert part.lab(alice).measured != part.lab(bob).measured


@pytest.mark.parametrize("student", ["alice", "bob", "carol"])
def test_the_tolerance_follows_the_fits_standard_error(student: str) -> None:
    part, variant = _student(student)
    fit = part.lab(variant).fit
    question = part.question(variant)
    for errors, right in ((0, True), (1.5, True), (-1.5, True), (2.5, False), (-2.5, False)):
        verdict = question.grade(f"{fit.value + errors * fit.standard_error:.6f} m/s^2")
        assert (verdict.outcome is Outcome.CORRECT) == right, (errors, verdict)
    assert question.grade(f"{fit.value * 100:.4f} cm/s^2").outcome is Outcome.CORRECT


def test_fitting_against_the_angle_or_a_factor_off_is_said() -> None:
    part, variant = _student("alice")
    lab, question = part.lab(variant), part.question(variant)
    angles = np.radians(lab.settings)
    against_angle = float(angles @ np.array(lab.measured) / (angles @ angles))
    verdict = question.grade(f"{against_angle:.5f} m/s^2")
    assert verdict.reason is Reason.KNOWN_MISTAKE and "against" in verdict.feedback
    doubled = question.grade(f"{2 * lab.fit.value:.5f} m/s^2")
    assert doubled.reason is Reason.KNOWN_MISTAKE and "2 times" in doubled.feedback


@pytest.mark.parametrize(
    ("scale", "units", "reason", "said"),
    [
        (1, "m/s^2", Reason.KNOWN_MISTAKE, "2 times"),
        (100, "cm/s^2", Reason.KNOWN_MISTAKE, "2 times"),  # held against the answer as read, in its units
        (1, "m/s", Reason.WRONG_DIMENSION, "is expected"),  # the units' message wins, as for a numeric part
    ],
)
def test_a_wrong_fit_is_named_from_the_answer_read_once(monkeypatch, scale, units, reason, said) -> None:
    # Each wrong fit was a question of its own that read the answer again: a regrade read every answer
    # once per wrong fit.
    from physics.numeric import check

    read_numeric_answer = check.read_numeric_answer
    part, variant = _student("alice")
    lab, question = part.lab(variant), part.question(variant)
    reads = []
    monkeypatch.setattr(
        check, "read_numeric_answer", lambda *a, **k: reads.append(a) or read_numeric_answer(*a, **k)
    )
    verdict = question.grade(f"{2 * lab.fit.value * scale:.5f} {units}")
    assert verdict.reason is reason and said in verdict.feedback
    assert len(question.mistakes) >= 2 and len(reads) == 1


def test_the_self_test_draws_each_students_data_once_more_only_to_see_it_reproduced(monkeypatch) -> None:
    # Whether the quantity is proportional to the fitted value is the part's, settled as it compiles: it
    # was simplified again for every student's question, and the self-test drew each student's data
    # for the question and again for the fit.
    from problems.kinds.data import CompiledDataPart, DataKind

    part, variant = _student("alice")
    draw = CompiledDataPart.lab
    draws = []
    monkeypatch.setattr(CompiledDataPart, "lab", lambda self, v: draws.append(v) or draw(self, v))
    monkeypatch.setattr(sympy, "simplify", lambda *a, **k: pytest.fail("simplified per student"))
    results = DataKind().selftest("incline-lab", part, [variant])
    assert all(result.ok for result in results), results
    assert [r.check for r in results if "wrong fit" in r.check] == [
        f"student 0 wrong fit {j}" for j in (1, 2, 3, 4)
    ]
    assert draws == [variant, variant]


def test_the_student_sees_their_own_table_plot_and_csv() -> None:
    doc, compiled = _lab()
    variant = draw_variant(doc, 1, "alice", "secret")
    view = student_view(doc, variant, compiled)
    part = next(p for p in _parts(view) if p["id"] == "g_fit")
    html = templates.env.get_template("data/student.html").render(part=part)
    measured = compiled.part("g_fit").lab(variant).measured
    assert all(f"<td>{measured_text(value)}</td>" in html for value in measured)
    assert "<svg" in html and html.count("<circle") == len(measured) and "text/csv" in html
    assert str(compiled.part("g_fit").lab(variant).fit.value)[:5] not in html  # never the fit itself


def test_an_ad_hoc_lab_check_grades_against_the_fit_of_the_data_sent() -> None:
    from pydantic import TypeAdapter

    from physics.checking import run_job
    from problems.kinds import CheckIn

    s, a = np.sin(ANGLES), np.array(KNOWN)
    slope = float(s @ a / (s @ s))
    body = {
        "kind": "data",
        "quantity": "g*sin(theta)",
        "vary": "theta",
        "fit": "g",
        "settings": ANGLES,
        "measured": KNOWN,
        "units": "m/s^2",
    }
    for answer, outcome in (
        (f"{slope:.4f} m/s^2", Outcome.CORRECT),
        (f"{slope * 1.1:.4f} m/s^2", Outcome.INCORRECT),
    ):
        verdict = run_job(TypeAdapter(CheckIn).validate_python({**body, "answer": answer}).job())
        assert verdict.outcome is outcome, verdict


@pytest.mark.parametrize(
    ("value", "shown"),
    [(1.6, "1.60"), (0.844, "0.844"), (5.0, "5.00"), (12.3, "12.3"), (123.0, "123"), (0.0501, "0.0501")],
)
def test_a_measurement_is_shown_to_three_significant_figures_with_its_zeros(value: float, shown: str) -> None:
    assert measured_text(value) == shown
