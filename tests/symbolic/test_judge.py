"""judge_symbolic as callers use it: reproducible, strict about names, and its bench cases."""

from __future__ import annotations

import pickle

import pytest
import sympy

from physics.errors import ParseError, UnknownSymbol
from physics.symbolic import bench_equivalence_cases, judge_symbolic, prepare_reference
from physics.symbolic.judge import REMEMBERED, Remembered
from physics.verdict import Reason
from tests.symbolic.support import context, g, m, sin, theta


def test_an_undeclared_symbol_in_the_answer_is_an_unknown_symbol_error():
    reference = prepare_reference(m * g, context(m * g))
    with pytest.raises(UnknownSymbol) as raised:
        judge_symbolic(m * g * sympy.Symbol("h"), reference)
    assert raised.value.symbol == "h"
    assert raised.value.allowed == ("g", "m")


def test_a_relation_is_not_an_answer():
    reference = prepare_reference(m * g, context(m * g))
    with pytest.raises(ParseError):
        judge_symbolic(sympy.Eq(m, g), reference)


@pytest.mark.parametrize("answer", [m, -m, sympy.Integer(0)], ids=["bare-symbol", "negated-symbol", "zero"])
def test_a_lone_symbol_or_number_is_an_answer_not_a_relation(answer):
    # sympy's Symbol is also a Boolean: that must not make `m` look like a relation.
    judgement = judge_symbolic(answer, prepare_reference(m, context(m)))
    assert judgement.correct == (answer == m)


def test_judging_twice_gives_the_same_judgement():
    expected = m * g * sin(theta)
    answer = m * g * sin(theta) * (1 + sympy.Rational(1, 10**9))
    first = judge_symbolic(answer, prepare_reference(expected, context(expected)))
    second = judge_symbolic(answer, prepare_reference(expected, context(expected)))
    assert first == second
    assert first.reason is Reason.CONSTANT_FACTOR


def test_a_prepared_reference_survives_pickling_for_worker_processes():
    expected = m * g * sin(theta)
    reference = pickle.loads(pickle.dumps(prepare_reference(expected, context(expected))))
    assert judge_symbolic(g * m * sin(theta), reference).correct


BENCH = bench_equivalence_cases()
BENCH_VERDICTS = [True, True, False, True, False, True, False, True, True, True]


@pytest.mark.parametrize(
    ("case", "correct"),
    list(zip(BENCH, BENCH_VERDICTS, strict=True)),
    ids=[f"bench-{i}" for i in range(len(BENCH))],
)
def test_bench_cases_get_their_known_verdicts(case, correct):
    answer, expected, ctx = case
    assert judge_symbolic(answer, prepare_reference(expected, ctx)).correct is correct


def test_a_remembered_judgement_belongs_to_its_reference_and_its_expression():
    answer = m * g * sin(theta)
    right = prepare_reference(answer, context(answer))
    negated = prepare_reference(-answer, context(-answer))
    for _ in range(2):  # the second round is answered from what each reference remembers
        assert judge_symbolic(answer, right).correct
        assert judge_symbolic(answer, negated).reason is Reason.SIGN_ERROR
        assert judge_symbolic(2 * answer, right).reason is Reason.CONSTANT_FACTOR
        assert judge_symbolic(-answer, right).reason is Reason.SIGN_ERROR


def test_an_answer_over_a_same_named_foreign_symbol_is_not_taken_for_a_remembered_one():
    # m without the context's assumptions: renamed to the context's m (the same judgement), never
    # looked up as if it were the context's m, and never stored under the foreign tree.
    expected = m * g
    reference = prepare_reference(expected, context(expected))
    foreign = sympy.Symbol("m") * g
    assert foreign != expected
    assert judge_symbolic(expected, reference).correct
    assert judge_symbolic(foreign, reference).correct
    assert REMEMBERED.get(reference, expected) is not None
    assert REMEMBERED.get(reference, foreign) is None


def test_judgements_are_remembered_up_to_a_bound_the_least_recently_used_forgotten_first():
    references = [prepare_reference(e, context(e)) for e in (m * g, -m * g, 2 * m * g)]
    remembered = Remembered(2)
    judgements = [judge_symbolic(m * g, reference) for reference in references]
    for reference, judgement in zip(references, judgements, strict=True):
        remembered.put(reference, m * g, judgement)
    assert len(remembered) == 2
    assert remembered.get(references[0], m * g) is None
    assert remembered.get(references[1], m * g) is judgements[1]
    assert remembered.get(references[2], m * g) is judgements[2]
    assert remembered.get(references[1], g) is None
    remembered.clear()  # what a benchmark does to measure an answer new to the worker
    assert len(remembered) == 0 and remembered.get(references[2], m * g) is None


def test_a_dropped_reference_is_never_matched_by_a_new_one():
    remembered = Remembered(8)
    reference = prepare_reference(m * g, context(m * g))
    remembered.put(reference, m * g, judge_symbolic(m * g, reference))
    other = pickle.loads(pickle.dumps(reference))  # equal in every field, another object
    assert remembered.get(other, m * g) is None


def test_a_prepared_reference_pickles_without_what_it_keeps_for_answers():
    expected = m * g * sin(theta)
    reference = prepare_reference(expected, context(expected))
    for k in range(2, 6):
        assert judge_symbolic(k * expected, reference).reason is Reason.CONSTANT_FACTOR
    assert "_grids" in reference.__dict__
    state = pickle.loads(pickle.dumps(reference)).__dict__
    assert "_grids" not in state
    assert (
        judge_symbolic(7 * expected, pickle.loads(pickle.dumps(reference))).reason is Reason.CONSTANT_FACTOR
    )
