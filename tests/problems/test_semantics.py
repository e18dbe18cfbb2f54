"""Meaning checks on well-shaped documents: every fault at once, each with its path."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from problems.errors import ProblemInvalid
from problems.loader import parse_problem
from tests.problems.documents import spring

Doc = dict[str, Any]


def _change(fn: Callable[[Doc], None]) -> Callable[[Doc], None]:
    return fn


def _unknown_symbol_in_answer(d: Doc) -> None:
    d["parts"][0]["answer"] = "sqrt(k/q)"


def _symbol_outside_part_symbols(d: Doc) -> None:
    d["parts"][0]["answer"] = "sqrt(k/m) * theta"


def _eval_attempt(d: Doc) -> None:
    d["parts"][0]["answer"] = "__import__('os').system('true')"


def _unknown_mistake_symbol(d: Doc) -> None:
    d["parts"][0]["mistakes"][0]["answer"] = "sqrt(k/z)"


def _si_part_in_non_si_units(d: Doc) -> None:
    d["parts"][1].update({"units": "rev/s", "units_system": "SI"})


def _given_for_unknown_symbol(d: Doc) -> None:
    d["given"]["v"] = {"min": 1, "max": 2, "unit": "m/s"}


def _empty_given_range(d: Doc) -> None:
    d["given"]["m"]["min"] = 3


def _range_low_not_below_high(d: Doc) -> None:
    d["symbols"]["theta"]["range"] = ["pi/2", 0]


def _range_bound_unreadable(d: Doc) -> None:
    d["symbols"]["theta"]["range"] = [0, "pi/"]


def _duplicate_part_ids(d: Doc) -> None:
    d["parts"][1]["id"] = "angular_frequency"


def _numeric_of_unknown_quantity(d: Doc) -> None:
    d["parts"][1]["of"] = "period"


def _unknown_units(d: Doc) -> None:
    d["parts"][1]["units"] = "smoots"


def _given_unit_of_wrong_dimension(d: Doc) -> None:
    d["given"]["m"]["unit"] = "m"


def _unknown_dimension(d: Doc) -> None:
    d["symbols"]["k"]["dimension"] = "blorps"


def _placeholder_without_given(d: Doc) -> None:
    d["statement"] += " And {x}."


def _given_outside_symbol_range(d: Doc) -> None:
    d["given"]["theta"]["max"] = 100


def _negative_given_for_positive_symbol(d: Doc) -> None:
    d["given"]["m"]["min"] = -1


def _limit_on_unknown_symbol(d: Doc) -> None:
    d["parts"][0]["limits"][0]["where"] = {"z": "oo"}


def _bad_constraint(d: Doc) -> None:
    d["constraints"] = ["m + k"]


def _no_answer_and_no_model(d: Doc) -> None:
    del d["parts"][0]["answer"]


def _part_symbols_unknown(d: Doc) -> None:
    d["parts"][0]["symbols"] = ["m", "k", "q"]


CASES = [
    pytest.param(_unknown_symbol_in_answer, ["parts[0].answer"], id="unknown-symbol-in-answer"),
    pytest.param(_symbol_outside_part_symbols, ["parts[0].answer"], id="symbol-not-allowed-in-part"),
    pytest.param(_eval_attempt, ["parts[0].answer"], id="code-in-answer-is-not-run"),
    pytest.param(_unknown_mistake_symbol, ["parts[0].mistakes[0].answer"], id="unknown-symbol-in-mistake"),
    pytest.param(_given_for_unknown_symbol, ["given.v"], id="given-for-unknown-symbol"),
    pytest.param(_empty_given_range, ["given.m"], id="given-min-above-max"),
    pytest.param(_range_low_not_below_high, ["symbols.theta.range"], id="range-low-not-below-high"),
    pytest.param(_range_bound_unreadable, ["symbols.theta.range[1]"], id="range-bound-unreadable"),
    pytest.param(_duplicate_part_ids, ["parts[1].id"], id="duplicate-part-ids"),
    pytest.param(_numeric_of_unknown_quantity, ["parts[1].of"], id="numeric-of-unknown-quantity"),
    pytest.param(_unknown_units, ["parts[1].units"], id="unknown-units"),
    pytest.param(_si_part_in_non_si_units, ["parts[1].units"], id="si-part-in-non-si-units"),
    pytest.param(_given_unit_of_wrong_dimension, ["given.m.unit"], id="given-unit-wrong-dimension"),
    pytest.param(_unknown_dimension, ["symbols.k.dimension"], id="unknown-dimension"),
    pytest.param(_placeholder_without_given, ["statement"], id="placeholder-without-given"),
    pytest.param(_given_outside_symbol_range, ["given.theta"], id="given-outside-symbol-range"),
    pytest.param(
        _negative_given_for_positive_symbol, ["given.m.min"], id="negative-given-for-positive-symbol"
    ),
    pytest.param(_limit_on_unknown_symbol, ["parts[0].limits[0].where.z"], id="limit-on-unknown-symbol"),
    pytest.param(_bad_constraint, ["constraints[0]"], id="constraint-without-relation"),
    pytest.param(_no_answer_and_no_model, ["parts[0]"], id="no-answer-and-no-model"),
    pytest.param(_part_symbols_unknown, ["parts[0].symbols[2]"], id="part-symbols-unknown"),
]


@pytest.mark.parametrize(("change", "paths"), CASES)
def test_meaning_fault_is_reported_at_its_path(change: Callable[[Doc], None], paths: list[str]) -> None:
    data = spring()
    change(data)
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(data)
    assert [path for path, _ in caught.value.errors] == paths, caught.value.errors


def test_every_meaning_fault_is_reported_at_once() -> None:
    data = spring()
    for change in (_unknown_symbol_in_answer, _given_for_unknown_symbol, _duplicate_part_ids, _unknown_units):
        change(data)
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(data)
    assert [path for path, _ in caught.value.errors] == [
        "given.v",
        "parts[0].answer",
        "parts[1].id",
        "parts[1].units",
    ]


def test_valid_document_has_no_meaning_faults() -> None:
    assert parse_problem(spring()).id == "tiny-spring"


def test_unknown_symbol_message_names_the_symbol() -> None:
    data = spring()
    _unknown_symbol_in_answer(data)
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(data)
    assert "q" in caught.value.errors[0][1]
