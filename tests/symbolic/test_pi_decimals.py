"""A decimal typed for π (`2*3.14*sqrt(L/g)`) is graded as typed, off by a constant factor, and the
feedback says that π in its place would be right; where π would not make it right, the feedback is the
plain constant-factor one."""

from __future__ import annotations

import pytest

from physics.checking import SymbolDecl, run_job
from physics.symbolic.judge import FACTOR_FEEDBACK
from physics.verdict import Outcome, Reason
from problems.kinds.symbolic import SymbolicJob

PENDULUM = (SymbolDecl("L", "m"), SymbolDecl("g", "m/s^2"))
PERIOD = "2*pi*sqrt(L/g)"

CASES = [
    # (answer, the hint's swaps, or None: the plain constant-factor feedback)
    ("2*3.14*sqrt(L/g)", "π for 3.14"),
    ("2·3.1416·√(L/g)", "π for 3.1416"),
    ("6.28 sqrt(L/g)", "2π for 6.28"),
    ("4*1.571*sqrt(L/g)", "π/2 for 1.571"),
    ("3.14 sqrt(L/g)", None),  # the 2 is missing too: π alone would not make it right
    ("2*3.1*sqrt(L/g)", None),  # two significant digits: not taken for π
    ("6 sqrt(L/g)", None),
]


@pytest.mark.parametrize(("answer", "swaps"), CASES, ids=[c[0] for c in CASES])
def test_a_decimal_for_pi_is_named_when_pi_would_make_the_answer_right(
    answer: str, swaps: str | None
) -> None:
    verdict = run_job(SymbolicJob(answer, PERIOD, PENDULUM))
    assert verdict.outcome is Outcome.INCORRECT  # graded as typed: a decimal is exact
    assert verdict.reason is Reason.CONSTANT_FACTOR
    if swaps is None:
        assert verdict.feedback == FACTOR_FEEDBACK
    else:
        assert verdict.feedback.startswith(f"Your answer would be right with {swaps}: ")
        assert "write pi (or π)" in verdict.feedback


def test_pi_itself_is_correct() -> None:
    assert run_job(SymbolicJob("2π√(L/g)", PERIOD, PENDULUM)).outcome is Outcome.CORRECT
