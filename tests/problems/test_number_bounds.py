"""Every number in a problem document is refused at upload unless the database and the grader can hold it."""

from __future__ import annotations

import json
from decimal import Decimal
from typing import Any

import pytest

from problems.errors import ProblemInvalid
from problems.loader import parse_problem
from problems.schema import MAX_ATTEMPTS
from tests.problems.documents import spring

# Where each number lives, as (path in the document, path in the error report).
ATTEMPTS = [
    (("max_attempts",), "max_attempts"),
    (("parts", 0, "max_attempts"), "parts[0].max_attempts"),
    (("parts", 1, "max_attempts"), "parts[1].max_attempts"),
]
WHOLE = [*ATTEMPTS, (("given", "m", "sigfigs"), "given.m.sigfigs")]
EXACT = [
    (("given", "k", "min"), "given.k.min"),
    (("given", "k", "max"), "given.k.max"),
    (("given", "k", "step"), "given.k.step"),
    (("parts", 1, "tolerance"), "parts[1].tolerance.rel"),
    (("symbols", "theta", "range"), "symbols.theta.range[1]"),
    (("parts", 0, "limits", 0, "where"), "parts[0].limits[0].where.m"),
]

TOO_BIG_FOR_ATTEMPTS = [
    pytest.param(2**63, id="2^63"),
    pytest.param(10**30, id="10^30"),
    pytest.param(MAX_ATTEMPTS + 1, id="one-over"),
    pytest.param(1e30, id="float-10^30"),
]
NOT_WHOLE = [pytest.param(True, id="true"), pytest.param(False, id="false"), pytest.param(2.5, id="2.5")]
UNGRADABLE = [
    pytest.param(10**101, id="10^101"),
    pytest.param(10**5000, id="5000-digit-int"),
    pytest.param("1e101", id="1e101-text"),
    pytest.param("1e-101", id="1e-101-text"),
    pytest.param("1e999999999", id="huge-exponent-text"),
    pytest.param("1." + "1" * 40, id="41-digits"),
    pytest.param(True, id="true"),
]


def _put(doc: dict[str, Any], where: tuple[str | int, ...], value: Any) -> None:
    target: Any = doc
    for key in where[:-1]:
        target = target[key]
    last = where[-1]
    if last == "tolerance":
        target[last] = {"rel": value}
    elif last == "range":
        target[last] = [0, value]
    elif last == "where":
        target[last] = {"m": value}
    else:
        target[last] = value
    if where == ("given", "k", "min"):
        doc["given"]["k"]["max"] = 10  # keep min <= max out of the question


def _errors(doc: dict[str, Any]) -> dict[str, str]:
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(doc, check_meaning=False)
    return dict(caught.value.errors)


@pytest.mark.parametrize("value", TOO_BIG_FOR_ATTEMPTS)
@pytest.mark.parametrize(("where", "reported"), ATTEMPTS)
def test_attempt_limits_beyond_what_the_counter_holds_are_refused(where, reported, value):
    doc = spring()
    _put(doc, where, value)
    assert _errors(doc) == {reported: f"must be <= {MAX_ATTEMPTS}"}


@pytest.mark.parametrize("value", NOT_WHOLE)
@pytest.mark.parametrize(("where", "reported"), WHOLE)
def test_whole_numbers_refuse_booleans_and_fractions(where, reported, value):
    doc = spring()
    _put(doc, where, value)
    assert list(_errors(doc)) == [reported]


@pytest.mark.parametrize("value", UNGRADABLE)
@pytest.mark.parametrize(("where", "reported"), EXACT)
def test_exact_numbers_too_large_small_or_precise_to_grade_are_refused(where, reported, value):
    doc = spring()
    _put(doc, where, value)
    errors = _errors(doc)
    assert reported in errors, errors


@pytest.mark.parametrize(
    "value",
    [MAX_ATTEMPTS, 1, 3.0],
)
def test_attempt_limits_within_range_are_kept(value):
    doc = spring()
    doc["max_attempts"] = value
    assert parse_problem(doc, check_meaning=False).max_attempts == value


@pytest.mark.parametrize(
    "value",
    ["6.02214076e23", "1.602176634e-19", "6.62607015e-34", "1e100", "1e-100", "0", "1." + "1" * 39],
)
def test_physical_constants_and_the_limits_themselves_are_kept(value):
    doc = spring()
    doc["given"]["k"] = {"min": value, "max": value, "unit": "N/m"}
    assert parse_problem(doc, check_meaning=False).given["k"].min == Decimal(value)


def test_json_upload_with_a_64_bit_attempt_limit_is_refused_with_its_path():
    doc = spring()
    doc["max_attempts"] = 2**63
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(json.dumps(doc).encode(), "json", check_meaning=False)
    assert caught.value.errors == [("max_attempts", f"must be <= {MAX_ATTEMPTS}")]


@pytest.mark.slow
def test_collecting_the_errors_of_a_document_is_linear_in_their_number():
    # 200,000 unknown keys: seconds when linear; the quadratic de-duplication it replaced would compare
    # some 2*10^10 pairs and run into the test timeout.
    doc = spring()
    doc.update({f"u{i}": 0 for i in range(200_000)})
    errors = _errors(doc)
    assert len(errors) == 200_000
    assert errors["u0"] == errors["u199999"] == "unknown field"
