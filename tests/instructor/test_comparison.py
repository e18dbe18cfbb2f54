"""The methods compared on a hand-out: each row's count of equations against unknowns is true (or said
to be uncounted, never "4 equations in 0 unknowns"), and every worked method is in the table or left
out of it saying why (app/instructor/worked.py)."""

from __future__ import annotations

import pytest

from app.instructor.worked import Comparison, MethodInfo, worked_solutions
from problems.compiled import compile_problem
from tests.bank import bank_documents

MODELLED = sorted(pid for pid, doc in bank_documents().items() if doc.model is not None)


def _worked(problem: str) -> tuple[tuple[MethodInfo, ...], Comparison | None]:
    compiled = compile_problem(bank_documents()[problem])
    assert compiled.derived is not None
    return worked_solutions(compiled, compiled.derived.raw, None)


@pytest.mark.parametrize("problem", MODELLED)
@pytest.mark.sample(3)
@pytest.mark.slow
def test_every_row_counts_truly_and_every_worked_method_is_in_the_table_or_said_left_out(
    problem: str,
) -> None:
    methods, comparison = _worked(problem)
    if comparison is None:  # fewer than two methods answer: there is nothing to compare
        assert sum(1 for m in methods if m.answers) < 2
        return
    rows = {row.method: row for row in comparison.rows}
    said = " ".join(comparison.notes)
    for method in methods:
        if not method.answers:
            assert f"{method.title} answer" in said and "leaves" in said, (problem, method.name)
            continue
        row = rows[method.title]
        if row.equations is None or row.unknowns is None:
            assert row.equations is row.unknowns is None, (problem, method.name)
            assert method.title in said, (problem, method.name)
        else:
            assert row.equations > 0 and row.unknowns > 0, (problem, method.name, row)


@pytest.mark.slow
def test_the_double_pendulums_table_counts_the_frequency_equation_and_leaves_out_newton_saying_why() -> None:
    # it read Lagrange "4 equations in 0 unknowns", conservation "0 / 0", and Newton's worked method
    # was missing without a word
    _, comparison = _worked("double-pendulum")
    assert comparison is not None
    counts = {row.method: (row.equations, row.unknowns) for row in comparison.rows}
    assert counts == {"Conservation laws": (1, 1), "Lagrange's equations": (5, 5)}
    assert "1 equation in 1 unknown, against 5 for Lagrange's equations" in comparison.advice
    assert comparison.notes[0] == (
        "Newton's laws answer no part here (Parts 1, 2, 3 and 4: Cartesian normal modes are done here "
        "only without constraints), so the table leaves them out."
    )


@pytest.mark.slow
def test_methods_whose_worked_steps_count_nothing_show_a_dash_said_under_the_table() -> None:
    # the ballistic pendulum's impact is worked without numbered equations: "0 equations in 0 unknowns"
    _, comparison = _worked("ballistic-pendulum")
    assert comparison is not None
    assert {(row.equations, row.unknowns) for row in comparison.rows} == {(None, None)}
    assert comparison.notes[-1].startswith(
        "—: the worked solutions by Newton's laws and Conservation laws do not number their equations"
    )
