"""`sin θ^2` is graded as sin(θ²); when that is wrong and (sin θ)² would be right, the feedback says how
to write (sin θ)². Its reading note leads the feedback otherwise."""

from __future__ import annotations

import pytest

from physics.checking import SymbolDecl, preview, run_job
from physics.verdict import Outcome, Reason
from problems.kinds.symbolic import SymbolicJob

WEDGE = (
    SymbolDecl("m", "kg"),
    SymbolDecl("M", "kg"),
    SymbolDecl("g", "m/s^2"),
    SymbolDecl("theta", "1", range=("0", "pi/2")),
)
WEDGE_ACCELERATION = "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)^2)"
NOTE = "sin θ^2 is read as sin(θ²); for (sin θ)² write sin^2 θ or (sin θ)^2"
HINT = "Read as sin(θ²); if you meant (sin θ)², write sin^2 θ"

HINTED = [
    # (answer, reference, the hint that leads the feedback)
    ("-m g sinθcosθ/(M + m sinθ^2)", WEDGE_ACCELERATION, HINT),
    ("g sin θ^2", "g*sin(theta)^2", HINT),
    ("g sin 2θ^2", "g*sin(2*theta)^2", "Read as sin(2θ²); if you meant (sin 2θ)², write sin^2 2θ"),
    ("g sin θ^3", "g*sin(theta)^3", "Read as sin(θ³); if you meant (sin θ)³, write sin^3 θ"),
    (
        "g sin θ^2 - g cos θ^2",
        "-g*cos(2*theta)",
        "Read as sin(θ²) and cos(θ²); if you meant (sin θ)² and (cos θ)², write sin^2 θ and cos^2 θ",
    ),
]


@pytest.mark.parametrize(("answer", "reference", "hint"), HINTED, ids=[c[0] for c in HINTED])
def test_a_wrong_answer_that_the_other_reading_makes_right_says_how_to_write_it(
    answer: str, reference: str, hint: str
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, WEDGE))
    assert verdict.outcome is Outcome.INCORRECT  # graded as read: the attempt counts
    assert verdict.feedback.startswith(f"{hint}. ")
    assert verdict.read_as is not None and verdict.read_as.note is not None
    assert "is read as" in verdict.read_as.note


NOT_HINTED = [
    # (answer, reference, outcome, reason): the note leads the feedback, with no claim about the other reading
    ("-m g sinθcosθ/(M + 2m sin θ^2)", WEDGE_ACCELERATION, Outcome.INCORRECT, Reason.WRONG_VALUE),
    ("g sin θ^2", "-g*sin(theta)^2", Outcome.INCORRECT, Reason.WRONG_VALUE),
    ("g sin θ^2", "g*sin(theta^2)", Outcome.CORRECT, Reason.EQUIVALENT),  # meant as read
]


@pytest.mark.parametrize(
    ("answer", "reference", "outcome", "reason"), NOT_HINTED, ids=[f"{c[0]} vs {c[1]}" for c in NOT_HINTED]
)
def test_the_note_leads_the_feedback_when_the_other_reading_is_no_better(
    answer: str, reference: str, outcome: Outcome, reason: Reason
) -> None:
    verdict = run_job(SymbolicJob(answer, reference, WEDGE))
    assert (verdict.outcome, verdict.reason) == (outcome, reason)
    assert verdict.read_as is not None and verdict.read_as.note is not None
    assert verdict.feedback.startswith(f"{verdict.read_as.note}. ")
    assert "if you meant" not in verdict.feedback


@pytest.mark.parametrize("answer", ["g sin^2 θ", "g sin(θ)^2", "g (sin θ)^2"])
def test_powers_written_unambiguously_carry_no_note(answer: str) -> None:
    verdict = run_job(SymbolicJob(answer, "g*sin(theta)^2", WEDGE))
    assert verdict.outcome is Outcome.CORRECT
    assert verdict.read_as is not None and verdict.read_as.note is None
    assert verdict.feedback == "Correct."


def test_preview_shows_the_note_before_submission() -> None:
    shown = preview(SymbolicJob("g sin θ^2", "g*sin(theta)^2", WEDGE))
    assert shown.read_as is not None
    assert shown.read_as.note == NOTE
