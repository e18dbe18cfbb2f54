"""Tolerance bounds are inclusive and exact; sig-fig rounding is half away from zero, exactly."""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction

import pytest

from physics.errors import SpecError
from physics.numeric import NumericSpec, Tolerance, check_numeric
from physics.numeric.tolerance import accepts
from physics.verdict import Outcome

D = Decimal
F = Fraction

EDGES = [
    # (answer, expected, tolerance, correct?): expected 4.5807 ± 1 % is [4.534893, 4.626507]
    ("4.5807", "4.5807", Tolerance(rel=D("0.01")), True),
    ("4.535", "4.5807", Tolerance(rel=D("0.01")), True),
    ("4.5349", "4.5807", Tolerance(rel=D("0.01")), True),
    ("4.534893", "4.5807", Tolerance(rel=D("0.01")), True),  # exactly on the lower bound
    ("4.5348929999", "4.5807", Tolerance(rel=D("0.01")), False),
    ("4.534892", "4.5807", Tolerance(rel=D("0.01")), False),
    ("4.5348", "4.5807", Tolerance(rel=D("0.01")), False),
    ("4.626507", "4.5807", Tolerance(rel=D("0.01")), True),  # exactly on the upper bound
    ("4.6265070001", "4.5807", Tolerance(rel=D("0.01")), False),
    ("1.01", "1", Tolerance(rel=D("0.01")), True),  # 1.01 is not 1.0100000000000000088817… here
    ("0.99", "1", Tolerance(rel=D("0.01")), True),
    ("0.3", "0.1", Tolerance(abs=D("0.2")), True),  # 0.1 + 0.2 is exactly 0.3
    ("0.30001", "0.1", Tolerance(abs=D("0.2")), False),
    ("-0.1", "0.1", Tolerance(abs=D("0.2")), True),
    ("5.05", "5", Tolerance(abs=D("0.05")), True),
    ("5.0500001", "5", Tolerance(abs=D("0.05")), False),
    ("0", "0", Tolerance(rel=D("0.01")), True),
    ("0.0000001", "0", Tolerance(rel=D("0.01")), False),  # rel of zero admits only zero
    ("4.58", "4.58", Tolerance(), True),  # no keys: exact
    ("4.5800001", "4.58", Tolerance(), False),
    # every key given must pass
    ("4.6", "4.5807", Tolerance(rel=D("0.01"), abs=D("0.001")), False),
    ("4.581", "4.5807", Tolerance(rel=D("0.01"), abs=D("0.001")), True),
    ("4.58", "4.5807", Tolerance(rel=D("0.01"), sigfigs=3), True),
    ("4.59", "4.5857", Tolerance(rel=D("0.01"), sigfigs=3), True),
    ("4.58", "4.5857", Tolerance(rel=D("0.01"), sigfigs=3), False),  # within 1 % but rounded wrongly
]


@pytest.mark.parametrize(
    ("answer", "expected", "tolerance", "correct"), EDGES, ids=[f"{c[0]} vs {c[1]} {c[2]}" for c in EDGES]
)
def test_tolerance_edge(answer: str, expected: str, tolerance: Tolerance, correct: bool) -> None:
    verdict = check_numeric(answer, NumericSpec(D(expected), tolerance=tolerance))
    assert verdict.outcome == (Outcome.CORRECT if correct else Outcome.INCORRECT)


@pytest.mark.parametrize(
    ("answer", "expected", "tolerance", "correct"), EDGES, ids=[f"{c[0]} vs {c[1]} {c[2]}" for c in EDGES]
)
def test_tolerance_accepts_a_value_exactly_as_it_grades_that_answer(
    answer: str, expected: str, tolerance: Tolerance, correct: bool
) -> None:
    assert accepts(tolerance, D(answer), D(expected)) is correct


@pytest.mark.parametrize(
    ("value", "expected", "taken"),
    [("4.58493", "4.5807", True), ("4.58512", "4.5807", False), ("-4.58", "4.58", False)],
)
def test_tolerance_in_sigfigs_accepts_a_value_of_any_figures_that_rounds_alike(
    value: str, expected: str, taken: bool
) -> None:
    assert accepts(Tolerance(sigfigs=3), D(value), D(expected)) is taken


def test_default_tolerance_is_one_percent_relative() -> None:
    assert NumericSpec(D(1)).tolerance == Tolerance(rel=D("0.01"))


BAD_TOLERANCES = [
    ({"rel": D("-0.01")}, ("tolerance", "rel")),
    ({"abs": D("NaN")}, ("tolerance", "abs")),
    ({"rel": D("Infinity")}, ("tolerance", "rel")),
    ({"sigfigs": 0}, ("tolerance", "sigfigs")),
    ({"sigfigs": 41}, ("tolerance", "sigfigs")),
]


@pytest.mark.parametrize(("fields", "path"), BAD_TOLERANCES, ids=[str(c[0]) for c in BAD_TOLERANCES])
def test_unusable_tolerance_is_a_spec_error(fields: dict[str, object], path: tuple[str, ...]) -> None:
    with pytest.raises(SpecError) as caught:
        Tolerance(**fields)  # type: ignore[arg-type]
    assert caught.value.path == path


@pytest.mark.parametrize(
    ("fields", "path"),
    [
        ({"expected": D("NaN")}, ("expected",)),
        ({"expected": D(1), "units": "smoot"}, ("units",)),
        ({"expected": D(1), "units": "m/"}, ("units",)),
    ],
    ids=["nan-expected", "unknown-units", "malformed-units"],
)
def test_unusable_spec_is_a_spec_error(fields: dict[str, object], path: tuple[str, ...]) -> None:
    with pytest.raises(SpecError) as caught:
        NumericSpec(**fields)  # type: ignore[arg-type]
    assert caught.value.path == path


def test_float_from_json_is_read_as_its_shortest_decimal() -> None:
    spec = NumericSpec(4.5807, "m/s^2", tolerance=Tolerance(rel=0.01))  # type: ignore[arg-type]
    assert spec.expected == D("4.5807")
    assert spec.tolerance.rel == D("0.01")
    assert check_numeric("4.534893 m/s^2", spec).outcome is Outcome.CORRECT


@pytest.mark.parametrize(
    "expected",
    [D("1e999999999"), D("1e-999999999"), "1" * 61, True, None, "abc", D("sNaN"), float("inf"), [1]],
    ids=["huge", "tiny", "too-many-digits", "bool", "none", "text", "snan", "inf", "list"],
)
def test_unusable_expected_value_is_a_spec_error_cheaply(expected: object) -> None:
    with pytest.raises(SpecError) as caught:
        NumericSpec(expected)  # type: ignore[arg-type]
    assert caught.value.path == ("expected",)


@pytest.mark.parametrize("sigfigs", [2.0, True, "3"], ids=["float", "bool", "text"])
def test_sigfigs_must_be_a_whole_number(sigfigs: object) -> None:
    with pytest.raises(SpecError):
        Tolerance(sigfigs=sigfigs)  # type: ignore[arg-type]
