"""Verdicts cross from a grading worker to the server pickled: every field comes back as it went."""

from __future__ import annotations

import copy
import pickle

import pytest

from physics.errors import AmbiguousInput
from physics.verdict import Judgement, Outcome, ReadAs, Reason, Verdict

VERDICTS = [
    Verdict.graded(Judgement(True, Reason.EQUIVALENT, "Correct."), ReadAs("m*g", "m g")),
    Verdict.graded(
        Judgement(False, Reason.SIGN_ERROR, "Check the sign."), ReadAs("-m*v/(q*B)", "x", "Read as")
    ),
    Verdict.graded(Judgement(False, Reason.WRONG_VALUE, "No."), None),
    Verdict.invalid(AmbiguousInput("2E-3: which?", 1, ("2*10^(-3)", "2*E-3"))),
]


@pytest.mark.parametrize("verdict", VERDICTS, ids=["correct", "noted", "no-reading", "invalid"])
def test_a_verdict_is_the_same_after_a_pickle_round_trip(verdict):
    for protocol in (2, pickle.DEFAULT_PROTOCOL, pickle.HIGHEST_PROTOCOL):
        back = pickle.loads(pickle.dumps(verdict, protocol=protocol))
        assert back == verdict
        assert type(back) is Verdict
        assert back.outcome is verdict.outcome and back.reason is verdict.reason  # the enum members
    assert copy.deepcopy(verdict) == verdict


def test_every_outcome_and_reason_survives_pickling():
    for outcome in Outcome:
        for reason in Reason:
            verdict = Verdict(outcome, 0.5, reason, "feedback")
            assert pickle.loads(pickle.dumps(verdict)) == verdict
