"""An orbit problem uploaded through `POST /v1/problems`: derived in polar coordinates by every method; a
model in which no circular orbit exists is refused saying why, at the quantity's path."""

from __future__ import annotations

from typing import Any

import pytest
import yaml

from tests.api.test_authoring import BANK, upload


def satellite(problem_id: str = "my-satellite") -> dict[str, Any]:
    doc = yaml.safe_load((BANK / "satellite-orbit" / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK / "satellite-orbit" / "model.yaml").read_text())
    doc["id"] = problem_id
    return doc


@pytest.mark.slow
def test_a_satellite_orbit_is_derived_by_every_method(client, instructor_headers):
    response = upload(client, instructor_headers, satellite())
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/my-satellite/solution", headers=instructor_headers).json()
    sources = {r["part"]: r["source"] for r in solution["references"]}
    assert sources["speed"] == sources["period"] == sources["energy"] == "derived"
    assert solution["methods_agree"] is True
    assert set(solution["agreement"]["period"]) >= {"lagrange", "newton", "conservation"}
    assert "revolution" in solution["simulation"]["period"]["compared"]


@pytest.mark.slow
def test_a_repulsive_centre_is_refused_with_the_reason(client, instructor_headers):
    doc = satellite("my-repelled-satellite")
    doc["model"]["potentials"][0]["energy"] = "G*M*m/d"
    response = upload(client, instructor_headers, doc)
    assert response.status_code == 422, response.text
    details = {d["path"]: d["message"] for d in response.json()["error"]["details"]}
    assert "pull towards the centre" in details["model.quantities.speed"]
