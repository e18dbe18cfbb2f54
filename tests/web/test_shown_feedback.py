"""What the student page shows after its own word for a verdict: the feedback without a second
"Correct.", and a settled reading's note as typed, not turned into emphasis by Markdown."""

from __future__ import annotations

import pytest

from app.web.rendering import render_inline
from app.web.student_work import shown_feedback
from physics.checking import SymbolDecl, run_job
from physics.verdict import Outcome
from problems.kinds.symbolic import SymbolicJob

SHOWN = [
    # (verdict, feedback as graded, as the page shows it after "Correct." / "Not correct.")
    (Outcome.CORRECT, "Correct.", ""),
    (
        Outcome.CORRECT,
        "Read as A·e^(-omega·t): the only reading that is a length. Correct.",
        "Read as A·e^(-omega·t): the only reading that is a length.",
    ),
    (
        Outcome.INCORRECT,
        "Your answer is off by a constant factor.",
        "Your answer is off by a constant factor.",
    ),
    (
        Outcome.CORRECT,
        "Correct. Hz is the unit of frequency; s⁻¹ reads the same.",
        "Hz is the unit of frequency; s⁻¹ reads the same.",
    ),
    (Outcome.INCORRECT, "Correct.", "Correct."),  # only a correct verdict's word says it already
]


@pytest.mark.parametrize(("verdict", "feedback", "shown"), SHOWN)
def test_the_page_drops_only_the_correct_its_verdict_word_already_says(
    verdict: Outcome, feedback: str, shown: str
) -> None:
    assert shown_feedback(verdict, feedback) == shown


@pytest.mark.parametrize(
    ("answer", "reference", "symbols", "typed"),
    [
        (
            "2π√m/k",
            "2*pi*sqrt(m/k)",
            (SymbolDecl("m", "kg"), SymbolDecl("k", "N/m")),
            "2·pi·sqrt(m/k)",
        ),
        (
            "A e^-ωt",
            "A*exp(-omega*t)",
            (SymbolDecl("A", "m"), SymbolDecl("omega", "1/s"), SymbolDecl("t", "s")),
            "A·e^(-omega·t)",
        ),
    ],
)
def test_a_settled_readings_note_renders_as_typed_without_emphasis(
    answer: str, reference: str, symbols: tuple[SymbolDecl, ...], typed: str
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, symbols))
    html = str(render_inline(shown_feedback(verdict.outcome, verdict.feedback)))
    assert "<em>" not in html and "<strong>" not in html
    assert html.startswith(f"Read as {typed}: the only reading that is")
