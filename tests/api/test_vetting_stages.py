"""An upload's vetting reports every error any stage can find at once: a shape or meaning fault elsewhere
does not hide the model's derivation faults, and a stage that cannot run says so at its path."""

from __future__ import annotations

from typing import Any

import pytest

from tests.api.test_authoring import atwood_upload, upload


def _details(response: Any) -> dict[str, str]:
    assert response.status_code == 422, response.text
    return {d["path"]: d["message"] for d in response.json()["error"]["details"]}


def _with_underivable_quantity(doc: dict[str, Any]) -> dict[str, Any]:
    """An Atwood machine has no equilibrium: no method derives an oscillation frequency."""
    doc["model"]["quantities"]["wobble"] = {"angular_frequency": "s"}
    doc["model"]["unused"] = ["wobble"]  # derived on purpose, so only its derivation can fault it
    return doc


def _bad_tolerance(doc: dict[str, Any]) -> None:
    doc["parts"][2]["tolerance"] = {"rel": -0.5}


def _given_in_wrong_unit(doc: dict[str, Any]) -> None:
    doc["given"]["g"]["unit"] = "kg"


@pytest.mark.parametrize(
    ("fault", "path"),
    [(_bad_tolerance, "parts[2].tolerance.rel"), (_given_in_wrong_unit, "given.g.unit")],
    ids=["shape", "meaning"],
)
def test_a_fault_outside_the_model_does_not_hide_its_derivation_faults(
    client, instructor_headers, fault, path
):
    doc = _with_underivable_quantity(atwood_upload())
    fault(doc)
    details = _details(upload(client, instructor_headers, doc))
    assert path in details
    assert "at least 2 are required" in details["model.quantities.wobble"]
    assert details["parts"].startswith("not self-tested")


def test_a_model_that_cannot_be_derived_for_faulty_symbols_says_so(client, instructor_headers):
    doc = atwood_upload()
    doc["symbols"]["m1"]["colour"] = "red"
    details = _details(upload(client, instructor_headers, doc))
    assert "symbols.m1.colour" in details
    assert details["model"].startswith("not derived: the symbols")
