"""The problem document's shape: what is accepted, and every fault reported at once with its path."""

from __future__ import annotations

from collections.abc import Callable
from decimal import Decimal
from typing import Any

import pytest

from problems.errors import ProblemInvalid
from problems.loader import parse_problem
from problems.schema import NumericPart, ProblemDocument, SymbolicPart
from tests.problems.documents import spring

Doc = dict[str, Any]


def test_valid_document_round_trips_through_its_dump() -> None:
    doc = parse_problem(spring(), check_meaning=False)
    again = ProblemDocument.model_validate(doc.model_dump())
    assert again == doc
    assert isinstance(doc.parts[0], SymbolicPart) and isinstance(doc.parts[1], NumericPart)


def test_attempt_limits_are_optional_per_problem_and_per_part() -> None:
    data = spring()
    data["max_attempts"] = 5
    data["parts"][1]["max_attempts"] = 2
    doc = parse_problem(data, check_meaning=False)
    assert (doc.max_attempts, doc.parts[0].max_attempts, doc.parts[1].max_attempts) == (5, None, 2)


def test_numbers_are_kept_exactly_as_written() -> None:
    data = spring()
    data["given"]["m"]["min"] = 0.1
    doc = parse_problem(data, check_meaning=False)
    assert doc.given["m"].min == Decimal("0.1")


def test_numeric_part_defaults_to_one_percent_and_required_units() -> None:
    part = parse_problem(spring(), check_meaning=False).parts[1]
    assert isinstance(part, NumericPart)
    assert part.tolerance.rel == Decimal("0.01") and part.tolerance.abs is None
    assert part.units_required


def test_a_numeric_part_may_state_its_value_and_dumps_only_what_it_was_given() -> None:
    data = spring()
    del data["parts"][1]["of"]
    data["parts"][1]["value"] = "6.02214076e23"
    stated = parse_problem(data, check_meaning=False)
    part = stated.parts[1]
    assert isinstance(part, NumericPart) and (part.of, part.value) == (None, Decimal("6.02214076e23"))
    assert ProblemDocument.model_validate(stated.model_dump(mode="json")) == stated
    # Neither dump names the one it lacks: a document without `value` dumps (and hashes) as it always did.
    assert "of" not in stated.model_dump()["parts"][1]
    assert "value" not in parse_problem(spring(), check_meaning=False).model_dump()["parts"][1]


def test_symbolic_part_quantity_defaults_to_its_id() -> None:
    part = parse_problem(spring(), check_meaning=False).parts[0]
    assert isinstance(part, SymbolicPart) and part.quantity_name == "angular_frequency"


def _set(path: str, value: Any) -> Callable[[Doc], None]:
    def apply(doc: Doc) -> None:
        *head, last = path.split(".")
        target: Any = doc
        for key in head:
            target = target[int(key)] if isinstance(target, list) else target[key]
        if isinstance(target, list):
            target[int(last)] = value
        else:
            target[last] = value

    return apply


def _delete(path: str) -> Callable[[Doc], None]:
    def apply(doc: Doc) -> None:
        *head, last = path.split(".")
        target: Any = doc
        for key in head:
            target = target[int(key)] if isinstance(target, list) else target[key]
        del target[last]

    return apply


def _all(*changes: Callable[[Doc], None]) -> Callable[[Doc], None]:
    def apply(doc: Doc) -> None:
        for change in changes:
            change(doc)

    return apply


