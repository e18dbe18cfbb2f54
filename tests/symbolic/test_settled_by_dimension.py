"""An ambiguous division (`mv/qB`) is settled by dimension where exactly one reading has the dimension
the answer must have; it is refused where dimensions cannot decide."""

from __future__ import annotations

import pytest

from physics.checking import SymbolDecl, preview, run_job
from physics.verdict import Outcome, Reason
from problems.kinds.symbolic import SymbolicJob

CHARGE = (
    SymbolDecl("m", "kg"),
    SymbolDecl("v", "m/s"),
    SymbolDecl("q", "C"),
    SymbolDecl("B", "T"),
)
PENDULUM = (SymbolDecl("m", "kg"), SymbolDecl("M", "kg"), SymbolDecl("g", "m/s^2"), SymbolDecl("L", "m"))
LENNARD_JONES = (SymbolDecl("U0", "J"), SymbolDecl("r0", "m"), SymbolDecl("r", "m"), SymbolDecl("m", "kg"))
MOMENTUM = (SymbolDecl("p", "kg*m/s"), SymbolDecl("m", "kg"))
FALL = (SymbolDecl("v", "m/s"), SymbolDecl("g", "m/s^2"))

SETTLED = [
    # (answer, reference, symbols, reading taken, what the answer must be)
    ("mv/qB", "m*v/(q*B)", CHARGE, "m*v/(q*B)", "a length"),
    ("m v/q B", "m*v/(q*B)", CHARGE, "m*v/(q*B)", "a length"),
    ("(m+M)/m sqrt(2gL)", "(m+M)/m*sqrt(2*g*L)", PENDULUM, "(m + M)/m*sqrt(2*g*L)", "a speed"),
    ("12/r0 sqrt(U0/m)", "12/r0*sqrt(U0/m)", LENNARD_JONES, "12/r0*sqrt(U0/m)", "an angular frequency"),
    ("p^2/2m", "p^2/(2*m)", MOMENTUM, "p**2/(2*m)", "an energy"),
    ("v^2/2g", "v^2/(2*g)", FALL, "v**2/(2*g)", "a length"),
]


@pytest.mark.parametrize(
    ("answer", "reference", "symbols", "reading", "kind"), SETTLED, ids=[c[0] for c in SETTLED]
)
def test_the_only_reading_with_the_expected_dimension_is_graded_and_shown(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], reading: str, kind: str
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert verdict.outcome is Outcome.CORRECT, verdict.feedback
    assert verdict.read_as is not None
    assert verdict.read_as.text == reading
    assert verdict.read_as.note is not None
    assert verdict.read_as.note.startswith(f"Read as {reading}: the only reading that is {kind}")
    assert verdict.feedback.startswith(f"Read as {reading}")


def test_a_settled_reading_that_is_wrong_is_graded_wrong() -> None:
    verdict = run_job(SymbolicJob("2mv/qB", "m*v/(q*B)", CHARGE))
    assert verdict.outcome is Outcome.INCORRECT
    assert verdict.reason is Reason.CONSTANT_FACTOR
    assert verdict.read_as is not None and verdict.read_as.note is not None


def test_preview_shows_the_settled_reading_before_submission() -> None:
    shown = preview(SymbolicJob("mv/qB", "m*v/(q*B)", CHARGE))
    assert shown.error is None
    assert shown.read_as is not None
    assert shown.read_as.text == "m*v/(q*B)"
    assert shown.read_as.note is not None


REFUSED = [
    # (answer, reference, symbols, why dimensions cannot decide)
    (
        "12 U0/r ((r0/r)^12 - (r0/r)^6)",
        "12*U0/r*((r0/r)^12 - (r0/r)^6)",
        LENNARD_JONES,
        "Both readings are a force",
    ),  # the bracket is a pure number: both readings are forces
    ("p^2/2m", "p^2/(2*m)", (SymbolDecl("p"), SymbolDecl("m", "kg")), "Add parentheses"),  # p undimensioned
    ("mv/qB", "m*v*B", CHARGE, "Add parentheses"),  # neither reading has the reference's dimension
]


@pytest.mark.parametrize(("answer", "reference", "symbols", "words"), REFUSED, ids=[c[0] for c in REFUSED])
def test_division_that_dimensions_cannot_settle_is_refused_with_both_readings(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], words: str
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    assert verdict.outcome is Outcome.INVALID
    assert verdict.reason is Reason.AMBIGUOUS
    assert words in verdict.feedback
    assert "Did you mean" in verdict.feedback


def test_several_ambiguous_divisions_are_settled_together() -> None:
    verdict = run_job(SymbolicJob("mv/qB + mv/2qB", "3*m*v/(2*q*B)", CHARGE))
    assert verdict.outcome is Outcome.CORRECT
    assert verdict.read_as is not None
    assert verdict.read_as.text == "m*v/(q*B) + m*v/(2*q*B)"


def test_more_ambiguous_divisions_than_the_budget_are_refused() -> None:
    answer = " + ".join(["mv/qB"] * 4)
    verdict = run_job(SymbolicJob(answer, "4*m*v/(q*B)", CHARGE))
    assert verdict.reason is Reason.AMBIGUOUS