SHAPE_CASES = [
    pytest.param(
        _set("parts.1.tolerance", {"rel": -1}), {"parts[1].tolerance.rel": "must be >= 0"}, id="negative-rel"
    ),
    pytest.param(
        _set("parts.1.tolerance", {}),
        {"parts[1].tolerance": "give at least one of rel, abs, sigfigs"},
        id="empty-tolerance",
    ),
    pytest.param(_delete("title"), {"title": "required"}, id="missing-title"),
    pytest.param(
        _set("version", 3),
        {"version": "assigned by storage; remove it from the document"},
        id="version-in-file",
    ),
    pytest.param(_set("id", "Not A Slug"), {"id": None}, id="bad-slug"),
    pytest.param(
        _set("parts.0.kind", "essay"),
        {
            "parts[0].kind": "kind must be 'symbolic', 'numeric', 'choice', 'lagrangian', 'kinetic_energy', 'potential_energy', 'equation', 'data' or 'free_body'"
        },
        id="bad-kind",
    ),
    pytest.param(_delete("parts.1.units"), {"parts[1].units": "required"}, id="numeric-without-units"),
    pytest.param(_delete("parts.1.of"), {"parts[1].of": "required"}, id="numeric-without-quantity"),
    pytest.param(
        _set("parts.1.value", 4.5), {"parts[1].of": "give of or value, not both"}, id="numeric-of-and-value"
    ),
    pytest.param(
        _all(_delete("parts.1.of"), _set("parts.1.value", "1e999")),
        {"parts[1].value": "must be 0 or of size from 1e-100 to below 1e101"},
        id="numeric-unreadable-value",
    ),
    pytest.param(_set("given.m.sigfigs", 0), {"given.m.sigfigs": "must be >= 1"}, id="zero-sigfigs"),
    pytest.param(
        _set("given.m.step", 0.1), {"given.m": "give sigfigs or step, not both"}, id="sigfigs-and-step"
    ),
    pytest.param(
        _set("given.m.min", True), {"given.m.min": "must be a number, not true/false"}, id="bool-as-number"
    ),
    pytest.param(_set("given.m.max", float("nan")), {"given.m.max": "must be a finite number"}, id="nan"),
    pytest.param(
        _set("symbols.theta.range", [0]), {"symbols.theta.range[1]": "required"}, id="one-sided-range"
    ),
    pytest.param(
        _set("symbols.theta.range", [0, {}]),
        {"symbols.theta.range[1]": "must be a number or expression text"},
        id="range-bound-mapping",
    ),
    pytest.param(_set("parts.0.typo", 1), {"parts[0].typo": "unknown field"}, id="unknown-part-field"),
    pytest.param(_set("parts", []), {"parts": "must have at least 1 item"}, id="no-parts"),
    pytest.param(
        _set("parts.0.max_attempts", 0), {"parts[0].max_attempts": "must be >= 1"}, id="zero-attempts"
    ),
    pytest.param(  # in words, not the regular expression it is checked with
        _set("id", "Sled Problem"),
        {"id": "must be lower-case letters and digits, words joined by '-' (like sled-on-slope)"},
        id="id-said-in-words",
    ),
    pytest.param(
        _set("parts.0.id", "Normal-Force"),
        {
            "parts[0].id": "must start with a lower-case letter, then lower-case letters, digits or '_' "
            "(like normal_force)"
        },
        id="part-id-said-in-words",
    ),
    pytest.param(
        _all(_set("parts.1.tolerance", {"rel": -0.1}), _delete("statement"), _set("given.k.unit", 5)),
        {"parts[1].tolerance.rel": "must be >= 0", "statement": "required", "given.k.unit": "must be text"},
        id="three-faults-at-once",
    ),
]


@pytest.mark.parametrize(("change", "expected"), SHAPE_CASES)
def test_broken_document_lists_every_error_with_its_path(
    change: Callable[[Doc], None], expected: dict[str, str | None]
) -> None:
    data = spring()
    change(data)
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(data, check_meaning=False)
    found = dict(caught.value.errors)
    assert set(found) == set(expected), caught.value.errors
    for path, message in expected.items():
        if message is not None:
            assert found[path] == message


def test_problem_invalid_is_a_spec_error_naming_the_problem() -> None:
    from physics.errors import SpecError

    data = spring()
    del data["title"]
    with pytest.raises(SpecError, match="tiny-spring"):
        parse_problem(data, check_meaning=False)
